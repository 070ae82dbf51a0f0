#version 450 core
// The equirectangular source (RGBA32F) resampled into a cube map's base level.
#include "../common/math.glsl"
#include "cube.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D uSource;
layout(binding = 0, rgba16f) uniform writeonly imageCube uCube;
// The first texel (x, y) and face (z) of this dispatch: a bake spread over frames writes a band
// of rows of a face at a time.
uniform ivec3 uOffset;

void main()
{
    ivec3 id = ivec3(gl_GlobalInvocationID) + uOffset;
    int size = imageSize(uCube).x;
    if (id.x >= size || id.y >= size) return;
    vec3 d = cubeDirection(uint(id.z), (vec2(id.xy) + 0.5) / float(size));
    vec2 uv = directionToEquirect(d);
    // Explicit lod 0 with the source's own bilinear filter; the cube is about as dense as the
    // source (a 1k map gives 0.35 degrees per texel, a 256 cube 0.35 at the face centre).
    vec3 radiance = textureLod(uSource, uv, 0.0).rgb;
    // Half floats top out at 65504: keep a real sun finite rather than Inf.
    imageStore(uCube, id, vec4(min(radiance, vec3(65504.0)), 1.0));
}
