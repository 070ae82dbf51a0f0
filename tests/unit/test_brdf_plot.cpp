// The BRDF explorer's curves (shading/BrdfPlot.h): each term as the material chooses it, equal
// to direct calls of shading/Brdf.h at the same angles, and different from the default BRDF
// where the choice matters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "shading/Brdf.h"
#include "shading/BrdfPlot.h"

using namespace specula;
using render::BrdfCurves;
using render::BrdfPlotKind;
using render::ResolvedShading;

namespace {

constexpr double kView = 30.0;
constexpr int kSamples = 179; // one a degree

render::BrdfPlotMaterial plastic()
{
    render::BrdfPlotMaterial m;
    m.baseColor = {0.8, 0.3, 0.2};
    m.metallic = 0.0;
    m.perceptualRoughness = 0.4;
    return m;
}

float luminance(const glm::dvec3& c)
{
    return float(0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b);
}

/// Directions of sample k as the curves define them: view at −kView, light at x degrees.
struct Angles {
    glm::dvec3 n{0, 0, 1}, v, l, h;
    double NoV, NoL, NoH, VoH;
};

Angles anglesAt(const BrdfCurves& c, size_t k)
{
    Angles a;
    const double tv = glm::radians(kView), tl = glm::radians(double(c.lightDegrees[k]));
    a.v = {-std::sin(tv), 0.0, std::cos(tv)};
    a.l = {std::sin(tl), 0.0, std::cos(tl)};
    a.h = glm::normalize(a.v + a.l);
    a.NoV = a.v.z;
    a.NoL = a.l.z;
    a.NoH = a.h.z;
    a.VoH = glm::dot(a.v, a.h);
    return a;
}

/// Largest relative difference between two curves.
double relativeDifference(const std::vector<float>& a, const std::vector<float>& b)
{
    double worst = 0.0;
    for (size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(double(a[k]) - b[k]) / std::max(std::abs(double(b[k])), 1e-6));
    return worst;
}

} // namespace

TEST(BrdfPlot, DefaultCurvesAreTheGltfBrdf)
{
    const render::BrdfPlotMaterial m = plastic();
    const BrdfCurves c = render::sampleBrdfCurves(m, ResolvedShading{}, kView, kSamples);
    ASSERT_EQ(c.kind, BrdfPlotKind::Microfacet);
    ASSERT_EQ(c.lightDegrees.size(), size_t(kSamples));
    EXPECT_FLOAT_EQ(c.lightDegrees.front(), -89.0f);
    EXPECT_FLOAT_EQ(c.lightDegrees.back(), 89.0f);
    render::brdf::Surface surface;
    surface.baseColor = m.baseColor;
    surface.metallic = m.metallic;
    surface.perceptualRoughness = m.perceptualRoughness;
    const double alpha = m.perceptualRoughness * m.perceptualRoughness;
    for (size_t k = 0; k < c.lightDegrees.size(); ++k) {
        const Angles a = anglesAt(c, k);
        EXPECT_NEAR(c.d[k], render::brdf::D_GGX(a.NoH, alpha), 1e-5 * render::brdf::D_GGX(a.NoH, alpha)) << k;
        EXPECT_NEAR(c.v[k], render::brdf::V_SmithGGX(a.NoV, a.NoL, alpha), 1e-5) << k;
        EXPECT_NEAR(c.f[k], luminance(render::brdf::F_Schlick(glm::dvec3(0.04), a.VoH)), 1e-6) << k;
        EXPECT_NEAR(c.whole[k], luminance(render::brdf::evaluate(surface, a.n, a.v, a.l)) * a.NoL, 1e-6) << k;
    }
    // A glossy lobe peaks at the mirror direction, +30°: within a few degrees.
    const size_t peak = size_t(std::max_element(c.d.begin(), c.d.end()) - c.d.begin());
    EXPECT_NEAR(c.lightDegrees[peak], kView, 3.0);
}

