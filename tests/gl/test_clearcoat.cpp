// KHR_materials_clearcoat on the GPU against the extension's layering, ported here from the
// specification (not from the shader): the base glTF BRDF (Appendix B: GGX, separable Smith,
// Schlick, Lambert weighted by 1 - F) dimmed by 1 - clearcoat Fc(n_c.v), plus the layer's own
// GGX lobe clearcoat F(v.h) D V with F0 0.04 (ior 1.5), F90 1, its roughness and its normal.
// Punctual light on spheres (factors) and on a glTF quad whose factor, roughness and normal
// come from textures; the white furnace for the image-based path.
#include "GlTestContext.h"
#include "LitSphere.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"
#include "GltfBrdfTerms.h"
#include "SphereTiles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/GltfImporter.h"
#include "scene/Procedural.h"
#include "shading/EnvironmentMap.h"

using namespace specula;
using specula::test::GlTest;
using glm::dvec3;
using specula::test::pixelRay;

using namespace specula::test::gltf;

namespace {

// ---- the specification's BRDF, in double precision -------------------------------------------

constexpr double kMinRoughness = 0.045; // the renderer's floor for punctual lights (docs/materials.md)

struct Coated {
    dvec3 baseColor{1.0};
    double metallic = 0.0;
    double roughness = 0.5;
    double clearcoat = 0.0;
    double clearcoatRoughness = 0.0;
};

/// Radiance towards v per unit illuminance from l: f NoL of the base (normal n) and of the
/// layer (normal nc), as the extension layers them.
dvec3 coatedRadiance(const Coated& m, const dvec3& n, const dvec3& nc, const dvec3& v, const dvec3& l)
{
    const dvec3 h = glm::normalize(v + l);
    const double VoH = std::clamp(glm::dot(v, h), 0.0, 1.0);
    dvec3 base(0.0);
    if (const double NoL = glm::dot(n, l); NoL > 0.0) {
        const double r = std::clamp(m.roughness, kMinRoughness, 1.0), alpha = r * r;
        const double NoV = std::max(glm::dot(n, v), 1e-4);
        const dvec3 f0 = glm::mix(dvec3(0.04), m.baseColor, m.metallic);
        const dvec3 F = schlick(f0, 1.0, VoH);
        const dvec3 diffuse = (1.0 - F) * m.baseColor * (1.0 - m.metallic) / kPi;
        base = (diffuse + F * D_GGX(std::clamp(glm::dot(n, h), 0.0, 1.0), alpha) * V_GGX(NoL, NoV, alpha)) * NoL;
    }
    const double NcoV = std::max(glm::dot(nc, v), 1e-4);
    const dvec3 attenuation = 1.0 - m.clearcoat * schlick(dvec3(0.04), 1.0, NcoV);
    dvec3 layer(0.0);
    if (const double NcoL = glm::dot(nc, l); NcoL > 0.0) {
        const double r = std::clamp(m.clearcoatRoughness, kMinRoughness, 1.0), alpha = r * r;
        layer = m.clearcoat * schlick(dvec3(0.04), 1.0, VoH) * D_GGX(std::clamp(glm::dot(nc, h), 0.0, 1.0), alpha) *
                V_GGX(NcoL, NcoV, alpha) * NcoL;
    }
    return base * attenuation + layer;
}

/// The layer's directional albedo E_c(n.v) = integral of F D V n.l over the hemisphere, by
/// GGX importance sampling of h on a stratified grid (pdf(l) = D n.h / (4 v.h)).
double clearcoatAlbedo(double NoV, double perceptualRoughness)
{
    const double alpha = perceptualRoughness * perceptualRoughness;
    const dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    constexpr int kGrid = 256;
    double sum = 0.0;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            const double u1 = (i + 0.5) / kGrid, u2 = (j + 0.5) / kGrid;
            const double cosTheta = std::sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1));
            const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
            const dvec3 h(sinTheta * std::cos(2.0 * kPi * u2), sinTheta * std::sin(2.0 * kPi * u2), cosTheta);
            const double VoH = glm::dot(v, h);
            if (VoH <= 0.0) continue;
            const dvec3 l = 2.0 * VoH * h - v;
            if (l.z <= 0.0) continue;
            // f n.l / pdf = F D V n.l 4 v.h / (D n.h) = F V n.l 4 v.h / n.h
            sum += schlick(dvec3(0.04), 1.0, VoH).x * V_GGX(l.z, NoV, alpha) * l.z * 4.0 * VoH / cosTheta;
        }
    return sum / (kGrid * kGrid);
}

// ---- rendering ----------------------------------------------------------------------------------

