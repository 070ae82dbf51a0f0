// The BRDF dispatch: pass shaders call evaluateBrdf and never a term directly.
// Default: the glTF 2.0 specification, Appendix B (metal-rough, GGX, separable Smith,
// Schlick Fresnel, Lambert weighted by 1 - F). Variants come from defines:
//   BRDF_G_SCHLICK_GGX  Schlick-GGX masking with k = (r + 1)^2 / 8 (UE4)
#include "../common/math.glsl"
#include "ggx.glsl"
#include "smith.glsl"
#include "fresnel.glsl"
#include "diffuse.glsl"

struct SurfaceBrdf {
    vec3 diffuseColor;        // c_diff = baseColor * (1 - metallic)
    vec3 f0;                  // mix(0.04, baseColor, metallic)
    float f90;                // 1, or KHR_materials_specular's factor for the dielectric part
    float perceptualRoughness;
    float alpha;              // perceptualRoughness^2
};

// KHR_materials_specular: the dielectric F0 is min(0.04 * specularColor, 1) * specularFactor
// and its F90 is specularFactor (both 1 without the extension); metals keep F0 = base colour.
SurfaceBrdf makeSurfaceBrdf(vec3 baseColor, float metallic, float perceptualRoughness, vec4 specular)
{
    SurfaceBrdf s;
    s.diffuseColor = baseColor * (1.0 - metallic);
    s.f0 = mix(min(vec3(0.04) * specular.rgb, vec3(1.0)) * specular.a, baseColor, metallic);
    s.f90 = mix(specular.a, 1.0, metallic);
    s.perceptualRoughness = perceptualRoughness;
    s.alpha = perceptualRoughness * perceptualRoughness;
    return s;
}

// f(l, v) for unit vectors n, v, l, split into its diffuse and specular lobes (1/sr), not
// yet multiplied by NoL.
void evaluateBrdfLobes(SurfaceBrdf s, vec3 n, vec3 v, vec3 l, out vec3 diffuse, out vec3 specular)
{
    vec3 h = normalize(v + l);
    float NoV = abs(dot(n, v));
    float NoL = saturate(dot(n, l));
    float NoH = saturate(dot(n, h));
    float VoH = saturate(dot(v, h));
    vec3 F = F_Schlick(s.f0, s.f90, VoH);
    float D = D_GGX(NoH, s.alpha);
#if defined(BRDF_G_SCHLICK_GGX)
    float V = V_SchlickGGX(NoV, NoL, s.perceptualRoughness);
#else
    float V = V_SmithGGX(NoV, NoL, s.alpha);
#endif
    specular = F * (D * V);
    diffuse = (1.0 - F) * Fd_Lambert(s.diffuseColor);
}

vec3 evaluateBrdf(SurfaceBrdf s, vec3 n, vec3 v, vec3 l)
{
    vec3 diffuse, specular;
    evaluateBrdfLobes(s, n, v, l, diffuse, specular);
    return diffuse + specular;
}
