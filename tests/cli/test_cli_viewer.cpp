// `specula view` under Xvfb (scripts/test.sh provides the display): --frames/--screenshot and
// scripts of UI actions (docs/viewer.md). Any GL debug error makes the viewer exit non-zero.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>

#include "CliRunner.h"
#include "core/ImageIO.h"

using specula::test::runCli;
using specula::test::tempDir;

namespace {

const std::string kHelmet = std::string(SPECULA_ASSETS_DIR) + "/models/DamagedHelmet/DamagedHelmet.glb";
const std::string kEnv = std::string(SPECULA_ASSETS_DIR) + "/env/venice_1k.hdr";

bool haveDisplay()
{
    return std::getenv("DISPLAY") != nullptr;
}

/// Mean over a rectangle of |a - b| (all colour channels), 0..255.
double meanDifference(const specula::ImageRGBA8& a, const specula::ImageRGBA8& b, int x0, int y0, int x1, int y1)
{
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) {
                const size_t i = (size_t(y) * size_t(a.width) + size_t(x)) * 4 + size_t(c);
                sum += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
            }
    return sum / (3.0 * double(x1 - x0) * double(y1 - y0));
}

double meanDifference(const specula::ImageRGBA8& a, const specula::ImageRGBA8& b)
{
    return meanDifference(a, b, 0, 0, a.width, a.height);
}

/// Mean of red minus green over a rectangle: how much redder it is.
double redness(const specula::ImageRGBA8& image, int x0, int y0, int x1, int y1)
{
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const size_t i = (size_t(y) * size_t(image.width) + size_t(x)) * 4;
            sum += double(image.pixels[i]) - double(image.pixels[i + 1]);
        }
    return sum / (double(x1 - x0) * double(y1 - y0));
}

} // namespace

TEST(CliViewer, FramesThenScreenshot)
{
    if (!haveDisplay()) GTEST_SKIP() << "no display (run through scripts/test.sh, which uses Xvfb)";
    const std::string dir = tempDir("viewer-frames");
    const auto r = runCli("view --frames 3 --screenshot " + dir + "/demo.png --width 160 --height 120");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const specula::ImageRGBA8 image = specula::readPng(dir + "/demo.png");
    EXPECT_EQ(image.width, 160);
    EXPECT_EQ(image.height, 120);
    EXPECT_NE(r.err.find("viewer: 3 frames"), std::string::npos) << r.err;
}

