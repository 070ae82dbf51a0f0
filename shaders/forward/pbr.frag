#version 450 core
// Forward pass: glTF metal-rough material lit by punctual lights. This file only
// orchestrates; the BRDF lives in brdf/, light falloff in lights/.
// Material features are compile-time variants (see Renderer's variant key): HAS_*_TEXTURE,
// VERTEX_COLOR, ALPHA_MASK, ALPHA_BLEND (premultiplied output; BLEND_TRANSPARENT: specular and
// emission unscaled by alpha), TRANSMISSION (forward/transmission.glsl), CLEARCOAT
// (forward/clearcoat.glsl), SHEEN (forward/sheen.glsl), ANISOTROPY (forward/anisotropy.glsl),
// IRIDESCENCE (forward/iridescence.glsl), SPECULAR_TEXTURES (forward/specular.glsl),
// TRANSMISSION_TEXTURES (with TRANSMISSION: its factor and the volume's thickness times their
// textures), DIFFUSE_TRANSMISSION (forward/diffuse_transmission.glsl; DIFFUSE_TRANSMISSION_TEXTURES:
// its textures), DOUBLE_SIDED; OIT
// (weighted blended transparency's two targets); per frame, SSAO, and DOOM_INDEXED (a
// Doom frame: with SHADING_DOOM, the output is a palette index and a colour-map level, not a
// colour; render/DoomPass). A material without a feature pays nothing for it; without
// ALPHA_MASK there is no discard, so early depth testing stays on.
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"
#include "../common/frame_block.glsl"
#include "../shared/MaterialData.h"
#include "../brdf/brdf.glsl"
// Before ibl/importance.glsl, which includes it in a branch: a file is included once, and the
// IRIDESCENCE variant needs it without IBL too (pure functions: unused, they cost nothing).
#include "../brdf/thin_film.glsl"
#include "../lights/light_list.glsl"
#include "../lights/punctual.glsl"
#if defined(IBL)
#include "../ibl/ibl.glsl"
#include "../ibl/bright_sources.glsl"
#if defined(IBL_IMPORTANCE)
#include "../ibl/importance.glsl"
#endif
#endif

#define SPECULA_FRAGMENT_STAGE
#include "../lights/shadow.glsl"
layout(std140, binding = SPECULA_BINDING_MATERIAL) uniform MaterialBlock { GpuMaterial material; };

layout(binding = SPECULA_UNIT_BASE_COLOR) uniform sampler2D uBaseColorTexture;
layout(binding = SPECULA_UNIT_METALLIC_ROUGHNESS) uniform sampler2D uMetallicRoughnessTexture;
layout(binding = SPECULA_UNIT_NORMAL) uniform sampler2D uNormalTexture;
layout(binding = SPECULA_UNIT_OCCLUSION) uniform sampler2D uOcclusionTexture;
layout(binding = SPECULA_UNIT_EMISSIVE) uniform sampler2D uEmissiveTexture;
#if defined(SSAO)
layout(binding = SPECULA_UNIT_SSAO) uniform sampler2D uSsao;
#endif
#if defined(IBL) || defined(ENERGY_COMPENSATION)
layout(binding = SPECULA_UNIT_DFG) uniform sampler2D uDfg;
#endif

in vec3 vWorldPosition;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv0;
in vec2 vUv1;
in vec4 vColor;

#if defined(DOOM_INDEXED)
layout(location = 0) out uvec4 outIndexed; // palette index, colour-map level (an RG8UI target)
#elif defined(OIT)
// Weighted blended OIT's targets (render/passes/ForwardPass, transparency/oit_composite.frag).
layout(location = 0) out vec4 outColor;     // Σ premultiplied colour × weight, Σ alpha × weight
layout(location = 1) out vec4 outRevealage; // r: Π (1 − alpha)
#else
layout(location = 0) out vec4 outColor;
#endif

// Filament's MIN_PERCEPTUAL_ROUGHNESS: below it D_GGX of a punctual light is a spike that
// neither half floats nor a single pixel can hold.
const float kMinPerceptualRoughness = 0.045;
// Largest finite half float: keeps a very bright highlight from becoming Inf in RGBA16F.
const float kHalfMax = 65504.0;

