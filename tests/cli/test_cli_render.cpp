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
