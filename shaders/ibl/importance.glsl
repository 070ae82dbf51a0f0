// View-dependent specular image-based light (--ibl importance): the specular integral
// ∫ f_s(l, v) L(l) (n·l) dω evaluated per pixel with the material's own BRDF, by filtered
// importance sampling (Colbert & Křivánek 2007, GPU Gems 3 ch. 20; Křivánek & Colbert 2008,
// "Real-time Shading with Filtered Importance Sampling"). Unlike the split sum it assumes
// nothing about n, v and r, so reflections stretch at grazing angles as they should.
// Each sample reads the environment cube's box-filtered mip whose texel covers the sample's
// share of the lobe, Ω_s = 1 / (N pdf), against a base texel's Ω_p = 4π / (6 w²): the filter
// then integrates what the N samples leave between them and no sample pattern shows.
#include "sampling.glsl"
#include "../brdf/thin_film.glsl"
#include "bright_sources.glsl"

// Samples per pixel by roughness, chosen by measurement against the noise-free reference
// (docs/ibl.md, GlTest.ImageBasedLightMatchesAMonteCarloReference, copper under studio, sunset
// and venice_1k): with 64 samples everywhere 2.6-3.4 % at roughness 0.5, 3.7-4.7 % at 0.75 and
// 4.3-6.0 % at 1; with 64 / 128 / 256 as below every roughness is within 2.2 %. A wide lobe
// needs more samples because each reads a coarser box mip, which blurs what it reads.
uint importanceSampleCount(float perceptualRoughness)
{
    return perceptualRoughness < 0.375 ? 64u : perceptualRoughness < 0.625 ? 128u : 256u;
}
// Křivánek & Colbert add one level; measured, that doubles the error (the wider box leaks bright
// sources across the horizon), so none.
const float kIblLodBias = 0.0;

// Radiance reflected by the specular lobe towards v (world space), not yet scaled by the
// environment's intensity. `perceptualRoughness` is the unclamped image-based one: 0 is the
// mirror, one fetch of level 0.
// With IRIDESCENCE, `film` replaces each sample's Fresnel by mix(F, the film's F(v.h), factor)
// (KHR_materials_iridescence; noThinFilm() for none).
vec3 importanceSampledSpecular(SurfaceBrdf surface, vec3 n, vec3 v, float perceptualRoughness, ThinFilm film)
{
    float NoV = max(dot(n, v), 1e-4);
    float alpha = perceptualRoughness * perceptualRoughness;
    // Below roughness 0.01 the lobe is narrower than a base texel of a 1024² face: the mirror.
    if (alpha < 1e-4) {
        vec3 r = reflect(-v, n);
        vec3 F = brdfF(surface, NoV);
#if defined(IRIDESCENCE)
        if (film.factor > 0.0) F = mix(F, thinFilmFresnel(film, NoV), film.factor);
#endif
        return F * textureLod(uEnvironmentCube, toEnvironment(r), 0.0).rgb;
    }
    SurfaceBrdf s = surface;
    s.perceptualRoughness = perceptualRoughness;
    s.alpha = alpha;
    float faceSize = float(textureSize(uEnvironmentCube, 0).x);
    float texelSolidAngle = 4.0 * PI / (6.0 * faceSize * faceSize);
    mat3 basis = basisAround(n);
#if defined(IBL_SOURCE_SPECULAR) && IBL_SOURCE_COUNT > 0
    float sourceWeight = brightSourceWeight(perceptualRoughness);
#endif
    uint samples = importanceSampleCount(perceptualRoughness);
    vec3 sum = vec3(0.0);
    for (uint i = 0u; i < samples; ++i) {
        vec2 xi = hammersley(i, samples);
        vec3 h = basis * importanceSampleGgx(xi, alpha);
        float VoH = dot(v, h);
        vec3 l = 2.0 * VoH * h - v;
        float NoL = dot(n, l);
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        float NoH = saturate(dot(n, h));
        // pdf(l) = D_GGX(h) (n·h) / (4 v·h) (Walter et al. 2007, eq. 14 and 38).
        float pdf = D_GGX(NoH, alpha) * NoH / (4.0 * VoH);
        float lod = max(0.5 * log2(1.0 / (float(samples) * pdf * texelSolidAngle)) + kIblLodBias, 0.0);
        vec3 le = toEnvironment(l);
#if defined(IBL_SOURCE_SPECULAR) && IBL_SOURCE_COUNT > 0
        // The map less its bright sources, which are added below as lights (ibl/bright_sources.glsl).
        vec3 radiance = vec3(0.0);
        if (sourceWeight < 1.0) radiance += (1.0 - sourceWeight) * textureLod(uEnvironmentCube, le, lod).rgb;
        if (sourceWeight > 0.0) radiance += sourceWeight * textureLod(uResidualCube, le, lod).rgb;
#else
        vec3 radiance = textureLod(uEnvironmentCube, le, lod).rgb;
#endif
        // f_s (n·l) / pdf = F D V (n·l) 4 (v·h) / (D_GGX (n·h)); D / D_GGX = 1 unless another D.
#if defined(BRDF_D_BECKMANN) || defined(BRDF_D_BLINN_PHONG)
        float dRatio = brdfD(NoH, alpha) / max(D_GGX(NoH, alpha), 1e-30);
#else
        const float dRatio = 1.0;
#endif
        float weight = dRatio * brdfV(s, NoV, NoL, NoH, VoH) * NoL * 4.0 * VoH / max(NoH, 1e-6);
        vec3 F = brdfF(s, VoH);
#if defined(IRIDESCENCE)
        if (film.factor > 0.0) F = mix(F, thinFilmFresnel(film, VoH), film.factor);
#endif
        sum += F * weight * radiance;
    }
    sum /= float(samples);
#if defined(IBL_SOURCE_SPECULAR) && IBL_SOURCE_COUNT > 0
    if (sourceWeight > 0.0) sum += sourceWeight * brightSourcesSpecular(s, n, v, film);
#endif
    return sum;
}