// The tolerance of tests/gl/test_shading.cpp: 1.5% relative plus 2e-3 cd/m² absolute (half
// floats, single precision, a tessellated sphere's interpolated normals).
constexpr double kRelative = 0.015;
constexpr double kAbsolute = 2e-3;

struct Comparison {
    int tested = 0;
    int coatDominated = 0; ///< pixels where the layer gives more than the base
    double maxRelativeError = 0.0;
};

/// A unit sphere at the origin under one point light, pixel by pixel against coatedRadiance.
Comparison compareSphere(const char* name, const Coated& c, const glm::vec3& lightPosition, float intensity)
{
    scene::Scene s;
    scene::Material material;
    material.baseColorFactor = glm::vec4(glm::vec3(c.baseColor), 1.0f);
    material.metallicFactor = float(c.metallic);
    material.roughnessFactor = float(c.roughness);
    material.clearcoatFactor = float(c.clearcoat);
    material.clearcoatRoughnessFactor = float(c.clearcoatRoughness);
    scene::addShape(s, scene::makeUvSphere(1.0f, 256, 128), material, glm::mat4(1.0f), "sphere");
    const scene::Light light = test::pointLight(intensity);
    scene::addLight(s, light, lightPosition, -lightPosition);

    const ImageFloat image = test::renderSphere(s, test::radianceFrame(96, 96, test::Brdf::Exact));

    Coated bare = c;
    bare.clearcoat = 0.0;
    Comparison result;
    for (const test::SpherePixel& px : test::spherePixels(image)) {
        const dvec3 n = px.n, v = px.v;
        const test::PointLightAt lit = test::pointLightAt(light, lightPosition, px.p);
        const dvec3 l = lit.l, E = lit.E;
        const dvec3 expected = coatedRadiance(c, n, n, v, l) * E;
        ++result.tested;
        if (glm::length(expected - coatedRadiance(bare, n, n, v, l) * E) > glm::length(coatedRadiance(bare, n, n, v, l) * E))
            ++result.coatDominated;
        for (int ch = 0; ch < 3; ++ch) {
            const double got = px.got[ch];
            const double error = std::abs(got - expected[ch]);
            EXPECT_LE(error, kRelative * expected[ch] + kAbsolute)
                << name << " pixel (" << px.x << ", " << px.y << ") channel " << ch << ": GPU " << got << " CPU " << expected[ch];
            if (expected[ch] > 0.05) result.maxRelativeError = std::max(result.maxRelativeError, error / expected[ch]);
        }
    }
    std::printf("clearcoat, %s: %d pixels, worst relative error %.3f%%\n", name, result.tested, 100.0 * result.maxRelativeError);
    return result;
}

} // namespace

TEST_F(GlTest, ClearcoatSpheresMatchTheExtensionsLayering)
{
    // A rough red dielectric under a smoother layer: the layer's highlight stands apart from the
    // base's; a rough gold metal under a partial layer (clearcoat 0.6).
    const Comparison red = compareSphere("red dielectric, coat 1 at 0.25", {{0.8, 0.2, 0.1}, 0.0, 0.7, 1.0, 0.25},
                                         {2.0f, 2.5f, 3.0f}, 30.0f);
    EXPECT_GT(red.tested, 2000);
    EXPECT_GT(red.coatDominated, 10); // the layer's highlight is in the picture, and checked
    compareSphere("gold, coat 0.6 at 0.4", {{0.95, 0.64, 0.54}, 1.0, 0.8, 0.6, 0.4}, {-2.0f, 1.0f, 3.0f}, 30.0f);
}

