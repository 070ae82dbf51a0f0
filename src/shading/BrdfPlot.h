#pragma once
// The viewer's BRDF explorer as data: one material's reflectance in the plane of incidence
// against the light's angle, for a fixed view angle, from shading/Brdf.h (the CPU port of the
// shaders) with the material's own shading model and BRDF terms. Factors only: textures are
// not sampled.
#include <vector>

#include <glm/glm.hpp>

#include "shading/ShadingVariant.h"

namespace specula::render {

/// A material's factors as the forward shader reads them from its record (Renderer::materialParameter).
struct BrdfPlotMaterial {
    glm::dvec3 baseColor{1.0};
    double metallic = 1.0;
    double perceptualRoughness = 1.0; ///< clamped to brdf::kMinPerceptualRoughness like the shader
    /// KHR_materials_specular colour × F0(ior) / 0.04: the dielectric F0 is min(0.04 × this, 1)
    /// × specularFactor (the record's specular.rgb).
    glm::dvec3 specularColor{1.0};
    double specularFactor = 1.0;
    glm::dvec3 phongSpecular{0.5}; ///< ks of the classic models, for dielectrics
    double shininess = 0.0;        ///< classic exponent; 0 = from roughness (brdf::classicShininess)
    double clearcoat = 0.0;        ///< KHR_materials_clearcoat factor (0 = no layer)
    double clearcoatRoughness = 0.0;
    glm::dvec3 sheenColor{0.0};    ///< KHR_materials_sheen colour (black = no sheen)
    double sheenRoughness = 0.0;
    /// KHR_materials_anisotropy strength (0 = isotropic); its direction is the plot's tangent.
    double anisotropy = 0.0;
    /// KHR_materials_iridescence (0 = no film): the film at its maximum thickness (no textures).
    double iridescence = 0.0;
    double iridescenceIor = 1.3;
    double iridescenceThickness = 400.0; ///< nm
};

/// What the curves show for a shading model.
enum class BrdfPlotKind {
    Microfacet, ///< Pbr: D, V, F and the whole BRDF
    Classic,    ///< Phong (also flat and Gouraud, which light like it) and Blinn-Phong: the lobe and the whole
    None,       ///< unlit, Doom: nothing depends on the light's direction
};

/// Samples at light angles from −89° to 89° from the normal, in the plane of incidence; the view
/// is at −viewDegrees, so the mirror direction is at +viewDegrees. Luminance (Rec. 709) of the
/// coloured quantities.
struct BrdfCurves {
    BrdfPlotKind kind = BrdfPlotKind::None;
    std::vector<float> lightDegrees;
    /// Microfacet: D(n·h) of the chosen distribution. Classic: the specular lobe, (R·V)^n or (N·H)^n.
    std::vector<float> d;
    std::vector<float> v;     ///< Microfacet: V = G / (4 n·l n·v) of the chosen masking-shadowing term
    std::vector<float> f;     ///< Microfacet: F(v·h) of the chosen Fresnel term (with a film: mixed with its Fresnel)
    /// Microfacet: F(v·h)'s red, green and blue apart (a film colours it: KHR_materials_iridescence).
    std::vector<float> fRed, fGreen, fBlue;
    /// The reflected radiance per unit illuminance: f(l, v) × n·l with the chosen diffuse lobe
    /// (Microfacet, single scattering); (kd n·l + ks lobe) / π (Classic, brdf::evaluateClassic).
    std::vector<float> whole;
    /// Microfacet with a sheen: the sheen lobe alone, sheenColor D_Charlie V_Charlie × n·l
    /// (luminance); empty without one. `whole` holds it over the scaled base.
    std::vector<float> sheen;
    /// Microfacet with anisotropy: the plane of incidence above holds the tangent (the rougher
    /// direction, the highlight's long axis); these are D and f × n·l in the plane across it,
    /// which holds the bitangent. Empty for an isotropic material.
    std::vector<float> dAcross, wholeAcross;
    double shininess = 0.0; ///< Classic: the exponent used
};

BrdfCurves sampleBrdfCurves(const BrdfPlotMaterial& material, const ResolvedShading& shading, double viewDegrees,
                            int samples = 90);

} // namespace specula::render
