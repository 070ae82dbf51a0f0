// Environments on the command line: the bake cache, `specula bake`, and bad environment files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "CliRunner.h"
#include "core/ImageIO.h"

namespace fs = std::filesystem;
using specula::test::runCli;
using specula::test::tempDir;

namespace {
const std::string kEnv = std::string(SPECULA_ASSETS_DIR) + "/env/";
}

TEST(CliEnvironment, SecondRunReadsTheBakeCache)
{
    const std::string dir = tempDir("bakecache");
    const std::string env = "SPECULA_CACHE_DIR=" + dir + "/cache ";
    const std::string command = "render learnopengl-ibl --env " + kEnv + "city_1k.hdr --width 64 --height 48 -o " + dir + "/out.png";
    // runCli prefixes the binary; set the variable through env(1).
    const auto first = runCli("--help >/dev/null; " + env + std::string(SPECULA_CLI_PATH) + " " + command);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_NE(first.err.find("baking environment"), std::string::npos) << first.err;
    const auto second = runCli("--help >/dev/null; " + env + std::string(SPECULA_CLI_PATH) + " " + command);
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_EQ(second.err.find("baking environment"), std::string::npos) << "baked again:\n" << second.err;
    EXPECT_NE(second.err.find("from the bake cache"), std::string::npos) << second.err;
    // The DFG table of the scene's BRDF too (the tutorial's Schlick-GGX); another BRDF
    // variant's table is baked once, then read.
    EXPECT_NE(first.err.find("baked the DFG table of ggx schlick-ggx schlick"), std::string::npos) << first.err;
    EXPECT_EQ(second.err.find("baked the DFG table"), std::string::npos) << second.err;
    const std::string variant = command + " --brdf-d beckmann --brdf-g neumann";
    const auto beckmann = runCli("--help >/dev/null; " + env + std::string(SPECULA_CLI_PATH) + " " + variant);
    ASSERT_EQ(beckmann.exitCode, 0) << beckmann.err;
    EXPECT_NE(beckmann.err.find("baked the DFG table of beckmann neumann schlick"), std::string::npos) << beckmann.err;
    const auto beckmannAgain = runCli("--help >/dev/null; " + env + std::string(SPECULA_CLI_PATH) + " " + variant);
    ASSERT_EQ(beckmannAgain.exitCode, 0) << beckmannAgain.err;
    EXPECT_EQ(beckmannAgain.err.find("baked the DFG table"), std::string::npos) << beckmannAgain.err;
    // A different bake preset is a different cache entry.
    const auto third = runCli("--help >/dev/null; " + env + std::string(SPECULA_CLI_PATH) + " " + command + " --bake-preset reference");
    ASSERT_EQ(third.exitCode, 0) << third.err;
    EXPECT_NE(third.err.find("baking environment"), std::string::npos) << third.err;
}

// Without an environment the DFG table is still needed (energy compensation under punctual
// lights), and cached like the others.
TEST(CliEnvironment, DfgTableIsCachedWithoutAnEnvironment)
{
    const std::string dir = tempDir("dfgcache");
    const std::string env = "SPECULA_CACHE_DIR=" + dir + "/cache ";
    const std::string command = "render learnopengl --width 64 --height 48 -o " + dir + "/out.png";
    const auto first = runCli("--help >/dev/null; " + env + std::string(SPECULA_CLI_PATH) + " " + command);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_NE(first.err.find("baked the DFG table of ggx schlick-ggx schlick"), std::string::npos) << first.err;
    const auto second = runCli("--help >/dev/null; " + env + std::string(SPECULA_CLI_PATH) + " " + command);
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_EQ(second.err.find("baked the DFG table"), std::string::npos) << "baked again:\n" << second.err;
}

TEST(CliEnvironment, BakeCommandPrintsWhatItWrote)
{
    const std::string dir = tempDir("bakecmd");
    const auto r = runCli("bake " + kEnv + "venice_1k.hdr --cache-dir " + dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("wrote " + dir), std::string::npos) << r.out;
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) files += entry.path().extension() == ".bin";
    EXPECT_EQ(files, 2u); // the environment and the glTF BRDF's DFG table
    const auto again = runCli("bake " + kEnv + "venice_1k.hdr --cache-dir " + dir);
    EXPECT_NE(again.out.find("already cached"), std::string::npos) << again.out;
}

