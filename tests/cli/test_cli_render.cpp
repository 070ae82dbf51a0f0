// `specula render` and `specula info` end to end.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

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

TEST(CliRender, ManyLightsStatsAndLightCountView)
{
    // The many-lights scene with --lights; --stats prints the clusters' line.
    const std::string dir = tempDir("many-lights");
    const auto stats = runCli("render many-lights --lights 256 --width 160 --height 90 --stats -o " + dir + "/many.png");
    ASSERT_EQ(stats.exitCode, 0) << stats.err;
    EXPECT_NE(stats.out.find("light culling"), std::string::npos) << stats.out;
    EXPECT_NE(stats.out.find("light clusters 16x9x24:"), std::string::npos) << stats.out;

    // The light-count view: black where no light reaches, heat elsewhere, the legend's ten
    // boxes in the bottom-left corner (its first, for 0 lights, black on the dark band).
    const auto view = runCli("render many-lights --lights 256 --width 320 --height 180 --msaa 1 --debug-view light-count -o " + dir +
                             "/count.png");
    ASSERT_EQ(view.exitCode, 0) << view.err;
    const specula::ImageRGBA8 image = specula::readPng(dir + "/count.png");
    ASSERT_EQ(image.width, 320);
    auto pixel = [&](int x, int yFromBottom) {
        const size_t i = (size_t(image.height - 1 - yFromBottom) * size_t(image.width) + size_t(x)) * 4;
        return std::array<int, 3>{image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
    };
    // The legend's band is (24, 24, 24); its "1" box (0.10, 0.10, 0.45) starts 4 + 30 pixels in.
    EXPECT_EQ(pixel(1, 1), (std::array<int, 3>{24, 24, 24}));
    EXPECT_EQ(pixel(40, 20), (std::array<int, 3>{26, 26, 115}));
    size_t heated = 0;
    for (int y = 40; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) heated += pixel(x, y)[0] + pixel(x, y)[1] + pixel(x, y)[2] > 0 ? 1 : 0;
    EXPECT_GT(heated, size_t(image.width * image.height / 10)) << "lights reach much of the floor";

    // Bad values are one clear line each.
    for (const auto& [flags, phrase] : {std::pair<std::string, std::string>{"--light-cutoff 1.5", "--light-cutoff must be"},
                                        {"--light-culling tiled", "--light-culling must be clustered or none"},
                                        {"--lights -3", "--lights must be between"},
                                        {"--transparency peeled", "--transparency must be sorted or oit"}}) {
        const auto r = runCli("render many-lights --width 16 --height 16 " + flags + " -o " + dir + "/bad.png");
        EXPECT_NE(r.exitCode, 0) << flags;
        EXPECT_NE(r.err.find(phrase), std::string::npos) << r.err;
    }
}

namespace {

/// "N triangles drawn" from a --stats table's title.
long trianglesDrawn(const std::string& out)
{
    const size_t at = out.find(" triangles drawn");
    if (at == std::string::npos) return -1;
    size_t begin = at;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(out[begin - 1]))) --begin;
    return std::stol(out.substr(begin, at - begin));
}

} // namespace

TEST(CliRender, LevelsOfDetailDrawFewerTrianglesForTheSameSilhouettes)
{
    // The IBL grid's 64 x 64 spheres at 320 x 180 are 30-50 pixels across: with a one-pixel
    // bound the camera draws coarser levels (scene/MeshLod.h). Off by default.
    const std::string dir = tempDir("lod");
    const std::string scene = "render learnopengl-ibl --env none --width 320 --height 180 --msaa 1 --stats ";
    const auto full = runCli(scene + "-o " + dir + "/full.png");
    const auto coarse = runCli(scene + "--lod-error 1 -o " + dir + "/lod.png");
    ASSERT_EQ(full.exitCode, 0) << full.err;
    ASSERT_EQ(coarse.exitCode, 0) << coarse.err;
    const long all = trianglesDrawn(full.out), fewer = trianglesDrawn(coarse.out);
    ASSERT_GT(all, 0) << full.out;
    EXPECT_LT(fewer, all / 2) << coarse.out;
    // The same picture within a pixel of each silhouette: few pixels change much.
    const specula::ImageRGBA8 a = specula::readPng(dir + "/full.png"), b = specula::readPng(dir + "/lod.png");
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    size_t changed = 0;
    for (size_t p = 0; p < a.pixels.size(); p += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixels[p + c]) - int(b.pixels[p + c])));
        changed += d > 24;
    }
    EXPECT_LT(double(changed) / double(a.width * a.height), 0.02);

    for (const char* bad : {"-1", "17", "nan"}) {
        const auto r = runCli(std::string("render --lod-error ") + bad + " -o " + dir + "/bad.png");
        EXPECT_NE(r.exitCode, 0) << bad;
        EXPECT_NE(r.err.find("--lod-error"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir + "/bad.png"));
    }
}

