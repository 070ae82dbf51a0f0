// KHR_materials_anisotropy on the GPU against the extension's lobe, ported here from the
// specification (not from the shader): alpha_t = mix(alpha, 1, strength²) along the direction
// (the tangent turned by anisotropyRotation, or the texture's RG turned by it), alpha_b = alpha
// across it, the anisotropic GGX D and height-correlated Smith V of its "Implementation", the
// glTF Schlick F and Lambert weighted by 1 - F. Punctual light on spheres (factors) and on a
// brushed glTF plate whose direction and strength come from a texture; image-based light
// against a converged Monte Carlo reference (IblReference.h) in both specular modes; the white
// furnace with the multiple-scattering compensation; the anisotropy debug view.
#include "GlTestContext.h"
#include "LitSphere.h"
#include "RadianceFrame.h"
#include "IblReference.h"
#include "ImageProbe.h"
#include "GltfBrdfTerms.h"
#include "SphereTiles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/GltfImporter.h"
#include "scene/Procedural.h"
#include "shading/Brdf.h"
#include "shading/EnvironmentMap.h"

using namespace specula;
using specula::test::GlTest;
using glm::dvec3;
using specula::test::pixelRay;

using namespace specula::test::gltf;

namespace {

// ---- the specification's lobe, in double precision -------------------------------------------

constexpr double kMinRoughness = 0.045; // the renderer's floor for punctual lights (docs/materials.md)

// KHR_materials_anisotropy, "Implementation": D_GGX_anisotropic and V_GGX_anisotropic.
double specD(double NoH, double ToH, double BoH, double at, double ab)
{
    const double a2 = at * ab;
    const dvec3 f(ab * ToH, at * BoH, a2 * NoH);
    const double w2 = a2 / glm::dot(f, f);
    return a2 * w2 * w2 / kPi;
}

double specV(double NoL, double NoV, double BoV, double ToV, double ToL, double BoL, double at, double ab)
{
    const double GGXV = NoL * glm::length(dvec3(at * ToV, ab * BoV, NoV));
    const double GGXL = NoV * glm::length(dvec3(at * ToL, ab * BoL, NoL));
    return std::clamp(0.5 / (GGXV + GGXL), 0.0, 1.0);
}

struct Brushed {
    dvec3 baseColor{1.0};
    double metallic = 1.0;
    double roughness = 0.4;
    double strength = 0.0;
};

/// f n.l (per unit illuminance from l) with the anisotropy direction t (unit, orthogonal to n).
dvec3 brushedRadiance(const Brushed& m, const dvec3& n, const dvec3& t, const dvec3& v, const dvec3& l)
{
    const double NoL = glm::dot(n, l);
    if (NoL <= 0.0) return dvec3(0.0);
    const dvec3 b = glm::cross(n, t);
    const dvec3 h = glm::normalize(v + l);
    const double r = std::clamp(m.roughness, kMinRoughness, 1.0), alpha = r * r;
    const double at = glm::mix(alpha, 1.0, m.strength * m.strength), ab = alpha;
    const double NoV = std::max(glm::dot(n, v), 1e-4);
    const dvec3 F = schlick(glm::mix(dvec3(0.04), m.baseColor, m.metallic), 1.0, glm::dot(v, h));
    const dvec3 diffuse = (1.0 - F) * m.baseColor * (1.0 - m.metallic) / kPi;
    const double D = specD(glm::dot(n, h), glm::dot(t, h), glm::dot(b, h), at, ab);
    const double V = specV(NoL, NoV, glm::dot(b, v), glm::dot(t, v), glm::dot(t, l), glm::dot(b, l), at, ab);
    return (diffuse + F * D * V) * NoL;
}

/// The UV sphere's tangent (scene::makeUvSphere: dP/du, along the parallels) at unit normal n,
/// turned by `rotation` towards the bitangent cross(n, t).
dvec3 sphereDirection(const dvec3& n, double rotation)
{
    const dvec3 t = glm::normalize(dvec3(n.z, 0.0, -n.x));
    return std::cos(rotation) * t + std::sin(rotation) * glm::cross(n, t);
}

// ---- punctual light -----------------------------------------------------------------------------

// The tolerance of tests/gl/test_shading.cpp and test_clearcoat.cpp: 1.5% relative plus 2e-3
// cd/m² absolute (half floats, single precision, a tessellated sphere's interpolated normals and
// tangents).
constexpr double kRelative = 0.015;
constexpr double kAbsolute = 2e-3;

struct Comparison {
    int tested = 0;
    int anisotropyMatters = 0; ///< pixels where the isotropic lobe is beyond 3 tolerances
    double maxRelativeError = 0.0;
};

Comparison compareSphere(const char* name, const Brushed& m, double rotation, const glm::vec3& lightPosition, float intensity)
{
    scene::Scene s;
    scene::Material material;
    material.baseColorFactor = glm::vec4(glm::vec3(m.baseColor), 1.0f);
    material.metallicFactor = float(m.metallic);
    material.roughnessFactor = float(m.roughness);
    material.anisotropyStrength = float(m.strength);
    material.anisotropyRotation = float(rotation);
    scene::addShape(s, scene::makeUvSphere(1.0f, 256, 128), material, glm::mat4(1.0f), "sphere");
    const scene::Light light = test::pointLight(intensity);
    scene::addLight(s, light, lightPosition, -lightPosition);

    const ImageFloat image = test::renderSphere(s, test::radianceFrame(96, 96, test::Brdf::Exact));

    Brushed isotropic = m;
    isotropic.strength = 0.0;
    Comparison result;
    for (const test::SpherePixel& px : test::spherePixels(image)) {
        const dvec3 n = px.n, v = px.v;
        if (std::abs(n.y) > 0.95) continue; // the poles, where the tangent turns within a pixel
        const test::PointLightAt lit = test::pointLightAt(light, lightPosition, px.p);
        const dvec3 l = lit.l, E = lit.E;
        const dvec3 t = sphereDirection(n, rotation);
        const dvec3 expected = brushedRadiance(m, n, t, v, l) * E;
        const dvec3 iso = brushedRadiance(isotropic, n, t, v, l) * E;
        ++result.tested;
        if (std::abs(iso.y - expected.y) > 3.0 * (kRelative * expected.y + kAbsolute)) ++result.anisotropyMatters;
        for (int ch = 0; ch < 3; ++ch) {
            const double got = px.got[ch];
            const double error = std::abs(got - expected[ch]);
            EXPECT_LE(error, kRelative * expected[ch] + kAbsolute)
                << name << " pixel (" << px.x << ", " << px.y << ") channel " << ch << ": GPU " << got << " CPU " << expected[ch]
                << " (isotropic " << iso[ch] << ")";
            if (expected[ch] > 0.05) result.maxRelativeError = std::max(result.maxRelativeError, error / expected[ch]);
        }
    }
    std::printf("anisotropy, %s: %d pixels (%d where it matters), worst relative error %.3f%%\n", name, result.tested,
                result.anisotropyMatters, 100.0 * result.maxRelativeError);
    return result;
}

} // namespace

