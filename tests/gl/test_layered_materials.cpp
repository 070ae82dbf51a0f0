// The glTF material extensions together on one surface: KHR_materials_anisotropy's lobe with
// KHR_materials_iridescence's film in its Fresnel, KHR_materials_sheen over both, and
// KHR_materials_clearcoat over everything (the layering each extension's text gives). Each
// extension's own test checks it alone against its spec; this one checks that the variants
// compose, against shading/Brdf.cpp's brdf::evaluate (double precision, every layer) at each
// pixel's analytic ray-sphere hit.
#include "GlTestContext.h"
#include "LitSphere.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"

#include <algorithm>
#include <vector>

#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"
#include "shading/Brdf.h"

using namespace specula;
using glm::dvec3;
using specula::test::GlTest;

namespace {

struct Layers {
    const char* name;
    glm::vec3 baseColor;
    float metallic;
    float roughness;
    float anisotropy = 0.0f;
    float iridescence = 0.0f;
    float filmIor = 1.5f;
    float filmThickness = 450.0f; // nm: no thickness texture, so the maximum
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.5f;
    float clearcoat = 0.0f;
    float clearcoatRoughness = 0.2f;
};

// The tolerance of the other GPU-against-CPU tests (1.5 % + 2e-3 cd/m²), plus, with a sheen,
// 1 % of the radiance for the table of E it reads (half floats, bilinear), as test_sheen.cpp.
constexpr double kRelative = 0.015;
constexpr double kAbsolute = 2e-3;

struct Comparison {
    int tested = 0;
    double worst = 0.0;
    double filmMatters = 0.0;       ///< max |expected without the film - expected| / tolerance
    double anisotropyMatters = 0.0; ///< the same without the anisotropy
};

/// The sheen lobe's directional albedo E(n·v) on a grid, interpolated (brdf::sheenDirectionalAlbedo
/// per pixel would be slow).
struct SheenAlbedoTable {
    std::vector<double> e;
    explicit SheenAlbedoTable(double roughness)
    {
        for (int i = 0; i <= 128; ++i) e.push_back(render::brdf::sheenDirectionalAlbedo(std::max(i / 128.0, 1e-4), roughness));
    }
    double at(double NoV) const
    {
        const double x = std::clamp(NoV, 0.0, 1.0) * 128.0;
        const int i = std::min(int(x), 127);
        return e[size_t(i)] + (e[size_t(i) + 1] - e[size_t(i)]) * (x - i);
    }
};

Comparison renderAndCompare(const Layers& c)
{
    scene::Scene s;
    scene::Material m;
    m.baseColorFactor = glm::vec4(c.baseColor, 1.0f);
    m.metallicFactor = c.metallic;
    m.roughnessFactor = c.roughness;
    m.anisotropyStrength = c.anisotropy;
    m.iridescenceFactor = c.iridescence;
    m.iridescenceIor = c.filmIor;
    m.iridescenceThicknessMaximum = c.filmThickness;
    m.sheenColorFactor = c.sheenColor;
    m.sheenRoughnessFactor = c.sheenRoughness;
    m.clearcoatFactor = c.clearcoat;
    m.clearcoatRoughnessFactor = c.clearcoatRoughness;
    scene::addShape(s, scene::makeUvSphere(1.0f, 256, 128), m, glm::mat4(1.0f), "sphere");
    scene::Light light;
    light.type = scene::Light::Type::Point;
    light.intensity = 30.0f;
    light.color = {1.0f, 0.9f, 0.8f};
    const glm::vec3 lightPosition(2.0f, 2.5f, 3.0f);
    scene::addLight(s, light, lightPosition, -lightPosition);

    render::FrameSettings settings = test::radianceFrame(96, 96, test::Brdf::Exact); // what brdf::evaluate gives
    // The anisotropic lobe's V is the height-correlated one (its variant resolves G to it): the
    // same G for every case, and for the clearcoat's lobe.
    settings.brdfGeometry = render::BrdfGeometry::SmithGGXCorrelated;
    const ImageFloat image = test::renderSphere(s, settings);

    render::brdf::Surface surface;
    surface.baseColor = dvec3(c.baseColor);
    surface.metallic = c.metallic;
    surface.perceptualRoughness = c.roughness;
    surface.geometry = render::brdf::Geometry::SmithGGXCorrelated;
    surface.anisotropy = c.anisotropy;
    surface.iridescence = {c.iridescence, c.filmIor, c.filmThickness};
    surface.sheenColor = dvec3(c.sheenColor);
    surface.sheenRoughness = c.sheenRoughness;
    surface.clearcoat = c.clearcoat;
    surface.clearcoatRoughness = c.clearcoatRoughness;
    const bool sheen = glm::any(glm::greaterThan(c.sheenColor, glm::vec3(0.0f)));
    const SheenAlbedoTable albedo(c.sheenRoughness);

    Comparison result;
    for (const test::SpherePixel& px : test::spherePixels(image)) {
        const dvec3 n = px.n, v = px.v;
        if (std::abs(n.y) > 0.95) continue;  // the poles, where the sphere's tangent turns within a pixel
        // scene::makeUvSphere's tangent, dP/du along the parallels.
        surface.anisotropyDirection = glm::normalize(dvec3(n.z, 0.0, -n.x));
        surface.sheenAlbedo = sheen ? albedo.at(glm::dot(n, v)) : 0.0;
        const test::PointLightAt lit = test::pointLightAt(light, lightPosition, px.p);
        const dvec3 l = lit.l, E = lit.E;
        const double NoL = glm::dot(n, l);
        if (NoL <= 0.0) continue;
        auto radiance = [&](const render::brdf::Surface& with) { return render::brdf::evaluate(with, n, v, l) * E * NoL; };
        const dvec3 expected = radiance(surface);
        render::brdf::Surface filmless = surface, isotropic = surface;
        filmless.iridescence.factor = 0.0;
        isotropic.anisotropy = 0.0;
        const dvec3 withoutFilm = radiance(filmless), withoutAnisotropy = radiance(isotropic);
        ++result.tested;
        for (int ch = 0; ch < 3; ++ch) {
            const double got = px.got[ch];
            const double error = std::abs(got - expected[ch]);
            const double tolerance = kRelative * expected[ch] + kAbsolute + (sheen ? 0.01 * expected[ch] : 0.0);
            EXPECT_LE(error, tolerance) << c.name << " pixel (" << px.x << ", " << px.y << ") channel " << ch << ": GPU " << got
                                        << " CPU " << expected[ch];
            if (expected[ch] > 0.05) result.worst = std::max(result.worst, error / expected[ch]);
            result.filmMatters = std::max(result.filmMatters, std::abs(withoutFilm[ch] - expected[ch]) / tolerance);
            result.anisotropyMatters = std::max(result.anisotropyMatters, std::abs(withoutAnisotropy[ch] - expected[ch]) / tolerance);
        }
    }
    return result;
}

} // namespace

