// Cube-map texel <-> direction, OpenGL's face conventions (ARB_texture_cube_map table 3.19):
// face 0..5 = +X, -X, +Y, -Y, +Z, -Z; st in [0, 1] with t going down the face.
vec3 cubeDirection(uint face, vec2 st)
{
    vec2 uv = st * 2.0 - 1.0;
    vec3 d;
    if (face == 0u) d = vec3(1.0, -uv.y, -uv.x);
    else if (face == 1u) d = vec3(-1.0, -uv.y, uv.x);
    else if (face == 2u) d = vec3(uv.x, 1.0, uv.y);
    else if (face == 3u) d = vec3(uv.x, -1.0, -uv.y);
    else if (face == 4u) d = vec3(uv.x, -uv.y, 1.0);
    else d = vec3(-uv.x, -uv.y, -1.0);
    return normalize(d);
}

// The equirectangular convention (docs/units.md): u = 0.5 + atan2(d.x, -d.z) / 2pi, v = acos(d.y) / pi.
vec2 directionToEquirect(vec3 d)
{
    return vec2(0.5 + atan(d.x, -d.z) * (0.5 * INV_PI), acos(clamp(d.y, -1.0, 1.0)) * INV_PI);
}