// Before the unconditional includes below: the loader's #line after a file included in a
// branch the preprocessor drops is dropped with it, and only the next include puts it right.
#if defined(TRANSMISSION)
#include "transmission.glsl"
#endif
#include "texture_uv.glsl"
#include "specular.glsl"
#if defined(CLEARCOAT)
#include "clearcoat.glsl"
#endif
#if defined(SHEEN)
#include "sheen.glsl"
#endif
#if defined(ANISOTROPY)
#include "anisotropy.glsl"
#endif
#if defined(IRIDESCENCE)
#include "iridescence.glsl"
#endif
#if defined(DIFFUSE_TRANSMISSION)
#include "diffuse_transmission.glsl"
#endif
#include "shading_models.glsl"
#include "debug_views.glsl"

#if defined(OIT)
// McGuire & Bavoil 2013, eq. 7: nearer layers weigh more, so the mean favours what is in
// front; |z| is the view depth in metres.
float oitWeight(float z, float alpha)
{
    float d = abs(z);
    return alpha * clamp(10.0 / (1e-5 + pow(d / 5.0, 2.0) + pow(d / 200.0, 6.0)), 1e-2, 3e3);
}
#endif

#if !defined(DOOM_INDEXED)
// Every colour leaves through here, premultiplied by its alpha (opaque surfaces: alpha 1).
void writeColor(vec4 premultiplied)
{
    premultiplied.rgb = min(premultiplied.rgb, vec3(kHalfMax));
#if defined(OIT)
    // The paper's listing 1: premultiplied colour and alpha, both times the weight.
    float w = oitWeight((frame.view * vec4(vWorldPosition, 1.0)).z, premultiplied.a);
    outColor = premultiplied * w;
    outRevealage = vec4(premultiplied.a);
#else
    outColor = premultiplied;
#endif
}
#endif

vec3 materialEmissive()
{
    vec3 emissive = material.emissive.rgb;
#if defined(HAS_EMISSIVE_TEXTURE)
    emissive *= texture(uEmissiveTexture, textureUv(TEX_EMISSIVE)).rgb;
#endif
    return emissive;
}

void main()
{
    vec4 baseColor = material.baseColorFactor;
#if defined(HAS_BASE_COLOR_TEXTURE)
    baseColor *= texture(uBaseColorTexture, textureUv(TEX_BASE_COLOR)); // sRGB texture: decoded by GL
#endif
#if defined(VERTEX_COLOR)
    baseColor *= vColor;
#endif
#if defined(ALPHA_MASK)
    if (baseColor.a < material.alpha.x) discard;
#endif
#if defined(ALPHA_BLEND)
    float alpha = baseColor.a;
#else
    float alpha = 1.0;
#endif

    vec4 params = material.params;
    float metallic = params.x;
    float perceptualRoughness = params.y;
#if defined(HAS_METALLIC_ROUGHNESS_TEXTURE)
    vec4 mr = texture(uMetallicRoughnessTexture, textureUv(TEX_METALLIC_ROUGHNESS));
    perceptualRoughness *= mr.g;
    metallic *= mr.b;
#endif
    metallic = saturate(metallic);
    // Image-based light has no spike to fear: roughness 0 is a true mirror there (the
    // prefiltered level 0 is the map at its own resolution); only punctual lights need the floor.
    float iblRoughness = saturate(perceptualRoughness);
    perceptualRoughness = clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0);

    vec3 n = normalize(vNormal);
#if defined(DOUBLE_SIDED)
    // Back faces of double-sided materials are lit from their own side.
    bool flip = !gl_FrontFacing;
    if (flip) n = -n;
#else
    const bool flip = false;
#endif
#if defined(CLEARCOAT) || defined(ANISOTROPY)
    // The clearcoat layer's, unless it has a normal map of its own; the anisotropy's tangent frame.
    vec3 geometricNormal = n;
