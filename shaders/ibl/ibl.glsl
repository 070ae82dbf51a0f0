// Image-based lighting for the forward pass: the irradiance cube (the exact cosine convolution
// of the environment, ibl/irradiance.comp) for the diffuse lobe, the prefiltered radiance and
// DFG table (split sum, Karis 2013) for the specular lobe.
#include "../shared/EnvironmentData.h"
#include "source_cosine.glsl"

layout(std140, binding = SPECULA_BINDING_ENVIRONMENT) uniform EnvironmentBlock { EnvironmentData environment; };
layout(binding = SPECULA_UNIT_PREFILTERED) uniform samplerCube uPrefiltered;
layout(binding = SPECULA_UNIT_IRRADIANCE) uniform samplerCube uIrradiance;
// The environment cube with its box-filtered mips: sampled per pixel by ibl/importance.glsl
// and by the sheen lobe (forward/sheen.glsl).
layout(binding = SPECULA_UNIT_ENVIRONMENT_CUBE) uniform samplerCube uEnvironmentCube;

// World directions to the map's own. With IBL_UNROTATED (the map not turned: ForwardPass and
// SkyboxPass compile it in while the rotation is a whole turn) they are the same, and no
// block is read per pixel: on llvmpipe the rotation was 4 ms of pair B's 80 ms forward pass
// (docs/performance.md).
vec3 toEnvironment(vec3 worldDirection)
{
#if defined(IBL_UNROTATED)
    return worldDirection;
#else
    return mat3(environment.worldToEnvironment) * worldDirection;
#endif
}

#if defined(IBL_SOURCE_COUNT)
// Irradiance E(n), lux, at environment-space normal n: the cube (the environment less its
// brightest parts) plus those parts summed here, exactly — a cube's bilinear filter would round
// the kink of max(0, n·d) at a bright source's terminator (which each part's spread rounds as
// its light does: source_cosine.glsl). The parts are constants of the
// program (IBL_SOURCE_COUNT, IBL_SOURCE_DIRECTIONS, IBL_SOURCE_FLUXES and IBL_SOURCE_SPREADS, written by
// render/passes/ForwardPass for the environment on screen, which recompiles when it changes):
// folded into the code they cost half of what reading them from a uniform block does on
// llvmpipe, whose gallivm loads every block member per lane (docs/performance.md).
vec3 irradianceCube(vec3 n)
{
    vec3 e = textureLod(uIrradiance, n, 0.0).rgb;
#if IBL_SOURCE_COUNT > 0
    const vec3 directions[IBL_SOURCE_COUNT] = vec3[](IBL_SOURCE_DIRECTIONS); // environment space
    const vec3 fluxes[IBL_SOURCE_COUNT] = vec3[](IBL_SOURCE_FLUXES);         // lux at normal incidence
    const float spreads[IBL_SOURCE_COUNT] = float[](IBL_SOURCE_SPREADS);     // radians
    for (int i = 0; i < IBL_SOURCE_COUNT; ++i) e += fluxes[i] * sourceCosine(dot(n, directions[i]), spreads[i]);
#endif
    return e;
}
#endif

// Irradiance E(n) from the order-2 SH of the radiance (Ramamoorthi & Hanrahan 2001, eq. 8,
// 13): the clamped-cosine convolution scales band l by A_0 = pi, A_1 = 2pi/3, A_2 = pi/4.
vec3 irradianceSh(vec3 n)
{
    const float c0 = 0.282095 * PI;
    const float c1 = 0.488603 * 2.0 * PI / 3.0;
    const float c2 = 1.092548 * PI / 4.0;
    const float c3 = 0.315392 * PI / 4.0;
    const float c4 = 0.546274 * PI / 4.0;
    vec3 e = environment.sh[0].rgb * c0
           + environment.sh[1].rgb * (c1 * n.y) + environment.sh[2].rgb * (c1 * n.z) + environment.sh[3].rgb * (c1 * n.x)
           + environment.sh[4].rgb * (c2 * n.x * n.y) + environment.sh[5].rgb * (c2 * n.y * n.z)
           + environment.sh[6].rgb * (c3 * (3.0 * n.z * n.z - 1.0)) + environment.sh[7].rgb * (c2 * n.x * n.z)
           + environment.sh[8].rgb * (c4 * (n.x * n.x - n.y * n.y));
    return max(e, vec3(0.0));
}

// The split sum prefilters with n = v = r; a real GGX lobe leans from r towards n as
// roughness grows. Sampling along this dominant direction instead of r removes most of that
// error (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", listing 22).
vec3 specularDominantDirection(vec3 n, vec3 r, float perceptualRoughness)
{
    float alpha = perceptualRoughness * perceptualRoughness;
    float smoothness = 1.0 - alpha;
    return normalize(mix(n, r, smoothness * (sqrt(smoothness) + alpha)));
}

vec3 prefilteredRadiance(vec3 r, float perceptualRoughness)
{
    float lod = perceptualRoughness * (environment.params.y - 1.0);
    return textureLod(uPrefiltered, toEnvironment(r), lod).rgb;
}

// Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", eq. 107: specular occlusion from
// ambient occlusion, tighter for smooth surfaces.
float specularOcclusion(float NoV, float ao, float perceptualRoughness)
{
    float alpha = perceptualRoughness * perceptualRoughness;
    return clamp(pow(NoV + ao, exp2(-16.0 * alpha - 1.0)) - 1.0 + ao, 0.0, 1.0);
}

// Horizon fading (Russell 2015, "Horizon Occlusion for Normal Mapped Reflections"): a normal
// map can reflect directions below the geometric surface; fade what they would fetch.
float horizonFade(vec3 r, vec3 geometricNormal)
{
    float horizon = clamp(1.0 + 1.3 * dot(r, geometricNormal), 0.0, 1.0);
    return horizon * horizon;
}
