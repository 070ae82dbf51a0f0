// Doom's light diminishing (id Software 1993; scene::doom::colormapIndex is the CPU twin): the
// colour-map level of a sector light level at a distance from the viewer.

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

// r_main.c, R_ExecuteSetViewSize: walls and things take scalelight[light][scale], scale =
// projection / distance >> LIGHTSCALESHIFT = 2560 / distance (map units, Doom's 320-column
// view), at most MAXLIGHTSCALE - 1 = 47; level = startmap - scale / DISTMAP. `contrast` is
// r_segs.c's fake contrast: -1 for a wall along the map's x axis, +1 along its y axis.
int doomWallColormapIndex(float light, float distanceUnits, int contrast)
{
    int lightNumber = clamp((clamp(int(light + 0.5), 0, 255) >> 4) + contrast, 0, 15);
    int startmap = ((16 - 1 - lightNumber) * 2) * 32 / 16;
    int scale = min(int(2560.0 / max(distanceUnits, 1.0)), 47);
    return clamp(startmap - scale / 2, 0, 31);
}

// The level of a wall or a thing `distanceMetres` from the viewer in a sector of light `light`.
uint doomWallLevel(float light, float distanceMetres, int contrast)
{
    return uint(doomWallColormapIndex(light, distanceMetres * kDoomUnitsPerMetre, contrast));
}

// The level of a surface `distanceMetres` from the viewer in a sector of light level `light` (0..255).
uint doomLevel(float light, float distanceMetres)
{
    return uint(doomColormapIndex(light, distanceMetres * kDoomUnitsPerMetre));
}
