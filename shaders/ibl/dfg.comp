#version 450 core
// The split-sum DFG table (Karis 2013) of one BRDF variant: for n.v = x and perceptual
// roughness = y, A = integral of f(l, v) (n.l) with F = 1 - Fc and B = the same with F = Fc,
// where F = f0 + (f90 - f0) Fc, so that the single-scattering specular albedo is f0 A + f90 B.
// One source for every variant: the forward pass's D, G and F defines (shading/ShadingVariant)
// select the terms of brdf/brdf.glsl, so the table integrates the BRDF the forward pass
// evaluates, with the visibility image-based light sees (brdfVImageBased: Schlick-GGX takes
// k = r^2 / 2 there). The half vectors are importance-sampled by the variant's own D, which
// therefore cancels from the estimator.
#include "../brdf/brdf.glsl"
#include "sampling.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rg16f) uniform writeonly image2D uLut;
uniform uint uSamples;

// Half vector around +Z with pdf brdfD(h) (n.h).
vec3 importanceSampleD(vec2 xi, float alpha)
{
#if defined(BRDF_D_BECKMANN)
    return importanceSampleBeckmann(xi, alpha);
#elif defined(BRDF_D_BLINN_PHONG)
    return importanceSampleBlinnPhong(xi, blinnPhongExponent(alpha));
#else
    return importanceSampleGgx(xi, alpha);
#endif
}

void main()
{
    ivec2 id = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uLut);
    if (id.x >= size.x || id.y >= size.y) return;
    float NoV = (float(id.x) + 0.5) / float(size.x);
    // The forward pass clamps roughness the same way (pbr.frag's kMinPerceptualRoughness).
    float perceptualRoughness = max((float(id.y) + 0.5) / float(size.y), 0.045);
    // Only the roughness enters D and V; colours are irrelevant here.
    SurfaceBrdf surface = makeSurfaceBrdf(vec3(1.0), 1.0, perceptualRoughness, vec4(1.0));
    vec3 v = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
    vec2 sum = vec2(0.0);
    for (uint i = 0u; i < uSamples; ++i) {
        vec3 h = importanceSampleD(hammersley(i, uSamples), surface.alpha);
        float VoH = dot(v, h);
        vec3 l = 2.0 * VoH * h - v;
        float NoL = l.z;
        float NoH = h.z;
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        // f (n.l) / pdf with pdf = D (n.h) / (4 v.h): D cancels, leaving V * 4 (v.h) (n.l) / (n.h).
        float w = brdfVImageBased(surface, NoV, NoL, NoH, VoH) * 4.0 * VoH * NoL / NoH;
        float fc = brdfFresnelWeight(VoH);
        sum += vec2((1.0 - fc) * w, fc * w);
    }
    imageStore(uLut, id, vec4(sum / float(uSamples), 0.0, 0.0));
}