TEST_F(GlTest, AnisotropySpheresMatchTheExtensionsLobe)
{
    // Broken on purpose (2026-12-03): the isotropic D and V in the light loop (evaluateBrdfLobes
    // instead of evaluateAnisotropicLobes in pbr.frag): worst 671 %, 150 %, 98 %, fails; the
    // rotation ignored (material.anisotropy.yz read as (1, 0)): the turned spheres 88 % and 57 %,
    // fails. Measured: worst 0.46 %, 0.34 %, 0.26 % (bound 1.5 % + 2e-3).
    const Comparison copper = compareSphere("copper, roughness 0.3, strength 0.8", {{0.955, 0.638, 0.538}, 1.0, 0.3, 0.8}, 0.0,
                                            {2.0f, 2.5f, 3.0f}, 30.0f);
    EXPECT_GT(copper.tested, 2000);
    EXPECT_GT(copper.anisotropyMatters, 200); // the stretched highlight is in the picture, and checked
    const Comparison turned = compareSphere("red dielectric, roughness 0.45, strength 1, rotated 60 degrees",
                                            {{0.8, 0.2, 0.1}, 0.0, 0.45, 1.0}, kPi / 3.0, {-2.0f, 1.0f, 3.0f}, 30.0f);
    EXPECT_GT(turned.anisotropyMatters, 100);
    compareSphere("rough gold, strength 0.5, rotated -30 degrees", {{1.0, 0.77, 0.34}, 1.0, 0.7, 0.5}, -kPi / 6.0,
                  {1.0f, -1.5f, 3.0f}, 30.0f);
}

