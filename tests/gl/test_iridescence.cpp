// KHR_materials_iridescence on the GPU against the extension's BRDF, ported here from the
// specification (not from the shader): the glTF base (GGX, separable Smith, Schlick, Lambert)
// whose specular Fresnel is F = mix(F_schlick, F_iridescence, iridescence), F_iridescence =
// mix(film over the dielectric F0, film over the base colour, metallic), and whose diffuse lobe
// is weighted by mix(1 - F_schlick, 1 - max(F_iridescence), iridescence) (the extension's
// rgb_mix). The film itself is the CPU port of shading/Iridescence.h, checked on its own in
// tests/unit/test_iridescence.cpp. Punctual light on spheres (thicknesses, IORs, factors, a
// metal and a dielectric), a glTF quad whose strength and thickness come from textures, image-
// based light in a uniform environment (split sum and --ibl importance, and the furnace bound),
// and the debug view. Broken on purpose (docs/materials.md), each fails: the optical path with
// cos theta1, the diffuse weight 1 - F per channel, the thickness texture ignored, the split
// sum's Fresnel left as the table's, no film per importance sample, the debug view without it.
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

#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/GltfImporter.h"
#include "scene/Procedural.h"
#include "shading/EnvironmentMap.h"
#include "shading/Iridescence.h"

using namespace specula;
using specula::test::GlTest;
using glm::dvec3;
using specula::test::pixelRay;

using namespace specula::test::gltf;

namespace {

// ---- the specification's BRDF, in double precision -------------------------------------------

constexpr double kMinRoughness = 0.045; // the renderer's floor for punctual lights (docs/materials.md)

dvec3 schlick(const dvec3& f0, double c)
{
    return f0 + (1.0 - f0) * std::pow(1.0 - std::clamp(c, 0.0, 1.0), 5.0);
}

double max3(const dvec3& c) { return std::max({c.r, c.g, c.b}); }

struct Filmed {
    dvec3 baseColor{1.0};
    double metallic = 0.0;
    double roughness = 0.5;
    double iridescence = 0.0; ///< factor x texture
    double ior = 1.3;
    double thickness = 400.0; ///< nm
};

/// F_iridescence of the extension's two layers mixed by metallic, at cos theta = c.
dvec3 filmF(const Filmed& m, double c)
{
    return glm::mix(render::brdf::iridescentFresnel(1.0, m.ior, c, m.thickness, dvec3(0.04)),
                    render::brdf::iridescentFresnel(1.0, m.ior, c, m.thickness, m.baseColor), m.metallic);
}

/// Radiance towards v per unit illuminance from l: f NoL.
dvec3 filmedRadiance(const Filmed& m, const dvec3& n, const dvec3& v, const dvec3& l)
{
    const double NoL = glm::dot(n, l);
    if (NoL <= 0.0) return dvec3(0.0);
    const dvec3 h = glm::normalize(v + l);
    const double VoH = std::clamp(glm::dot(v, h), 0.0, 1.0);
    const double NoV = std::max(glm::dot(n, v), 1e-4);
    const double r = std::clamp(m.roughness, kMinRoughness, 1.0), alpha = r * r;
    const dvec3 Fs = schlick(glm::mix(dvec3(0.04), m.baseColor, m.metallic), VoH);
    const dvec3 film = filmF(m, VoH);
    const dvec3 F = glm::mix(Fs, film, m.iridescence);
    const dvec3 diffuseWeight = glm::mix(1.0 - Fs, dvec3(std::max(1.0 - max3(film), 0.0)), m.iridescence);
    const dvec3 diffuse = diffuseWeight * m.baseColor * (1.0 - m.metallic) / kPi;
    return (diffuse + F * D_GGX(std::clamp(glm::dot(n, h), 0.0, 1.0), alpha) * V_GGX(NoL, NoV, alpha)) * NoL;
}

/// Directional integrals of the specular lobe by GGX importance sampling of h on a stratified
/// grid (pdf(l) = D n.h / (4 v.h)): the split sum's A and B (F = 1 - Fc and Fc, the DFG table's
/// terms) and, for --ibl importance, the lobe with the film per sample.
struct LobeIntegrals {
    double A = 0.0, B = 0.0;
    dvec3 filmed{0.0}; ///< integral of mix(F_schlick, F_iridescence, factor)(v.h) D V n.l
};

LobeIntegrals lobeIntegrals(const Filmed& m, double NoV, double perceptualRoughness)
{
    const double alpha = perceptualRoughness * perceptualRoughness;
    const dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    const dvec3 f0 = glm::mix(dvec3(0.04), m.baseColor, m.metallic);
    constexpr int kGrid = 128;
    LobeIntegrals out;
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
            const double w = V_GGX(l.z, NoV, alpha) * l.z * 4.0 * VoH / cosTheta; // f n.l / pdf without F
            const double fc = std::pow(1.0 - VoH, 5.0);
            out.A += (1.0 - fc) * w;
            out.B += fc * w;
            out.filmed += glm::mix(schlick(f0, VoH), filmF(m, VoH), m.iridescence) * w;
        }
    out.A /= kGrid * kGrid;
    out.B /= kGrid * kGrid;
    out.filmed /= double(kGrid * kGrid);
    return out;
}