#if defined(ANISOTROPY)
// importanceSampledSpecular for KHR_materials_anisotropy's lobe (forward/anisotropy.glsl):
// half vectors from D_GGX_Anisotropic, the extension's anisotropic V. `albedo` is the same
// samples' estimate of the lobe's split-sum terms, as the DFG table holds them (albedo = f0 x +
// f90 y): the table has only isotropic lobes.
// t, b, n: the lobe's orthonormal frame; alphas: its alpha_t and alpha_b (unclamped). With
// IRIDESCENCE, `film` mixes into each sample's Fresnel as in importanceSampledSpecular (the
// terms stay the film-less lobe's: the caller mixes the film's albedo from them).
vec3 importanceSampledSpecularAnisotropic(SurfaceBrdf surface, ThinFilm film, vec3 n, vec3 t, vec3 b, vec2 alphas, vec3 v, out vec2 dfg)
{
    float NoV = max(dot(n, v), 1e-4);
    // The mirror's: F(n.v) = f0 (1 - Fc) + f90 Fc.
    dfg = vec2(1.0 - brdfFresnelWeight(NoV), brdfFresnelWeight(NoV));
    // Only a mirror in both directions is one (strength 0 at roughness 0): as the isotropic one.
    if (alphas.x < 1e-4) {
        vec3 r = reflect(-v, n);
        vec3 F = brdfF(surface, NoV);
#if defined(IRIDESCENCE)
        if (film.factor > 0.0) F = mix(F, thinFilmFresnel(film, NoV), film.factor);
#endif
        return F * textureLod(uEnvironmentCube, toEnvironment(r), 0.0).rgb;
    }
    // Below roughness 0.01 across the lobe its samples would all fall on a line; the floor
    // (the punctual lights' 0.045, alpha 0.002) keeps D finite and is narrower than a texel.
    alphas.y = max(alphas.y, 0.002);
    float faceSize = float(textureSize(uEnvironmentCube, 0).x);
    float texelSolidAngle = 4.0 * PI / (6.0 * faceSize * faceSize);
    mat3 basis = mat3(t, b, n);
    // As many samples as the isotropic lobe of the wider roughness takes.
    uint samples = importanceSampleCount(sqrt(max(alphas.x, alphas.y)));
    vec3 sum = vec3(0.0);
    vec2 terms = vec2(0.0);
    for (uint i = 0u; i < samples; ++i) {
        vec2 xi = hammersley(i, samples);
        vec3 hl = importanceSampleGgxAnisotropic(xi, alphas.x, alphas.y);
        vec3 h = basis * hl;
        float VoH = dot(v, h);
        vec3 l = 2.0 * VoH * h - v;
        float NoL = dot(n, l);
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        float NoH = hl.z;
        // pdf(l) = D(h) (n.h) / (4 v.h), as the isotropic sampler's.
        float pdf = D_GGX_Anisotropic(NoH, hl.x, hl.y, alphas.x, alphas.y) * NoH / (4.0 * VoH);
        float lod = max(0.5 * log2(1.0 / (float(samples) * pdf * texelSolidAngle)) + kIblLodBias, 0.0);
        vec3 radiance = textureLod(uEnvironmentCube, toEnvironment(l), lod).rgb;
        // f_s (n.l) / pdf = F V (n.l) 4 (v.h) / (n.h).
        float weight = V_SmithGGXCorrelatedAnisotropic(NoV, NoL, dot(t, v), dot(b, v), dot(t, l), dot(b, l), alphas.x, alphas.y) *
                       NoL * 4.0 * VoH / max(NoH, 1e-6);
        vec3 F = brdfF(surface, VoH);
#if defined(IRIDESCENCE)
        if (film.factor > 0.0) F = mix(F, thinFilmFresnel(film, VoH), film.factor);
#endif
        sum += F * weight * radiance;
        float fc = brdfFresnelWeight(VoH);
        terms += weight * vec2(1.0 - fc, fc);
    }
    dfg = terms / float(samples);
    return sum / float(samples);
}
#endif

vec3 importanceSampledSpecular(SurfaceBrdf surface, vec3 n, vec3 v, float perceptualRoughness)
{
    return importanceSampledSpecular(surface, n, v, perceptualRoughness, noThinFilm());
}
