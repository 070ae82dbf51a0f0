// The GL layer against a real context: buffers, uniform buffers, textures of every format,
// framebuffers, programs and their error messages, timer queries.
#include "GlTestContext.h"

#include <unistd.h>
#include <epoxy/gl.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <glm/glm.hpp>

#include "core/Error.h"
#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/TimerQuery.h"
#include "gl/UniformBuffer.h"
#include "gl/VertexArray.h"

using namespace specula;
using specula::test::GlTest;

namespace {

struct alignas(16) TestBlock {
    glm::vec4 a;
    glm::vec4 items[4];
    glm::vec4 b;
};

} // namespace

TEST_F(GlTest, BufferUpdatesOnlyTheRange)
{
    std::vector<uint8_t> initial(256);
    for (size_t i = 0; i < initial.size(); ++i) initial[i] = uint8_t(i);
    gl::Buffer buffer(initial.size(), initial.data(), "test buffer");
    const uint8_t patch[4] = {0xAA, 0xBB, 0xCC, 0xDD};
    buffer.update(100, 4, patch);
    const auto bytes = buffer.read(0, 256);
    for (size_t i = 0; i < 256; ++i) {
        const uint8_t expected = (i >= 100 && i < 104) ? patch[i - 100] : uint8_t(i);
        ASSERT_EQ(uint8_t(bytes[i]), expected) << "byte " << i;
    }
    EXPECT_EQ(buffer.lastUpdate().offset, 100u);
    EXPECT_EQ(buffer.lastUpdate().size, 4u);
    gl::Buffer moved = std::move(buffer);
    EXPECT_FALSE(buffer);
    EXPECT_TRUE(moved);
}

TEST_F(GlTest, UniformBufferUploadsOneFieldOrElement)
{
    gl::UniformBuffer<TestBlock> ubo("test block");
    auto before = ubo.buffer().read(0, sizeof(TestBlock));
    ubo.data().a = glm::vec4(1.0f);   // changed on the CPU, not uploaded
    ubo.data().items[2] = glm::vec4(7.0f, 8.0f, 9.0f, 10.0f);
    ubo.upload(&TestBlock::items, 2);
    EXPECT_EQ(ubo.buffer().lastUpdate().offset, offsetof(TestBlock, items) + 2 * sizeof(glm::vec4));
    EXPECT_EQ(ubo.buffer().lastUpdate().size, sizeof(glm::vec4));
    auto after = ubo.buffer().read(0, sizeof(TestBlock));
    for (size_t i = 0; i < sizeof(TestBlock); ++i) {
        const bool inside = i >= offsetof(TestBlock, items) + 32 && i < offsetof(TestBlock, items) + 48;
        if (!inside) {
            ASSERT_EQ(before[i], after[i]) << "byte " << i << " changed";
        }
    }
    float item[4];
    std::memcpy(item, after.data() + offsetof(TestBlock, items) + 32, 16);
    EXPECT_EQ(item[2], 9.0f);
    ubo.data().b = glm::vec4(3.0f);
    ubo.upload(&TestBlock::b);
    EXPECT_EQ(ubo.buffer().lastUpdate().offset, offsetof(TestBlock, b));
}

TEST_F(GlTest, TexturesOfEveryFormatRoundTrip)
{
    struct Case {
        gl::Format format;
        int channels;
    };
    const Case cases[] = {{gl::Format::R8, 1},      {gl::Format::RG8, 2},     {gl::Format::RGBA8, 4},
                          {gl::Format::R16F, 1},    {gl::Format::RG16F, 2},   {gl::Format::RGBA16F, 4},
                          {gl::Format::R32F, 1},    {gl::Format::RG32F, 2},   {gl::Format::RGBA32F, 4}};
    for (const Case& c : cases) {
        gl::TextureDesc desc;
        desc.format = c.format;
        desc.width = 4;
        desc.height = 2;
        gl::Texture texture(desc);
        std::vector<float> pixels(size_t(8 * c.channels));
        for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i % 5) * 0.25f;
        texture.upload(0, 0, c.channels, gl::PixelType::Float, pixels.data());
        const auto back = texture.readFloat(0, c.channels);
        for (size_t i = 0; i < pixels.size(); ++i) EXPECT_NEAR(back[i], pixels[i], 1.0 / 255.0) << int(c.format) << " " << i;
    }
    // sRGB: stored encoded, read back as stored; sampling decodes (tested through rendering).
    gl::TextureDesc srgb;
    srgb.format = gl::Format::SRGB8_ALPHA8;
    srgb.width = srgb.height = 2;
    gl::Texture s(srgb);
    const uint8_t bytes[16] = {0, 64, 128, 255, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120};
    s.upload(0, 0, 4, gl::PixelType::UnsignedByte, bytes);
    EXPECT_EQ(s.readBytes(0, 4), std::vector<uint8_t>(bytes, bytes + 16));
}