TEST_F(GlTest, LayeredMaterialExtensionsComposeAsTheCpuPortDoes)
{
    const Layers cases[] = {
        // The anisotropic lobe with the film's Fresnel (forward/iridescence.glsl's combined lobes).
        {"anisotropic iridescent dielectric", {0.2f, 0.3f, 0.6f}, 0.0f, 0.35f, 0.8f, 1.0f, 1.8f, 500.0f},
        {"anisotropic iridescent metal", {0.9f, 0.7f, 0.4f}, 1.0f, 0.4f, 0.9f, 0.8f, 1.5f, 350.0f},
        // Everything: sheen over the filmed, brushed base, a clearcoat over all of it.
        {"all four layers", {0.6f, 0.2f, 0.2f}, 0.3f, 0.45f, 0.7f, 0.8f, 1.6f, 420.0f, {0.5f, 0.6f, 0.9f}, 0.4f, 0.6f, 0.15f},
    };
    for (const Layers& c : cases) {
        const Comparison r = renderAndCompare(c);
        EXPECT_GT(r.tested, 2000) << c.name;
        // Leaving the film or the anisotropy out would fail far outside the tolerance.
        EXPECT_GT(r.filmMatters, 3.0) << c.name;
        EXPECT_GT(r.anisotropyMatters, 3.0) << c.name;
        RecordProperty(std::string("worst ") + c.name, std::to_string(r.worst));
        std::printf("%s: %d pixels, worst %.4f, film %.1fx, anisotropy %.1fx the tolerance\n", c.name, r.tested, r.worst,
                    r.filmMatters, r.anisotropyMatters);
    }
}
