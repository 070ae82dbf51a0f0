// Post-processing from the command line and the scene file: the pass switches and parameters,
// --ev100, --stats (a per-pass GPU table on stdout), --debug-view ssao|bloom, bench's table,
// and one clear line for every bad value.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <type_traits>

#include "CliRunner.h"
#include "core/ImageIO.h"
#include "settings/PassSettings.h"

namespace fs = std::filesystem;
using specula::test::runCli;
using specula::test::tempDir;

namespace {

// Small frames and the constant-colour environment keep each run short.
const std::string kSmall = " --width 96 --height 54 --env-color 0.2,0.2,0.2 ";

double sumRed(const specula::ImageFloat& image)
{
    double sum = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 4) sum += image.pixels[i];
    return sum;
}

void expectOneLineFailure(const std::string& arguments, const std::string& phrase)
{
    const auto r = runCli(arguments);
    EXPECT_NE(r.exitCode, 0) << arguments;
    EXPECT_LT(r.exitCode, 128) << "crashed: " << r.err;
    EXPECT_EQ(r.errorLines(), 1) << r.err;
    EXPECT_NE(r.err.find(phrase), std::string::npos) << "expected '" << phrase << "' in: " << r.err;
}

} // namespace

TEST(CliPost, EveryPassWithStats)
{
    const std::string dir = tempDir("post-stats");
    const auto r = runCli("render" + kSmall + "--bloom on --ssao on --fxaa on --auto-exposure on --bloom-intensity 0.1 "
                          "--bloom-levels 4 --bloom-radius 1.5 --bloom-threshold 0 --ssao-radius 0.3 --ssao-bias 0.01 "
                          "--ssao-power 2 --ssao-samples 8 --tonemap agx --stats -o " + dir + "/all.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* pass : {"wall ms", "ssao prepass", "ssao blur", "forward", "resolve", "bloom", "exposure", "tonemap", "fxaa", "total"})
        EXPECT_NE(r.out.find(pass), std::string::npos) << pass << " missing from:\n" << r.out;
    EXPECT_EQ(specula::readPng(dir + "/all.png").width, 96);
    // Without the passes the table has just the two passes of the plain frame.
    const auto plain = runCli("render" + kSmall + "--stats -o " + dir + "/plain.png");
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    EXPECT_NE(plain.out.find("resolve+tonemap"), std::string::npos) << plain.out;
    EXPECT_EQ(plain.out.find("bloom"), std::string::npos) << plain.out;
}

TEST(CliPost, BloomAddsLightAndTheSceneFileSwitchesIt)
{
    const std::string dir = tempDir("post-bloom");
    ASSERT_EQ(runCli("render" + kSmall + "-o " + dir + "/off.exr").exitCode, 0);
    ASSERT_EQ(runCli("render" + kSmall + "--bloom on --bloom-intensity 0.5 --bloom-firefly-filter off -o " + dir + "/on.exr").exitCode, 0);
    const double off = sumRed(specula::readFloatImage(dir + "/off.exr"));
    const double on = sumRed(specula::readFloatImage(dir + "/on.exr"));
    // The glow adds intensity × the frame's energy (a little leaves through the border).
    EXPECT_NEAR(on / off, 1.5, 0.05);

    std::ofstream(dir + "/scene.json") << R"({"shapes": [{"type": "sphere"}],
        "post": {"bloom": {"intensity": 0.5, "fireflyFilter": false}}, "render": {"width": 96, "height": 54}})";
    ASSERT_EQ(runCli("render " + dir + "/scene.json --env-color 0.2,0.2,0.2 -o " + dir + "/file.exr").exitCode, 0);
    ASSERT_EQ(runCli("render " + dir + "/scene.json --env-color 0.2,0.2,0.2 --bloom off -o " + dir + "/override.exr").exitCode, 0);
    const double file = sumRed(specula::readFloatImage(dir + "/file.exr"));
    const double overridden = sumRed(specula::readFloatImage(dir + "/override.exr"));
    EXPECT_NEAR(file / overridden, 1.5, 0.05) << "--bloom off on the command line wins over the file";
}

TEST(CliPost, PhysicalCameraExposure)
{
    const std::string dir = tempDir("post-ev100");
    ASSERT_EQ(runCli("render" + kSmall + "-o " + dir + "/plain.exr").exitCode, 0);
    ASSERT_EQ(runCli("render" + kSmall + "--ev100 4 --exposure 1 -o " + dir + "/camera.exr").exitCode, 0);
    const double plain = sumRed(specula::readFloatImage(dir + "/plain.exr"));
    const double camera = sumRed(specula::readFloatImage(dir + "/camera.exr"));
    // 2^1 / (1.2 × 2^4), within half-float rounding.
    EXPECT_NEAR(camera / plain, 2.0 / (1.2 * 16.0), 0.002);

    std::ofstream(dir + "/camera.json") << R"({"shapes": [{"type": "sphere"}],
        "camera": {"position": [0, 0, 4], "aperture": 4, "shutter": 0.0625, "iso": 100}})";
    // f/4, 1/16 s, ISO 100: EV100 = log2(16 × 16) = 8.
    ASSERT_EQ(runCli("render " + dir + "/camera.json" + kSmall + "-o " + dir + "/file.exr").exitCode, 0);
    ASSERT_EQ(runCli("render " + dir + "/camera.json" + kSmall + "--ev100 8 -o " + dir + "/flag.exr").exitCode, 0);
    EXPECT_EQ(specula::readFloatImage(dir + "/file.exr").pixels, specula::readFloatImage(dir + "/flag.exr").pixels);
}