TEST(BrdfPlot, EachTermFollowsTheMaterialsChoice)
{
    const render::BrdfPlotMaterial m = plastic();
    const BrdfCurves base = render::sampleBrdfCurves(m, ResolvedShading{}, kView, kSamples);
    const double alpha = m.perceptualRoughness * m.perceptualRoughness;

    // D: Beckmann changes D (and hence the whole) and nothing else.
    ResolvedShading beckmann;
    beckmann.distribution = scene::BrdfDistribution::Beckmann;
    const BrdfCurves d = render::sampleBrdfCurves(m, beckmann, kView, kSamples);
    EXPECT_GT(relativeDifference(d.d, base.d), 0.1);
    EXPECT_EQ(d.v, base.v);
    EXPECT_EQ(d.f, base.f);
    EXPECT_GT(relativeDifference(d.whole, base.whole), 0.01);
    for (size_t k = 0; k < d.d.size(); ++k)
        EXPECT_NEAR(d.d[k], render::brdf::D_Beckmann(anglesAt(d, k).NoH, alpha), 1e-5 * d.d[k] + 1e-9) << k;

    // G: the height-correlated Smith term, which parts from the separable one on rough
    // surfaces towards grazing angles.
    render::BrdfPlotMaterial rough = m;
    rough.perceptualRoughness = 1.0;
    ResolvedShading correlated;
    correlated.geometry = scene::BrdfGeometry::SmithGGXCorrelated;
    const BrdfCurves g = render::sampleBrdfCurves(rough, correlated, kView, kSamples);
    const BrdfCurves roughBase = render::sampleBrdfCurves(rough, ResolvedShading{}, kView, kSamples);
    EXPECT_EQ(g.d, roughBase.d);
    EXPECT_GT(relativeDifference(g.v, roughBase.v), 0.05);
    for (size_t k = 0; k < g.v.size(); ++k) {
        const Angles a = anglesAt(g, k);
        EXPECT_NEAR(g.v[k], render::brdf::V_SmithGGXCorrelated(a.NoV, a.NoL, 1.0), 1e-5) << k;
    }

    // F: none is F0 at every angle; Schlick's grows towards grazing.
    ResolvedShading noFresnel;
    noFresnel.fresnel = scene::BrdfFresnel::None;
    const BrdfCurves f = render::sampleBrdfCurves(m, noFresnel, kView, kSamples);
    for (float value : f.f) EXPECT_NEAR(value, 0.04f, 1e-6f);
    // Light on the view (−30°, sample 59): v·h = 1, F = F0; at +89° v·h = cos 59.5°.
    ASSERT_FLOAT_EQ(base.lightDegrees[59], -30.0f);
    EXPECT_NEAR(base.f[59], 0.04f, 1e-6f);
    EXPECT_GT(base.f.back(), 1.5f * base.f[59]);

    // Diffuse: Burley changes only the whole BRDF.
    ResolvedShading burley;
    burley.diffuse = scene::BrdfDiffuse::Burley;
    const BrdfCurves fd = render::sampleBrdfCurves(m, burley, kView, kSamples);
    EXPECT_EQ(fd.d, base.d);
    EXPECT_EQ(fd.v, base.v);
    EXPECT_EQ(fd.f, base.f);
    EXPECT_GT(relativeDifference(fd.whole, base.whole), 0.02);
    render::brdf::Surface surface;
    surface.baseColor = m.baseColor;
    surface.metallic = m.metallic;
    surface.perceptualRoughness = m.perceptualRoughness;
    surface.diffuse = scene::BrdfDiffuse::Burley;
    for (size_t k = 0; k < fd.whole.size(); ++k) {
        const Angles a = anglesAt(fd, k);
        EXPECT_NEAR(fd.whole[k], luminance(render::brdf::evaluate(surface, a.n, a.v, a.l)) * a.NoL, 1e-6) << k;
    }
}

