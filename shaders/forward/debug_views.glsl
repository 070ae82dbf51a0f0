// Debug views of the forward pass (render::DebugView): one material input or one term of the
// BRDF in place of the frame. The renderer turns exposure and tone mapping off for them, so
// the sRGB output shows colours (base colour, emissive) as authored, and scalars, normals and
// BRDF terms are written sRGB-decoded so that the 8-bit output is value × 255.
// Included by pbr.frag after brdf/brdf.glsl and lights/ (light_list.glsl, punctual.glsl).
#include "../common/color.glsl"

#if defined(DEBUG_VIEW_BASE_COLOR) || defined(DEBUG_VIEW_NORMAL) || defined(DEBUG_VIEW_ROUGHNESS) || \
    defined(DEBUG_VIEW_METALLIC) || defined(DEBUG_VIEW_OCCLUSION) || defined(DEBUG_VIEW_EMISSIVE) || \
    defined(DEBUG_VIEW_BRDF_D) || defined(DEBUG_VIEW_BRDF_G) || defined(DEBUG_VIEW_BRDF_F) || defined(DEBUG_VIEW_CASCADES) || \
    defined(DEBUG_VIEW_LIGHT_COUNT) || defined(DEBUG_VIEW_SHEEN) || defined(DEBUG_VIEW_ANISOTROPY) || \
    defined(DEBUG_VIEW_IRIDESCENCE) || defined(DEBUG_VIEW_CLEARCOAT) || defined(DEBUG_VIEW_CLEARCOAT_NORMAL)
#define DEBUG_VIEW
#endif

vec3 debugBytes(vec3 value)
{
    return srgbToLinear(clamp(value, 0.0, 1.0));
}

// D relative to its peak D(n·h = 1) (every D here peaks at the normal), G, and F, for the
// first light of the frame (black without lights and where it does not reach).
vec3 debugBrdfTerm(vec3 baseColor, float metallic, float perceptualRoughness, vec3 n, vec3 v)
{
#if defined(SHADING_UNLIT)
    // An unlit material (KHR_materials_unlit) has no BRDF: no light reaches its colour.
    return vec3(0.0);
#endif
    if (frameLightCount() == 0u) return vec3(0.0);
    vec3 l;
    lightIlluminance(lightAt(0u), vWorldPosition, l);
    float NoL = dot(n, l);
    if (NoL <= 0.0) return vec3(0.0);
    SurfaceBrdf s = makeSurfaceBrdf(baseColor, metallic, perceptualRoughness, materialSpecular());
    vec3 h = normalize(v + l);
    float NoV = abs(dot(n, v));
    float NoH = saturate(dot(n, h));
    float VoH = saturate(dot(v, h));
#if defined(ANISOTROPY) && (defined(DEBUG_VIEW_BRDF_D) || defined(DEBUG_VIEW_BRDF_G))
    // KHR_materials_anisotropy's D and G (forward/anisotropy.glsl) in the frame pbr.frag gives it.
    vec3 ng = normalize(vNormal);
#if defined(DOUBLE_SIDED)
    bool flip = !gl_FrontFacing;
    if (flip) ng = -ng;
#else
    const bool flip = false;
#endif
    AnisotropicLobe a = makeAnisotropicLobe(n, ng, flip);
    vec2 alphas = anisotropicAlphas(a, s.alpha);
#if defined(DEBUG_VIEW_BRDF_D)
    return vec3(D_GGX_Anisotropic(NoH, dot(a.t, h), dot(a.b, h), alphas.x, alphas.y) / D_GGX_Anisotropic(1.0, 0.0, 0.0, alphas.x, alphas.y));
#else
    return vec3(V_SmithGGXCorrelatedAnisotropic(NoV, NoL, dot(a.t, v), dot(a.b, v), dot(a.t, l), dot(a.b, l), alphas.x, alphas.y) * 4.0 * NoL * NoV);
#endif
#endif
#if defined(DEBUG_VIEW_BRDF_D)
    return vec3(brdfD(NoH, s.alpha) / brdfD(1.0, s.alpha));
#elif defined(DEBUG_VIEW_BRDF_G)
    return vec3(brdfV(s, NoV, NoL, NoH, VoH) * 4.0 * NoL * NoV);
#else
    return brdfF(s, VoH);
#endif
}

