// Doom-era lighting in the forward pass (id Software 1993; docs/materials.md): a sector light
// level (the material's), light diminishing with distance from the viewer (doom/light.glsl),
// and the palette's colour tables (doom/palette.glsl). Doom's textures were palette indices
// and its colour map turned (level, index) into the index the screen showed; here the base
// colour becomes its palette index through the nearest-index table. Lights, environment and
// emission are ignored. Included by pbr.frag through shading_models.glsl in every variant;
// only SHADING_DOOM (and a Doom frame's DOOM_INDEXED) call it.
#include "../doom/light.glsl"
#include "../doom/palette.glsl"

// This fragment's palette index and colour-map level.
uvec2 doomIndexLevel(vec3 baseColor)
{
    float light = material.emissive.w * 255.0; // the sector light level, 0..255
    return uvec2(doomPaletteIndex(baseColor), doomLevel(light, length(frame.cameraPosition.xyz - vWorldPosition)));
}

// A Doom material in an otherwise normal frame: the colour-map pass's lookup done here, as the
// linear radiance that an sRGB target encodes back to the palette colour's bytes.
vec3 shadeDoom(vec3 baseColor)
{
    uvec2 indexLevel = doomIndexLevel(baseColor);
    return srgbToLinear(doomColor(indexLevel.x, indexLevel.y));
}