TEST_F(GlTest, MipmapsCubesArraysAndDepth)
{
    gl::TextureDesc desc;
    desc.format = gl::Format::RGBA8;
    desc.width = 64;
    desc.height = 16;
    desc.levels = 0;
    gl::Texture mipmapped(desc);
    EXPECT_EQ(mipmapped.levels(), 7);
    std::vector<uint8_t> white(64 * 16 * 4, 255);
    mipmapped.upload(0, 0, 4, gl::PixelType::UnsignedByte, white.data());
    mipmapped.generateMipmaps();
    EXPECT_EQ(mipmapped.readBytes(6, 4), std::vector<uint8_t>({255, 255, 255, 255}));

    gl::TextureDesc cube;
    cube.type = gl::TextureType::Cube;
    cube.format = gl::Format::RGBA16F;
    cube.width = cube.height = 8;
    gl::Texture cubeTexture(cube);
    std::vector<float> face(8 * 8 * 4);
    for (int f = 0; f < 6; ++f) {
        std::fill(face.begin(), face.end(), float(f));
        cubeTexture.upload(0, f, 4, gl::PixelType::Float, face.data());
    }
    const auto all = cubeTexture.readFloat(0, 4);
    ASSERT_EQ(all.size(), size_t(6 * 8 * 8 * 4));
    for (int f = 0; f < 6; ++f) EXPECT_EQ(all[size_t(f) * 8 * 8 * 4], float(f));

    gl::TextureDesc array;
    array.type = gl::TextureType::Texture2DArray;
    array.format = gl::Format::RG16F;
    array.width = array.height = 4;
    array.layers = 3;
    gl::Texture arrayTexture(array);
    std::vector<float> layer(4 * 4 * 2, 0.5f);
    arrayTexture.upload(0, 2, 2, gl::PixelType::Float, layer.data());

    gl::TextureDesc depth;
    depth.format = gl::Format::Depth32F;
    depth.width = depth.height = 4;
    gl::Texture depthTexture(depth);
    EXPECT_TRUE(depthTexture.isDepth());
}

TEST_F(GlTest, FramebufferWithFloatTargetsClearsAndReports)
{
    gl::TextureDesc desc;
    desc.format = gl::Format::RGBA16F;
    desc.width = desc.height = 8;
    gl::Texture color0(desc);
    desc.format = gl::Format::RGBA32F;
    gl::Texture color1(desc);
    desc.format = gl::Format::Depth24;
    gl::Texture depth(desc);
    gl::Framebuffer fb("two targets");
    fb.attachColor(0, color0).attachColor(1, color1).attachDepth(depth).check();
    fb.clearColor(1, 100000.0f, -2.0f, 0.25f, 1.0f);
    const auto pixels = color1.readFloat(0, 4);
    EXPECT_EQ(pixels[0], 100000.0f); // beyond half-float range: a true 32-bit float target
    EXPECT_EQ(pixels[1], -2.0f);

    // A framebuffer without attachments is incomplete: a clear error naming it.
    gl::Framebuffer empty("empty one");
    try {
        empty.check();
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("framebuffer 'empty one' is incomplete"), std::string::npos) << e.what();
    }
    // Mixing sample counts is incomplete too.
    gl::TextureDesc ms;
    ms.type = gl::TextureType::Texture2DMultisample;
    ms.samples = 4;
    ms.format = gl::Format::RGBA16F;
    ms.width = ms.height = 8;
    gl::Texture multisampled(ms);
    gl::Framebuffer mixed("mixed");
    mixed.attachColor(0, multisampled).attachColor(1, color1);
    EXPECT_THROW(mixed.check(), Error);
}

TEST_F(GlTest, ProgramErrorsNameFileAndLine)
{
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / ("specula-program-test-" + std::to_string(::getpid()));
    fs::create_directories(root / "lib");
    std::ofstream(root / "lib/broken.glsl") << "float ok() { return 1.0; }\nfloat bad() { return undefinedThing; }\n";
    std::ofstream(root / "test.vert") << "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    std::ofstream(root / "test.frag") << "#version 450 core\n#include \"lib/broken.glsl\"\nout vec4 c;\nvoid main() { c = vec4(bad()); }\n";
    try {
        gl::Program program({.vertex = "test.vert", .fragment = "test.frag", .root = root});
        FAIL() << "compiled a broken shader";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("shaders/lib/broken.glsl:2:"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    }
    // The driver also reported the compile error through KHR_debug: expected here.
    debug().clear();
    fs::remove_all(root);
}

TEST_F(GlTest, EveryShippedProgramCompiles)
{
    EXPECT_NO_THROW(gl::Program({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag"}));
    EXPECT_NO_THROW(gl::Program({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = {"BRDF_G_SCHLICK_GGX"}}));
    EXPECT_NO_THROW(gl::Program({.vertex = "post/fullscreen.vert", .fragment = "post/tonemap.frag"}));
}

TEST_F(GlTest, TimerQueryMeasuresWork)
{
    gl::TimerQuery query;
    query.begin();
    glFinish();
    query.end();
    EXPECT_GE(query.elapsedMs(), 0.0);
    EXPECT_TRUE(query.available());
}