// ---- rendering ----------------------------------------------------------------------------------

// The tolerance of tests/gl/test_shading.cpp: 1.5% relative plus 2e-3 cd/m² absolute (half
// floats, single precision, a tessellated sphere's interpolated normals).
constexpr double kRelative = 0.015;
constexpr double kAbsolute = 2e-3;

scene::Material materialOf(const Filmed& c)
{
    scene::Material material;
    material.baseColorFactor = glm::vec4(glm::vec3(c.baseColor), 1.0f);
    material.metallicFactor = float(c.metallic);
    material.roughnessFactor = float(c.roughness);
    material.iridescenceFactor = float(c.iridescence);
    material.iridescenceIor = float(c.ior);
    material.iridescenceThicknessMaximum = float(c.thickness); // no thickness texture: the maximum
    return material;
}

struct Comparison {
    int tested = 0;
    double maxRelativeError = 0.0;
    double filmMatters = 0.0; ///< the largest |film - no film| in tolerances
};

/// A unit sphere at the origin under one point light, pixel by pixel against filmedRadiance.
Comparison compareSphere(const char* name, const Filmed& c, const glm::vec3& lightPosition, float intensity)
{
    scene::Scene s;
    scene::addShape(s, scene::makeUvSphere(1.0f, 256, 128), materialOf(c), glm::mat4(1.0f), "sphere");
    const scene::Light light = test::pointLight(intensity, {1.0f, 0.95f, 0.9f});
    scene::addLight(s, light, lightPosition, -lightPosition);

    const ImageFloat image = test::renderSphere(s, test::radianceFrame(96, 96, test::Brdf::Exact));

    Filmed bare = c;
    bare.iridescence = 0.0;
    Comparison result;
    for (const test::SpherePixel& px : test::spherePixels(image)) {
        const dvec3 n = px.n, v = px.v;
        const test::PointLightAt lit = test::pointLightAt(light, lightPosition, px.p);
        const dvec3 l = lit.l, E = lit.E;
        const dvec3 expected = filmedRadiance(c, n, v, l) * E;
        const dvec3 plain = filmedRadiance(bare, n, v, l) * E;
        ++result.tested;
        for (int ch = 0; ch < 3; ++ch) {
            const double got = px.got[ch];
            const double error = std::abs(got - expected[ch]);
            const double tolerance = kRelative * expected[ch] + kAbsolute;
            EXPECT_LE(error, tolerance) << name << " pixel (" << px.x << ", " << px.y << ") channel " << ch << ": GPU " << got
                                        << " CPU " << expected[ch];
            if (expected[ch] > 0.05) result.maxRelativeError = std::max(result.maxRelativeError, error / expected[ch]);
            result.filmMatters = std::max(result.filmMatters, std::abs(plain[ch] - expected[ch]) / tolerance);
        }
    }
    std::printf("iridescence, %s: %d pixels, worst relative error %.3f%%, film vs none up to %.0f tolerances\n", name,
                result.tested, 100.0 * result.maxRelativeError, result.filmMatters);
    return result;
}

} // namespace