TEST_F(GlTest, ClearcoatTexturesAndNormalMapFromGltf)
{
    // tests/assets/gltf/clearcoat_quad.gltf: factor 1 x R 204/255, roughness 0.5 x G 128/255,
    // the layer's normal map a constant texel (171, 128, 247) at scale 0.8 in the quad's tangent
    // frame (+X, +Y, +Z); the base keeps the geometric normal (no normalTexture).
    scene::Scene s = scene::loadGltf(std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/clearcoat_quad.gltf");
    ASSERT_EQ(s.materials.size(), 1u);
    const glm::vec3 lightPosition(-0.6f, 0.3f, 1.5f);
    const scene::Light light = test::pointLight(4.0f);
    scene::addLight(s, light, lightPosition, -lightPosition);
    constexpr int kSize = 128;
    const glm::vec3 eye(0.0f, 0.0f, 3.0f);
    const render::View view = render::lookAtView(eye, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 20.0f);
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, test::radianceFrame(kSize, kSize, test::Brdf::Exact));
    const ImageFloat image = renderer.readRadiance();

    Coated c{{0.8, 0.2, 0.1}, 0.0, 0.6, 1.0 * 204.0 / 255.0, 0.5 * 128.0 / 255.0};
    dvec3 tn = dvec3(171.0, 128.0, 247.0) / 255.0 * 2.0 - 1.0;
    tn.x *= 0.8;
    tn.y *= 0.8;
    const dvec3 n(0.0, 0.0, 1.0);
    const dvec3 nc = glm::normalize(tn); // tangent frame = world axes
    const glm::dmat4 inverse = test::inverseViewProjection(view);
    int tested = 0;
    double worst = 0.0, tiltMatters = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const test::Ray ray = pixelRay(inverse, x, y, kSize, kSize);
            const dvec3 p = ray.origin + ray.direction * (-ray.origin.z / ray.direction.z);
            if (std::abs(p.x) > 0.97 || std::abs(p.y) > 0.97) continue; // the quad's edge pixels
            const dvec3 v = glm::normalize(dvec3(eye) - p);
            const test::PointLightAt lit = test::pointLightAt(light, lightPosition, p);
            const dvec3 l = lit.l, E = lit.E;
            const dvec3 expected = coatedRadiance(c, n, nc, v, l) * E;
            const dvec3 untilted = coatedRadiance(c, n, n, v, l) * E;
            tiltMatters = std::max(tiltMatters, std::abs(untilted.x - expected.x) / (kRelative * expected.x + kAbsolute));
            ++tested;
            for (int ch = 0; ch < 3; ++ch) {
                const double got = image.pixels[(size_t(y) * kSize + x) * 4 + ch];
                const double error = std::abs(got - expected[ch]);
                EXPECT_LE(error, kRelative * expected[ch] + kAbsolute)
                    << "pixel (" << x << ", " << y << ") channel " << ch << ": GPU " << got << " CPU " << expected[ch];
                if (expected[ch] > 0.05) worst = std::max(worst, error / expected[ch]);
            }
        }
    EXPECT_GT(tested, 5000);
    // Ignoring the layer's normal map would be far outside the tolerance somewhere.
    EXPECT_GT(tiltMatters, 3.0);
    std::printf("clearcoat quad (textures, normal map): %d pixels, worst relative error %.3f%%\n", tested, 100.0 * worst);
}

TEST_F(GlTest, ClearcoatWhiteFurnace)
{
    // Uniform environment L, energy compensation off. A white dielectric reflects all of L
    // (what its specular lobe takes its diffuse lobe gives back), so under a layer of strength 1
    // the expected radiance is L (1 - Fc(n.v) + E_c(n.v)): the layer's own directional albedo
    // (clearcoatAlbedo, the quadrature above) over the base dimmed by Fresnel. It never exceeds
    // L by more than 1% (the furnace bound of docs/testing.md): E_c <= Fc up to the single-
    // scattering GGX's small excess at rough normal incidence.
    // Tolerance 1.5% + 0.005 L per channel, as FurnaceMatchesEachBrdfVariantsAlbedo (the RG16F
    // DFG table and its bilinear lookup); pixels with n.v >= 0.15 along a radius.
    const std::vector<double> roughnesses = {0.1, 0.5, 1.0};
    std::vector<scene::Material> materials;
    for (double r : roughnesses) {
        scene::Material m;
        m.baseColorFactor = glm::vec4(1.0f);
        m.metallicFactor = 0.0f;
        m.roughnessFactor = 0.5f;
        m.clearcoatFactor = 1.0f;
        m.clearcoatRoughnessFactor = float(r);
        materials.push_back(m);
    }
    render::Renderer renderer;
    const glm::vec3 L(0.8f);
    renderer.setEnvironment(render::constantEnvironment(L));
    // Both specular paths: the split sum (the layer's DFG lookup and prefiltered fetch) and
    // --ibl importance (the layer's own importance-sampled lobe, 64 samples; in a uniform
    // environment as close: measured 0.0017 L worst, the same tolerance holds).
    for (render::IblSpecular mode : {render::IblSpecular::SplitSum, render::IblSpecular::Importance}) {
    render::FrameSettings settings;
    settings.energyCompensation = false;
    settings.environment.skybox = false;
    settings.environment.specular = mode;
    const test::SphereRender r = test::renderSpheres(renderer, materials, settings);
    const int count = int(materials.size());
    const int y = test::kSize / 2 - 1;
    double highest = 0.0;
    for (int i = 0; i < count; ++i) {
        int tested = 0;
        double worst = 0.0, separation = 0.0;
        for (int x = test::kSize / 2; x < test::kSize; x += 2) {
            glm::vec3 nf;
            if (!test::sphereNormal(x, y, nf)) continue;
            const dvec3 n(nf);
            const double NoV = glm::dot(n, test::viewVector(i, count, n));
            if (NoV < 0.15) continue;
            ++tested;
            const double expected = double(L.x) * (1.0 - schlick(dvec3(0.04), 1.0, NoV).x + clearcoatAlbedo(NoV, roughnesses[size_t(i)]));
            const double tolerance = 0.015 * expected + 0.005 * double(L.x);
            // Without the layer's own albedo at its own roughness (the base's 0.5 instead) the
            // expectation would be this far off, in tolerances.
            const double wrongRoughness = double(L.x) * (1.0 - schlick(dvec3(0.04), 1.0, NoV).x + clearcoatAlbedo(NoV, 0.5));
            separation = std::max(separation, std::abs(wrongRoughness - expected) / tolerance);
            const glm::vec3 got = test::pixel(r.image, i * test::kSize + x, y);
            for (int ch = 0; ch < 3; ++ch) {
                EXPECT_NEAR(got[ch], expected, tolerance) << "clearcoat roughness " << roughnesses[size_t(i)] << " n.v " << NoV;
                EXPECT_LE(got[ch], 1.01 * L[ch]) << "clearcoat roughness " << roughnesses[size_t(i)] << " n.v " << NoV;
                worst = std::max(worst, std::abs(double(got[ch]) - expected));
                highest = std::max(highest, double(got[ch]) / double(L[ch]));
            }
        }
        EXPECT_GE(tested, 12);
        if (roughnesses[size_t(i)] != 0.5) {
            EXPECT_GT(separation, 1.0) << "roughness " << roughnesses[size_t(i)];
        }
        std::printf("clearcoat furnace, %s, roughness %.1f: worst |GPU - CPU| %.4f L (%d pixels)\n", render::iblSpecularName(mode),
                    roughnesses[size_t(i)], worst / double(L.x), tested);
    }
    std::printf("clearcoat furnace, %s: highest reflected fraction %.4f\n", render::iblSpecularName(mode), highest);
    }
}

