// The environment's bright sources as the specular lobe's lights (IBL_SOURCE_SPECULAR).
// Maps whose light comes mostly from a few small bright parts (a studio's softboxes, a sun:
// ImageBasedLighting::brightSourcesSpecular) give the specular lobe those parts as lights —
// the same sources, constants of the program, that the diffuse term sums (ibl.glsl) — and
// filter only the rest of the map (the residual cube and prefiltered levels, with their texels
// black). Box-filtered mips or a prefilter that assumes n = v = r would spread a softbox over
// tens of degrees, across a rough lobe's horizon; as lights each is exact to its block's size
// (1.4° at 1k). After ibl.glsl and the BRDF.
#include "../brdf/thin_film.glsl"

#if defined(IBL_SOURCE_SPECULAR) && IBL_SOURCE_COUNT > 0
layout(binding = SPECULA_UNIT_RESIDUAL_CUBE) uniform samplerCube uResidualCube;
layout(binding = SPECULA_UNIT_RESIDUAL_PREFILTERED) uniform samplerCube uResidualPrefiltered;

// Σ f_s(l_i, v) (n·l_i) Φ_i over the first IBL_SOURCE_SPECULAR_COUNT sources (those that hold 98 %
// of the sources' flux; the rest stay in the residual map) (Φ_i: the source's radiance × solid angle, lux at
// normal incidence), with the material's own D, V and F; n and v in world space.
vec3 brightSourcesSpecular(SurfaceBrdf s, vec3 n, vec3 v, ThinFilm film)
{
    const vec3 directions[IBL_SOURCE_COUNT] = vec3[](IBL_SOURCE_DIRECTIONS);
    const vec3 fluxes[IBL_SOURCE_COUNT] = vec3[](IBL_SOURCE_FLUXES);
    vec3 ne = toEnvironment(n), ve = toEnvironment(v);
    float NoV = max(dot(ne, ve), 1e-4);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < IBL_SOURCE_SPECULAR_COUNT; ++i) {
        vec3 l = directions[i];
        float NoL = dot(ne, l);
        if (NoL <= 0.0) continue;
        vec3 h = normalize(ve + l);
        float NoH = saturate(dot(ne, h));
        float VoH = saturate(dot(ve, h));
        vec3 F = brdfF(s, VoH);
#if defined(IRIDESCENCE)
        if (film.factor > 0.0) F = mix(F, thinFilmFresnel(film, VoH), film.factor);
#endif
        sum += F * (brdfD(NoH, s.alpha) * brdfV(s, NoV, NoL, NoH, VoH) * NoL) * fluxes[i];
    }
    return sum;
}

// Importance sampling (ibl/importance.glsl): how much of the lobe takes the sources as
// lights — none below perceptual roughness 0.15, where the lobe is narrow enough to show the
// blocks the sources stand for as separate points (and the fine mips it reads keep a
// softbox's shape), all from 0.25.
float brightSourceWeight(float perceptualRoughness)
{
    return smoothstep(0.15, 0.25, perceptualRoughness);
}

// The split sum's prefiltered radiance of the map less the sources, and in `weight` how much
// of the lobe that is: as importance sampling's (brightSourceWeight), the whole map's chain
// below roughness 0.15 (a narrow lobe sees the sources' shapes), the residual chain from 0.25;
// between, the two mix. The residual chain starts at IBL_RESIDUAL_FIRST_LEVEL (1, roughness
// 1/7 with 8 levels), so that from 0.15 on the whole map's levels, which hold the sources, no
// longer mix in: with the residual from level 2 on, roughness 0.25 read a quarter of its light
// from the whole map's level 1-2 mix, whose softboxes were 2.8 times too bright at their
// centres (docs/ibl.md). The caller adds weight × the sources (brightSourcesSpecular).
vec3 prefilteredRadianceLessSources(vec3 r, float perceptualRoughness, out float weight)
{
    float lod = perceptualRoughness * (environment.params.y - 1.0);
    vec3 d = toEnvironment(r);
    weight = brightSourceWeight(perceptualRoughness);
    vec3 radiance = vec3(0.0);
    if (weight < 1.0) radiance += (1.0 - weight) * textureLod(uPrefiltered, d, lod).rgb;
    if (weight > 0.0) radiance += weight * textureLod(uResidualPrefiltered, d, max(lod - float(IBL_RESIDUAL_FIRST_LEVEL), 0.0)).rgb;
    return radiance;
}
#endif
