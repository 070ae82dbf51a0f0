// KHR_materials_sheen: a Charlie sheen lobe (brdf/sheen.glsl) over the material, with the
// extension's albedo scaling in its view-only form: the base (its diffuse and specular lobes and
// transmitted light) keeps 1 - max3(sheenColor) E(n.v), where E is the lobe's directional albedo
// (ibl/sheen_albedo.comp), so the sum never reflects more than arrives (KHR_materials_sheen,
// "Albedo-scaling technique"; Estevez & Kulla 2017). The lobe uses the base's shading normal.
// Under KHR_materials_clearcoat, the layer lies over the sheen (pbr.frag dims both).
// Included by pbr.frag after its blocks and texture_uv.glsl.
#include "../brdf/sheen.glsl"
#if defined(IBL)
#include "../ibl/sampling.glsl"
#endif

layout(binding = SPECULA_UNIT_SHEEN_COLOR) uniform sampler2D uSheenColorTexture;
layout(binding = SPECULA_UNIT_SHEEN_ROUGHNESS) uniform sampler2D uSheenRoughnessTexture;
layout(binding = SPECULA_UNIT_SHEEN_ALBEDO) uniform sampler2D uSheenAlbedo;

struct SheenLayer {
    vec3 color;                // sheenColorFactor x sheenColorTexture.rgb (sRGB, decoded by GL)
    float perceptualRoughness; // sheenRoughnessFactor x sheenRoughnessTexture.a, clamped as the base's
    float alpha;
    float albedo;              // E(n.v) of the lobe with colour 1
    float scaling;             // what the base keeps: 1 - max3(color) albedo
};

SheenLayer makeSheen(float NoV)
{
    SheenLayer s;
    s.color = material.sheen.rgb * texture(uSheenColorTexture, textureUv(TEX_SHEEN_COLOR)).rgb;
    float roughness = material.sheen.a * texture(uSheenRoughnessTexture, textureUv(TEX_SHEEN_ROUGHNESS)).a;
    // The base's floor: below it 1/alpha overflows the exponent of D_Charlie and the lobe is a
    // line at the horizon no pixel resolves; the table is baked with the same clamp.
    s.perceptualRoughness = clamp(roughness, kMinPerceptualRoughness, 1.0);
    s.alpha = s.perceptualRoughness * s.perceptualRoughness;
    s.albedo = texture(uSheenAlbedo, vec2(NoV, s.perceptualRoughness)).r;
    s.scaling = 1.0 - max(max(s.color.r, s.color.g), s.color.b) * s.albedo;
    return s;
}

// The lobe for one light, f_sheen (n.l) (1/sr); the caller has checked n.l > 0.
vec3 sheenPunctual(SheenLayer s, vec3 n, vec3 v, vec3 l, float NoV, float NoL)
{
    float NoH = saturate(dot(n, normalize(v + l)));
    return s.color * (D_Charlie(NoH, s.alpha) * V_Charlie(NoV, NoL, s.alpha) * NoL);
}

#if defined(IBL)
#ifndef SHEEN_IBL_SAMPLES
#define SHEEN_IBL_SAMPLES 64
#endif

// Image-based sheen, integral of f_sheen L (n.l) over the hemisphere, as sheenColor E(n.v) times
// the environment averaged over the lobe: the Charlie-weighted mean of the environment cube
// around (n, v), per pixel, by filtered importance sampling of D_Charlie (Krivanek & Colbert
// 2008, as ibl/importance.glsl): each sample reads the box mip whose texel matches its share of
// the lobe. Weighting by the samples' own f (n.l) / pdf and dividing by their sum makes the mean
// exact in a uniform environment whatever the sample count, and E is the baked table's. In both
// --ibl modes (no prefiltered Charlie chain is baked; only sheen materials pay for this).
vec3 sheenEnvironment(SheenLayer s, vec3 n, vec3 v, float NoV)
{
    float faceSize = float(textureSize(uEnvironmentCube, 0).x);
    float texelSolidAngle = 4.0 * PI / (6.0 * faceSize * faceSize);
    mat3 basis = basisAround(n);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (uint i = 0u; i < uint(SHEEN_IBL_SAMPLES); ++i) {
        vec3 h = basis * importanceSampleCharlie(hammersley(i, uint(SHEEN_IBL_SAMPLES)), s.alpha);
        float VoH = dot(v, h);
        vec3 l = 2.0 * VoH * h - v;
        float NoL = dot(n, l);
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        float NoH = max(dot(n, h), 1e-6); // n.h > n.v / 2 when l is above the horizon
        float pdf = D_Charlie(NoH, s.alpha) * NoH / (4.0 * VoH);
        float lod = max(0.5 * log2(1.0 / (float(SHEEN_IBL_SAMPLES) * pdf * texelSolidAngle)), 0.0);
        float w = V_Charlie(NoV, NoL, s.alpha) * 4.0 * VoH * NoL / NoH;
        sum += w * textureLod(uEnvironmentCube, toEnvironment(l), lod).rgb;
        weights += w;
    }
    // A smooth sheen seen head-on sends every sample below the horizon, and reflects almost
    // nothing there (E tiny): the cosine-weighted mean, irradiance / pi, stands in.
    vec3 mean = weights > 0.0 ? sum / weights : irradianceCube(toEnvironment(n)) * INV_PI;
    return s.color * s.albedo * mean;
}
#endif