TEST_F(GlTest, IridescentSpheresMatchTheExtensionsFresnel)
{
    // Dielectrics (where the film's colour is all of the highlight) at three thicknesses and two
    // IORs, a partial film, and metals (where it tints the whole reflection). The light near the
    // eye puts the highlight, and thus the film, in the picture.
    const glm::vec3 light(1.5f, 1.5f, 4.0f);
    struct Case {
        const char* name;
        Filmed m;
    };
    const Case cases[] = {
        {"dielectric, 250 nm IOR 1.3", {{0.2, 0.3, 0.6}, 0.0, 0.3, 1.0, 1.3, 250.0}},
        {"dielectric, 500 nm IOR 1.8", {{0.2, 0.3, 0.6}, 0.0, 0.3, 1.0, 1.8, 500.0}},
        {"dielectric, 700 nm IOR 1.6, factor 0.6", {{0.5, 0.5, 0.5}, 0.0, 0.25, 0.6, 1.6, 700.0}},
        {"gold, 400 nm IOR 1.5", {{1.0, 0.78, 0.34}, 1.0, 0.4, 1.0, 1.5, 400.0}},
        {"grey metal, 350 nm IOR 2.0, metallic 0.6", {{0.9, 0.9, 0.9}, 0.6, 0.5, 0.8, 2.0, 350.0}},
    };
    for (const Case& c : cases) {
        const Comparison r = compareSphere(c.name, c.m, light, 25.0f);
        EXPECT_GT(r.tested, 2000) << c.name;
        EXPECT_GT(r.filmMatters, 3.0) << c.name; // without the film it would fail somewhere
    }
}

TEST_F(GlTest, IridescenceThicknessAndStrengthFromGltfTextures)
{
    // tests/assets/gltf/iridescence_quad.gltf: a grey metal (0.8, roughness 0.45) under a film of
    // IOR 1.6, strength 1 x R 230/255, thickness mix(100, 700 nm, G) from a 2 x 2 texture through
    // KHR_texture_transform (u' = 1 - u): quadrant (u < 0.5, v < 0.5) reads texel (1, 0), G 85.
    scene::Scene s = scene::loadGltf(std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/iridescence_quad.gltf");
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_FLOAT_EQ(s.materials[0].iridescenceIor, 1.6f);
    EXPECT_FLOAT_EQ(s.materials[0].iridescenceThicknessMinimum, 100.0f);
    EXPECT_FLOAT_EQ(s.materials[0].iridescenceThicknessMaximum, 700.0f);
    const glm::vec3 lightPosition(0.4f, 0.3f, 2.0f);
    const scene::Light light = test::pointLight(6.0f, {1.0f, 0.95f, 0.9f});
    scene::addLight(s, light, lightPosition, -lightPosition);
    constexpr int kSize = 128;
    const glm::vec3 eye(0.0f, 0.0f, 3.0f);
    const render::View view = render::lookAtView(eye, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 20.0f);
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, test::radianceFrame(kSize, kSize, test::Brdf::Exact));
    const ImageFloat image = renderer.readRadiance();

    const int texelG[2][2] = {{0, 85}, {170, 255}}; // [row][column] of the PNG
    const dvec3 n(0.0, 0.0, 1.0);
    const glm::dmat4 inverse = test::inverseViewProjection(view);
    int tested = 0;
    double worst = 0.0, thicknessMatters = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const test::Ray ray = pixelRay(inverse, x, y, kSize, kSize);
            const dvec3 p = ray.origin + ray.direction * (-ray.origin.z / ray.direction.z);
            if (std::abs(p.x) > 0.97 || std::abs(p.y) > 0.97) continue; // the quad's edge pixels
            if (std::abs(p.x) < 0.03 || std::abs(p.y) < 0.03) continue; // the texels' edges (nearest)
            const double u = (p.x + 1.0) / 2.0, v = (1.0 - p.y) / 2.0;
            const int column = (1.0 - u) < 0.5 ? 0 : 1, row = v < 0.5 ? 0 : 1;
            Filmed m{{0.8, 0.8, 0.8}, 1.0, 0.45, 230.0 / 255.0, 1.6, 100.0 + 600.0 * texelG[row][column] / 255.0};
            const dvec3 vv = glm::normalize(dvec3(eye) - p);
            const test::PointLightAt lit = test::pointLightAt(light, lightPosition, p);
            const dvec3 l = lit.l, E = lit.E;
            const dvec3 expected = filmedRadiance(m, n, vv, l) * E;
            Filmed untextured = m;
            untextured.thickness = 700.0; // the maximum: the thickness texture ignored
            const dvec3 wrong = filmedRadiance(untextured, n, vv, l) * E;
            ++tested;
            for (int ch = 0; ch < 3; ++ch) {
                const double got = image.pixels[(size_t(y) * kSize + x) * 4 + ch];
                const double error = std::abs(got - expected[ch]);
                const double tolerance = kRelative * expected[ch] + kAbsolute;
                EXPECT_LE(error, tolerance) << "pixel (" << x << ", " << y << ") channel " << ch << ": GPU " << got << " CPU "
                                            << expected[ch];
                if (expected[ch] > 0.05) worst = std::max(worst, error / expected[ch]);
                thicknessMatters = std::max(thicknessMatters, std::abs(wrong[ch] - expected[ch]) / tolerance);
            }
        }
    EXPECT_GT(tested, 5000);
    EXPECT_GT(thicknessMatters, 3.0); // ignoring the thickness texture would fail far outside the tolerance
    std::printf("iridescence quad (strength and thickness textures): %d pixels, worst relative error %.3f%%, thickness "
                "texture matters by %.0f tolerances\n",
                tested, 100.0 * worst, thicknessMatters);
}