TEST(CliEnvironment, BadEnvironmentFiles)
{
    const std::string dir = tempDir("badenv");
    std::ifstream in(kEnv + "city_1k.hdr", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir + "/cut.hdr", std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 3));
    std::ifstream inExr(kEnv + "city.exr", std::ios::binary);
    std::string exr((std::istreambuf_iterator<char>(inExr)), std::istreambuf_iterator<char>());
    std::ofstream(dir + "/cut.exr", std::ios::binary).write(exr.data(), std::streamsize(exr.size() / 2));
    for (const std::string file : {"cut.hdr", "cut.exr", "missing.hdr"}) {
        const auto r = runCli("render --env " + dir + "/" + file + " --no-cache -o " + dir + "/out.png");
        EXPECT_NE(r.exitCode, 0) << file;
        EXPECT_LT(r.exitCode, 128) << file << " crashed";
        EXPECT_EQ(r.errorLines(), 1) << r.err;
        EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir + "/out.png"));
    }
    const auto color = runCli("render --env-color 1,x,2 -o " + dir + "/out.png");
    EXPECT_NE(color.exitCode, 0);
    EXPECT_EQ(color.errorLines(), 1) << color.err;
    const auto sky = runCli("render --skybox blur=3 -o " + dir + "/out.png");
    EXPECT_NE(sky.exitCode, 0);
    EXPECT_EQ(sky.errorLines(), 1) << sky.err;
}

TEST(CliEnvironment, ExrEnvironmentRenders)
{
    const std::string dir = tempDir("exrenv");
    const auto r = runCli("render --env " + kEnv + "studio.exr --env-rotation 45 --env-intensity 0.5 --skybox blur=0.3 --no-cache "
                          "--width 64 --height 48 -o " + dir + "/out.png");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/out.png"));
}

TEST(CliEnvironment, SunExtractionAndImportanceSampledSpecular)
{
    // --env-sun extract turns park_1k's sun into a directional light (SunExtraction's tests
    // check its numbers); --ibl importance renders; bad values of either are one-line errors.
    const std::string dir = tempDir("envsun");
    const auto sun = runCli("render --env " + kEnv + "park_1k.hdr --env-sun extract --ibl importance --no-cache --width 64 "
                            "--height 48 -o " + dir + "/sun.png");
    EXPECT_EQ(sun.exitCode, 0) << sun.err;
    EXPECT_NE(sun.err.find("now a directional light"), std::string::npos) << sun.err;
    EXPECT_TRUE(fs::exists(dir + "/sun.png"));
    const auto noSun = runCli("render --env " + kEnv + "studio_1k.hdr --env-sun extract --no-cache --width 32 --height 24 -o " +
                              dir + "/studio.png");
    EXPECT_EQ(noSun.exitCode, 0) << noSun.err;
    EXPECT_NE(noSun.err.find("has no sun"), std::string::npos) << noSun.err;
    for (const std::string bad : {"--env-sun maybe", "--ibl fancy"}) {
        const auto r = runCli("render " + bad + " -o " + dir + "/bad.png");
        EXPECT_NE(r.exitCode, 0) << bad;
        EXPECT_EQ(r.errorLines(), 1) << r.err;
        EXPECT_FALSE(fs::exists(dir + "/bad.png"));
    }
}

// `specula bake --env-sun extract` writes the entry that render --env-sun extract reads: the map
// less its sun (its own cache key). Expected: render names bake's file as the one it read.
// Fails if bake writes the whole map (the key without the extraction's mark).
TEST(CliEnvironment, BakeWarmsTheExtractedSunsEntry)
{
    const std::string dir = tempDir("bakesun");
    const auto bake = runCli("bake " + kEnv + "park_1k.hdr --env-sun extract");
    ASSERT_EQ(bake.exitCode, 0) << bake.err;
    const size_t at = bake.out.find(" /");
    ASSERT_NE(at, std::string::npos) << bake.out;
    const std::string file = bake.out.substr(at + 1, bake.out.find(' ', at + 1) - at - 1);
    EXPECT_NE(file.find(":sun-extracted"), std::string::npos) << file;
    const auto render = runCli("render --env " + kEnv + "park_1k.hdr --env-sun extract --width 32 --height 24 -o " + dir + "/sun.png");
    ASSERT_EQ(render.exitCode, 0) << render.err;
    EXPECT_NE(render.err.find("environment from the bake cache " + file), std::string::npos) << file << "\n" << render.err;
    const auto bad = runCli("bake " + kEnv + "park_1k.hdr --env-sun maybe");
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_EQ(bad.errorLines(), 1) << bad.err;
}

// An environment wider than the GPU's texture limit (16384 on llvmpipe; the fuzzer's OpenEXR
// file was 5,373,953 × 2) is downscaled with a warning before the bake uploads it, not a GL
// error: it renders, exit 0.
TEST(CliEnvironment, EnvironmentWiderThanTheTextureLimitIsDownscaled)
{
    const std::string dir = tempDir("wideenv");
    specula::ImageFloat wide;
    wide.width = 16400;
    wide.height = 2;
    wide.pixels.assign(size_t(wide.width) * size_t(wide.height) * 4, 0.5f);
    specula::writeHdr(dir + "/wide.hdr", wide);
    const auto r = runCli("render --env " + dir + "/wide.hdr --no-cache --width 32 --height 18 -o " + dir + "/out.png");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("the environment is 16400x2, larger than this GPU's texture limit of"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("OpenGL reported"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/out.png"));
}
