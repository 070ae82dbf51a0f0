#version 450 core
// The split-sum DFG table (Karis 2013): for n.v = x and perceptual roughness = y,
// R = integral of f(l, v) (n.l) with F = 1 - Fc and G = integral with F = Fc, where
// Fc = (1 - v.h)^5, so the specular albedo is F0 * R + G. Integrated by GGX importance
// sampling with the same masking-shadowing term as the BRDF: separable Smith GGX (glTF), or
// with BRDF_G_SCHLICK_GGX Schlick-GGX with k = alpha / 2 = r^2 / 2 (Karis' remap for IBL).
#include "../common/math.glsl"
#include "../brdf/ggx.glsl"
#include "../brdf/smith.glsl"
#include "sampling.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rg16f) uniform writeonly image2D uLut;
uniform uint uSamples;

float visibility(float NoV, float NoL, float alpha)
{
#if defined(BRDF_G_SCHLICK_GGX)
    float k = alpha * 0.5;
    float gl = NoL / (NoL * (1.0 - k) + k);
    float gv = NoV / (NoV * (1.0 - k) + k);
    return gl * gv / (4.0 * NoL * NoV);
#else
    return V_SmithGGX(NoV, NoL, alpha);
#endif
}

void main()
{
    ivec2 id = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uLut);
    if (id.x >= size.x || id.y >= size.y) return;
    float NoV = (float(id.x) + 0.5) / float(size.x);
    float perceptualRoughness = max((float(id.y) + 0.5) / float(size.y), 0.045);
    float alpha = perceptualRoughness * perceptualRoughness;
    vec3 v = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
    vec2 sum = vec2(0.0);
    for (uint i = 0u; i < uSamples; ++i) {
        vec3 h = importanceSampleGgx(hammersley(i, uSamples), alpha);
        float VoH = dot(v, h);
        vec3 l = 2.0 * VoH * h - v;
        float NoL = l.z;
        float NoH = h.z;
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        // f (n.l) / pdf with pdf = D (n.h) / (4 v.h): D cancels, leaving V * 4 (v.h) (n.l) / (n.h).
        float w = visibility(NoV, NoL, alpha) * 4.0 * VoH * NoL / NoH;
        float fc = pow5(1.0 - VoH);
        sum += vec2((1.0 - fc) * w, fc * w);
    }
    imageStore(uLut, id, vec4(sum / float(uSamples), 0.0, 0.0));
}