TEST_F(GlTest, AnisotropyTextureFromGltf)
{
    // tests/assets/gltf/anisotropy_plate.gltf: a brushed plate, its direction (RG) and strength
    // (B) from an 8 x 8 texture with nearest filtering, anisotropyStrength 0.9, anisotropyRotation
    // 0.25 rad, tangent frame = world axes. The texel under each pixel is read from the decoded
    // image here; pixels within 0.15 texel of a texel edge are skipped.
    // Broken on purpose (2026-12-03): the texture's B not multiplied in: worst 66 %, fails; the
    // rotation ignored: 101 %, fails; the isotropic lobe: 375 %, fails. Measured: worst 0.10 %.
    scene::Scene s = scene::loadGltf(std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/anisotropy_plate.gltf");
    ASSERT_EQ(s.materials.size(), 1u);
    ASSERT_EQ(s.images.size(), 1u);
    const scene::Image& texture = s.images[0];
    ASSERT_EQ(texture.width, 8);
    const glm::vec3 lightPosition(-0.5f, 0.4f, 1.2f);
    const scene::Light light = test::pointLight(3.0f);
    scene::addLight(s, light, lightPosition, -lightPosition);
    constexpr int kSize = 128;
    const glm::vec3 eye(0.0f, 0.0f, 3.0f);
    const render::View view = render::lookAtView(eye, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 20.0f);
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, test::radianceFrame(kSize, kSize, test::Brdf::Exact));
    const ImageFloat image = renderer.readRadiance();

    const double rotation = 0.25;
    const dvec3 n(0.0, 0.0, 1.0);
    const glm::dmat4 inverse = test::inverseViewProjection(view);
    int tested = 0, strengthMatters = 0;
    double worst = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const test::Ray ray = pixelRay(inverse, x, y, kSize, kSize);
            const dvec3 p = ray.origin + ray.direction * (-ray.origin.z / ray.direction.z);
            if (std::abs(p.x) > 0.97 || std::abs(p.y) > 0.97) continue; // the plate's edge pixels
            const double tu = (p.x + 1.0) * 0.5 * 8.0, tv = (1.0 - p.y) * 0.5 * 8.0;
            const auto nearEdge = [](double c) { return std::abs(c - std::round(c)) < 0.15; };
            if (nearEdge(tu) || nearEdge(tv)) continue;
            const uint8_t* texel = &texture.pixels[(size_t(tv) * 8 + size_t(tu)) * 4];
            // The extension's decoding: RG x 2 - 1, normalised, turned by the rotation; B x strength.
            const glm::dvec2 d = glm::normalize(glm::dvec2(texel[0], texel[1]) / 255.0 * 2.0 - 1.0);
            const glm::dvec2 turned(std::cos(rotation) * d.x - std::sin(rotation) * d.y, std::sin(rotation) * d.x + std::cos(rotation) * d.y);
            const dvec3 t(turned, 0.0);
            const Brushed m{{0.9, 0.9, 0.92}, 1.0, 0.35, 0.9 * texel[2] / 255.0};
            const dvec3 v = glm::normalize(dvec3(eye) - p);
            const test::PointLightAt lit = test::pointLightAt(light, lightPosition, p);
            const dvec3 l = lit.l, E = lit.E;
            const dvec3 expected = brushedRadiance(m, n, t, v, l) * E;
            Brushed full = m;
            full.strength = 0.9; // the texture's B ignored
            if (std::abs(brushedRadiance(full, n, t, v, l).x * E.x - expected.x) > 3.0 * (kRelative * expected.x + kAbsolute))
                ++strengthMatters;
            ++tested;
            for (int ch = 0; ch < 3; ++ch) {
                const double got = image.pixels[(size_t(y) * kSize + x) * 4 + ch];
                const double error = std::abs(got - expected[ch]);
                EXPECT_LE(error, kRelative * expected[ch] + kAbsolute)
                    << "pixel (" << x << ", " << y << ") channel " << ch << ": GPU " << got << " CPU " << expected[ch];
                if (expected[ch] > 0.05) worst = std::max(worst, error / expected[ch]);
            }
        }
    EXPECT_GT(tested, 3000);
    EXPECT_GT(strengthMatters, 50);
    std::printf("anisotropy plate (texture): %d pixels (%d where B matters), worst relative error %.3f%%\n", tested, strengthMatters,
                100.0 * worst);
}