TEST_F(GlTest, IridescenceImageBasedLightInAUniformEnvironment)
{
    // Uniform environment L, energy compensation off: irradiance pi L, so the diffuse lobe gives
    // L c_diff w and the specular lobe L E. Split sum: E = mix(f0 A + B, F_iridescence(n.v)
    // (A + B), factor), w = mix(1 - (f0 A + B), 1 - max(F_iridescence(n.v) (A + B)), factor),
    // A and B the DFG table's terms by quadrature (lobeIntegrals); --ibl importance: E the lobe
    // integrated with the film per sample, w the split sum's. Tolerance 1.5% + 0.005 L per
    // channel, as the clearcoat furnace (the RG16F table and its bilinear lookup, 64 samples).
    // The furnace bound: a white dielectric with a film never reflects more than L (1%), as the
    // extension's rgb_mix promises (1 - max F below, F above).
    const std::vector<Filmed> films = {
        {{1.0, 1.0, 1.0}, 0.0, 0.5, 1.0, 1.3, 300.0},
        {{1.0, 1.0, 1.0}, 0.0, 0.3, 1.0, 1.8, 550.0},
        {{0.9, 0.9, 0.9}, 1.0, 0.5, 0.7, 1.5, 400.0},
    };
    std::vector<scene::Material> materials;
    for (const Filmed& f : films) materials.push_back(materialOf(f));
    render::Renderer renderer;
    const glm::vec3 L(0.8f);
    renderer.setEnvironment(render::constantEnvironment(L));
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
            const Filmed& m = films[size_t(i)];
            int tested = 0;
            double worst = 0.0, separation = 0.0;
            for (int x = test::kSize / 2; x < test::kSize; x += 2) {
                glm::vec3 nf;
                if (!test::sphereNormal(x, y, nf)) continue;
                const dvec3 n(nf);
                const double NoV = glm::dot(n, test::viewVector(i, count, n));
                if (NoV < 0.15) continue;
                ++tested;
                const LobeIntegrals lobe = lobeIntegrals(m, NoV, std::clamp(m.roughness, kMinRoughness, 1.0));
                const dvec3 f0 = glm::mix(dvec3(0.04), m.baseColor, m.metallic);
                const dvec3 Es = f0 * lobe.A + lobe.B;
                const dvec3 Ef = filmF(m, NoV) * (lobe.A + lobe.B);
                const dvec3 w = glm::mix(1.0 - Es, dvec3(std::max(1.0 - max3(Ef), 0.0)), m.iridescence);
                const dvec3 specular = mode == render::IblSpecular::SplitSum ? glm::mix(Es, Ef, m.iridescence) : lobe.filmed;
                const dvec3 expected = double(L.x) * (m.baseColor * (1.0 - m.metallic) * w + specular);
                const dvec3 plain = double(L.x) * (m.baseColor * (1.0 - m.metallic) * (1.0 - Es) + Es);
                const glm::vec3 got = test::pixel(r.image, i * test::kSize + x, y);
                for (int ch = 0; ch < 3; ++ch) {
                    const double tolerance = 0.015 * expected[ch] + 0.005 * double(L.x);
                    EXPECT_NEAR(got[ch], expected[ch], tolerance)
                        << render::iblSpecularName(mode) << " film " << i << " n.v " << NoV << " channel " << ch;
                    worst = std::max(worst, std::abs(double(got[ch]) - expected[ch]));
                    separation = std::max(separation, std::abs(plain[ch] - expected[ch]) / tolerance);
                    if (m.metallic == 0.0) { // the furnace bound, for the white dielectrics
                        EXPECT_LE(got[ch], 1.01 * L[ch]) << "furnace, film " << i << " n.v " << NoV;
                        highest = std::max(highest, double(got[ch]) / double(L[ch]));
                    }
                }
            }
            EXPECT_GE(tested, 12);
            EXPECT_GT(separation, 1.0) << "film " << i; // without the film the expectation would not hold
            std::printf("iridescence IBL, %s, film %d: worst |GPU - CPU| %.4f L (%d pixels), film vs none %.1f tolerances\n",
                        render::iblSpecularName(mode), i, worst / double(L.x), tested, separation);
        }
        std::printf("iridescence furnace, %s: highest reflected fraction %.4f\n", render::iblSpecularName(mode), highest);
    }
}

