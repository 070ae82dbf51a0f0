// Doom-era lighting in the forward pass (id Software 1993; docs/materials.md): a sector light
// level (the material's), light diminishing with distance from the viewer (doom/light.glsl),
// and the palette's colour tables (doom/palette.glsl). Doom's textures were palette indices
// and its colour map turned (level, index) into the index the screen showed; here the base
// colour becomes its palette index through the nearest-index table. Lights, environment and
// emission are ignored. Included by pbr.frag through shading_models.glsl in every variant;
// only SHADING_DOOM (and a Doom frame's DOOM_INDEXED) call it.
#include "../doom/light.glsl"
#include "../doom/palette.glsl"

// This fragment's palette index and colour-map level. Doom had walls (vertical) and flats
// (horizontal), lit by two tables: a vertical surface (its normal within 1e-3 of horizontal) is
// lit as a wall, with the fake contrast of walls along the map's axes (x and z here); anything
// else as a flat. Distance is Doom's: the depth along the view direction (r_plane.c's
// planeheight · yslope, r_segs.c's rw_scale), so equal light runs in straight bands across the
// screen, not in circles around the viewer.
uvec2 doomIndexLevel(vec3 baseColor)
{
    float light = material.emissive.w * 255.0; // the sector light level, 0..255
    float distance = -(frame.view * vec4(vWorldPosition, 1.0)).z;
    vec3 n = normalize(vNormal);
    uint level;
    if (abs(n.y) < 1e-3) {
        int contrast = abs(n.x) < 1e-3 ? -1 : abs(n.z) < 1e-3 ? 1 : 0;
        level = doomWallLevel(light, distance, contrast);
    } else {
        level = doomLevel(light, distance);
    }
    return uvec2(doomPaletteIndex(baseColor), level);
}

// A Doom material in an otherwise normal frame: the colour-map pass's lookup done here, as the
// linear radiance that an sRGB target encodes back to the palette colour's bytes.
vec3 shadeDoom(vec3 baseColor)
{
    uvec2 indexLevel = doomIndexLevel(baseColor);
    return srgbToLinear(doomColor(indexLevel.x, indexLevel.y));
}