TEST(BrdfPlot, IorAndSpecularFactorSetTheFresnelCurve)
{
    render::BrdfPlotMaterial m = plastic();
    // ior 2: F0 = (1/3)² = 0.111, carried as the record does, 0.04 × specular colour.
    m.specularColor = glm::dvec3(scene::f0FromIor(2.0f) / 0.04);
    const BrdfCurves c = render::sampleBrdfCurves(m, ResolvedShading{.fresnel = scene::BrdfFresnel::None}, kView, kSamples);
    for (float value : c.f) EXPECT_NEAR(value, 1.0f / 9.0f, 1e-6f);
    // KHR_materials_specular factor 0: no specular lobe, Lambert only.
    m.specularFactor = 0.0;
    const BrdfCurves lambert = render::sampleBrdfCurves(m, ResolvedShading{}, kView, kSamples);
    for (size_t k = 0; k < lambert.whole.size(); ++k) {
        EXPECT_EQ(lambert.f[k], 0.0f);
        EXPECT_NEAR(lambert.whole[k], luminance(m.baseColor) / render::brdf::kPi * anglesAt(lambert, k).NoL, 1e-6) << k;
    }
}

TEST(BrdfPlot, ClassicModelsPlotTheirLobe)
{
    render::BrdfPlotMaterial m = plastic();
    m.shininess = 40.0;
    const BrdfCurves blinn = render::sampleBrdfCurves(m, ResolvedShading{.model = scene::ShadingModel::BlinnPhong}, kView, kSamples);
    const BrdfCurves phong = render::sampleBrdfCurves(m, ResolvedShading{.model = scene::ShadingModel::Phong}, kView, kSamples);
    ASSERT_EQ(blinn.kind, BrdfPlotKind::Classic);
    ASSERT_EQ(phong.kind, BrdfPlotKind::Classic);
    EXPECT_TRUE(blinn.v.empty());
    EXPECT_EQ(blinn.shininess, 40.0);
    const glm::dvec3 kd = m.baseColor, ks = m.phongSpecular;
    for (size_t k = 0; k < blinn.d.size(); ++k) {
        const Angles a = anglesAt(blinn, k);
        EXPECT_NEAR(blinn.d[k], std::pow(a.NoH, 40.0), 1e-5) << k;
        EXPECT_NEAR(phong.d[k], std::pow(std::max(glm::dot(glm::reflect(-a.l, a.n), a.v), 0.0), 40.0), 1e-5) << k;
        EXPECT_NEAR(blinn.whole[k], luminance(render::brdf::evaluateClassic(kd, ks, 40.0, true, a.n, a.v, a.l)), 1e-6) << k;
        EXPECT_NEAR(phong.whole[k], luminance(render::brdf::evaluateClassic(kd, ks, 40.0, false, a.n, a.v, a.l)), 1e-6) << k;
    }
    // The same exponent gives Blinn-Phong a wider lobe than Phong (N·H falls off half as fast).
    auto width = [](const std::vector<float>& lobe) { return std::count_if(lobe.begin(), lobe.end(), [](float x) { return x > 0.5f; }); };
    EXPECT_GT(width(blinn.d), width(phong.d));
    // Without an exponent the material's roughness gives one.
    m.shininess = 0.0;
    EXPECT_EQ(render::sampleBrdfCurves(m, ResolvedShading{.model = scene::ShadingModel::Phong}, kView).shininess,
              render::brdf::classicShininess(m.perceptualRoughness));
    // Unlit and Doom shading have nothing that depends on the light.
    EXPECT_EQ(render::sampleBrdfCurves(m, ResolvedShading{.model = scene::ShadingModel::Unlit}, kView).kind, BrdfPlotKind::None);
    EXPECT_TRUE(render::sampleBrdfCurves(m, ResolvedShading{.model = scene::ShadingModel::Doom}, kView).whole.empty());
}

