// `specula render` and `specula info` end to end.
#include <gtest/gtest.h>

#include <filesystem>

#include "CliRunner.h"
#include "core/ImageIO.h"

namespace fs = std::filesystem;
using specula::test::runCli;
using specula::test::tempDir;

TEST(CliRender, DemoToPngHdrAndExr)
{
    const std::string dir = tempDir("demo");
    const auto png = runCli("render --width 160 --height 90 -o " + dir + "/demo.png");
    ASSERT_EQ(png.exitCode, 0) << png.err;
    EXPECT_NE(png.err.find("first frame"), std::string::npos) << "timings go to stderr: " << png.err;
    const specula::ImageRGBA8 image = specula::readPng(dir + "/demo.png");
    EXPECT_EQ(image.width, 160);
    EXPECT_EQ(image.height, 90);

    ASSERT_EQ(runCli("render --width 160 --height 90 --exposure 0 -o " + dir + "/demo.hdr").exitCode, 0);
    ASSERT_EQ(runCli("render --width 160 --height 90 --exposure 1 -o " + dir + "/demo.exr").exitCode, 0);
    const specula::ImageFloat hdr = specula::readFloatImage(dir + "/demo.hdr");
    const specula::ImageFloat exr = specula::readFloatImage(dir + "/demo.exr");
    ASSERT_EQ(hdr.pixels.size(), exr.pixels.size());
    // --exposure 1 doubles the linear values (RGBE keeps ~1% precision, half floats 0.1%).
    double sumHdr = 0, sumExr = 0;
    for (size_t i = 0; i < hdr.pixels.size(); i += 4) {
        sumHdr += hdr.pixels[i];
        sumExr += exr.pixels[i];
    }
    EXPECT_GT(sumHdr, 0.0);
    EXPECT_NEAR(sumExr / sumHdr, 2.0, 0.02);
}

TEST(CliRender, Info)
{
    const auto r = runCli("info");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* field : {"vendor:", "renderer:", "version:", "GL_MAX_UNIFORM_BLOCK_SIZE", "GL_MAX_SAMPLES"})
        EXPECT_NE(r.out.find(field), std::string::npos) << field << " missing from:\n" << r.out;
}

TEST(CliRender, GizmosDrawTheLights)
{
    // The demo's red point light sits at (-3.5, 1, 2); with --gizmos a disc of its colour marks it
    // (and rods the spot light's cone), so the image changes, and only where gizmos are drawn.
    const std::string dir = tempDir("gizmos");
    ASSERT_EQ(runCli("render --width 160 --height 90 --msaa 1 -o " + dir + "/plain.png").exitCode, 0);
    const auto r = runCli("render --width 160 --height 90 --msaa 1 --gizmos -o " + dir + "/gizmos.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const specula::ImageRGBA8 plain = specula::readPng(dir + "/plain.png");
    const specula::ImageRGBA8 gizmos = specula::readPng(dir + "/gizmos.png");
    ASSERT_EQ(plain.pixels.size(), gizmos.pixels.size());
    size_t changed = 0;
    for (size_t i = 0; i < plain.pixels.size(); i += 4)
        if (plain.pixels[i] != gizmos.pixels[i] || plain.pixels[i + 1] != gizmos.pixels[i + 1] || plain.pixels[i + 2] != gizmos.pixels[i + 2])
            ++changed;
    // Three or four 24-pixel discs in view (the sun's and spot's may fall outside), and the spot
    // and sun lights' rods, 2-pixel lines: a few thousand pixels (2684 when written), far from all.
    EXPECT_GT(changed, 100u);
    EXPECT_LT(changed, 5000u);
}
