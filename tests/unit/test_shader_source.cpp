// The GLSL include loader: resolution, include-once, cycles, #line mapping of errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "core/Error.h"
#include "gl/ShaderSource.h"

namespace fs = std::filesystem;
using namespace specula;

namespace {

class ShaderSourceTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        root = fs::temp_directory_path() / ("specula-shaders-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        fs::create_directories(root / "brdf");
        fs::create_directories(root / "common");
    }
    void TearDown() override { fs::remove_all(root); }
    void write(const std::string& path, const std::string& text) { std::ofstream(root / path) << text; }
    fs::path root;
};

} // namespace

TEST_F(ShaderSourceTest, ResolvesIncludesOnceWithLineDirectives)
{
    write("common/math.glsl", "const float PI = 3.14;\n");
    write("brdf/ggx.glsl", "#include \"../common/math.glsl\"\nfloat D() { return PI; }\n");
    write("main.frag", "#version 450 core\n#include \"brdf/ggx.glsl\"\n#include \"common/math.glsl\"\nvoid main() {}\n");
    const gl::ShaderSource source = gl::loadShaderSource(root, "main.frag", {"FOO 1"});
    EXPECT_EQ(source.text.rfind("#version 450 core\n#define FOO 1\n", 0), 0u) << source.text;
    // math.glsl included twice: emitted twice, each time inside the same guard, so the GLSL
    // preprocessor keeps the first (IncludeOnceFollowsThePreprocessor compiles this).
    const size_t first = source.text.find("const float PI"), second = source.text.rfind("const float PI");
    EXPECT_NE(first, second);
    EXPECT_NE(source.text.rfind("#ifndef SPECULA_INCLUDED_2\n#define SPECULA_INCLUDED_2\n", first), std::string::npos);
    EXPECT_NE(source.text.find("#ifndef SPECULA_INCLUDED_2\n#define SPECULA_INCLUDED_2\n", first), std::string::npos);
    ASSERT_EQ(source.files.size(), 3u);
    EXPECT_EQ(source.files[0], "main.frag");
    EXPECT_EQ(source.files[1], "brdf/ggx.glsl");
    EXPECT_EQ(source.files[2], "common/math.glsl");
    // After the include of ggx.glsl the main file continues at its line 3.
    // Line numbers encode the file: file * 100000 + line.
    EXPECT_NE(source.text.find("#line 3 0\n"), std::string::npos) << source.text;
    EXPECT_NE(source.text.find("#line 100002 1\nfloat D()"), std::string::npos) << source.text;
}

TEST_F(ShaderSourceTest, ReportsCycles)
{
    write("a.glsl", "#include \"b.glsl\"\n");
    write("b.glsl", "#include \"a.glsl\"\n");
    write("main.frag", "#version 450 core\n#include \"a.glsl\"\n");
    try {
        gl::loadShaderSource(root, "main.frag");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "shader include cycle: a.glsl -> b.glsl -> a.glsl");
    }
}

TEST_F(ShaderSourceTest, MissingIncludeNamesFileAndLine)
{
    write("main.frag", "#version 450 core\n\n#include \"nope.glsl\"\n");
    try {
        gl::loadShaderSource(root, "main.frag");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "shaders/main.frag:3: cannot include \"nope.glsl\": file not found");
    }
    EXPECT_THROW(gl::loadShaderSource(root, "absent.frag"), Error);
}

TEST(ShaderLog, MapsMesaAndNvidiaReferencesToFiles)
{
    const std::vector<std::string> files = {"forward/pbr.frag", "brdf/ggx.glsl"};
    EXPECT_EQ(gl::mapShaderLog("1:41(12): error: `x' undeclared\n", files), "shaders/brdf/ggx.glsl:41: error: `x' undeclared");
    EXPECT_EQ(gl::mapShaderLog("0(7) : error C1008: undefined variable \"y\"", files),
              "shaders/forward/pbr.frag:7: error C1008: undefined variable \"y\"");
    EXPECT_EQ(gl::mapShaderLog("0:100041(3): error: z", files), "shaders/brdf/ggx.glsl:41: error: z");
    EXPECT_EQ(gl::mapShaderLog("something else", files), "something else");
}

// A file first included where the preprocessor drops it is still there where it is included
// again: include-once is the GLSL preprocessor's decision (guards), not the loader's. Checked
// by compiling with glslangValidator: a loader that skipped the second include fails with
// "undeclared identifier".
TEST_F(ShaderSourceTest, IncludeOnceFollowsThePreprocessor)
{
    ASSERT_EQ(std::system("command -v glslangValidator >/dev/null"), 0) << "glslangValidator missing (Debian: glslang-tools)";
    write("common/math.glsl", "const float PI = 3.14;\n");
    write("main.frag", "#version 450 core\n#if defined(NEVER)\n#include \"common/math.glsl\"\n#endif\n"
                       "#include \"common/math.glsl\"\n#include \"common/math.glsl\"\n"
                       "layout(location = 0) out vec4 colour;\nvoid main() { colour = vec4(PI); }\n");
    const gl::ShaderSource source = gl::loadShaderSource(root, "main.frag", {});
    std::ofstream(root / "expanded.frag") << source.text;
    const fs::path log = root / "log.txt";
    const int status = std::system(("glslangValidator " + (root / "expanded.frag").string() + " >" + log.string() + " 2>&1").c_str());
    std::ifstream in(log);
    const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(status, 0) << gl::mapShaderLog(output, source.files) << "\n" << source.text;
}
