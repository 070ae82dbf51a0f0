#pragma once
// CPU port of shaders/brdf/ and shaders/lights/punctual.glsl: the same equations, in double
// precision, for unit tests and GPU-against-CPU comparisons. Keep the two in step.
#include <glm/glm.hpp>

#include "scene/MaterialModel.h"
#include "shading/Iridescence.h"

namespace specula::render::brdf {

constexpr double kPi = 3.14159265358979323846;
/// Same clamp as the shader (Filament's MIN_PERCEPTUAL_ROUGHNESS).
constexpr double kMinPerceptualRoughness = 0.045;

using Distribution = scene::BrdfDistribution;
using Geometry = scene::BrdfGeometry;
using Fresnel = scene::BrdfFresnel;
using Diffuse = scene::BrdfDiffuse;

using dvec3 = glm::dvec3;

// The terms, named and cited as in shaders/brdf/. V = G / (4 NoL NoV).
double D_GGX(double NoH, double alpha);
double D_Beckmann(double NoH, double alpha);
double D_BlinnPhong(double NoH, double alpha);
double V_SmithGGX(double NoV, double NoL, double alpha);
double V_SchlickGGX(double NoV, double NoL, double perceptualRoughness);
double V_SchlickGGXImageBased(double NoV, double NoL, double alpha);
double V_SmithGGXCorrelated(double NoV, double NoL, double alpha);
double V_Neumann(double NoV, double NoL);
double V_Kelemen(double VoH);
double V_CookTorrance(double NoV, double NoL, double NoH, double VoH);
double V_Implicit();
/// KHR_materials_anisotropy's terms (shaders/brdf/ggx.glsl, smith.glsl): t, b the lobe's
/// directions, at and ab its alphas along them.
double D_GGX_Anisotropic(double NoH, double ToH, double BoH, double at, double ab);
double V_SmithGGXCorrelatedAnisotropic(double NoV, double NoL, double ToV, double BoV, double ToL, double BoL, double at,
                                       double ab);
dvec3 F_Schlick(const dvec3& f0, double VoH);
dvec3 F_Schlick(const dvec3& f0, double f90, double VoH);
dvec3 F_SchlickSG(const dvec3& f0, double f90, double VoH);
double Fd_Burley(double perceptualRoughness, double NoV, double NoL, double LoH);    ///< × albedo
double Fd_OrenNayar(double perceptualRoughness, double NoV, double NoL, double VoL); ///< × albedo

/// The dispatch of shaders/brdf/brdf.glsl, one function per group.
double distribution(Distribution d, double NoH, double alpha);
double visibility(Geometry g, double NoV, double NoL, double NoH, double VoH, double perceptualRoughness);
/// brdfVImageBased: the visibility the split-sum DFG table integrates (Schlick-GGX with k = α/2).
double visibilityImageBased(Geometry g, double NoV, double NoL, double NoH, double VoH, double perceptualRoughness);
dvec3 fresnel(Fresnel f, const dvec3& f0, double f90, double VoH);
double diffuseLobe(Diffuse d, double perceptualRoughness, double NoV, double NoL, double LoH, double VoL); ///< × albedo

struct Surface {
    dvec3 baseColor{1.0};
    double metallic = 0.0;
    double perceptualRoughness = 0.5; ///< clamped to kMinPerceptualRoughness like the shader
    Geometry geometry = Geometry::SmithGGX;
    double specularFactor = 1.0; ///< KHR_materials_specular (dielectric F0 and F90)
    Distribution distribution = Distribution::GGX;
    Fresnel fresnel = Fresnel::Schlick;
    Diffuse diffuse = Diffuse::Lambert;
    double f0Dielectric = 0.04;  ///< scene::f0FromIor(ior) when the material gives an ior
    /// The BRDF as image-based light sees it: visibilityImageBased instead of visibility.
    bool imageBased = false;
    dvec3 specularColor{1.0};    ///< KHR_materials_specular colour: dielectric F0 = min(f0Dielectric × it, 1) × specularFactor
    /// KHR_materials_clearcoat (shaders/forward/clearcoat.glsl) with the layer's normal = n: the
    /// lobes are dimmed by 1 − clearcoat Fc(n·v) and the layer's F D V × clearcoat is added to
    /// the specular lobe (F0 0.04, F90 1, the same D, V and F terms).
    double clearcoat = 0.0;
    double clearcoatRoughness = 0.0; ///< perceptual, clamped like perceptualRoughness
    /// KHR_materials_sheen (shaders/forward/sheen.glsl): with a colour above 0 the lobes are
    /// scaled by 1 − max3(sheenColor) sheenAlbedo and sheenColor D_Charlie V_Charlie is added
    /// to the specular lobe. sheenAlbedo is E(n·v) of that view, sheenDirectionalAlbedo(n·v,
    /// sheenRoughness): the caller's, as it depends on the view only.
    dvec3 sheenColor{0.0};
    double sheenRoughness = 0.0; ///< perceptual, clamped like perceptualRoughness
    double sheenAlbedo = 0.0;
    /// KHR_materials_anisotropy (shaders/forward/anisotropy.glsl), GGX only: the specular lobe's
    /// D and V become the anisotropic ones with alpha_t = mix(alpha, 1, anisotropy²) along
    /// anisotropyDirection (made orthogonal to n) and alpha_b = alpha across it.
    double anisotropy = 0.0;
    dvec3 anisotropyDirection{1.0, 0.0, 0.0};
    /// KHR_materials_iridescence (shaders/forward/iridescence.glsl): F = mix(F, filmFresnel(v·h),
    /// factor) in the specular lobe and the diffuse lobe weighted by mix(1 − F, 1 − max(film F), factor).
    ThinFilm iridescence;
};

/// The "Charlie" sheen distribution and visibility (Estevez & Kulla 2017, as KHR_materials_sheen
/// gives them; shaders/brdf/sheen.glsl), alpha = sheen perceptual roughness².
double D_Charlie(double NoH, double alpha);
double V_Charlie(double NoV, double NoL, double alpha);
/// E(n·v) = ∫ D_Charlie V_Charlie (n·l) dω of the sheen lobe with colour 1, by a midpoint
/// quadrature over the hemisphere (`steps`² points); the roughness is clamped as the shader's.
double sheenDirectionalAlbedo(double NoV, double perceptualRoughness, int steps = 96);

/// f(l, v) (1/sr) for unit n, v, l, not multiplied by NoL. Zero when NoL <= 0.
dvec3 evaluate(const Surface& surface, const dvec3& n, const dvec3& v, const dvec3& l);
/// The two lobes of evaluate() apart (their sum is evaluate()): the diffuse one, (1 − F) ×
/// diffuse colour × Fd, and the specular one, F D V (a blended "transparent" surface scales
/// only the first by alpha).
void evaluateLobes(const Surface& surface, const dvec3& n, const dvec3& v, const dvec3& l, dvec3& diffuse, dvec3& specular);

/// The classic models of shaders/forward/classic_lighting.glsl for one light of unit
/// illuminance, NoL included: kd NoL / π + ks (R·V)^n / π (Phong 1975), (N·H)^n with `blinn`
/// (Blinn 1977); zero when NoL <= 0.
dvec3 evaluateClassic(const dvec3& kd, const dvec3& ks, double shininess, bool blinn, const dvec3& n, const dvec3& v,
                      const dvec3& l);
/// The exponent the classic models take from perceptual roughness when a material gives none.
double classicShininess(double perceptualRoughness);

/// KHR_lights_punctual falloffs.
double rangeAttenuation(double range, double distance);
double spotAttenuation(const dvec3& lightDirection, const dvec3& toLight, double innerCone, double outerCone);

} // namespace specula::render::brdf