TEST_F(GlTest, AnisotropyDebugViewShowsDirectionAndStrength)
{
    // --debug-view anisotropy: RG = the turned direction x 0.5 + 0.5, B = the strength, as bytes
    // (sRGB-decoded output, so byte = value x 255): rotation 1 rad, strength 0.7 -> (196, 235, 178 or 179).
    scene::Scene s;
    scene::Material material;
    material.anisotropyStrength = 0.7f;
    material.anisotropyRotation = 1.0f;
    scene::addShape(s, scene::makeUvSphere(1.0f, 64, 32), material, glm::mat4(1.0f), "sphere");
    scene::Material plain;
    scene::addShape(s, scene::makeUvSphere(0.3f, 32, 16), plain, glm::translate(glm::mat4(1.0f), glm::vec3(1.6f, 0.0f, 0.0f)), "plain");
    render::Renderer renderer;
    renderer.setScene(s);
    render::FrameSettings settings = test::radianceFrame(64, 64, test::Brdf::Exact);
    settings.debugView = DebugView::Anisotropy;
    const render::View view = render::lookAtView({0.0f, 0.0f, 4.0f}, {0, 0, 0}, {0, 1, 0}, glm::radians(60.0f), 1.0f, 0.1f, 20.0f);
    renderer.render(view, settings);
    const ImageRGBA8 out = renderer.readImage();
    const uint8_t* centre = &out.pixels[(32u * 64u + 32u) * 4u];
    EXPECT_NEAR(centre[0], std::lround((std::cos(1.0) * 0.5 + 0.5) * 255.0), 1);
    EXPECT_NEAR(centre[1], std::lround((std::sin(1.0) * 0.5 + 0.5) * 255.0), 1);
    EXPECT_NEAR(centre[2], std::lround(0.7 * 255.0), 1);
    // The isotropic sphere: (0.5, 0.5, 0).
    const glm::ivec2 at = test::projectToPixel(view, {1.6f, 0.0f, 0.3f}, 64, 64);
    const uint8_t* plainPixel = &out.pixels[(size_t(at.y) * 64u + size_t(at.x)) * 4u];
    EXPECT_NEAR(plainPixel[0], 128, 1);
    EXPECT_NEAR(plainPixel[1], 128, 1);
    EXPECT_EQ(plainPixel[2], 0);
}

// ---- image-based light --------------------------------------------------------------------------

