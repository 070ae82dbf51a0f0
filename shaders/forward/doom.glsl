// Doom-era lighting (id Software 1993; scene/DoomLighting.h is the CPU twin): a sector light
// level, light diminishing with distance from the viewer, and a 256-colour palette with a
// 32-level colour map. Doom's textures are palette indices and its colour map turns
// (light level, index) into an index; here the base colour is first quantised to the palette
// (the index), darkened by the colour map's level and quantised again (the colour map's
// entry), so the frame holds only palette colours. The palette (6 × 6 × 6 cube + 40 greys)
// is regular, so the nearest colour needs no table: per-channel rounding for the cube, and a
// scan of the greys.
#include "../common/color.glsl"

const float kDoomUnitsPerMetre = 32.0; // Doom's player is 56 units tall, about 1.75 m

// r_main.c, R_InitLightTables: startmap = (15 - light/16) * 2 * 32/16, level = startmap -
// (160 / (distance/16 + 1)) / 2, clamped to the 32 colour maps (0 = full bright).
int doomColormapIndex(float light, float distanceUnits)
{
    int lightNumber = clamp(int(light + 0.5), 0, 255) >> 4;
    int startmap = ((16 - 1 - lightNumber) * 2) * 32 / 16;
    int z = clamp(int(max(distanceUnits, 0.0) / 16.0), 0, 127);
    int scale = 160 / (z + 1);
    return clamp(startmap - scale / 2, 0, 31);
}

// Nearest palette colour (sRGB, 0..255 per channel) to `c` (sRGB, 0..255), as nearestIndex().
vec3 doomNearest(vec3 c)
{
    vec3 best = clamp(floor(c / 51.0 + 0.5), 0.0, 5.0) * 51.0; // the cube: a separable grid
    vec3 d = best - c;
    float bestDistance = dot(d, d);
    for (int k = 0; k < 40; ++k) {
        float g = floor((float(k) + 1.0) * 255.0 / 41.0 + 0.5);
        vec3 e = vec3(g) - c;
        float distance = dot(e, e);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = vec3(g);
        }
    }
    return best;
}

vec3 shadeDoom(vec3 baseColor, float light, float distanceMetres)
{
    int level = doomColormapIndex(light, distanceMetres * kDoomUnitsPerMetre);
    vec3 index = doomNearest(floor(linearToSrgb(clamp(baseColor, 0.0, 1.0)) * 255.0 + 0.5));
    vec3 lit = doomNearest(floor(index * (1.0 - float(level) / 32.0) + 0.5));
    // Linear radiance that the sRGB output encodes back to exactly these bytes.
    return srgbToLinear(lit / 255.0);
}