// The issue's acceptance script, headless: a coloured spot light, a shading model switched and
// switched back, bloom turned up, a bad file dropped.
TEST(CliViewer, ScriptEditsLightMaterialAndBloom)
{
    if (!haveDisplay()) GTEST_SKIP() << "no display (run through scripts/test.sh, which uses Xvfb)";
    const std::string dir = tempDir("viewer-script");
    std::ofstream(dir + "/script.txt") << "frames 2\n"
                                          "pick 120 90 0   # clicking the helmet picks its material\n"
                                          "add-light spot\n"
                                          "frames 1\n"
                                          "screenshot " << dir << "/white.png\n"
                                          "light-color 0 1 0 0   # only light 0's 64 bytes change\n"
                                          "expect-light-upload 0\n"
                                          "frames 1\n"
                                          "screenshot " << dir << "/red.png\n"
                                          "material-model 0 blinn-phong\n"
                                          "frames 1\n"
                                          "screenshot " << dir << "/blinn.png\n"
                                          "material-model 0 pbr\n"
                                          "frames 1\n"
                                          "screenshot " << dir << "/pbr.png\n"
                                          "toggle bloom\n"
                                          "set bloom-intensity 0.5\n"
                                          "frames 1\n"
                                          "screenshot " << dir << "/bloom.png\n"
                                          "open " << dir << "/missing.glb\n"
                                          "expect-error\n"
                                          "frames 1\n"
                                          "screenshot " << dir << "/kept.png\n";
    const auto r = runCli("view " + kHelmet + " --env " + kEnv + " --width 240 --height 180 --script " + dir + "/script.txt");
    ASSERT_EQ(r.exitCode, 0) << r.err; // non-zero on any GL debug error
    EXPECT_NE(r.err.find("picked material 0"), std::string::npos) << r.err;

    // The edit rewrote light 0's bytes and no others.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.err, m, std::regex(R"(light 0 wrote (\d+) bytes, last range \[(\d+), (\d+)\); light 0 is \[(\d+), (\d+)\))")))
        << r.err;
    EXPECT_EQ(m[1].str(), "64");
    EXPECT_EQ(m[2].str(), m[4].str());
    EXPECT_EQ(m[3].str(), m[5].str());

    const auto white = specula::readPng(dir + "/white.png");
    const auto red = specula::readPng(dir + "/red.png");
    const auto blinn = specula::readPng(dir + "/blinn.png");
    const auto pbr = specula::readPng(dir + "/pbr.png");
    const auto bloom = specula::readPng(dir + "/bloom.png");
    const auto kept = specula::readPng(dir + "/kept.png");
    const int w = white.width, h = white.height;
    // The helmet fills the middle; the top corners are sky, which lights do not reach.
    const int cx0 = w * 3 / 8, cx1 = w * 5 / 8, cy0 = h * 3 / 8, cy1 = h * 5 / 8;
    EXPECT_GT(redness(red, cx0, cy0, cx1, cy1), redness(white, cx0, cy0, cx1, cy1) + 2.0) << "the red light does not show";
    EXPECT_EQ(meanDifference(white, red, 0, 0, w / 8, h / 8), 0.0) << "the light changed the sky";
    EXPECT_GT(meanDifference(red, blinn, cx0, cy0, cx1, cy1), 2.0) << "Blinn-Phong looks like PBR";
    EXPECT_EQ(meanDifference(blinn, pbr, 0, 0, w / 8, h / 8), 0.0) << "the shading model changed the sky";
    EXPECT_LT(meanDifference(red, pbr), 0.01) << "switching back to PBR does not restore the image";
    EXPECT_GT(meanDifference(pbr, bloom), 0.2) << "bloom changed nothing";
    EXPECT_LT(meanDifference(bloom, kept), 0.01) << "a failed load changed the scene";
}

TEST(CliViewer, ResizingTheWindowResizesTheFrame)
{
    if (!haveDisplay()) GTEST_SKIP() << "no display (run through scripts/test.sh, which uses Xvfb)";
    const std::string dir = tempDir("viewer-resize");
    // Gizmos off: they keep their size in pixels, the rest of the frame scales.
    std::ofstream(dir + "/resize.txt") << "toggle gizmos\nframes 1\nscreenshot " << dir << "/small.png\nresize 200 150\nframes 3\nscreenshot "
                                       << dir << "/large.png\n";
    const auto r = runCli("view --width 120 --height 90 --script " + dir + "/resize.txt");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto small = specula::readPng(dir + "/small.png");
    const auto large = specula::readPng(dir + "/large.png");
    EXPECT_EQ(small.width, 120);
    EXPECT_EQ(small.height, 90);
    EXPECT_EQ(large.width, 200);
    EXPECT_EQ(large.height, 150);
    // The same view at both sizes: the same average colour.
    const auto mean = [](const specula::ImageRGBA8& image) {
        double sum = 0.0;
        for (size_t i = 0; i < image.pixels.size(); i += 4) sum += image.pixels[i] + image.pixels[i + 1] + image.pixels[i + 2];
        return sum / double(image.pixels.size() / 4);
    };
    EXPECT_NEAR(mean(small), mean(large), 0.05 * mean(large));
}

TEST(CliViewer, ScriptErrorsNameFileAndLine)
{
    if (!haveDisplay()) GTEST_SKIP() << "no display (run through scripts/test.sh, which uses Xvfb)";
    const std::string dir = tempDir("viewer-bad-script");
    std::ofstream(dir + "/bad.txt") << "frames 1\nspin 3\n";
    const auto r = runCli("view --width 64 --height 48 --script " + dir + "/bad.txt");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("bad.txt:2: unknown action 'spin'"), std::string::npos) << r.err;
    const auto missing = runCli("view --width 64 --height 48 --script " + dir + "/none.txt");
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_NE(missing.err.find("cannot read script"), std::string::npos) << missing.err;
}