TEST_F(GlTest, AnisotropyImageBasedLightAgainstAMonteCarloReference)
{
    // Spheres of brushed copper (roughness 0.3, strength 0.8) and of a brushed orange dielectric
    // (roughness 0.5, strength 1) under venice_1k, in both specular modes, against the converged
    // CPU estimate of the rendering equation with the extension's lobe (IblReference: MIS of
    // the anisotropic GGX and the map), energy compensation off in both. Metric as
    // test_ibl_reference.cpp's: Σ|GPU − reference| / Σ reference over the sphere (every third
    // pixel, 2 × 1024 samples). The same spheres rendered isotropic (strength 0) are measured
    // against the same reference: the anisotropic render must be closer, by the factor below.
    // Broken on purpose (2026-12-03): the split sum without the bent normal (lookupNormal = n):
    // copper 23.5 %, fails; the importance sampler on the isotropic lobe (alphas.x = alphas.y):
    // copper 39.3 %, dielectric 9.4 %, fails.
    const std::string file = std::string(SPECULA_ASSETS_DIR) + "/env/venice_1k.hdr";
    ASSERT_TRUE(std::filesystem::exists(file)) << "shared assets missing";
    const render::EnvironmentMap map = render::loadEnvironmentMap(file);
    const test::EnvironmentSampler sampler(map);
    render::Renderer renderer;
    renderer.setEnvironment(map);

    struct Sphere {
        const char* name;
        glm::vec3 baseColor;
        float metallic, roughness, strength;
    };
    const Sphere spheres[] = {{"brushed copper", {0.955f, 0.638f, 0.538f}, 1.0f, 0.3f, 0.8f},
                              {"brushed orange dielectric", {0.8f, 0.3f, 0.05f}, 0.0f, 0.5f, 1.0f}};
    const int count = 2;
    std::vector<scene::Material> anisotropic, isotropic;
    for (const Sphere& sp : spheres) {
        scene::Material m;
        m.baseColorFactor = glm::vec4(sp.baseColor, 1.0f);
        m.metallicFactor = sp.metallic;
        m.roughnessFactor = sp.roughness;
        m.anisotropyStrength = sp.strength;
        anisotropic.push_back(m);
        m.anisotropyStrength = 0.0f;
        isotropic.push_back(m);
    }
    struct Pixel {
        int x, y;
        dvec3 n;
    };
    std::vector<Pixel> pixels;
    for (int y = 0; y < test::kSize; y += 3)
        for (int x = 0; x < test::kSize; x += 3) {
            glm::vec3 n;
            if (test::sphereNormal(x, y, n) && std::abs(n.y) < 0.95f) pixels.push_back({x, y, dvec3(n)});
        }
    std::vector<test::ReferenceSample> reference(size_t(count) * pixels.size());
    test::parallelFor(reference.size(), [&](size_t k) {
        const int i = int(k / pixels.size());
        const Pixel& p = pixels[k % pixels.size()];
        render::brdf::Surface surface;
        surface.baseColor = dvec3(spheres[i].baseColor);
        surface.metallic = spheres[i].metallic;
        surface.perceptualRoughness = spheres[i].roughness;
        surface.anisotropy = spheres[i].strength;
        surface.anisotropyDirection = sphereDirection(p.n, 0.0);
        // The renderer's anisotropic lobe has the height-correlated V (docs/materials.md).
        surface.geometry = render::brdf::Geometry::SmithGGXCorrelated;
        reference[k] = test::referenceRadiance(surface, p.n, test::viewVector(i, count, p.n), map, sampler, dvec3(1.0), 1024, k);
    });

    for (render::IblSpecular mode : {render::IblSpecular::SplitSum, render::IblSpecular::Importance}) {
        render::FrameSettings settings;
        settings.environment.specular = mode;
        settings.energyCompensation = false;
        const test::SphereRender a = test::renderSpheres(renderer, anisotropic, settings);
        const test::SphereRender iso = test::renderSpheres(renderer, isotropic, settings);
        for (int i = 0; i < count; ++i) {
            double sumAbs = 0.0, sumIso = 0.0, sumReference = 0.0, noise = 0.0;
            for (size_t k = 0; k < pixels.size(); ++k) {
                const test::ReferenceSample& ref = reference[size_t(i) * pixels.size() + k];
                const dvec3 got(test::pixel(a.image, i * test::kSize + pixels[k].x, pixels[k].y));
                const dvec3 gotIso(test::pixel(iso.image, i * test::kSize + pixels[k].x, pixels[k].y));
                const dvec3 d = glm::abs(got - ref.radiance), di = glm::abs(gotIso - ref.radiance);
                sumAbs += d.x + d.y + d.z;
                sumIso += di.x + di.y + di.z;
                sumReference += ref.radiance.x + ref.radiance.y + ref.radiance.z;
                noise += ref.relativeError;
            }
            const double error = sumAbs / sumReference, isoError = sumIso / sumReference;
            const bool importance = mode == render::IblSpecular::Importance;
            std::printf("anisotropy IBL, %s, %s: error %.2f %% (isotropic render %.2f %%, reference noise %.2f %%)\n",
                        spheres[i].name, render::iblSpecularName(mode), 100.0 * error, 100.0 * isoError,
                        100.0 * noise / double(pixels.size()));
            // Measured (2026-12-03): split sum 16.4 % (copper) and 3.0 % (dielectric), importance
            // 4.3 % and 2.7 %, against 56 % and 15-16 % for the isotropic renders; the reference's
            // own noise is 2.4-2.9 %. The split sum's bound is the isotropic one's under the same
            // map (test_ibl_reference.cpp, 16 %) plus the reference's noise.
            const double bound = importance ? 0.06 : 0.19;
            EXPECT_LT(error, bound) << spheres[i].name << " " << render::iblSpecularName(mode);
            EXPECT_LT(error, 0.75 * isoError) << spheres[i].name << " " << render::iblSpecularName(mode)
                                              << ": the anisotropic render should be nearer the reference than the isotropic one";
        }
    }
}

