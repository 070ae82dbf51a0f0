#pragma once
// The Doom model's colours as plain data (no GL): a 256-colour palette laid out as Doom's
// PLAYPAL is (ramps of shades, dark to light), a 32-level colour map (Doom's COLORMAP), and a
// nearest-index table that turns any sRGB colour into a palette index the way Doom-style
// renderers do (a 3D lookup table, not a search per pixel). The colours are generated here
// from our own ramp parameters; none is id Software's. render/DoomPass uploads these tables
// and shaders/doom/palette.glsl reads them, so CPU and GPU agree byte for byte.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace specula::scene::doom {

using Rgb = std::array<uint8_t, 3>;
using Palette = std::array<Rgb, 256>;
/// One level of the colour map: palette index → palette index.
using ColormapLevel = std::array<uint8_t, 256>;

constexpr int kColormaps = 32; ///< Doom's NUMCOLORMAPS: 0 = full bright, 31 = darkest

/// A ramp of the palette: `count` shades from `dark` through `mid` (halfway) to `light`,
/// piecewise linear in sRGB.
struct PaletteRamp {
    const char* name;
    int count;
    Rgb dark, mid, light;
};
/// The ramps in palette order; their counts add up to 256.
std::span<const PaletteRamp> paletteRamps();

/// The palette: the ramps of paletteRamps() one after the other, sRGB.
Palette makePalette();
/// The colour map: for each of the 32 levels and each palette colour, the palette index
/// nearest that colour darkened by (1 − level / 32) in sRGB (as Doom's COLORMAP lump).
std::vector<ColormapLevel> makeColormap(const Palette& palette);
/// Index of the palette colour nearest `c` (squared distance in sRGB; the lowest index on a tie).
uint8_t nearestIndex(const Palette& palette, Rgb c);

/// The nearest-index table: kNearestCells³ cells of kNearestCellSize sRGB steps per channel,
/// each holding nearestIndex() of the cell's centre (exact, computed once). Cell (r, g, b) is
/// entry (b · kNearestCells + g) · kNearestCells + r (red fastest, as a 3D texture's texels).
constexpr int kNearestCellSize = 4;
constexpr int kNearestCells = 256 / kNearestCellSize;
std::vector<uint8_t> makeNearestTable(const Palette& palette);

/// The three tables the Doom model needs, built once per process (lookUp() and render/DoomPass
/// share them).
struct ColorTables {
    Palette palette;
    std::vector<ColormapLevel> colormap; ///< kColormaps levels
    std::vector<uint8_t> nearest;        ///< makeNearestTable(palette)

    /// The palette index of an sRGB colour, through the nearest-index table.
    uint8_t lookUp(Rgb c) const;
    /// What the Doom model shades a texel of sRGB colour `c` with at colour-map `level`:
    /// colormap[level][lookUp(c)] (the GPU twin is doomShade in shaders/doom/palette.glsl).
    uint8_t shade(Rgb c, int level) const;
};
const ColorTables& colorTables();

} // namespace specula::scene::doom
