// Compute programs through the same loader: a shader writes its invocation ids to an image.
#include "GlTestContext.h"

#include <unistd.h>
#include <epoxy/gl.h>

#include <filesystem>
#include <fstream>

#include "gl/Program.h"
#include "gl/Texture.h"

using namespace specula;
using specula::test::GlTest;

TEST_F(GlTest, ComputeProgramWritesAnImage)
{
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / ("specula-compute-test-" + std::to_string(::getpid()));
    fs::create_directories(root);
    std::ofstream(root / "ids.comp") << "#version 450 core\n"
                                        "layout(local_size_x = 8, local_size_y = 8) in;\n"
                                        "layout(binding = 0, r32f) uniform writeonly image2D uOut;\n"
                                        "void main() { ivec2 p = ivec2(gl_GlobalInvocationID.xy);\n"
                                        "  imageStore(uOut, p, vec4(float(p.x + 100 * p.y))); }\n";
    const gl::Program program({.compute = "ids.comp", .label = "ids", .root = root});
    gl::TextureDesc desc;
    desc.format = gl::Format::R32F;
    desc.width = 16;
    desc.height = 8;
    gl::Texture image(desc);
    glUseProgram(program.id());
    glBindImageTexture(0, image.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glDispatchCompute(2, 1, 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    glUseProgram(0);
    const auto values = image.readFloat(0, 1);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) EXPECT_EQ(values[size_t(y * 16 + x)], float(x + 100 * y));
    fs::remove_all(root);
}