#endif
#if defined(HAS_NORMAL_TEXTURE)
    vec3 t = vTangent.xyz - n * dot(n, vTangent.xyz);
    // A zero tangent (degenerate uv) would give NaN: fall back to the geometric normal.
    if (dot(t, t) > 1e-12) {
        t = normalize(flip ? -t : t);
        vec3 b = cross(n, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
        vec3 tn = texture(uNormalTexture, textureUv(TEX_NORMAL)).xyz * 2.0 - 1.0;
        tn.xy *= params.z;
        n = normalize(mat3(t, b, n) * tn);
    }
#endif

    vec3 v = normalize(frame.cameraPosition.xyz - vWorldPosition);
    float occlusion = 1.0;
#if defined(HAS_OCCLUSION_TEXTURE)
    occlusion = 1.0 + params.w * (texture(uOcclusionTexture, textureUv(TEX_OCCLUSION)).r - 1.0);
#endif
#if defined(SSAO)
    // Screen-space ambient occlusion (render/SsaoPass), same size as this target: it scales
    // the material's occlusion, so it darkens ambient light only, never the lights above.
    occlusion *= texelFetch(uSsao, ivec2(gl_FragCoord.xy), 0).r;
#endif

#if defined(DEBUG_VIEW)
    // One input or BRDF term instead of the frame (debug_views.glsl).
    vec3 debugValue = debugViewValue(baseColor.rgb, metallic, perceptualRoughness, n, v, occlusion, materialEmissive());
#if defined(CLEARCOAT) && defined(DEBUG_VIEW_CLEARCOAT)
    // The layer's factor and roughness as it reads them (forward/clearcoat.glsl).
    ClearcoatLayer debugCoat = makeClearcoat(geometricNormal, flip, v);
    debugValue = debugBytes(vec3(debugCoat.factor, debugCoat.iblRoughness, 0.0));
#elif defined(CLEARCOAT) && defined(DEBUG_VIEW_CLEARCOAT_NORMAL)
    debugValue = debugBytes(makeClearcoat(geometricNormal, flip, v).n * 0.5 + 0.5); // world space
#endif
    writeColor(vec4(debugValue, 1.0));
#elif defined(DOOM_INDEXED)
    // Doom's 8-bit frame (doom.glsl; the colour-map pass makes the colours). An index cannot
    // be blended: a blended material is cut out at half coverage instead.
    if (alpha < 0.5) discard;
    outIndexed = uvec4(doomIndexLevel(baseColor.rgb), 0u, 0u);
#elif defined(SHADING_CLASSIC)
    // The models before physically based shading (shading_models.glsl): no BRDF, no split sum.
    // They have no lobes apart: a blended one fades (alpha scales all of it).
    writeColor(vec4(min(shadeClassic(baseColor.rgb, metallic, perceptualRoughness, n, v, occlusion, materialEmissive()), vec3(kHalfMax)), 1.0) * alpha);
#else

    vec4 specular = materialSpecular();
    SurfaceBrdf surface = makeSurfaceBrdf(baseColor.rgb, metallic, perceptualRoughness, specular);

    float NoV = max(dot(n, v), 1e-4); // 1e-4: normal-mapped texels can face away from the viewer
#if defined(ANISOTROPY)
    AnisotropicLobe anisotropy = makeAnisotropicLobe(n, geometricNormal, flip);
    // The split-sum table holds isotropic lobes: the one of about the same albedo.
    float tableRoughness = anisotropicTableRoughness(anisotropy, perceptualRoughness);
#else
    float tableRoughness = perceptualRoughness;
#endif
#if defined(CLEARCOAT)
    ClearcoatLayer coat = makeClearcoat(geometricNormal, flip, v);
    vec3 coatLight = vec3(0.0); // the layer's own reflection, added over the dimmed base
#endif
#if defined(SHEEN)
    SheenLayer sheen = makeSheen(NoV);
    vec3 sheenLight = vec3(0.0); // the sheen lobe's reflection, added over the scaled base
#endif
#if defined(IRIDESCENCE)
    ThinFilm film = makeIridescence(baseColor.rgb, metallic, specular);
#endif
#if defined(DIFFUSE_TRANSMISSION)
    DiffuseTransmission diffuseTransmission = makeDiffuseTransmission(metallic);
    vec3 throughLight = vec3(0.0); // what the BTDF lets through from behind (mixed in below)
#endif

#if defined(IBL) || defined(ENERGY_COMPENSATION)
    // Split-sum DFG terms of this draw's own D, G and F (the renderer binds the table baked for
    // its variant): single-scattering specular albedo E = f0 * dfg.x + f90 * dfg.y.
    vec2 dfg = texture(uDfg, vec2(NoV, tableRoughness)).rg;
#if defined(BRDF_F_NONE)
    // F = f0 at every angle, so f0 scales the grazing term too: E = f0 (dfg.x + dfg.y). The
    // variant reads Schlick's table, whose sum is the integral without F (dfgVariant).
    dfg = vec2(dfg.x + dfg.y, 0.0);
#endif
#endif
#if defined(ENERGY_COMPENSATION)
    // The multiple-scattering compensation scales the specular lobe by 1 + f0 (1 / E(1) - 1), so
    // a white metal reflects all the energy single scattering loses (Fdez-Aguera 2019, "A
    // Multiple-Scattering Microfacet Model for Real-Time Image-based Lighting"; Filament).
    // 1e-4 keeps the factor finite where a variant's E(1) vanishes: towards n.v = 0 with the
    // implicit or Neumann G, whose single scattering reflects almost nothing there.
    vec3 energyCompensation = 1.0 + surface.f0 * (1.0 / max(dfg.x + dfg.y, 1e-4) - 1.0);
#else
    const vec3 energyCompensation = vec3(1.0);
#endif

    // The diffuse and specular parts apart: blending scales them differently ("transparent").
    vec3 diffuseLight = vec3(0.0), specularLight = vec3(0.0);
    LightList list = lightList(vWorldPosition, gl_FragCoord);
    for (uint k = 0u; k < list.count; ++k) {
        uint index = lightListIndex(list, k);
        vec3 l;
        GpuLight light = lightAt(index);
        vec3 illuminance = lightIlluminance(light, vWorldPosition, l);
        float NoL = dot(n, l);
#if defined(DIFFUSE_TRANSMISSION)
        // A light behind the surface, through it; the shadow map's offset towards that light.
        if (NoL < 0.0)
            throughLight += diffuseTransmittedPunctual(surface, diffuseTransmission, n, v, l) * illuminance *
                            shadowVisibility(light, vWorldPosition, -n, l);
#endif
#if defined(CLEARCOAT)
        // The layer's normal may face a light the base's does not, and the other way round.
        if (NoL <= 0.0 && dot(coat.n, l) <= 0.0) continue;
        illuminance *= shadowVisibility(light, vWorldPosition, n, l);
        coatLight += clearcoatPunctual(coat, v, l) * illuminance;
        if (NoL <= 0.0) continue;
#else
        if (NoL <= 0.0) continue;
        illuminance *= shadowVisibility(light, vWorldPosition, n, l);
#endif
#if defined(SHEEN)
        sheenLight += sheenPunctual(sheen, n, v, l, NoV, NoL) * illuminance;
#endif
        vec3 diffuse, specular;
#if defined(ANISOTROPY) && defined(IRIDESCENCE)
        evaluateIridescentAnisotropicLobes(surface, film, anisotropy, n, v, l, diffuse, specular);
#elif defined(ANISOTROPY)
        evaluateAnisotropicLobes(surface, anisotropy, n, v, l, diffuse, specular);
#elif defined(IRIDESCENCE)
        evaluateIridescentLobes(surface, film, n, v, l, diffuse, specular);
#else
        evaluateBrdfLobes(surface, n, v, l, diffuse, specular);
#endif
        diffuseLight += diffuse * illuminance * NoL;
        specularLight += specular * energyCompensation * illuminance * NoL;
    }

    // Constant ambient (non-physical, 0 unless a scene asks): lights the diffuse part only.
    diffuseLight += frame.ambient.rgb * surface.diffuseColor * occlusion;
#if defined(DIFFUSE_TRANSMISSION)
    throughLight += frame.ambient.rgb * diffuseTransmission.color; // from every direction behind too
#endif

#if defined(IBL)
#if defined(ANISOTROPY)
    // The split sum's reflection off the bent normal (forward/anisotropy.glsl).
    vec3 lookupNormal = anisotropicBentNormal(anisotropy, n, v, iblRoughness);
#else
    vec3 lookupNormal = n;
#endif
    vec3 r = reflect(-v, lookupNormal);
#if defined(IRIDESCENCE)
    ThinFilm iblFilm = film;
#else
    ThinFilm iblFilm = noThinFilm();
#endif
    // The split-sum terms of E = f0 A + f90 B and the multiple-scattering compensation: the
    // DFG table's, or the anisotropic sampler's own (below).
    vec2 albedoTerms = dfg;
    vec3 albedoCompensation = energyCompensation;
#if defined(IBL_IMPORTANCE) && defined(ANISOTROPY)
    // The anisotropic lobe per pixel; its split-sum terms (the albedo the diffuse lobe leaves,
    // the compensation) from the same samples: the table's are an isotropic lobe's, which at
    // grazing angles can reflect far less than a lobe that is smooth across b.
    vec3 specularIbl = importanceSampledSpecularAnisotropic(surface, iblFilm, n, anisotropy.t, anisotropy.b,
                                                            anisotropicAlphas(anisotropy, iblRoughness * iblRoughness), v, albedoTerms);
#if defined(ENERGY_COMPENSATION)
    albedoCompensation = 1.0 + surface.f0 * (1.0 / max(albedoTerms.x + albedoTerms.y, 1e-4) - 1.0);
#endif
    specularIbl *= albedoCompensation;
#endif
    // With KHR_materials_specular's F90 < 1 the split sum's grazing term scales with it.
    vec3 specularAlbedo = (surface.f0 * albedoTerms.x + surface.f90 * albedoTerms.y) * albedoCompensation;
#if defined(IRIDESCENCE)
    // The film's Fresnel at n.v in place of the table's: E = F_iridescence(n.v) (A + B), and
    // the diffuse lobe below it weighted by 1 - max(E) (forward/iridescence.glsl).
    vec3 filmAlbedo = thinFilmFresnel(film, NoV) * (albedoTerms.x + albedoTerms.y) * albedoCompensation;
    vec3 diffuseWeightIbl = iridescentDiffuseWeight(specularAlbedo, filmAlbedo, film.factor);
    specularAlbedo = mix(specularAlbedo, filmAlbedo, film.factor);
#else
    vec3 diffuseWeightIbl = 1.0 - specularAlbedo;
#endif
    // What the specular lobe reflects, the diffuse lobe below it cannot: 1 - E keeps a white
    // dielectric in a white furnace at or below the environment's radiance.
    vec3 diffuseIbl = irradianceCube(toEnvironment(n)) * surface.diffuseColor * INV_PI * diffuseWeightIbl;
#if defined(IBL_IMPORTANCE) && defined(ANISOTROPY)
    // Above, before the diffuse lobe's weight.
#elif defined(IBL_IMPORTANCE)
    // The lobe integrated per pixel with this material's BRDF (ibl/importance.glsl); the
    // diffuse lobe keeps the split sum's 1 - E, E the DFG table's.
    vec3 specularIbl = importanceSampledSpecular(surface, n, v, iblRoughness, iblFilm) * energyCompensation;
#elif defined(IBL_SOURCE_SPECULAR) && IBL_SOURCE_COUNT > 0 && !defined(ANISOTROPY)
    // The map less its bright sources, prefiltered, and the sources as lights (ibl/bright_sources.glsl).
    float sourceWeight;
    vec3 specularIbl = prefilteredRadianceLessSources(specularDominantDirection(lookupNormal, r, iblRoughness), iblRoughness, sourceWeight) *
                       specularAlbedo;
    if (sourceWeight > 0.0) {
        SurfaceBrdf sourceSurface = surface;
        sourceSurface.perceptualRoughness = iblRoughness;
        sourceSurface.alpha = iblRoughness * iblRoughness;
        specularIbl += sourceWeight * brightSourcesSpecular(sourceSurface, n, v, iblFilm) * albedoCompensation;
    }
#else
    vec3 specularIbl = prefilteredRadiance(specularDominantDirection(lookupNormal, r, iblRoughness), iblRoughness) * specularAlbedo;
#endif
    float specularAo = specularOcclusion(NoV, occlusion, perceptualRoughness);
#if defined(HAS_NORMAL_TEXTURE)
    specularAo *= horizonFade(r, flip ? -normalize(vNormal) : normalize(vNormal));
#endif
    diffuseLight += diffuseIbl * occlusion * environment.params.x;
    specularLight += specularIbl * specularAo * environment.params.x;
#if defined(DIFFUSE_TRANSMISSION)
    // The BTDF's irradiance is the hemisphere behind, about -n, weighted as the diffuse lobe is
    // (the occlusion maps describe the side in front: not applied).
    throughLight += irradianceCube(toEnvironment(-n)) * diffuseTransmission.color * INV_PI * diffuseWeightIbl *
                    environment.params.x;
#endif
#if defined(SHEEN)
    // The broad lobe is occluded as the diffuse one is.
    sheenLight += sheenEnvironment(sheen, n, v, NoV) * occlusion * environment.params.x;
#endif
#if defined(CLEARCOAT)
    // The layer's lobe: its own prefiltered lookup along its own normal, at its roughness, and
    // its own split-sum albedo (F0 0.04, F90 1) from the same table.
#if defined(IBL_IMPORTANCE)
    vec3 coatIbl = importanceSampledSpecular(coat.brdf, coat.n, v, coat.iblRoughness);
#else
    vec2 coatDfg = texture(uDfg, vec2(coat.NoV, coat.brdf.perceptualRoughness)).rg;
#if defined(BRDF_F_NONE)
    coatDfg = vec2(coatDfg.x + coatDfg.y, 0.0);
#endif
    vec3 coatR = reflect(-v, coat.n);
    vec3 coatIbl = prefilteredRadiance(specularDominantDirection(coat.n, coatR, coat.iblRoughness), coat.iblRoughness) *
                   (coat.brdf.f0 * coatDfg.x + coat.brdf.f90 * coatDfg.y);
#endif
    coatLight += coatIbl * coat.factor * specularOcclusion(coat.NoV, occlusion, coat.brdf.perceptualRoughness) * environment.params.x;
#endif
#endif

#if defined(DIFFUSE_TRANSMISSION)
    // The extension's mix(diffuse_brdf, diffuse_btdf, fraction), before transmission (which
    // replaces both where the two extensions meet, as the extension says).
    diffuseLight = mix(diffuseLight, throughLight, diffuseTransmission.fraction);
#endif

#if defined(TRANSMISSION)
    // KHR_materials_transmission: that fraction of the dielectric's diffuse light is replaced
    // by light from behind, tinted by the base colour and let through by the Fresnel factor at
    // the viewing angle, 1 − F(n·v) (Schlick with F0 from the ior; exact at normal incidence).
    float transmission = material.transmission.x * (1.0 - metallic);
    float thickness = material.transmission.z;
#if defined(TRANSMISSION_TEXTURES)
    transmission *= texture(uTransmissionTexture, textureUv(TEX_TRANSMISSION)).r;
    thickness *= texture(uThicknessTexture, textureUv(TEX_THICKNESS)).g;
#endif
    vec3 behind = transmittedRadiance(n, v, vWorldPosition, material.transmission.y, thickness, iblRoughness);
#if defined(IRIDESCENCE)
    vec3 transmitted = transmission * iridescentDiffuseWeight(brdfF(surface, NoV), thinFilmFresnel(film, NoV), film.factor) * baseColor.rgb * behind;
#else
    vec3 transmitted = transmission * (1.0 - brdfF(surface, NoV)) * baseColor.rgb * behind;
#endif
    diffuseLight = diffuseLight * (1.0 - transmission) + transmitted;
#endif

#if defined(SHEEN)
    // The base's lobes (transmitted light included) give up what the sheen reflects; emission
    // is no part of the BRDF the extension scales. Then the sheen's own light, under any clearcoat.
    diffuseLight *= sheen.scaling;
    specularLight = specularLight * sheen.scaling + sheenLight;
#endif

    vec3 emissive = materialEmissive();
#if defined(CLEARCOAT)
    // The layer lies over everything below it, emission included (the extension's layering).
    diffuseLight *= coat.attenuation;
    specularLight = specularLight * coat.attenuation + coatLight;
    emissive *= coat.attenuation;
#endif
#if defined(BLEND_TRANSPARENT)
    // Alpha is the opacity of the diffuse part only: reflection and emission stay whole, as a
    // clear glass keeps its highlights (Newell, Newell & Sancha 1972; Filament's "transparent").
    writeColor(vec4(min(diffuseLight, vec3(kHalfMax)) * alpha + specularLight + emissive, alpha));
#else
    // Alpha is coverage (the glTF specification's "over", Filament's "fade"): all of it scales.
    writeColor(vec4(min(diffuseLight + specularLight + emissive, vec3(kHalfMax)), 1.0) * alpha);
#endif
#endif
}
