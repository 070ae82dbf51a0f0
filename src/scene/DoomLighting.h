#pragma once
// Doom-era lighting as plain data and integer arithmetic (no GL): sectors with light levels,
// light spreading between adjacent sectors, and Doom's light diminishing (colour-map level
// from light level and distance). The palette and colour map are in scene/DoomPalette.h, the
// demo level in scene/DoomLevel.h; shaders/doom/light.glsl is the GPU twin of colormapIndex
// and wallColormapIndex.
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scene/DoomPalette.h"

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

/// Doom's light diminishing for floors and ceilings (r_main.c, R_InitLightTables, 1993):
/// startmap = (15 − light/16) · 2 · 32/16, level = startmap − 80 / (distance/16 + 1), clamped
/// to [0, 31]; `distance` in map units (1 unit ≈ 3 cm). Also usable as fog.
int colormapIndex(int light, double distance);

/// The wall's fake contrast (r_segs.c): a wall along the map's x axis is one light level (16)
/// darker, one along its y axis one brighter, others as their sector.
enum class WallContrast { AlongX = -1, None = 0, AlongY = 1 };
/// Doom's light diminishing for walls and things (r_main.c, R_ExecuteSetViewSize's
/// scalelight): scale = projection / distance >> LIGHTSCALESHIFT = 2560 / distance at Doom's
/// 320-column view, at most 47; level = startmap − scale/2, startmap from the light level
/// shifted by `contrast` (clamped to 0–15 levels), clamped to [0, 31].
int wallColormapIndex(int light, double distance, WallContrast contrast = WallContrast::None);

} // namespace specula::scene::doom