TEST_F(GlTest, AnisotropyWhiteFurnace)
{
    // Uniform environment L. A white metal with the multiple-scattering compensation reflects L,
    // anisotropic or not: within 2 % where n.v > 0.1, WhiteFurnace's bound (test_ibl.cpp), in both
    // specular modes (split sum: the table's E at the lobe's table roughness cancels; importance:
    // the per-pixel samples' own albedo). Without compensation a white dielectric never exceeds L
    // by more than 1 % (what its specular lobe takes its diffuse lobe gives back).
    // Broken on purpose (2026-12-03): the importance path compensated by the table's E at the
    // lobe's table roughness (energyCompensation) instead of the samples' own: the white metal
    // is off by 13-94 % (at grazing n.v, where the isotropic stand-in's albedo is far below the
    // anisotropic lobe's), fails.
    const glm::vec3 L(0.6f);
    render::Renderer renderer;
    renderer.setEnvironment(render::constantEnvironment(L));
    const std::vector<float> roughnesses = {0.1f, 0.3f, 0.6f, 1.0f};
    for (float strength : {0.5f, 1.0f}) {
        std::vector<scene::Material> metals, dielectrics;
        for (float r : roughnesses) {
            scene::Material m;
            m.baseColorFactor = glm::vec4(1.0f);
            m.metallicFactor = 1.0f;
            m.roughnessFactor = r;
            m.anisotropyStrength = strength;
            metals.push_back(m);
            m.metallicFactor = 0.0f;
            dielectrics.push_back(m);
        }
        const int count = int(roughnesses.size());
        for (render::IblSpecular mode : {render::IblSpecular::SplitSum, render::IblSpecular::Importance}) {
            render::FrameSettings settings;
            settings.environment.skybox = false;
            settings.environment.specular = mode;
            const test::SphereRender metal = test::renderSpheres(renderer, metals, settings);
            settings.energyCompensation = false;
            const test::SphereRender dielectric = test::renderSpheres(renderer, dielectrics, settings);
            for (int i = 0; i < count; ++i) {
                double worst = 0.0, highest = 0.0;
                int tested = 0;
                for (int y = 0; y < test::kSize; ++y)
                    for (int x = 0; x < test::kSize; ++x) {
                        glm::vec3 n;
                        if (!test::sphereNormal(x, y, n) || n.z < 0.1f) continue;
                        ++tested;
                        const glm::vec3 c = test::pixel(metal.image, i * test::kSize + x, y);
                        const glm::vec3 d = test::pixel(dielectric.image, i * test::kSize + x, y);
                        for (int ch = 0; ch < 3; ++ch) {
                            worst = std::max(worst, double(std::abs(c[ch] - L[ch]) / L[ch]));
                            highest = std::max(highest, double(d[ch] / L[ch]));
                        }
                    }
                EXPECT_GT(tested, 2000);
                EXPECT_LT(worst, 0.02) << "strength " << strength << " roughness " << roughnesses[size_t(i)] << " "
                                       << render::iblSpecularName(mode);
                EXPECT_LE(highest, 1.01) << "strength " << strength << " roughness " << roughnesses[size_t(i)] << " "
                                         << render::iblSpecularName(mode);
                std::printf("anisotropy furnace, strength %.1f, roughness %.1f, %s: white metal worst %.2f %%, white dielectric "
                            "highest %.4f L\n",
                            strength, roughnesses[size_t(i)], render::iblSpecularName(mode), 100.0 * worst, highest);
            }
        }
    }
}
