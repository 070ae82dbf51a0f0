#include "scene/DoomPalette.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace specula::scene::doom {
namespace {

// Ramps as Doom's PLAYPAL groups its colours (greys, browns, skin, greens, reds, blues,
// oranges, yellows...), each a run of shades; ours run dark to light. The end points are our
// own choices, picked for coverage: wide ramps for what levels are made of (stone, earth,
// wood, brick), narrow ones for the saturated accents. No ramp starts at black but the greys,
// so the palette has one black and 256 distinct colours.
constexpr PaletteRamp kRamps[] = {
    {"greys", 32, {0, 0, 0}, {124, 124, 124}, {255, 255, 255}},
    {"browns", 32, {22, 12, 4}, {118, 76, 38}, {214, 170, 118}},
    {"skin", 16, {48, 22, 14}, {170, 104, 76}, {255, 206, 176}},
    {"tans", 16, {40, 34, 22}, {150, 128, 92}, {246, 230, 194}},
    {"olive", 16, {18, 22, 8}, {98, 102, 44}, {206, 204, 138}},
    {"greens", 24, {0, 18, 0}, {40, 110, 28}, {170, 240, 140}},
    {"reds", 24, {30, 0, 0}, {170, 16, 12}, {255, 140, 120}},
    {"oranges", 16, {52, 18, 0}, {208, 96, 8}, {255, 206, 110}},
    {"yellows", 8, {92, 76, 0}, {206, 184, 16}, {255, 255, 150}},
    {"blues", 16, {0, 0, 40}, {32, 56, 176}, {160, 186, 255}},
    {"steel", 24, {12, 16, 24}, {84, 96, 116}, {206, 216, 234}},
    {"teals", 16, {0, 24, 28}, {16, 120, 130}, {150, 250, 250}},
    {"purples", 8, {30, 0, 38}, {122, 34, 146}, {236, 156, 255}},
    {"pinks", 8, {58, 18, 30}, {196, 86, 120}, {255, 192, 214}},
};

int distanceSquared(Rgb a, Rgb b)
{
    const int dr = int(a[0]) - b[0], dg = int(a[1]) - b[1], db = int(a[2]) - b[2];
    return dr * dr + dg * dg + db * db;
}

} // namespace

std::span<const PaletteRamp> paletteRamps()
{
    return kRamps;
}

Palette makePalette()
{
    Palette palette{};
    size_t i = 0;
    for (const PaletteRamp& ramp : kRamps) {
        for (int k = 0; k < ramp.count; ++k) {
            // Dark → mid over the first half, mid → light over the second.
            const double t = double(k) / double(ramp.count - 1);
            const Rgb& a = t < 0.5 ? ramp.dark : ramp.mid;
            const Rgb& b = t < 0.5 ? ramp.mid : ramp.light;
            const double u = t < 0.5 ? 2.0 * t : 2.0 * t - 1.0;
            Rgb c;
            for (size_t ch = 0; ch < 3; ++ch) c[ch] = uint8_t(std::lround(a[ch] + (b[ch] - a[ch]) * u));
            assert(i < palette.size());
            palette[i++] = c;
        }
    }
    assert(i == palette.size());
    return palette;
}

uint8_t nearestIndex(const Palette& palette, Rgb c)
{
    int best = 0, bestDistance = 1 << 30;
    for (int i = 0; i < 256; ++i) {
        const int d = distanceSquared(palette[size_t(i)], c);
        if (d < bestDistance) bestDistance = d, best = i;
    }
    return uint8_t(best);
}

std::vector<ColormapLevel> makeColormap(const Palette& palette)
{
    std::vector<ColormapLevel> map(kColormaps);
    for (int level = 0; level < kColormaps; ++level) {
        const double scale = 1.0 - double(level) / kColormaps;
        for (int i = 0; i < 256; ++i) {
            Rgb c;
            for (size_t ch = 0; ch < 3; ++ch) c[ch] = uint8_t(std::lround(palette[size_t(i)][ch] * scale));
            map[size_t(level)][size_t(i)] = nearestIndex(palette, c);
        }
    }
    return map;
}

std::vector<uint8_t> makeNearestTable(const Palette& palette)
{
    // Exact nearest of each cell's centre, 4c + 1.5: in doubled coordinates (8c + 3 against
    // 2p) everything is an integer. The distance and the index are packed into one key,
    // distance << 8 | index, so the smallest key is the nearest colour with the lowest index
    // on a tie (as nearestIndex) and the inner loop is a plain minimum over 256 keys.
    constexpr int kN = kNearestCells;
    std::array<std::array<int, 256>, 3> doubled{};
    for (size_t i = 0; i < 256; ++i)
        for (size_t ch = 0; ch < 3; ++ch) doubled[ch][i] = 2 * palette[i][ch];
    std::vector<uint8_t> table(size_t(kN) * kN * kN);
    std::array<uint32_t, 256> rg{};
    for (int g = 0; g < kN; ++g) {
        for (int r = 0; r < kN; ++r) {
            const int cr = 2 * kNearestCellSize * r + kNearestCellSize - 1, cg = 2 * kNearestCellSize * g + kNearestCellSize - 1;
            for (size_t i = 0; i < 256; ++i) {
                const int dr = cr - doubled[0][i], dg = cg - doubled[1][i];
                rg[i] = uint32_t(dr * dr + dg * dg);
            }
            for (int b = 0; b < kN; ++b) {
                const int cb = 2 * kNearestCellSize * b + kNearestCellSize - 1;
                uint32_t best = ~0u;
                // Largest key: 3 · 510² < 2^20, shifted by 8 bits: fits in 32.
                for (uint32_t i = 0; i < 256; ++i) {
                    const int db = cb - doubled[2][i];
                    best = std::min(best, (rg[i] + uint32_t(db * db)) << 8 | i);
                }
                table[(size_t(b) * kN + size_t(g)) * kN + size_t(r)] = uint8_t(best & 0xffu);
            }
        }
    }
    return table;
}

uint8_t ColorTables::lookUp(Rgb c) const
{
    constexpr int kN = kNearestCells;
    const size_t r = c[0] / kNearestCellSize, g = c[1] / kNearestCellSize, b = c[2] / kNearestCellSize;
    return nearest[(b * kN + g) * kN + r];
}

uint8_t ColorTables::shade(Rgb c, int level) const
{
    return colormap[size_t(std::clamp(level, 0, kColormaps - 1))][lookUp(c)];
}

const ColorTables& colorTables()
{
    // Built on first use (the nearest-index table is the slow part); immutable afterwards.
    static const ColorTables tables = [] {
        ColorTables t;
        t.palette = makePalette();
        t.colormap = makeColormap(t.palette);
        t.nearest = makeNearestTable(t.palette);
        return t;
    }();
    return tables;
}

} // namespace specula::scene::doom
