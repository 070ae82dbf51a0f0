#pragma once
// Doom-era lighting as plain data and integer arithmetic (no GL): sectors with light levels
// and light spreading between adjacent sectors, Doom's light diminishing (colour-map index
// from light level and distance), and a 256-colour palette with a 32-level colour map used
// to quantise an image. The forward pass's Doom model (shaders/forward/doom.glsl) is the GPU
// twin of colormapIndex, makePalette and makeColormap.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace specula::scene::doom {

/// A region of the floor plan: an axis-aligned rectangle (x, z in map units) with a light level.
struct Sector {
    glm::ivec2 min{0}, max{0};
    int light = 160; ///< 0 (dark) to 255 (full bright), as Doom's sector light level
};

/// Pairs (a, b), a < b, of sectors whose rectangles share an edge of positive length.
std::vector<std::pair<int, int>> adjacentSectors(const std::vector<Sector>& sectors);

/// Light spreading: each sector ends at max(own level, neighbour's final level − attenuation),
/// clamped to [0, 255] (a fixed point, reached by relaxation: light leaks through openings and
/// fades by `attenuation` per sector crossed).
std::vector<int> spreadLight(const std::vector<Sector>& sectors, int attenuation);

constexpr int kColormaps = 32;   ///< Doom's NUMCOLORMAPS: 0 = full bright, 31 = darkest
/// Doom's light diminishing for floors and ceilings (r_main.c, R_InitLightTables, 1993):
/// startmap = (15 − light/16) · 2 · 32/16, level = startmap − 80 / (distance/16 + 1), clamped
/// to [0, 31]; `distance` in map units (1 unit ≈ 3 cm). Also usable as fog.
int colormapIndex(int light, double distance);

using Rgb = std::array<uint8_t, 3>;

/// 256 colours: a 6 × 6 × 6 colour cube (216) and 40 greys, sRGB.
std::array<Rgb, 256> makePalette();
/// The colour map: for each of the 32 levels and each palette colour, the palette index
/// nearest that colour darkened by (1 − level / 32) in sRGB (as Doom's COLORMAP lump).
std::vector<std::array<uint8_t, 256>> makeColormap(const std::array<Rgb, 256>& palette);
/// Index of the palette colour nearest `c` (squared distance in sRGB).
uint8_t nearestIndex(const std::array<Rgb, 256>& palette, Rgb c);

/// Sectors of the demo level (map units: 32 a metre), with their own light levels.
struct LevelSector {
    Sector sector;
    int floor = 0, ceiling = 128; ///< heights, map units
    // Linear; saturated enough to land on the palette's colour cube rather than its greys.
    glm::vec3 floorColor{0.35f, 0.20f, 0.08f}, wallColor{0.15f, 0.25f, 0.10f}, ceilingColor{0.45f, 0.45f, 0.42f};
};
std::vector<LevelSector> demoLevelSectors();
/// The demo level: a lit start room, a corridor, a hall, a dark side room and a nook, their
/// light spread with attenuation 64, as floors, ceilings and walls of Doom-model materials,
/// with a camera in the start room looking down the corridor.
Scene makeDemoLevel();

} // namespace specula::scene::doom