// The specular lobe's Fresnel at n.v: with KHR_materials_iridescence mix(F, the film's, factor)
// (forward/iridescence.glsl; the IRIDESCENCE variant stays on for this view), else F alone.
vec3 debugIridescence(vec3 baseColor, float metallic, float perceptualRoughness, vec3 n, vec3 v)
{
    SurfaceBrdf s = makeSurfaceBrdf(baseColor, metallic, perceptualRoughness, materialSpecular());
    float NoV = max(dot(n, v), 1e-4);
#if defined(IRIDESCENCE)
    return iridescentFresnelAt(s, makeIridescence(baseColor, metallic, materialSpecular()), NoV);
#else
    return brdfF(s, NoV);
#endif
}

vec3 debugViewValue(vec3 baseColor, float metallic, float perceptualRoughness, vec3 n, vec3 v, float occlusion, vec3 emissive)
{
#if defined(DEBUG_VIEW_BASE_COLOR)
    return baseColor;
#elif defined(DEBUG_VIEW_NORMAL)
    return debugBytes(n * 0.5 + 0.5); // world space
#elif defined(DEBUG_VIEW_ROUGHNESS)
    return debugBytes(vec3(perceptualRoughness));
#elif defined(DEBUG_VIEW_METALLIC)
    return debugBytes(vec3(metallic));
#elif defined(DEBUG_VIEW_OCCLUSION)
    return debugBytes(vec3(occlusion));
#elif defined(DEBUG_VIEW_EMISSIVE)
    return emissive;
#elif defined(DEBUG_VIEW_SHEEN)
#if defined(SHEEN)
    // What the sheen lobe reflects of light from every direction, sheen colour x E(n.v).
    SheenLayer s = makeSheen(max(dot(n, v), 1e-4));
    return debugBytes(s.color * s.albedo);
#else
    return vec3(0.0);
#endif
#elif defined(DEBUG_VIEW_IRIDESCENCE)
    return debugBytes(debugIridescence(baseColor, metallic, perceptualRoughness, n, v));
#elif defined(DEBUG_VIEW_CLEARCOAT) || defined(DEBUG_VIEW_CLEARCOAT_NORMAL)
    // No layer (a coated material's variant has CLEARCOAT, and pbr.frag shows the layer's own).
    return vec3(0.0);
#elif defined(DEBUG_VIEW_LIGHT_COUNT)
    // The length of this point's light list (its cluster's, directional lights included), in
    // the heat map's bins (shared/ClusterData.h; the legend is render/passes/DebugViewPass's).
    return srgbToLinear(vec3(lightCountColor(lightCountBin(lightList(vWorldPosition, gl_FragCoord).count))));
#elif defined(DEBUG_VIEW_ANISOTROPY)
    // KHR_materials_anisotropy's direction (x 0.5 + 0.5) and strength, as its texture holds them.
#if defined(ANISOTROPY)
    vec3 ds = anisotropyDirectionStrength();
    return debugBytes(vec3(ds.xy * 0.5 + 0.5, ds.z));
#else
    return debugBytes(vec3(0.5, 0.5, 0.0));
#endif
#elif defined(DEBUG_VIEW_CASCADES)
    // The first directional light with cascades: its cascade's colour, darkened in its shadow;
    // grey beyond the shadow distance or without one.
    for (uint i = 0u; i < frameLightCount(); ++i) {
        GpuLight light = lightAt(i);
        int cascade = shadowCascade(light, vWorldPosition);
        if (cascade == -2) continue;
        if (cascade < 0) return debugBytes(vec3(0.5));
        const vec3 colors[4] = vec3[4](vec3(1.0, 0.25, 0.25), vec3(0.25, 1.0, 0.25), vec3(0.3, 0.45, 1.0), vec3(1.0, 1.0, 0.25));
        vec3 l = -light.directionType.xyz;
        vec3 lit = dot(n, l) > 0.0 ? shadowVisibility(light, vWorldPosition, n, l) : vec3(0.0);
        return debugBytes(colors[cascade] * (0.35 + 0.65 * lit));
    }
    return debugBytes(vec3(0.5));
#else
    return debugBytes(debugBrdfTerm(baseColor, metallic, perceptualRoughness, n, v));
#endif
}
