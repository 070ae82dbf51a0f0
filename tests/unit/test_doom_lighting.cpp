// Doom-era lighting (scene/DoomLighting.h): sector light spreading against hand-computed
// levels and Doom's light diminishing. The palette is tested in test_doom_palette.cpp, the
// demo level in test_doom_level.cpp.
#include <gtest/gtest.h>

#include <set>

#include "scene/DoomLighting.h"

using namespace specula::scene::doom;

TEST(DoomLighting, LightSpreadsToAdjacentSectorsWithAttenuation)
{
    // Floor plan (map units):   A | B | C        A 255, B 0, C 0, D 160; D lies below C.
    //                                 D          E is apart (touches nothing) at 40.
    const std::vector<Sector> sectors = {
        {{0, 0}, {64, 64}, 255},     // A
        {{64, 0}, {128, 64}, 0},     // B
        {{128, 0}, {192, 64}, 0},    // C
        {{128, 64}, {192, 128}, 160}, // D
        {{400, 400}, {464, 464}, 40}, // E
    };
    const auto pairs = adjacentSectors(sectors);
    const std::set<std::pair<int, int>> expectedPairs = {{0, 1}, {1, 2}, {2, 3}};
    const std::set<std::pair<int, int>> gotPairs(pairs.begin(), pairs.end());
    EXPECT_EQ(gotPairs, expectedPairs);
    // By hand, attenuation 64: B = 255 − 64 = 191; C = max(191 − 64, 160 − 64) = 127;
    // D keeps its own 160 (> 127 − 64); E is isolated and keeps 40.
    EXPECT_EQ(spreadLight(sectors, 64), (std::vector<int>{255, 191, 127, 160, 40}));
    // Attenuation 255: nothing spreads.
    EXPECT_EQ(spreadLight(sectors, 255), (std::vector<int>{255, 0, 0, 160, 40}));
    // Corners only (diagonal neighbours) do not count as adjacent.
    EXPECT_TRUE(adjacentSectors({{{0, 0}, {10, 10}, 0}, {{10, 10}, {20, 20}, 0}}).empty());
}

TEST(DoomLighting, LightDiminishesWithDistance)
{
    // Light 160: startmap = (15 − 10) · 4 = 20; at distance 0 the scale 160 makes it full bright.
    EXPECT_EQ(colormapIndex(160, 0.0), 0);
    EXPECT_EQ(colormapIndex(160, 16.0 * 9), 20 - 160 / 10 / 2); // z = 9: scale 16, level 12
    EXPECT_EQ(colormapIndex(160, 1e6), 20);                     // far: the sector's own level
    EXPECT_EQ(colormapIndex(255, 1e6), 0);                      // full bright never dims
    EXPECT_EQ(colormapIndex(0, 1e6), 31);                       // darkness is the darkest map
    for (int light = 0; light <= 255; light += 15)
        for (double d = 0.0; d < 2000.0; d += 50.0) EXPECT_LE(colormapIndex(light, d), colormapIndex(light, d + 50.0));
}

TEST(DoomLighting, WallsAndThingsTakeTheScaleTable)
{
    // Light 160: startmap = (15 − 10) · 4 = 20. At 100 units, scale = 2560 / 100 = 25.6 → 25,
    // level 20 − 12 = 8 (a flat at the same distance: z = 6, 160 / 7 = 22, level 20 − 11 = 9).
    EXPECT_EQ(wallColormapIndex(160, 100.0), 8);
    EXPECT_EQ(colormapIndex(160, 100.0), 9);
    // Fake contrast: along x one light level darker (startmap 24, level 12), along y brighter
    // (startmap 16, level 4).
    EXPECT_EQ(wallColormapIndex(160, 100.0, WallContrast::AlongX), 12);
    EXPECT_EQ(wallColormapIndex(160, 100.0, WallContrast::AlongY), 4);
    // Near: the scale stops at 47 (level startmap − 23); far: the sector's own level.
    EXPECT_EQ(wallColormapIndex(160, 10.0), 0); // 20 − 23, clamped
    EXPECT_EQ(wallColormapIndex(96, 10.0), 13); // startmap 36 − 23
    EXPECT_EQ(wallColormapIndex(96, 1.0), 13);  // closer changes nothing
    EXPECT_EQ(wallColormapIndex(160, 1e6), 20);
    // The contrast stays within the 16 light levels.
    EXPECT_EQ(wallColormapIndex(255, 1e6, WallContrast::AlongY), 0);
    EXPECT_EQ(wallColormapIndex(0, 1e6, WallContrast::AlongX), 31);
    for (int light = 0; light <= 255; light += 15)
        for (double d = 1.0; d < 2000.0; d += 25.0) EXPECT_LE(wallColormapIndex(light, d), wallColormapIndex(light, d + 25.0));
}
