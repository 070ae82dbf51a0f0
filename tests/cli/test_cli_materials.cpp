// The material system on the command line: --shading, --brdf-*, --debug-view, gallery and the Doom level.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "CliRunner.h"
#include "core/ImageIO.h"
#include "scene/DoomPalette.h"

using namespace specula::test;
namespace fs = std::filesystem;

TEST(CliMaterials, ShadingAndBrdfFlagsRender)
{
    const std::string dir = tempDir("materials-flags");
    const auto r = runCli("render -o " + dir + "/phong.png --width 96 --height 64 --shading blinn-phong");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/phong.png"));
    const auto v = runCli("render -o " + dir + "/variants.png --width 96 --height 64 --brdf-d beckmann --brdf-g kelemen "
                          "--brdf-f schlick-sg --brdf-diffuse burley --debug-view brdf-g");
    ASSERT_EQ(v.exitCode, 0) << v.err;
    EXPECT_TRUE(fs::exists(dir + "/variants.png"));
}

TEST(CliMaterials, BadNamesFailInOneLine)
{
    const std::string dir = tempDir("materials-bad");
    for (const char* flags : {"--shading toon", "--brdf-d ggx2", "--brdf-g smith", "--brdf-f fresnel", "--brdf-diffuse disney",
                              "--debug-view albedo"}) {
        const auto r = runCli("render -o " + dir + "/out.png --width 32 --height 32 " + flags);
        EXPECT_NE(r.exitCode, 0) << flags;
        EXPECT_EQ(r.errorLines(), 1) << flags << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir + "/out.png"));
    }
}

TEST(CliMaterials, GalleryWritesOneSheet)
{
    const std::string dir = tempDir("materials-gallery");
    const auto r = runCli("gallery -o " + dir + "/sheet.png --width 64 --height 48 --columns 3");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const specula::ImageRGBA8 sheet = specula::readPng(dir + "/sheet.png");
    // Seven models, then fade and newell-newell-sancha: three rows of three 64-pixel tiles,
    // with captions and padding.
    EXPECT_GT(sheet.width, 3 * 64);
    EXPECT_GT(sheet.height, 3 * 48);
}

// The built-in Doom level renders as Doom's 8-bit frame by default (its "render.shading"),
// every pixel a palette colour; --shading overrides it, and then the tone curve leaves the palette.
TEST(CliMaterials, DoomLevelIsADoomFrameByDefault)
{
    const std::string dir = tempDir("materials-doom");
    const auto r = runCli("render doom -o " + dir + "/doom.png --width 96 --height 64");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto& palette = specula::scene::doom::colorTables().palette;
    const std::set<specula::scene::doom::Rgb> colours(palette.begin(), palette.end());
    auto offPalette = [&](const specula::ImageRGBA8& image) {
        size_t off = 0;
        for (size_t i = 0; i < image.pixels.size(); i += 4)
            off += colours.count({image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]}) == 0;
        return off;
    };
    EXPECT_EQ(offPalette(specula::readPng(dir + "/doom.png")), 0u);
    const auto pbr = runCli("render doom -o " + dir + "/pbr.png --width 96 --height 64 --shading pbr");
    ASSERT_EQ(pbr.exitCode, 0) << pbr.err;
    EXPECT_GT(offPalette(specula::readPng(dir + "/pbr.png")), 96u * 64u / 4); // lit by the lamps, tone-mapped
    EXPECT_EQ(r.err.find("left out"), std::string::npos) << r.err; // nothing asked for, nothing to say
    // What a Doom frame cannot have is left out, and said: the frame stays palette-only.
    const auto bloom = runCli("render doom -o " + dir + "/bloom.png --width 96 --height 64 --bloom on --msaa 4");
    ASSERT_EQ(bloom.exitCode, 0) << bloom.err;
    EXPECT_NE(bloom.err.find("a Doom frame is palette colours only: MSAA, bloom left out"), std::string::npos) << bloom.err;
    EXPECT_EQ(offPalette(specula::readPng(dir + "/bloom.png")), 0u);
}

TEST(CliMaterials, SheenDebugViewShowsOnlyTheSheen)
{
    // tests/assets/materials/sheen_spheres.json: a bare sphere left, two with sheen (middle and
    // right). --debug-view sheen is black on the bare one and not on the others.
    const std::string dir = tempDir("materials-sheen");
    const auto r = runCli(std::string("render ") + SPECULA_SOURCE_DIR + "/tests/assets/materials/sheen_spheres.json --env none -o " + dir +
                          "/sheen.png --width 192 --height 72 --msaa 1 --debug-view sheen");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const specula::ImageRGBA8 image = specula::readPng(dir + "/sheen.png");
    auto at = [&](int x, int y) { return image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4]; };
    const int y = image.height / 2;
    // The frame spans x = -2 .. 2 m at the spheres (yfov 32 degrees at 2.6 m, 192 x 72): the bare
    // sphere's centre (x = -1) is pixel 48, the velvet's (x = 0, radius 0.45 m) 96 ± 21.
    EXPECT_EQ(at(48, y), 0);
    EXPECT_GT(at(80, y), 10); // red of c E(n.v) for the pink sheen, n.v about 0.7
}

// The BRDF views show the first punctual light's term: a scene without one is black, and the
// render says why. With --env none it gets the default rig, and nothing is said.
TEST(CliMaterials, FirstLightDebugViewsSayWhenThereIsNoLight)
{
    const std::string dir = tempDir("materials-first-light");
    const std::string model = std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/clearcoat_quad.gltf";
    for (const char* view : {"brdf-d", "brdf-g", "brdf-f"}) {
        const auto dark = runCli("render " + model + " -o " + dir + "/dark.png --width 32 --height 32 --debug-view " + view);
        ASSERT_EQ(dark.exitCode, 0) << dark.err;
        EXPECT_NE(dark.err.find(std::string("--debug-view ") + view + ": the term is the first punctual light's and this scene has none"),
                  std::string::npos)
            << dark.err;
        const auto lit = runCli("render " + model + " --env none -o " + dir + "/lit.png --width 32 --height 32 --debug-view " + view);
        ASSERT_EQ(lit.exitCode, 0) << lit.err;
        EXPECT_EQ(lit.err.find("has none"), std::string::npos) << lit.err;
    }
}