TEST(CliPost, DebugViews)
{
    const std::string dir = tempDir("post-debug");
    const auto ssao = runCli("render" + kSmall + "--debug-view ssao -o " + dir + "/ssao.png");
    ASSERT_EQ(ssao.exitCode, 0) << ssao.err;
    const specula::ImageRGBA8 image = specula::readPng(dir + "/ssao.png");
    // Occlusion as grey: mostly open (white), some contact shadow under the spheres.
    int white = 0, darker = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        EXPECT_EQ(image.pixels[i], image.pixels[i + 1]);
        white += image.pixels[i] > 250;
        darker += image.pixels[i] < 200;
    }
    EXPECT_GT(white, int(image.pixels.size() / 4) / 2);
    EXPECT_GT(darker, 0);
    ASSERT_EQ(runCli("render" + kSmall + "--debug-view bloom -o " + dir + "/bloom.exr").exitCode, 0);
    ASSERT_EQ(runCli("render" + kSmall + "-o " + dir + "/frame.exr").exitCode, 0);
    // Only the glow: a small fraction (0.04 by default) of the frame's energy.
    const double glow = sumRed(specula::readFloatImage(dir + "/bloom.exr"));
    const double frame = sumRed(specula::readFloatImage(dir + "/frame.exr"));
    EXPECT_GT(glow, 0.0);
    EXPECT_LT(glow, 0.06 * frame);
}

TEST(CliPost, BenchPrintsPerPassTable)
{
    const std::string dir = tempDir("post-bench");
    const auto r = runCli("bench --scene demo --frames 2 --warmup 0 --width 64 --height 36 --bloom on --ssao on -o " + dir + "/b.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* pass : {"time per pass", "timer ms", "wall ms", "ssao prepass", "bloom", "resolve", "total"})
        EXPECT_NE(r.out.find(pass), std::string::npos) << pass << " missing from:\n" << r.out;
}

TEST(CliPost, BadValues)
{
    const std::string out = " -o " + tempDir("post-bad") + "/out.png";
    expectOneLineFailure("render --bloom maybe" + out, "--bloom");
    expectOneLineFailure("render --ssao 1" + out, "--ssao");
    expectOneLineFailure("render --fxaa yes" + out, "--fxaa");
    expectOneLineFailure("render --auto-exposure auto" + out, "--auto-exposure");
    expectOneLineFailure("render --bloom-intensity -1" + out, "--bloom-intensity must not be negative");
    expectOneLineFailure("render --bloom-levels 9" + out, "--bloom-levels must be between 1 and 8");
    expectOneLineFailure("render --bloom-radius 0" + out, "--bloom-radius must be positive");
    expectOneLineFailure("render --bloom-knee 3" + out, "--bloom-knee must be between 0 and 1");
    expectOneLineFailure("render --ssao-radius 0" + out, "--ssao-radius must be positive");
    expectOneLineFailure("render --ssao-samples 100" + out, "--ssao-samples must be between 1 and 64");
    expectOneLineFailure("render --ssao-power -2" + out, "--ssao-power must be positive");
    expectOneLineFailure("render --debug-view glow" + out, "--debug-view");
    expectOneLineFailure("render --tonemap filmic" + out, "agx");
}

TEST(CliPost, FlagsAreTheTablesRows)
{
    // Every command line takes exactly the passes' command-line rows as flags (and --ev100).
    std::set<std::string> expected;
    specula::PostOverrides none;
    specula::forEachPass([&](auto& pass) {
        using T = typename std::decay_t<decltype(pass)>::Settings;
        const auto& table = specula::settingsTable<T>();
        for (const auto& field : table.fields)
            if (field.commandLine) expected.insert("--" + specula::flagName(table, field));
    }, none);
    for (const char* command : {"render", "bench", "view", "gallery"}) {
        const auto r = runCli(std::string(command) + " --help");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::set<std::string> listed;
        const std::regex flag(R"(--(shadows|bloom|ssao|fxaa|auto-exposure)[a-z0-9-]*)");
        for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), flag); it != std::sregex_iterator(); ++it)
            listed.insert(it->str());
        EXPECT_EQ(listed, expected) << command << " --help:\n" << r.out;
    }
}