TEST_F(GlTest, ClearcoatDebugViewsShowTheLayersFactorRoughnessAndNormal)
{
    // --debug-view clearcoat and clearcoat-normal on tests/assets/gltf/clearcoat_quad.gltf: the
    // factor 1 x R 204/255 and roughness 0.5 x G 128/255 (B 0), and the layer's normal from its
    // constant texel (171, 128, 247) at scale 0.8 in the quad's tangent frame (the world axes),
    // n x 0.5 + 0.5; each written sRGB-decoded (the output's value x 255). The same quad without
    // a layer is black in both. Within 0.004 (half floats).
    const std::string file = std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/clearcoat_quad.gltf";
    dvec3 tn = dvec3(171.0, 128.0, 247.0) / 255.0 * 2.0 - 1.0;
    tn.x *= 0.8;
    tn.y *= 0.8;
    const dvec3 layerNormal = glm::normalize(tn) * 0.5 + 0.5;
    const dvec3 layer(204.0 / 255.0, 0.5 * 128.0 / 255.0, 0.0);
    constexpr int kSize = 64;
    const glm::vec3 eye(0.0f, 0.0f, 3.0f);
    const render::View view = render::lookAtView(eye, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 20.0f);
    auto toValue = [](double linear) { return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055; };
    for (DebugView debugView : {DebugView::Clearcoat, DebugView::ClearcoatNormal}) {
        SCOPED_TRACE(debugViewName(debugView));
        for (bool coated : {true, false}) {
            scene::Scene s = scene::loadGltf(file);
            if (!coated) s.materials.at(0).clearcoatFactor = 0.0f;
            render::Renderer renderer;
            renderer.setScene(s);
            render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
            settings.debugView = debugView;
            renderer.render(view, settings);
            const ImageFloat image = renderer.readRadiance();
            const dvec3 expected = !coated ? dvec3(0.0) : debugView == DebugView::Clearcoat ? layer : layerNormal;
            int tested = 0;
            for (int y = 8; y < kSize - 8; ++y)
                for (int x = 8; x < kSize - 8; ++x) {
                    ++tested;
                    for (int ch = 0; ch < 3; ++ch)
                        EXPECT_NEAR(toValue(image.pixels[(size_t(y) * kSize + x) * 4 + ch]), expected[ch], 0.004)
                            << (coated ? "coated" : "bare") << " pixel (" << x << ", " << y << ") channel " << ch;
                }
            EXPECT_EQ(tested, 48 * 48);
        }
    }
}
