// The Doom model's colours (scene/DoomPalette.h): a palette of ramps, dark to light; a colour
// map that only ever yields palette colours and never brightens; and a nearest-index table
// that holds, for every cell, the palette colour nearest the cell's centre (checked against an
// independent search in doubles).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <set>

#include "scene/DoomPalette.h"

using namespace specula::scene::doom;

namespace {

int luma(const Rgb& c)
{
    return 2 * c[0] + 5 * c[1] + c[2];
}

/// Rec. 709 luma of the sRGB bytes.
double luminance(const Rgb& c)
{
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

double distance(const Rgb& a, double r, double g, double b)
{
    return std::sqrt((a[0] - r) * (a[0] - r) + (a[1] - g) * (a[1] - g) + (a[2] - b) * (a[2] - b));
}

bool isGrey(const Rgb& c)
{
    return c[0] == c[1] && c[1] == c[2];
}

} // namespace

TEST(DoomPalette, RampsOfDistinctColoursDarkToLight)
{
    const auto ramps = paletteRamps();
    EXPECT_EQ(std::accumulate(ramps.begin(), ramps.end(), 0, [](int sum, const PaletteRamp& r) { return sum + r.count; }), 256);
    const Palette palette = makePalette();
    EXPECT_EQ(std::set<Rgb>(palette.begin(), palette.end()).size(), 256u);
    // Each ramp runs from its dark end to its light end, every shade brighter than the last.
    size_t i = 0;
    for (const PaletteRamp& ramp : ramps) {
        EXPECT_EQ(palette[i], ramp.dark) << ramp.name;
        EXPECT_EQ(palette[i + size_t(ramp.count) - 1], ramp.light) << ramp.name;
        for (int k = 1; k < ramp.count; ++k)
            EXPECT_GT(luma(palette[i + size_t(k)]), luma(palette[i + size_t(k) - 1])) << ramp.name << " " << k;
        i += size_t(ramp.count);
    }
    // The first ramp is the greys, black to white, as the colour map's darkest entries need.
    EXPECT_EQ(palette[0], (Rgb{0, 0, 0}));
    for (int k = 0; k < ramps[0].count; ++k) EXPECT_TRUE(isGrey(palette[size_t(k)])) << k;
    EXPECT_EQ(palette[size_t(ramps[0].count) - 1], (Rgb{255, 255, 255}));
    // Low-saturation colours (steel, khaki, earth, skin) find a colour of their own hue within
    // 15 steps, not a grey: what a cube and a grey ramp could not do (DamagedHelmet went grey).
    for (const Rgb c : {Rgb{100, 110, 130}, Rgb{150, 140, 100}, Rgb{120, 90, 70}, Rgb{200, 150, 130}, Rgb{90, 95, 60},
                        Rgb{70, 80, 100}, Rgb{160, 120, 90}}) {
        const Rgb& p = palette[nearestIndex(palette, c)];
        EXPECT_FALSE(isGrey(p)) << int(c[0]) << "," << int(c[1]) << "," << int(c[2]);
        EXPECT_LT(distance(p, c[0], c[1], c[2]), 15.0) << int(c[0]) << "," << int(c[1]) << "," << int(c[2]);
    }
}

TEST(DoomPalette, ColormapOutputsOnlyPaletteColoursAndNeverBrightens)
{
    const Palette palette = makePalette();
    const auto colormap = makeColormap(palette);
    ASSERT_EQ(colormap.size(), size_t(kColormaps));
    // Level 0 is the identity (every palette colour is its own nearest); every entry of every
    // level is a palette index (uint8_t: 0–255 by construction) whose colour is no brighter
    // than the undarkened one, give or take one step of the greys (255/31: the nearest colour
    // of a darkened deep blue, (0, 0, 21), is the dark grey (8, 8, 8)).
    for (int i = 0; i < 256; ++i) EXPECT_EQ(colormap[0][size_t(i)], i);
    for (int level = 1; level < kColormaps; ++level)
        for (int i = 0; i < 256; ++i)
            EXPECT_LE(luminance(palette[colormap[size_t(level)][size_t(i)]]), luminance(palette[size_t(i)]) + 255.0 / 31.0)
                << "level " << level << ", index " << i;
    // Darker levels are darker: the mean luma of a level falls with every level.
    double previous = 1e9;
    for (int level = 0; level < kColormaps; ++level) {
        double mean = 0.0;
        for (int i = 0; i < 256; ++i) mean += luminance(palette[colormap[size_t(level)][size_t(i)]]) / 256.0;
        EXPECT_LT(mean, previous) << "level " << level;
        previous = mean;
    }
    // Level k holds the colour darkened by 1 − k/32: at level 16 white is the grey nearest 128.
    const uint8_t white = nearestIndex(palette, {255, 255, 255});
    EXPECT_EQ(colormap[16][white], nearestIndex(palette, {128, 128, 128}));
    // The darkest level of white is a dark grey.
    EXPECT_TRUE(isGrey(palette[colormap[31][white]]));
    EXPECT_LT(luminance(palette[colormap[31][white]]), 16.0);
}

TEST(DoomPalette, NearestTableHoldsTheNearestColourOfEachCellCentre)
{
    const ColorTables& tables = colorTables();
    const Palette& palette = tables.palette;
    ASSERT_EQ(tables.nearest.size(), size_t(kNearestCells) * kNearestCells * kNearestCells);
    // Independently of makeNearestTable's integer search: distances in doubles from each cell's
    // centre, 4c + 1.5 per channel. The table's colour must be at the smallest distance.
    int wrong = 0;
    for (int b = 0; b < kNearestCells; ++b) {
        for (int g = 0; g < kNearestCells; ++g) {
            for (int r = 0; r < kNearestCells; ++r) {
                const double cr = r * kNearestCellSize + 1.5, cg = g * kNearestCellSize + 1.5, cb = b * kNearestCellSize + 1.5;
                double best = 1e9;
                for (const Rgb& p : palette) best = std::min(best, distance(p, cr, cg, cb));
                const uint8_t index = tables.nearest[(size_t(b) * kNearestCells + size_t(g)) * kNearestCells + size_t(r)];
                if (distance(palette[index], cr, cg, cb) > best + 1e-9) ++wrong;
            }
        }
    }
    EXPECT_EQ(wrong, 0);
    // Every palette colour is its own index through the table, so a texture painted in palette
    // colours keeps them.
    for (int i = 0; i < 256; ++i) EXPECT_EQ(tables.lookUp(palette[size_t(i)]), i);
    // Any colour: the table's colour is at most the exact nearest's distance plus twice the
    // distance to the cell's centre (triangle inequality; ≤ 1.5 √3 per cell).
    const double slack = 2.0 * 1.5 * std::sqrt(3.0) + 1e-9;
    int beyond = 0;
    for (int r = 0; r < 256; r += 5) {
        for (int g = 0; g < 256; g += 7) {
            for (int b = 0; b < 256; b += 3) {
                const Rgb c{uint8_t(r), uint8_t(g), uint8_t(b)};
                const double exact = distance(palette[nearestIndex(palette, c)], r, g, b);
                if (distance(palette[tables.lookUp(c)], r, g, b) > exact + slack) ++beyond;
            }
        }
    }
    EXPECT_EQ(beyond, 0);
    // shade = the colour map at the level, of the table's index; levels outside 0–31 clamp.
    const Rgb orange{230, 120, 40};
    EXPECT_EQ(tables.shade(orange, 0), tables.lookUp(orange));
    EXPECT_EQ(tables.shade(orange, 20), tables.colormap[20][tables.lookUp(orange)]);
    EXPECT_EQ(tables.shade(orange, 99), tables.colormap[31][tables.lookUp(orange)]);
}
