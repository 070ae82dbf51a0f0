// The shaders embedded in the library at build time (gl/EmbeddedShaders.h) are shaders/, file
// for file, and the loader reads them as it reads the directory.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include "TestFiles.h"
#include "gl/EmbeddedShaders.h"
#include "gl/Program.h"
#include "gl/ShaderSource.h"

namespace fs = std::filesystem;
using namespace specula;

namespace {

const fs::path kShaders = fs::path(SPECULA_SOURCE_DIR) / "shaders";

bool isShader(const fs::path& path)
{
    static const std::set<std::string> extensions{".glsl", ".vert", ".frag", ".comp", ".h"};
    return extensions.count(path.extension().string()) > 0;
}

} // namespace

TEST(EmbeddedShaders, AreTheSourceTreesShadersFileForFile)
{
    size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(kShaders)) {
        if (!entry.is_regular_file() || !isShader(entry.path())) continue;
        ++files;
        const std::string path = fs::relative(entry.path(), kShaders).generic_string();
        const gl::EmbeddedShader* embedded = gl::findEmbeddedShader(path);
        ASSERT_NE(embedded, nullptr) << path;
        EXPECT_EQ(embedded->text, test::readFile(entry.path())) << path;
    }
    EXPECT_GT(files, 40u);
    EXPECT_EQ(gl::embeddedShaders().size(), files);
    EXPECT_EQ(gl::findEmbeddedShader("forward/no-such.frag"), nullptr);
}

TEST(EmbeddedShaders, LoadLikeTheDirectory)
{
    for (const char* path : {"forward/pbr.frag", "forward/pbr.vert", "ibl/prefilter.comp", "post/bloom_downsample.comp"}) {
        const gl::ShaderSource disk = gl::loadShaderSource(kShaders, path, {"SPECULA_IBL 1"});
        const gl::ShaderSource embedded = gl::loadShaderSource({}, path, {"SPECULA_IBL 1"});
        EXPECT_EQ(embedded.text, disk.text) << path;
        EXPECT_EQ(embedded.files, disk.files) << path;
    }
    EXPECT_THROW(gl::loadShaderSource({}, "forward/no-such.frag"), Error);
}

TEST(EmbeddedShaders, TheBuildTreeReadsTheSourcesOnDisk)
{
    // build/share/specula/shaders links to shaders/: edits and hot reload need no rebuild.
    if (std::getenv("SPECULA_SHADER_DIR")) GTEST_SKIP() << "SPECULA_SHADER_DIR is set";
    EXPECT_EQ(fs::weakly_canonical(gl::shaderRoot()), fs::weakly_canonical(kShaders));
}