TEST(CliRender, SeveralScenesAndCamerasInOneProcess)
{
    // A batch pays start-up once: one context and renderer for every image. Each image is the
    // one a render of that scene alone writes, byte for byte.
    const std::string dir = tempDir("batch");
    const std::string size = " --width 96 --height 54 ";
    const auto batch = runCli("render demo learnopengl" + size + "-o " + dir + "/{scene}.png");
    ASSERT_EQ(batch.exitCode, 0) << batch.err;
    EXPECT_NE(batch.err.find("[2/2] learnopengl"), std::string::npos) << "progress per image: " << batch.err;
    for (const char* scene : {"demo", "learnopengl"}) {
        ASSERT_EQ(runCli(std::string("render ") + scene + size + "-o " + dir + "/alone-" + scene + ".png").exitCode, 0);
        const specula::ImageRGBA8 a = specula::readPng(dir + "/" + scene + ".png");
        const specula::ImageRGBA8 b = specula::readPng(dir + "/alone-" + scene + ".png");
        EXPECT_EQ(a.width, 96);
        EXPECT_TRUE(a.pixels == b.pixels) << scene << ": the batch's image differs from the scene rendered alone";
    }

    // --camera all: one image per camera; a scene file's camera comes first, the model's after it.
    const std::string scene = dir + "/two-cameras.json";
    std::ofstream(scene) << R"({"camera": {"position": [0, 1, 6], "target": [0, 0, 0]},
        "models": [{"path": ")" << SPECULA_SOURCE_DIR << R"(/../shared/assets/models/ShadowsSpot/shadows-spot.gltf"}]})";
    const auto cameras = runCli("render " + scene + " --allow-external-files --camera all" + size + "-o " + dir + "/{scene}-{camera}.png");
    ASSERT_EQ(cameras.exitCode, 0) << cameras.err;
    const specula::ImageRGBA8 first = specula::readPng(dir + "/two-cameras-0.png");
    const specula::ImageRGBA8 second = specula::readPng(dir + "/two-cameras-1.png");
    EXPECT_EQ(first.width, 96);
    EXPECT_FALSE(first.pixels == second.pixels) << "two cameras, one picture";

    // Names that clash are refused before anything renders, naming the file and the fix.
    const auto clash = runCli("render demo learnopengl" + size + "-o " + dir + "/same.png");
    EXPECT_NE(clash.exitCode, 0);
    EXPECT_NE(clash.err.find("same.png"), std::string::npos) << clash.err;
    EXPECT_NE(clash.err.find("{scene}"), std::string::npos) << clash.err;
    EXPECT_FALSE(fs::exists(dir + "/same.png"));
    const auto clashCameras = runCli("render " + scene + " --allow-external-files --camera all" + size + "-o " + dir + "/{scene}.png");
    EXPECT_NE(clashCameras.exitCode, 0);
    EXPECT_FALSE(fs::exists(dir + "/two-cameras.png"));
    // A bad scene anywhere in the batch stops it before the first image.
    const auto bad = runCli("render demo " + dir + "/missing.gltf" + size + "-o " + dir + "/bad-{scene}.png");
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.err.find("missing.gltf"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(dir + "/bad-demo.png"));
    // Only render takes --camera all.
    EXPECT_NE(runCli("bench --camera all --frames 1").exitCode, 0);
}

// A camera's aspectRatio (glTF's, or a scene file's) sizes the image where no size is given
// whole: the height 720 (or the one given) and the width to match, or the height for a width
// given alone; a size given whole wins. The image sized so is the one that size asked for
// byte for byte. Broken on purpose (2026-12-07): without fitSizeToCamera the sizes were 1280x720,
// 1280x60 and 90x720.
TEST(CliRender, CameraAspectRatioSizesTheImage)
{
    const std::string dir = tempDir("aspect");
    const std::string scene = dir + "/camera.json";
    std::ofstream(scene) << R"({"camera": {"position": [0, 1, 6], "target": [0, 0, 0], "aspectRatio": 1.5},
        "shapes": [{"type": "sphere", "radius": 1}]})";
    const auto size = [&](const std::string& options, const std::string& name) {
        const auto run = runCli("render " + scene + " --msaa 1 --env-color 0.5,0.5,0.5 " + options + " -o " + dir + "/" + name);
        EXPECT_EQ(run.exitCode, 0) << run.err;
        const specula::ImageRGBA8 image = specula::readPng(dir + "/" + name);
        return std::pair(image.width, image.height);
    };
    EXPECT_EQ(size("", "default.png"), std::pair(1080, 720));
    EXPECT_EQ(size("--height 60", "height.png"), std::pair(90, 60));
    EXPECT_EQ(size("--width 90", "width.png"), std::pair(90, 60));
    EXPECT_EQ(size("--width 64 --height 64", "both.png"), std::pair(64, 64));
    EXPECT_TRUE(specula::readPng(dir + "/height.png").pixels == specula::readPng(dir + "/width.png").pixels);
}