TEST_F(GlTest, IridescenceDebugViewShowsTheFresnelAtNormalIncidenceToView)
{
    // DebugView::Iridescence writes mix(F_schlick(n.v), F_iridescence(n.v), factor) as bytes
    // (value x 255), for a filmed sphere and a plain one (F alone). Tolerance 2 levels: the
    // 8-bit rounding and n.v across a pixel.
    const std::vector<Filmed> films = {{{0.2, 0.3, 0.6}, 0.0, 0.4, 1.0, 1.5, 450.0}, {{0.9, 0.6, 0.3}, 1.0, 0.4, 0.0, 1.3, 400.0}};
    std::vector<scene::Material> materials;
    for (const Filmed& f : films) materials.push_back(materialOf(f));
    render::Renderer renderer;
    render::FrameSettings settings;
    settings.debugView = DebugView::Iridescence;
    test::renderSpheres(renderer, materials, settings);
    const ImageRGBA8 image = renderer.readImage();
    const int y = test::kSize / 2 - 1;
    int tested = 0;
    for (int i = 0; i < 2; ++i)
        for (int x = test::kSize / 2; x < test::kSize; x += 3) {
            glm::vec3 nf;
            if (!test::sphereNormal(x, y, nf)) continue;
            const dvec3 n(nf);
            const double NoV = glm::dot(n, test::viewVector(i, 2, n));
            if (NoV < 0.2) continue;
            const Filmed& m = films[size_t(i)];
            const dvec3 F = glm::mix(schlick(glm::mix(dvec3(0.04), m.baseColor, m.metallic), NoV), filmF(m, NoV), m.iridescence);
            const uint8_t* got = &image.pixels[(size_t(y) * image.width + size_t(i * test::kSize + x)) * 4];
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(double(got[ch]), std::clamp(F[ch], 0.0, 1.0) * 255.0, 2.0) << "sphere " << i << " n.v " << NoV << " channel " << ch;
            ++tested;
        }
    EXPECT_GE(tested, 16);
}