TEST(BrdfPlot, AnisotropyPlotsAlongAndAcrossTheTangent)
{
    // KHR_materials_anisotropy: along the tangent (the plot's plane) the lobe has alpha_t =
    // mix(alpha, 1, s^2), across it alpha_b = alpha: D at the mirror direction (h = n in both
    // planes) is the same, 1 / (pi alpha_t alpha_b), and off it the lobe along the tangent is
    // wider: its D falls less steeply. Isotropic materials have no "across" curves.
    render::BrdfPlotMaterial m = plastic();
    EXPECT_TRUE(render::sampleBrdfCurves(m, ResolvedShading{}, kView, kSamples).dAcross.empty());
    m.anisotropy = 0.8;
    const BrdfCurves c = render::sampleBrdfCurves(m, ResolvedShading{}, kView, kSamples);
    ASSERT_EQ(c.dAcross.size(), c.d.size());
    ASSERT_EQ(c.wholeAcross.size(), c.d.size());
    const double alpha = 0.4 * 0.4, at = alpha + (1.0 - alpha) * 0.64;
    const size_t mirror = size_t(kView + 89.0); // light at +30 degrees: h = n
    EXPECT_NEAR(c.d[mirror], 1.0 / (render::brdf::kPi * at * alpha), 1e-4 * c.d[mirror]);
    EXPECT_NEAR(c.dAcross[mirror], c.d[mirror], 1e-4 * c.d[mirror]);
    const size_t off = mirror + 20; // 20 degrees past the mirror direction
    EXPECT_GT(c.d[off] / c.d[mirror], 2.0 * c.dAcross[off] / c.dAcross[mirror]);
    // The whole BRDF along the tangent is brdf::evaluate with the direction +x.
    render::brdf::Surface s;
    s.baseColor = m.baseColor;
    s.metallic = m.metallic;
    s.perceptualRoughness = m.perceptualRoughness;
    s.geometry = render::brdf::Geometry::SmithGGXCorrelated;
    s.anisotropy = 0.8;
    for (size_t k = 0; k < c.lightDegrees.size(); ++k) {
        const Angles a = anglesAt(c, k);
        EXPECT_NEAR(c.whole[k], luminance(render::brdf::evaluate(s, a.n, a.v, a.l)) * a.NoL, 1e-6) << k;
    }
}

TEST(BrdfPlot, FresnelCurveCarriesTheIridescentFilm)
{
    // KHR_materials_iridescence: F = mix(Schlick, the film's F_iridescence(v.h), factor) in each
    // channel (shading/Iridescence.h), its luminance in f; the whole BRDF uses the same F. The
    // film colours F (red and blue apart from Schlick's) more than it changes its luminance.
    render::BrdfPlotMaterial m = plastic();
    m.iridescence = 0.9;
    m.iridescenceIor = 1.8;
    m.iridescenceThickness = 500.0;
    const BrdfCurves c = render::sampleBrdfCurves(m, ResolvedShading{}, kView, kSamples);
    const BrdfCurves plain = render::sampleBrdfCurves(plastic(), ResolvedShading{}, kView, kSamples);
    const render::brdf::ThinFilm film{0.9, 1.8, 500.0};
    double differs = 0.0;
    for (size_t k = 0; k < c.f.size(); ++k) {
        const Angles a = anglesAt(c, k);
        const glm::dvec3 expected = glm::mix(render::brdf::F_Schlick(glm::dvec3(0.04), a.VoH),
                                             render::brdf::filmFresnel(film, glm::dvec3(0.04), m.baseColor, 0.0, a.VoH), 0.9);
        EXPECT_NEAR(c.fRed[k], expected.r, 1e-6);
        EXPECT_NEAR(c.fGreen[k], expected.g, 1e-6);
        EXPECT_NEAR(c.fBlue[k], expected.b, 1e-6);
        EXPECT_NEAR(c.f[k], luminance(expected), 1e-6);
        differs = std::max({differs, std::abs(double(c.fRed[k]) - plain.fRed[k]), std::abs(double(c.fBlue[k]) - plain.fBlue[k])});
    }
    EXPECT_GT(differs, 0.01);
    EXPECT_GT(relativeDifference(c.whole, plain.whole), 0.01);
}
