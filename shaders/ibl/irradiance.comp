#version 450 core
// The irradiance cube: E(n) = ∫ L(ω) max(0, n·ω) dω at the centre of each texel, the exact
// cosine convolution of the environment summed over its sources — the equirectangular map
// reduced on the CPU to blocks of texels, each its flux (Σ L dω, kept in 32-bit float so that
// a sun beyond half-float range keeps its energy) seen from the centroid of its radiance
// with its spread across the horizon (shading/EnvironmentMap: irradianceSources, and
// irradianceCube, this shader's CPU twin).
#include "../common/math.glsl"
#include "cube.glsl"
#include "source_cosine.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly imageCube uTarget;

struct Source {
    vec4 direction; // xyz; w: the spread (source_cosine.glsl)
    vec4 flux;      // rgb, lux at normal incidence
};
layout(std430, binding = 0) readonly buffer Sources { Source sources[]; };

void main()
{
    ivec3 id = ivec3(gl_GlobalInvocationID);
    int size = imageSize(uTarget).x;
    if (id.x >= size || id.y >= size) return;
    vec3 n = cubeDirection(uint(id.z), (vec2(id.xy) + 0.5) / float(size));
    vec3 e = vec3(0.0);
    int count = sources.length();
    for (int i = 0; i < count; ++i) e += sources[i].flux.rgb * sourceCosine(dot(n, sources[i].direction.xyz), sources[i].direction.w);
    imageStore(uTarget, id, vec4(e, 1.0));
}
