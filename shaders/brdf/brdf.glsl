// The BRDF dispatch: pass shaders call evaluateBrdf and never a term directly.
// Default: the glTF 2.0 specification, Appendix B (metal-rough, GGX, separable Smith,
// Schlick Fresnel, Lambert weighted by 1 - F). Variants come from defines, at most one per
// group (shading/ShadingVariant makes them from a material's scene::MaterialShading):
//   D        BRDF_D_BECKMANN, BRDF_D_BLINN_PHONG                         (else GGX)
//   G        BRDF_G_SCHLICK_GGX (Schlick-GGX, k = (r + 1)^2 / 8, UE4; k = r^2 / 2 for image-based
//            light), BRDF_G_SMITH_GGX_CORRELATED,
//            BRDF_G_NEUMANN, BRDF_G_KELEMEN, BRDF_G_COOK_TORRANCE, BRDF_G_IMPLICIT (else separable Smith)
//   F        BRDF_F_SCHLICK_SG, BRDF_F_NONE                              (else Schlick)
//   diffuse  BRDF_DIFFUSE_OREN_NAYAR, BRDF_DIFFUSE_BURLEY                (else Lambert)
// Every variant keeps the glTF mix: (1 - F) x diffuse + F x D x V.
#include "../common/math.glsl"
#include "ggx.glsl"
#include "beckmann.glsl"
#include "blinn_phong.glsl"
#include "smith.glsl"
#include "masking.glsl"
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

float brdfD(float NoH, float alpha)
{
#if defined(BRDF_D_BECKMANN)
    return D_Beckmann(NoH, alpha);
#elif defined(BRDF_D_BLINN_PHONG)
    return D_BlinnPhong(NoH, alpha);
#else
    return D_GGX(NoH, alpha);
#endif
}

// Visibility V = G / (4 NoL NoV).
float brdfV(SurfaceBrdf s, float NoV, float NoL, float NoH, float VoH)
{
#if defined(BRDF_G_SCHLICK_GGX)
    return V_SchlickGGX(NoV, NoL, s.perceptualRoughness);
#elif defined(BRDF_G_SMITH_GGX_CORRELATED)
    return V_SmithGGXCorrelated(NoV, NoL, s.alpha);
#elif defined(BRDF_G_NEUMANN)
    return V_Neumann(NoV, NoL);
#elif defined(BRDF_G_KELEMEN)
    return V_Kelemen(VoH);
#elif defined(BRDF_G_COOK_TORRANCE)
    return V_CookTorrance(NoV, NoL, NoH, VoH);
#elif defined(BRDF_G_IMPLICIT)
    return V_Implicit();
#else
    return V_SmithGGX(NoV, NoL, s.alpha);
#endif
}

// The visibility image-based light sees (the split-sum bake, ibl/dfg.comp, integrates it):
// brdfV, but Schlick-GGX without its punctual-light remap, k = alpha / 2, as UE4 does.
float brdfVImageBased(SurfaceBrdf s, float NoV, float NoL, float NoH, float VoH)
{
#if defined(BRDF_G_SCHLICK_GGX)
    return V_SchlickGGXImageBased(NoV, NoL, s.alpha);
#else
    return brdfV(s, NoV, NoL, NoH, VoH);
#endif
}

vec3 brdfF(SurfaceBrdf s, float VoH)
{
#if defined(BRDF_F_SCHLICK_SG)
    return F_SchlickSG(s.f0, s.f90, VoH);
#elif defined(BRDF_F_NONE)
    return F_None(s.f0);
#else
    return F_Schlick(s.f0, s.f90, VoH);
#endif
}

// The weight of (f90 - f0) in F, F = f0 + (f90 - f0) * brdfFresnelWeight(VoH): what the
// split-sum DFG bake integrates for the table's bias term (ibl/dfg.comp). F = none has none.
float brdfFresnelWeight(float VoH)
{
#if defined(BRDF_F_SCHLICK_SG)
    return Fc_SchlickSG(VoH);
#elif defined(BRDF_F_NONE)
    return 0.0;
#else
    return Fc_Schlick(VoH);
#endif
}

vec3 brdfDiffuse(SurfaceBrdf s, float NoV, float NoL, float LoH, float VoL)
{
#if defined(BRDF_DIFFUSE_OREN_NAYAR)
    return Fd_OrenNayar(s.diffuseColor, s.perceptualRoughness, NoV, NoL, VoL);
#elif defined(BRDF_DIFFUSE_BURLEY)
    return Fd_Burley(s.diffuseColor, s.perceptualRoughness, NoV, NoL, LoH);
#else
    return Fd_Lambert(s.diffuseColor);
#endif
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
    vec3 F = brdfF(s, VoH);
    float D = brdfD(NoH, s.alpha);
    float V = brdfV(s, NoV, NoL, NoH, VoH);
    specular = F * (D * V);
    diffuse = (1.0 - F) * brdfDiffuse(s, NoV, NoL, VoH, dot(v, l));
}

vec3 evaluateBrdf(SurfaceBrdf s, vec3 n, vec3 v, vec3 l)
{
    vec3 diffuse, specular;
    evaluateBrdfLobes(s, n, v, l, diffuse, specular);
    return diffuse + specular;
}
