// Doom's colour tables (scene/DoomPalette.h, uploaded by render/DoomPass): the nearest-index
// table, the colour map and the palette. Texture colour → palette index → colour map at a
// level → palette colour, every step a texelFetch, so nothing blends two indices and the
// result is a palette colour. Used by the forward pass (per-material Doom materials, inline),
// the billboard pass and the colour-map pass of a Doom frame (colormap.frag).
#include "../common/color.glsl"

layout(binding = SPECULA_UNIT_DOOM_NEAREST) uniform usampler3D uDoomNearest;   // 64^3 cells of 4 sRGB steps
layout(binding = SPECULA_UNIT_DOOM_COLORMAP) uniform usampler2D uDoomColormap; // x = index, y = level
layout(binding = SPECULA_UNIT_DOOM_PALETTE) uniform sampler2D uDoomPalette;    // x = index, sRGB bytes / 255

const int kDoomNearestCellSize = 4; // scene::doom::kNearestCellSize

// The palette index of a linear colour: its sRGB bytes, then the nearest-index table's cell
// (ColorTables::lookUp). A colour brighter than white (an HDR sprite tint, a light gizmo) is
// scaled down to its brightest channel = 1 first, keeping its hue rather than clipping to white.
uint doomPaletteIndex(vec3 linearColor)
{
    vec3 c = max(linearColor, vec3(0.0));
    c /= max(1.0, max(c.r, max(c.g, c.b)));
    ivec3 srgb = ivec3(floor(linearToSrgb(c) * 255.0 + 0.5));
    return texelFetch(uDoomNearest, srgb / kDoomNearestCellSize, 0).r;
}

// What Doom's screen shows for palette index `index` lit at colour-map `level`: the palette
// colour of colormap[level][index], sRGB in 0..1 (ColorTables::shade).
vec3 doomColor(uint index, uint level)
{
    uint lit = texelFetch(uDoomColormap, ivec2(int(index), int(level)), 0).r;
    return texelFetch(uDoomPalette, ivec2(int(lit), 0), 0).rgb;
}
