// The package as a user gets it: `cmake --install` to a fresh prefix, examples/embed built
// against it by a separate CMake configure (find_package(Specula)) and by pkg-config, run away
// from the build tree, and the installed command line run from elsewhere, moved, and without
// its shaders on disk. One process, in order: each test uses what the ones before it made.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "core/ImageIO.h"
#include "specula/Version.h"

namespace fs = std::filesystem;
using specula::ImageRGBA8;

namespace {

const fs::path kWork = fs::path(SPECULA_TEST_OUTPUT_DIR) / "install";
const fs::path kPrefix = kWork / "prefix";
const fs::path kMoved = kWork / "prefix-moved";
const fs::path kModel = fs::path(SPECULA_ASSETS_DIR) / "models/BoxTextured/BoxTextured.gltf";

struct Result {
    int code = -1;
    std::string output; // stdout and stderr
};

/// Runs `command` with sh from `cwd`, without SPECULA_SHADER_DIR: what a user's shell has.
Result run(const std::string& command, const fs::path& cwd = kWork)
{
    const std::string line = "cd '" + cwd.string() + "' && env -u SPECULA_SHADER_DIR " + command + " 2>&1";
    Result result;
    FILE* pipe = ::popen(line.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    result.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    return result;
}

std::string quoted(const fs::path& path)
{
    return "'" + path.string() + "'";
}

struct Rgb {
    double r = 0, g = 0, b = 0;
};

Rgb pixel(const ImageRGBA8& image, int x, int y)
{
    const size_t i = (size_t(y) * size_t(image.width) + size_t(x)) * 4;
    return {double(image.pixels[i]), double(image.pixels[i + 1]), double(image.pixels[i + 2])};
}

Rgb mean(const ImageRGBA8& image)
{
    Rgb sum;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Rgb p = pixel(image, x, y);
            sum.r += p.r, sum.g += p.g, sum.b += p.b;
        }
    const double n = double(image.width) * image.height;
    return {sum.r / n, sum.g / n, sum.b / n};
}

int maxDifference(const ImageRGBA8& a, const ImageRGBA8& b)
{
    if (a.width != b.width || a.height != b.height) return 256;
    int worst = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) worst = std::max(worst, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
    return worst;
}

/// BoxTextured framed under the procedural sky, 320×240 (measured: centre (3, 46, 93), sky
/// (124, 135, 155), ground (59, 55, 51), mean (67, 76, 84)): the logo's blue at the centre, a
/// bright bluish sky above, the darker ground below. Broken shaders, no environment or a black
/// frame fail it.
void expectBoxUnderSky(const fs::path& file)
{
    SCOPED_TRACE(file.string());
    const ImageRGBA8 image = specula::readPng(file);
    ASSERT_EQ(image.width, 320);
    ASSERT_EQ(image.height, 240);
    const Rgb centre = pixel(image, 160, 120), sky = pixel(image, 160, 4), ground = pixel(image, 160, 236);
    const Rgb average = mean(image);
    EXPECT_GT(centre.b, centre.r + 40.0) << "the logo's blue";
    EXPECT_GT(centre.b, 60.0) << "the logo is lit";
    EXPECT_GT(sky.r, 90.0) << "the sky";
    EXPECT_GT(sky.b, sky.r + 10.0) << "the sky is blue";
    EXPECT_LT(ground.r + ground.g + ground.b, sky.r + sky.g + sky.b - 100.0) << "the ground is darker";
    const double sum = average.r + average.g + average.b;
    EXPECT_GT(sum, 150.0) << "not black";
    EXPECT_LT(sum, 350.0) << "not white";
}

std::string slurp(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

} // namespace

TEST(Install, InstallsToAPrefix)
{
    fs::remove_all(kWork);
    fs::create_directories(kWork / "elsewhere");
    const Result install = run(std::string(SPECULA_CMAKE_COMMAND) + " --install " + quoted(SPECULA_BUILD_DIR) +
                            " --prefix " + quoted(kPrefix));
    ASSERT_EQ(install.code, 0) << install.output;
    for (const char* file : {"bin/specula", "include/specula/Specula.h", "include/specula/Version.h",
                             "include/specula/render/Renderer.h", "include/specula/core/Error.h",
                             "share/specula/shaders/forward/pbr.vert", "share/man/man1/specula.1",
                             "share/doc/specula/README.md", "share/doc/specula/api.md"})
        EXPECT_TRUE(fs::is_regular_file(kPrefix / file)) << file;
    const fs::path lib = fs::exists(kPrefix / "lib/libspecula.a") || fs::exists(kPrefix / "lib/libspecula.so")
                             ? kPrefix / "lib"
                             : kPrefix / "lib/x86_64-linux-gnu";
    EXPECT_TRUE(fs::exists(lib / "cmake/Specula/SpeculaConfig.cmake"));
    EXPECT_TRUE(fs::exists(lib / "pkgconfig/specula.pc"));
    // No GL in the public API: no header of the GL layer or the renderer's internals, and no
    // GL type named in any installed header.
    EXPECT_FALSE(fs::exists(kPrefix / "include/specula/gl"));
    EXPECT_FALSE(fs::exists(kPrefix / "include/specula/render/ImageBasedLighting.h"));
    for (const auto& entry : fs::recursive_directory_iterator(kPrefix / "include/specula")) {
        if (!entry.is_regular_file()) continue;
        const std::string text = slurp(entry.path());
        for (const char* word : {"gl::", "GLuint", "GLenum", "<epoxy/", "<EGL/", "<GL/", "\"gl/"})
            EXPECT_EQ(text.find(word), std::string::npos) << entry.path() << " names " << word;
    }
}

TEST(Install, ExampleBuildsWithFindPackageAndRenders)
{
    const fs::path build = kWork / "example-cmake";
    std::string configure = std::string(SPECULA_CMAKE_COMMAND) + " -S " + quoted(fs::path(SPECULA_SOURCE_DIR) / "examples/embed") +
                            " -B " + quoted(build) + " -G '" SPECULA_CMAKE_GENERATOR "' -DCMAKE_BUILD_TYPE=Release" +
                            " -DCMAKE_PREFIX_PATH=" + quoted(kPrefix) + " -DCMAKE_CXX_COMPILER=" SPECULA_CXX_COMPILER +
                            " '-DCMAKE_CXX_FLAGS=" SPECULA_EXAMPLE_CXX_FLAGS "'";
    if (std::string(SPECULA_CXX_LAUNCHER).size()) configure += " -DCMAKE_CXX_COMPILER_LAUNCHER=" SPECULA_CXX_LAUNCHER;
    const Result configured = run(configure);
    ASSERT_EQ(configured.code, 0) << configured.output;
    EXPECT_NE(configured.output.find("its shaders: " + fs::weakly_canonical(kPrefix / "share/specula/shaders").string()),
              std::string::npos)
        << configured.output;
    const Result built = run(std::string(SPECULA_CMAKE_COMMAND) + " --build " + quoted(build));
    ASSERT_EQ(built.code, 0) << built.output;

    // Run from elsewhere: nothing beside the program but the program.
    const fs::path elsewhere = kWork / "elsewhere";
    const Result rendered = run(quoted(build / "specula_embed") + " " + quoted(kModel) + " embed.png", elsewhere);
    ASSERT_EQ(rendered.code, 0) << rendered.output;
    EXPECT_NE(rendered.output.find("Specula 0."), std::string::npos) << rendered.output;
    expectBoxUnderSky(elsewhere / "embed.png");

    // The same frame from the installed command line: the library in someone else's program
    // renders what specula renders with the same settings (its defaults, bloom on; identical
    // here, 2 levels allowed for rounding).
    const Result cli = run(quoted(kPrefix / "bin/specula") + " render " + quoted(kModel) +
                            " --width 320 --height 240 --bloom on -o cli.png",
                        elsewhere);
    ASSERT_EQ(cli.code, 0) << cli.output;
    EXPECT_LE(maxDifference(specula::readPng(elsewhere / "embed.png"), specula::readPng(elsewhere / "cli.png")), 2);

    // A bad argument is an error message and a non-zero exit, not a crash.
    const Result missing = run(quoted(build / "specula_embed") + " no-such.glb x.png", elsewhere);
    EXPECT_EQ(missing.code, 1) << missing.output;
    EXPECT_NE(missing.output.find("no-such.glb"), std::string::npos) << missing.output;
}

TEST(Install, ExampleBuildsWithPkgConfig)
{
    const fs::path lib = fs::exists(kPrefix / "lib/pkgconfig") ? kPrefix / "lib" : kPrefix / "lib/x86_64-linux-gnu";
    const fs::path program = kWork / "specula_embed_pc";
    const Result built = run("env PKG_CONFIG_PATH=" + quoted(lib / "pkgconfig") + " sh -c '" SPECULA_CXX_COMPILER
                          " -std=c++20 " SPECULA_EXAMPLE_CXX_FLAGS " -o " + program.string() + " " +
                          (fs::path(SPECULA_SOURCE_DIR) / "examples/embed/main.cpp").string() +
                          " $(pkg-config --cflags --libs specula)'");
    ASSERT_EQ(built.code, 0) << built.output;
    const Result rendered = run(quoted(program) + " " + quoted(kModel) + " embed-pc.png", kWork / "elsewhere");
    ASSERT_EQ(rendered.code, 0) << rendered.output;
    expectBoxUnderSky(kWork / "elsewhere/embed-pc.png");
}

TEST(Install, CommandLineRunsFromTheInstallPrefixAlone)
{
    const fs::path elsewhere = kWork / "elsewhere";
    const fs::path specula = kPrefix / "bin/specula";
    const Result version = run(quoted(specula) + " --version", elsewhere);
    EXPECT_EQ(version.code, 0);
    EXPECT_EQ(version.output, "specula " SPECULA_VERSION_STRING "\n");
    const Result info = run(quoted(specula) + " info", elsewhere);
    EXPECT_EQ(info.code, 0) << info.output;

    // The installed binary holds no path into the source or build tree among its constants:
    // its shaders are found relative to itself, or embedded.
    const Result rodata = run("objcopy -O binary --only-section=.rodata " + quoted(specula) + " rodata.bin");
    ASSERT_EQ(rodata.code, 0) << rodata.output;
    const std::string constants = slurp(kWork / "rodata.bin");
    ASSERT_GT(constants.size(), 1000u);
    EXPECT_EQ(constants.find(SPECULA_SOURCE_DIR "/shaders"), std::string::npos);
    // A sanitizer build keeps the names of the files it compiled for its reports (ASan's
    // globals, UBSan's source locations), and some of those are headers and generated sources
    // under the build tree: names only, never opened. Nothing else may point into the tree.
    const std::string build = SPECULA_BUILD_DIR;
    for (size_t at = constants.find(build); at != std::string::npos; at = constants.find(build, at + 1)) {
        const std::string path = constants.substr(at, constants.find('\0', at) - at);
#ifdef SPECULA_SANITIZE
        const bool reportName = path.starts_with(build + "/include/") || path.starts_with(build + "/generated/");
#else
        const bool reportName = false;
#endif
        EXPECT_TRUE(reportName) << "the installed binary holds a path into the build tree: " << path;
    }

    const std::string demo = " render --width 160 --height 120 --msaa 1 -o ";
    const Result rendered = run(quoted(specula) + demo + "demo.png", elsewhere);
    ASSERT_EQ(rendered.code, 0) << rendered.output;
    const ImageRGBA8 image = specula::readPng(elsewhere / "demo.png");
    const Rgb average = mean(image);
    EXPECT_GT(average.r + average.g + average.b, 60.0);

    // It reads the shaders installed beside it: broken there, it fails and names the file.
    const fs::path forward = kPrefix / "share/specula/shaders/forward/pbr.vert";
    const std::string good = slurp(forward);
    { std::ofstream(forward, std::ios::binary) << "#version 450 core\nthis is not GLSL\n"; }
    const Result broken = run(quoted(specula) + demo + "broken.png", elsewhere);
    EXPECT_NE(broken.code, 0);
    EXPECT_NE(broken.output.find("forward/pbr.vert"), std::string::npos) << broken.output;
    { std::ofstream(forward, std::ios::binary) << good; }

    // Moved, and then with no shaders on disk at all (the embedded copy): the same image.
    fs::rename(kPrefix, kMoved);
    const Result moved = run(quoted(kMoved / "bin/specula") + demo + "moved.png", elsewhere);
    ASSERT_EQ(moved.code, 0) << moved.output;
    fs::remove_all(kMoved / "share/specula/shaders");
    const Result embedded = run(quoted(kMoved / "bin/specula") + demo + "embedded.png", elsewhere);
    fs::rename(kMoved, kPrefix);
    ASSERT_EQ(embedded.code, 0) << embedded.output;
    EXPECT_EQ(maxDifference(image, specula::readPng(elsewhere / "moved.png")), 0);
    EXPECT_EQ(maxDifference(image, specula::readPng(elsewhere / "embedded.png")), 0);
}
