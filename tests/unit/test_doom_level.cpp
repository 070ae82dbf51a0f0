// The Doom model's demo level (scene/DoomLevel.h): its light spread as computed by hand, its
// textures and sprites made of palette colours only, and its things lit by their sectors.
#include <gtest/gtest.h>

#include <set>

#include "scene/DoomLevel.h"

using namespace specula::scene;
using namespace specula::scene::doom;

TEST(DoomLevel, LightSpreadsThroughTheLevelAsComputedByHand)
{
    std::vector<Sector> sectors;
    for (const LevelSector& l : demoLevelSectors()) sectors.push_back(l.sector);
    // Start room 0 (208) — corridor 1 (96) — hall 2 (160); the hall opens on the dark room 3
    // (24) and the nook 4 (0).
    const auto pairs = adjacentSectors(sectors);
    using Pairs = std::set<std::pair<int, int>>;
    EXPECT_EQ(Pairs(pairs.begin(), pairs.end()), (Pairs{{0, 1}, {1, 2}, {2, 3}, {2, 4}}));
    // By hand, attenuation 64: corridor max(96, 208 − 64) = 144; hall max(160, 144 − 64) = 160;
    // dark room max(24, 160 − 64) = 96; nook max(0, 160 − 64) = 96.
    EXPECT_EQ(spreadLight(sectors, kDemoLevelAttenuation), (std::vector<int>{208, 144, 160, 96, 96}));
}

TEST(DoomLevel, TexturesAndSpritesArePaletteColours)
{
    const Palette& palette = colorTables().palette;
    const std::set<Rgb> colours(palette.begin(), palette.end());
    for (int t = 0; t < int(LevelTexture::Count); ++t) {
        const std::vector<uint8_t> indices = makeTextureIndices(LevelTexture(t));
        const Image image = makeTextureImage(LevelTexture(t));
        ASSERT_EQ(indices.size(), size_t(kTextureSize * kTextureSize));
        ASSERT_EQ(image.width, kTextureSize);
        ASSERT_EQ(image.pixels.size(), indices.size() * 4);
        for (size_t i = 0; i < indices.size(); ++i) {
            const Rgb c{image.pixels[4 * i], image.pixels[4 * i + 1], image.pixels[4 * i + 2]};
            ASSERT_EQ(c, palette[indices[i]]) << image.name << " texel " << i;
            ASSERT_EQ(image.pixels[4 * i + 3], 255) << image.name << " texel " << i;
        }
        // A pattern, not a flat colour: bricks, stones, planks and panels take many shades.
        EXPECT_GE(std::set<uint8_t>(indices.begin(), indices.end()).size(), 8u) << image.name;
    }
    for (const ThingKind kind : {ThingKind::Lamp, ThingKind::Barrel}) {
        const Image sprite = makeSpriteImage(kind);
        size_t opaque = 0;
        for (size_t i = 0; i < sprite.pixels.size(); i += 4) {
            const uint8_t alpha = sprite.pixels[i + 3];
            ASSERT_TRUE(alpha == 0 || alpha == 255) << sprite.name; // cutout: no partial coverage
            if (alpha == 0) continue;
            ++opaque;
            ASSERT_TRUE(colours.count({sprite.pixels[i], sprite.pixels[i + 1], sprite.pixels[i + 2]})) << sprite.name;
        }
        const size_t texels = sprite.pixels.size() / 4;
        EXPECT_GT(opaque, texels / 5) << sprite.name;
        EXPECT_LT(opaque, texels) << sprite.name; // and a transparent outline
    }
}

TEST(DoomLevel, ThingsStandInTheirSectorsLitByThem)
{
    const Scene level = makeDemoLevel();
    const std::vector<LevelSector> sectors = demoLevelSectors();
    const std::vector<int> light = {208, 144, 160, 96, 96}; // LightSpreadsThroughTheLevelAsComputedByHand
    size_t billboards = 0, lamps = 0;
    for (const BillboardGroup& g : level.billboards) {
        EXPECT_EQ(g.kind, BillboardKind::AxisAligned) << g.name; // turning about the vertical, as Doom's sprites
        EXPECT_EQ(g.alphaMode, AlphaMode::Mask) << g.name;
        const bool isLamp = g.name.starts_with("lamps");
        for (const Billboard& b : g.billboards) {
            // The sector under the billboard, from its position in map units.
            const glm::ivec2 p(int(b.position.x * 32.0f + 0.5f), int(b.position.z * 32.0f + 0.5f));
            int sector = -1;
            for (size_t i = 0; i < sectors.size(); ++i) {
                const Sector& t = sectors[i].sector;
                if (glm::all(glm::greaterThanEqual(p, t.min)) && glm::all(glm::lessThan(p, t.max))) sector = int(i);
            }
            ASSERT_GE(sector, 0) << g.name;
            EXPECT_FLOAT_EQ(b.position.y, float(sectors[size_t(sector)].floor) / 32.0f) << g.name; // on the floor
            // Lamps are full bright; barrels take their sector's spread light.
            EXPECT_EQ(g.sectorLight, isLamp ? 255 : light[size_t(sector)]) << g.name;
            ++billboards;
            lamps += isLamp ? 1 : 0;
        }
    }
    EXPECT_EQ(billboards, demoLevelThings().size());
    // A point light at each lamp, for the models that use lights.
    EXPECT_EQ(level.lights.size(), lamps);
    // Every surface is a Doom material at its sector's light, textured, texels unfiltered.
    ASSERT_FALSE(level.materials.empty());
    for (const Material& m : level.materials) {
        EXPECT_EQ(m.shading.model, ShadingModel::Doom) << m.name;
        const int sector = m.name[7] - '0'; // "sector N ..."
        EXPECT_EQ(m.sectorLight, light[size_t(sector)]) << m.name;
        ASSERT_TRUE(m.baseColorTexture.valid()) << m.name;
        const Sampler& s = level.samplers[size_t(m.baseColorTexture.sampler)];
        EXPECT_TRUE(s.magFilter == Filter::Nearest && s.minFilter == Filter::Nearest && !s.mipmaps) << m.name;
    }
}
