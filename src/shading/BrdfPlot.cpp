#include "shading/BrdfPlot.h"

#include <algorithm>
#include <cmath>

#include "shading/Brdf.h"

namespace specula::render {
namespace {

float luminance(const glm::dvec3& c)
{
    return float(0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b);
}

BrdfPlotKind kindOf(scene::ShadingModel model)
{
    switch (model) {
    case scene::ShadingModel::Pbr: return BrdfPlotKind::Microfacet;
    case scene::ShadingModel::Flat:
    case scene::ShadingModel::Gouraud:
    case scene::ShadingModel::Phong:
    case scene::ShadingModel::BlinnPhong: return BrdfPlotKind::Classic;
    case scene::ShadingModel::Unlit:
    case scene::ShadingModel::Doom: return BrdfPlotKind::None;
    }
    return BrdfPlotKind::None;
}

} // namespace

BrdfCurves sampleBrdfCurves(const BrdfPlotMaterial& m, const ResolvedShading& shading, double viewDegrees, int samples)
{
    BrdfCurves curves;
    curves.kind = kindOf(shading.model);
    if (curves.kind == BrdfPlotKind::None || samples < 2) return curves;

    const double r = std::clamp(m.perceptualRoughness, brdf::kMinPerceptualRoughness, 1.0);
    const double metallic = std::clamp(m.metallic, 0.0, 1.0);
    brdf::Surface surface;
    surface.baseColor = m.baseColor;
    surface.metallic = metallic;
    surface.perceptualRoughness = r;
    surface.specularFactor = m.specularFactor;
    surface.specularColor = m.specularColor;
    surface.f0Dielectric = 0.04; // specularColor carries the ior, as the record does
    surface.distribution = shading.distribution;
    surface.geometry = shading.geometry;
    surface.fresnel = shading.fresnel;
    surface.diffuse = shading.diffuse;
    surface.clearcoat = std::clamp(m.clearcoat, 0.0, 1.0);
    surface.clearcoatRoughness = m.clearcoatRoughness;
    const bool sheen = glm::any(glm::greaterThan(m.sheenColor, glm::dvec3(0.0)));
    surface.sheenColor = glm::clamp(m.sheenColor, 0.0, 1.0);
    surface.sheenRoughness = m.sheenRoughness;
    const double sheenRoughness = std::clamp(m.sheenRoughness, brdf::kMinPerceptualRoughness, 1.0);
    // KHR_materials_anisotropy with its tangent along +x, the plot's plane; its V is the
    // height-correlated one, as resolveShading gives the ANISOTROPY variant.
    const bool anisotropic = m.anisotropy > 0.0 && render::anisotropic(shading);
    surface.anisotropy = anisotropic ? std::clamp(m.anisotropy, 0.0, 1.0) : 0.0;
    surface.anisotropyDirection = glm::dvec3(1.0, 0.0, 0.0);
    if (anisotropic) surface.geometry = scene::BrdfGeometry::SmithGGXCorrelated;
    const double alpha = r * r, alphaT = glm::mix(alpha, 1.0, surface.anisotropy * surface.anisotropy);
    surface.iridescence = {std::clamp(m.iridescence, 0.0, 1.0), std::max(m.iridescenceIor, 1.0), std::max(m.iridescenceThickness, 0.0)};
    const glm::dvec3 f0Dielectric = glm::min(0.04 * m.specularColor, glm::dvec3(1.0)) * m.specularFactor;
    // The same F0 and F90 as brdf::evaluate and makeSurfaceBrdf in shaders/brdf/brdf.glsl.
    const glm::dvec3 f0 = glm::mix(f0Dielectric, m.baseColor, metallic);
    const double f90 = m.specularFactor + (1.0 - m.specularFactor) * metallic;
    const glm::dvec3 kd = m.baseColor * (1.0 - metallic);
    const glm::dvec3 ks = glm::mix(m.phongSpecular, m.baseColor, metallic);
    curves.shininess = m.shininess > 0.0 ? m.shininess : brdf::classicShininess(r);
    const bool blinn = shading.model == scene::ShadingModel::BlinnPhong;

    const glm::dvec3 n(0.0, 0.0, 1.0);
    const double thetaV = glm::radians(viewDegrees);
    const glm::dvec3 view(-std::sin(thetaV), 0.0, std::cos(thetaV));
    if (sheen) surface.sheenAlbedo = brdf::sheenDirectionalAlbedo(std::cos(thetaV), m.sheenRoughness);
    for (int k = 0; k < samples; ++k) {
        const double degrees = -89.0 + 178.0 * double(k) / double(samples - 1);
        const double thetaL = glm::radians(degrees);
        const glm::dvec3 l(std::sin(thetaL), 0.0, std::cos(thetaL));
        const double NoL = std::clamp(glm::dot(n, l), 0.0, 1.0);
        curves.lightDegrees.push_back(float(degrees));
        if (curves.kind == BrdfPlotKind::Classic) {
            const double lobe = blinn ? std::clamp(glm::dot(n, glm::normalize(l + view)), 0.0, 1.0)
                                      : std::clamp(glm::dot(glm::reflect(-l, n), view), 0.0, 1.0);
            curves.d.push_back(float(std::pow(lobe, curves.shininess)));
            curves.whole.push_back(luminance(brdf::evaluateClassic(kd, ks, curves.shininess, blinn, n, view, l)));
            continue;
        }
        // The clamps of brdf::evaluate (and evaluateBrdfLobes in the shader).
        const glm::dvec3 h = glm::normalize(view + l);
        const double NoV = std::abs(glm::dot(n, view));
        const double NoH = std::clamp(glm::dot(n, h), 0.0, 1.0);
        const double VoH = std::clamp(glm::dot(view, h), 0.0, 1.0);
        if (anisotropic) {
            // Along the tangent (x: h.x = t.h), then the same angles across it (y: b.h).
            curves.d.push_back(float(brdf::D_GGX_Anisotropic(NoH, h.x, h.y, alphaT, alpha)));
            curves.v.push_back(float(brdf::V_SmithGGXCorrelatedAnisotropic(NoV, NoL, view.x, view.y, l.x, l.y, alphaT, alpha)));
            const glm::dvec3 viewAcross(0.0, view.x, view.z), lAcross(0.0, l.x, l.z);
            const glm::dvec3 hAcross = glm::normalize(viewAcross + lAcross);
            curves.dAcross.push_back(float(brdf::D_GGX_Anisotropic(std::clamp(hAcross.z, 0.0, 1.0), hAcross.x, hAcross.y, alphaT, alpha)));
            curves.wholeAcross.push_back(luminance(brdf::evaluate(surface, n, viewAcross, lAcross)) * float(NoL));
        } else {
            curves.d.push_back(float(brdf::distribution(shading.distribution, NoH, r * r)));
            curves.v.push_back(float(brdf::visibility(surface.geometry, NoV, NoL, NoH, VoH, r)));
        }
        glm::dvec3 F = brdf::fresnel(shading.fresnel, f0, f90, VoH);
        if (surface.iridescence.factor > 0.0)
            F = glm::mix(F, brdf::filmFresnel(surface.iridescence, f0Dielectric, m.baseColor, metallic, VoH), surface.iridescence.factor);
        curves.f.push_back(luminance(F));
        curves.fRed.push_back(float(F.r));
        curves.fGreen.push_back(float(F.g));
        curves.fBlue.push_back(float(F.b));
        curves.whole.push_back(luminance(brdf::evaluate(surface, n, view, l)) * float(NoL));
        if (sheen && NoL > 0.0)
            curves.sheen.push_back(luminance(surface.sheenColor) *
                                   float(brdf::D_Charlie(NoH, sheenRoughness * sheenRoughness) *
                                         brdf::V_Charlie(std::max(NoV, 1e-4), NoL, sheenRoughness * sheenRoughness) * NoL));
        else if (sheen)
            curves.sheen.push_back(0.0f);
    }
    return curves;
}

} // namespace specula::render
