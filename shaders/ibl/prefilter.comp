#version 450 core
// Prefiltered radiance for the split-sum specular term (Karis 2013): mip level m of the output
// holds the GGX-weighted average of the environment around each direction, for perceptual
// roughness m / (levels - 1), with n = v = r. Filtered importance sampling (Křivánek & Colbert
// 2008, "Real-time Shading with Filtered Importance Sampling", eq. 11-12) reads each sample at
// the mip whose texel solid angle matches the sample's, so a bright sun cannot alias into
// fireflies with few samples.
#include "../common/math.glsl"
#include "../brdf/ggx.glsl"
#include "cube.glsl"
#include "sampling.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform samplerCube uSource;
layout(binding = 0, rgba16f) uniform writeonly imageCube uTarget;

uniform float uPerceptualRoughness;
uniform uint uSamples;
uniform float uSourceSize;   // base level size of uSource
uniform float uSourceLevels; // mip count of uSource
// Every uStride-th texel of a level of uLevelSize² faces, into a target of (uLevelSize /
// uStride)² (a converged reference of a few texels: tests/gl/test_ibl.cpp); 0: the target's
// own texels (the bake).
uniform int uStride;
uniform int uLevelSize;
// The first texel (x, y) and face (z) of this dispatch: a bake spread over frames writes a band
// of rows of a face at a time.
uniform ivec3 uOffset;

void main()
{
    ivec3 id = ivec3(gl_GlobalInvocationID) + uOffset;
    int size = imageSize(uTarget).x;
    if (id.x >= size || id.y >= size) return;
    vec2 texel = vec2(id.xy);
    if (uStride > 0) {
        texel = texel * float(uStride) + float(uStride / 2);
        size = uLevelSize;
    }
    vec3 n = cubeDirection(uint(id.z), (texel + 0.5) / float(size));

    if (uPerceptualRoughness <= 0.0) {
        // A mirror: the source at the level whose texels match this output's.
        float lod = log2(uSourceSize / float(size));
        imageStore(uTarget, id, vec4(textureLod(uSource, n, lod).rgb, 1.0));
        return;
    }

    float alpha = uPerceptualRoughness * uPerceptualRoughness;
    mat3 frame = basisAround(n);
    // Solid angle of one source texel at the base level (6 faces of size^2 over 4 pi).
    float texelSolidAngle = 4.0 * PI / (6.0 * uSourceSize * uSourceSize);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (uint i = 0u; i < uSamples; ++i) {
        // The half vector in n's frame: its z is n.h, and with v = n, n.l = 2 (n.h)^2 - 1. Both, the
        // pdf and the mip below are then the same for every texel (none is read from n per
        // texel): 14 % off the bake on llvmpipe.
        vec3 hs = importanceSampleGgx(hammersley(i, uSamples), alpha);
        vec3 h = frame * hs;
        float NoH = hs.z;
        vec3 l = 2.0 * NoH * h - n; // reflect v = n about h
        float NoL = 2.0 * NoH * NoH - 1.0;
        if (NoL <= 0.0) continue;
        // With n = v, the pdf of l is D(h) (n.h) / (4 v.h) = D(h) / 4.
        float pdf = D_GGX(NoH, alpha) * 0.25;
        float sampleSolidAngle = 1.0 / (float(uSamples) * pdf + 1e-6);

        float lod = clamp(0.5 * log2(sampleSolidAngle / texelSolidAngle), 0.0, uSourceLevels - 1.0);
        sum += textureLod(uSource, l, lod).rgb * NoL;
        weight += NoL;
    }
    imageStore(uTarget, id, vec4(sum / max(weight, 1e-6), 1.0));
}
