// Image-based lighting on the GPU: furnace tests in a uniform environment (also per BRDF
// variant, each with its own DFG table), the direction convention with a bright patch and a
// mirror sphere, the split sum against a CPU Monte Carlo integral of the same BRDF under a
// real HDR, and the environment block's partial uploads.
#include "GlTestContext.h"
#include "RadianceFrame.h"
#include "SphereTiles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/Brdf.h"
#include "shading/EnvironmentMap.h"
#include "shading/SunExtraction.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "render/ImageBasedLighting.h"
#include "render/Renderer.h"
#include "scene/Procedural.h"
#include "shaders/shared/EnvironmentData.h"

using namespace specula;
using specula::test::GlTest;
using namespace specula::test;


TEST_F(GlTest, WhiteFurnace)
{
    // Uniform environment of radiance L: a white metal of every roughness reflects L (the
    // multiple-scattering compensation restores what single scattering loses), a white
    // dielectric too (what the specular lobe takes the diffuse lobe gives back), and a
    // coloured dielectric never exceeds L. Tolerance 2% (the bound) over the sphere
    // where n.v > 0.1; half floats and the RG16F table contribute ~0.2%.
    const glm::vec3 L(0.6f, 0.6f, 0.6f);
    render::Renderer renderer;
    renderer.setEnvironment(render::constantEnvironment(L));
    double worst = 0.0;
    for (float roughness : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
        for (float metallic : {1.0f, 0.0f}) {
            const SphereRender r = renderSphere(renderer, metallic, roughness, glm::vec3(1.0f));
            int tested = 0;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    glm::vec3 n;
                    if (!sphereNormal(x, y, n) || n.z < 0.1f) continue;
                    ++tested;
                    const glm::vec3 c = pixel(r.image, x, y);
                    worst = std::max(worst, double(std::abs(c.x - L.x) / L.x));
                    for (int ch = 0; ch < 3; ++ch)
                        ASSERT_NEAR(c[ch], L[ch], 0.02f * L[ch]) << "metallic " << metallic << " roughness " << roughness
                                                                  << " pixel " << x << "," << y;
                }
            EXPECT_GT(tested, 2000);
        }
        std::printf("white furnace up to roughness %.2f: worst deviation %.2f%%\n", roughness, 100.0 * worst);
        const SphereRender coloured = renderSphere(renderer, 0.0f, roughness, {0.9f, 0.5f, 0.1f});
        for (size_t i = 0; i < coloured.image.pixels.size(); i += 4)
            for (int ch = 0; ch < 3; ++ch) EXPECT_LE(coloured.image.pixels[i + size_t(ch)], L[ch] * 1.005f);
    }
}

TEST_F(GlTest, UniformEnvironmentLightsLambertAtAlbedo)
{
    // Irradiance from a uniform L is pi L, so a Lambertian surface of albedo a reflects a L at
    // every pixel. A pure Lambertian dielectric is KHR_materials_specular's specularFactor 0.
    // Bound 2%; measured within 0.05%.
    const glm::vec3 L(0.8f, 0.5f, 0.25f);
    render::Renderer renderer;
    renderer.setEnvironment(render::constantEnvironment(L));
    double worst = 0.0;
    for (float albedo : {0.2f, 0.5f, 1.0f}) {
        const SphereRender r = renderSphere(renderer, 0.0f, 0.5f, glm::vec3(albedo), {}, 0.0f);
        int tested = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                glm::vec3 n;
                if (!sphereNormal(x, y, n) || n.z < 0.1f) continue;
                ++tested;
                const glm::vec3 c = pixel(r.image, x, y);
                for (int ch = 0; ch < 3; ++ch) {
                    worst = std::max(worst, double(std::abs(c[ch] - albedo * L[ch]) / (albedo * L[ch])));
                    ASSERT_NEAR(c[ch], albedo * L[ch], 0.02f * albedo * L[ch]) << "albedo " << albedo;
                }
            }
        EXPECT_GT(tested, 2000);
        std::printf("Lambert in a uniform environment, albedo %.1f: worst deviation %.2f%%\n", albedo, 100.0 * worst);
    }
}

TEST_F(GlTest, BrightPatchReflectsWhereTheConventionSays)
{
    // Black environment with one bright patch at direction d: a mirror sphere seen along -Z
    // reflects it at the normal halfway between the view direction (+Z) and d.
    const glm::vec3 d = glm::normalize(glm::vec3(0.5f, 0.4f, 0.6f));
    render::EnvironmentMap map;
    map.width = 512;
    map.height = 256;
    map.texels.assign(size_t(512 * 256), glm::vec3(0.0f));
    const glm::vec2 uv = render::directionToEquirect(d);
    const int cx = int(uv.x * 512), cy = int(uv.y * 256);
    // 11 × 11 texels (7.7°): a pixel of the sphere reflects about 3.6° of directions, and a true
    // mirror (roughness 0 under image-based light) can fall between pixel centres on a smaller one.
    for (int y = cy - 5; y <= cy + 5; ++y)
        for (int x = cx - 5; x <= cx + 5; ++x) map.texels[size_t(y * 512 + x)] = glm::vec3(50.0f);
    map.key = "test-patch";
    render::Renderer renderer;
    renderer.setEnvironment(map);
    for (float rotation : {0.0f, 90.0f, -35.0f}) {
        render::FrameSettings settings;
        settings.environment.rotationDegrees = rotation;
        settings.environment.skybox = false;
        const SphereRender r = renderSphere(renderer, 1.0f, 0.0f, glm::vec3(1.0f), settings);
        const glm::vec3 world = render::environmentRotation(rotation) * d;
        // v points from the surface to the eye: iterate n = normalize(v + d).
        glm::vec3 n = glm::normalize(world + glm::vec3(0, 0, 1));
        for (int i = 0; i < 8; ++i) n = glm::normalize(world + glm::vec3(viewVector(0, 1, glm::dvec3(n))));
        // Predicted pixel of that normal (orthographic, half extent 1.2).
        const float px = (n.x / kHalfExtent + 1.0f) * 0.5f * kSize, py = (1.0f - n.y / kHalfExtent) * 0.5f * kSize;
        int bx = 0, by = 0;
        float best = -1.0f;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                if (pixel(r.image, x, y).x > best) best = pixel(r.image, x, y).x, bx = x, by = y;
        EXPECT_GT(best, 1.0f) << "rotation " << rotation;
        EXPECT_NEAR(bx + 0.5f, px, 1.5f) << "rotation " << rotation;
        EXPECT_NEAR(by + 0.5f, py, 1.5f) << "rotation " << rotation;
    }
}

namespace {

using render::brdf::Distribution;
using render::brdf::Fresnel;
using render::brdf::Geometry;

struct BrdfVariant {
    Distribution distribution = Distribution::GGX;
    Geometry geometry = Geometry::SmithGGX;
    Fresnel fresnel = Fresnel::Schlick;
};

std::string variantName(const BrdfVariant& v)
{
    return std::string(scene::brdfDistributionName(v.distribution)) + " " + scene::brdfGeometryName(v.geometry) + " " +
           scene::brdfFresnelName(v.fresnel);
}

scene::MaterialShading materialShading(const BrdfVariant& v)
{
    scene::MaterialShading s;
    s.distribution = v.distribution;
    s.geometry = v.geometry;
    s.fresnel = v.fresnel;
    return s;
}

// Directional albedo ∫ f(l, v) (n.l) dω_l of shading/Brdf's BRDF at n.v = NoV, per channel,
// by the midpoint rule in (cos θ_l, φ_l) around n: φ over [0, π], doubled, as the integrand
// is symmetric about the plane of n and v. A quadrature independent of the GPU's importance
// sampling; at roughness 0.5 and 1, for every D and G, it agrees with 4x the cells to 1e-5.
glm::dvec3 directionalAlbedo(const render::brdf::Surface& surface, double NoV, int nMu = 1200, int nPhi = 240)
{
    const glm::dvec3 n(0, 0, 1), v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    const double dMu = 1.0 / nMu, dPhi = render::brdf::kPi / nPhi;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < nMu; ++i) {
        const double mu = (i + 0.5) * dMu, sinTheta = std::sqrt(1.0 - mu * mu);
        for (int j = 0; j < nPhi; ++j) {
            const double phi = (j + 0.5) * dPhi;
            const glm::dvec3 l(sinTheta * std::cos(phi), sinTheta * std::sin(phi), mu);
            sum += render::brdf::evaluate(surface, n, v, l) * mu;
        }
    }
    return 2.0 * sum * dMu * dPhi;
}

scene::Material metal(const glm::vec3& baseColor, float roughness, const BrdfVariant& variant)
{
    scene::Material m;
    m.baseColorFactor = glm::vec4(baseColor, 1.0f);
    m.metallicFactor = 1.0f;
    m.roughnessFactor = roughness;
    m.shading = materialShading(variant);
    return m;
}

render::brdf::Surface cpuMetal(const glm::vec3& baseColor, float roughness, const BrdfVariant& variant)
{
    render::brdf::Surface s;
    s.baseColor = glm::dvec3(baseColor);
    s.metallic = 1.0;
    s.perceptualRoughness = roughness;
    s.distribution = variant.distribution;
    s.geometry = variant.geometry;
    s.fresnel = variant.fresnel;
    s.imageBased = true; // the G the DFG table integrates (Schlick-GGX: k = r²/2)
    return s;
}

// Half vector around n distributed as D_GGX(h) (n.h) (Walter et al. 2007, eq. 35-36), for the
// point (u1, u2) of the unit square; t, b, n an orthonormal frame.
glm::dvec3 sampleGgxHalfVector(double u1, double u2, double alpha, const glm::dvec3& t, const glm::dvec3& b, const glm::dvec3& n)
{
    const double phi = 2.0 * render::brdf::kPi * u2;
    const double cosT = std::sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1));
    const double sinT = std::sqrt(1.0 - cosT * cosT);
    return t * (sinT * std::cos(phi)) + b * (sinT * std::sin(phi)) + n * cosT;
}

// Monte Carlo estimate of ∫ f(l, v) L(l) (n.l) dω_l for shading/Brdf's BRDF, with `samples`
// GGX-importance half vectors (a stratified u1 and a golden-ratio u2 lattice): f (n.l) / pdf,
// pdf = D_GGX (n.h) / (4 v.h), which is also unbiased for the other D (the GGX lobe with the
// same α has the heavier tails, so D / D_GGX stays below 1.5). L = 1 without a map.
glm::dvec3 monteCarloRadiance(const render::brdf::Surface& surface, const glm::dvec3& n, const glm::dvec3& v, int samples,
                              const render::EnvironmentMap* map, double u2Offset)
{
    const double r = std::max(surface.perceptualRoughness, render::brdf::kMinPerceptualRoughness);
    const double alpha = r * r;
    const glm::dvec3 t = glm::normalize(glm::cross(std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0), n));
    const glm::dvec3 b = glm::cross(n, t);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < samples; ++i) {
        const double u1 = (i + 0.5) / samples, u2 = std::fmod(i * 0.6180339887498949 + u2Offset, 1.0);
        const glm::dvec3 h = sampleGgxHalfVector(u1, u2, alpha, t, b, n);
        const double VoH = glm::dot(v, h);
        const glm::dvec3 l = 2.0 * VoH * h - v;
        const double NoL = glm::dot(n, l), NoH = glm::dot(n, h);
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        const double pdf = render::brdf::D_GGX(NoH, alpha) * NoH / (4.0 * VoH);
        const glm::dvec3 radiance = map ? glm::dvec3(map->sample(glm::vec3(l))) : glm::dvec3(1.0);
        sum += render::brdf::evaluate(surface, n, v, l) * NoL / pdf * radiance;
    }
    return sum / double(samples);
}

} // namespace

TEST_F(GlTest, SplitSumMatchesMonteCarloUnderARealHdr)
{
    // Metals (no diffuse lobe, so the split sum is the only approximation) under venice_1k.hdr:
    // the GPU pixel against a CPU Monte Carlo estimate of the integral of f(l, v) L(l) (n.l)
    // with the same BRDF and the same energy compensation, 2048 samples per pixel, for normals
    // with n.v >= 0.5. The split sum assumes n = v = r when prefiltering, which is exact at
    // normal incidence and drifts off it (less with the dominant direction).
    // One sphere per D in each frame. The prefiltered environment is GGX's for every D (only
    // the DFG table is the variant's own), which adds the lobe-shape error for Beckmann and
    // Blinn-Phong measured here.
    // Bounds: mean relative error (RGB length) < 12% per roughness for GGX, < 20% for Beckmann
    // and Blinn-Phong; every GGX pixel with n.v >= 0.8 < 25%. Measured (default preset), mean
    // at roughness 0.3 / 0.6 / 1: GGX 5.7% / 7.0% / 1.5%, Beckmann 16.2% / 12.1% / 5.2%,
    // Blinn-Phong 16.1% / 9.8% / 1.5% (its D is GGX's at roughness 1).
    const std::string file = std::string(SPECULA_ASSETS_DIR) + "/env/venice_1k.hdr";
    ASSERT_TRUE(std::filesystem::exists(file)) << "shared assets missing";
    const render::EnvironmentMap map = render::loadEnvironmentMap(file);
    const glm::vec3 f0(0.95f, 0.64f, 0.54f);
    const std::vector<BrdfVariant> variants = {{Distribution::GGX}, {Distribution::Beckmann}, {Distribution::BlinnPhong}};
    const int count = int(variants.size());
    render::Renderer renderer;
    // Both bake presets are measured (printed); the bounds apply to the default one.
    for (const char* presetName : {"reference", "default"}) {
        renderer.setEnvironment(map, *render::bakePreset(presetName));
        const bool checked = std::string(presetName) == "default";
        for (float roughness : {0.3f, 0.6f, 1.0f}) {
            std::vector<scene::Material> materials;
            for (const BrdfVariant& v : variants) materials.push_back(metal(f0, roughness, v));
            const SphereRender r = renderSpheres(renderer, materials, {});
            for (int s = 0; s < count; ++s) {
                const BrdfVariant& variant = variants[size_t(s)];
                const bool ggx = variant.distribution == Distribution::GGX;
                double worst = 0.0, total = 0.0;
                int tested = 0;
                for (int y = 4; y < kSize; y += 7) {
                    for (int x = 4; x < kSize; x += 7) {
                        glm::vec3 nf;
                        if (!sphereNormal(x, y, nf) || nf.z < 0.5f) continue;
                        const glm::dvec3 n(nf), v = viewVector(s, count, n);
                        // Energy compensation from E(1), a CPU estimate independent of the GPU table.
                        const double e1 = monteCarloRadiance(cpuMetal(glm::vec3(1.0f), roughness, variant), n, v, 4096, nullptr, 0.0).x;
                        const glm::dvec3 compensation = glm::dvec3(1.0) + glm::dvec3(f0) * (1.0 / e1 - 1.0);
                        const glm::dvec3 expected =
                            monteCarloRadiance(cpuMetal(f0, roughness, variant), n, v, 2048, &map, 0.1) * compensation;
                        const glm::dvec3 got(pixel(r.image, s * kSize + x, y));
                        const double error = glm::length(got - expected) / glm::length(expected);
                        worst = std::max(worst, error);
                        total += error;
                        ++tested;
                        if (checked && ggx && glm::dot(n, v) >= 0.8) {
                            EXPECT_LT(error, 0.25) << "roughness " << roughness << " n " << n.x << "," << n.y << "," << n.z << " GPU "
                                                   << got.x << " CPU " << expected.x;
                        }
                    }
                }
                std::printf("split sum vs Monte Carlo, venice, preset %s, D %s, roughness %.1f: mean error %.1f%%, worst %.1f%% (%d pixels)\n",
                            presetName, scene::brdfDistributionName(variant.distribution), roughness, 100.0 * total / tested,
                            100.0 * worst, tested);
                if (checked) {
                    EXPECT_LT(total / tested, ggx ? 0.12 : 0.20) << variantName(variant) << " roughness " << roughness;
                }
            }
        }
    }
}

TEST_F(GlTest, FurnaceMatchesEachBrdfVariantsAlbedo)
{
    // Uniform environment L, energy compensation off: a metal reflects L times its directional
    // albedo, which the split sum gives as f0 A + f90 B from the DFG table of the material's own
    // D, G and F. Base colour (1, 0.5, 0) puts A + B, A/2 + B and B (F = none: f0 (A + B)) in
    // the three channels. Every variant is one sphere of the same frame, so each draw must bind
    // its own table. Expected: the quadrature of shading/Brdf's BRDF (directionalAlbedo) at the
    // n.v of sample pixels along a radius, n.v >= 0.15.
    // Tolerance 1.5% + 0.005 L per channel: the RG16F table, its bilinear lookup, 512
    // low-discrepancy samples and the tessellated sphere; measured worst 0.011 L (n.v = 0.2).
    // Each variant must differ from what the glTF BRDF's table (ggx, smith-ggx, schlick) would
    // give by more than 3x the tolerance at some pixel, so reading that table fails the test.
    const glm::vec3 baseColor(1.0f, 0.5f, 0.0f);
    const std::vector<BrdfVariant> variants = {
        {Distribution::Beckmann, Geometry::SmithGGX, Fresnel::Schlick},
        {Distribution::BlinnPhong, Geometry::CookTorrance, Fresnel::Schlick},
        {Distribution::GGX, Geometry::Neumann, Fresnel::Schlick},
        {Distribution::GGX, Geometry::SchlickGGX, Fresnel::Schlick},
        {Distribution::GGX, Geometry::SmithGGXCorrelated, Fresnel::Schlick},
        {Distribution::Beckmann, Geometry::Kelemen, Fresnel::None},
        {Distribution::BlinnPhong, Geometry::Implicit, Fresnel::SchlickSG},
    };
    const int count = int(variants.size());
    render::Renderer renderer;
    const glm::vec3 L(0.8f);
    renderer.setEnvironment(render::constantEnvironment(L));
    render::FrameSettings settings;
    settings.energyCompensation = false;
    settings.environment.skybox = false;
    auto tolerance = [&](double expected) { return 0.015 * expected + 0.005 * double(L.x); };
    std::vector<double> separation(variants.size(), 0.0); // largest margin over 3x the tolerance
    const int y = kSize / 2 - 1;
    // At roughness 1 the height-correlated Smith term leaves the separable one far enough apart.
    for (float roughness : {0.5f, 1.0f}) {
        std::vector<scene::Material> materials;
        for (const BrdfVariant& v : variants) materials.push_back(metal(baseColor, roughness, v));
        const SphereRender r = renderSpheres(renderer, materials, settings);
        for (int i = 0; i < count; ++i) {
            const BrdfVariant& variant = variants[size_t(i)];
            double worst = 0.0;
            int tested = 0;
            for (int x = kSize / 2; x < kSize; x += 2) {
                glm::vec3 nf;
                if (!sphereNormal(x, y, nf)) continue;
                const glm::dvec3 n(nf);
                const double NoV = glm::dot(n, viewVector(i, count, n));
                if (NoV < 0.15) continue;
                ++tested;
                const glm::dvec3 expected = directionalAlbedo(cpuMetal(baseColor, roughness, variant), NoV) * double(L.x);
                // The glTF table's A and B, from the same quadrature with f0 = (1, 0, 0).
                const glm::dvec3 e = directionalAlbedo(cpuMetal({1.0f, 0.0f, 0.0f}, roughness, {}), NoV);
                const double a = e.x - e.y, b = e.y;
                const glm::dvec3 gltfTable = (variant.fresnel == Fresnel::None ? glm::dvec3(baseColor) * (a + b)
                                                                                  : glm::dvec3(baseColor) * a + b) *
                                             double(L.x);
                const glm::dvec3 got(pixel(r.image, i * kSize + x, y));
                for (int c = 0; c < 3; ++c) {
                    worst = std::max(worst, std::abs(got[c] - expected[c]));
                    EXPECT_NEAR(got[c], expected[c], tolerance(expected[c]))
                        << variantName(variant) << " roughness " << roughness << " n.v " << NoV << " channel " << c;
                    separation[size_t(i)] = std::max(separation[size_t(i)], std::abs(gltfTable[c] - expected[c]) / (3.0 * tolerance(expected[c])));
                }
            }
            EXPECT_GE(tested, 12);
            std::printf("furnace, %s, roughness %.1f: worst |GPU - CPU| %.4f L (%d pixels)\n", variantName(variant).c_str(), roughness,
                        worst / double(L.x), tested);
        }
    }
    for (size_t i = 0; i < variants.size(); ++i)
        EXPECT_GT(separation[i], 1.0) << variantName(variants[i]) << " is too close to the glTF BRDF for this test to tell their tables apart";
}

TEST_F(GlTest, EnergyCompensationKeepsEveryVariantsWhiteMetalInTheFurnace)
{
    // With the multiple-scattering compensation, a white metal reflects the whole uniform
    // environment whatever its D, G and F: E(1) and the compensation come from the same table.
    // Every (D, G) with Schlick's F, and the other two Fresnel terms, each a sphere of one
    // frame. Bound 2% over every pixel with n.v > 0.1, as WhiteFurnace's; measured 0.23%.
    // This catches a missing or non-finite table, not a wrong one (any table cancels here):
    // FurnaceMatchesEachBrdfVariantsAlbedo does that.
    std::vector<BrdfVariant> variants;
    for (Distribution d : {Distribution::GGX, Distribution::Beckmann, Distribution::BlinnPhong})
        for (int g = 0; g < 7; ++g) variants.push_back({d, Geometry(g), Fresnel::Schlick});
    variants.push_back({Distribution::Beckmann, Geometry::Neumann, Fresnel::None});
    variants.push_back({Distribution::BlinnPhong, Geometry::Kelemen, Fresnel::SchlickSG});
    const int count = int(variants.size());
    render::Renderer renderer;
    const glm::vec3 L(0.6f);
    renderer.setEnvironment(render::constantEnvironment(L));
    render::FrameSettings settings;
    settings.environment.skybox = false;
    for (float roughness : {0.5f, 1.0f}) {
        std::vector<scene::Material> materials;
        for (const BrdfVariant& v : variants) materials.push_back(metal(glm::vec3(1.0f), roughness, v));
        const SphereRender r = renderSpheres(renderer, materials, settings);
        double worstOfAll = 0.0;
        for (int i = 0; i < count; ++i) {
            double worst = 0.0;
            int tested = 0;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    glm::vec3 n;
                    if (!sphereNormal(x, y, n) || n.z < 0.1f) continue;
                    ++tested;
                    const double c = pixel(r.image, i * kSize + x, y).x;
                    worst = std::max(worst, std::abs(c - L.x) / L.x);
                }
            EXPECT_GT(tested, 2000);
            EXPECT_LT(worst, 0.02) << variantName(variants[size_t(i)]) << " roughness " << roughness;
            worstOfAll = std::max(worstOfAll, worst);
        }
        std::printf("compensated white metal, %d variants, roughness %.1f: worst deviation %.2f%%\n", count, roughness,
                    100.0 * worstOfAll);
    }
}

TEST_F(GlTest, EnvironmentBlockUploadsOnlyWhatChanged)
{
    // The environment's uniform block (SH, rotation, inverse view-projection, parameters) is
    // written field by field, and only where a field changed: a still frame uploads nothing,
    // a moved camera one matrix, a new environment its SH and bright sources. The image follows
    // each change.
    scene::Scene s;
    scene::Material m;
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.5f;
    scene::addShape(s, scene::makeUvSphere(1.0f, 32, 16), m, glm::mat4(1.0f), "sphere");
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.setEnvironment(render::constantEnvironment(glm::vec3(0.5f)));
    render::FrameSettings settings = test::radianceFrame(32, 32);
    const render::View near = render::lookAtView({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, glm::radians(40.0f), 1.0f, 0.1f, 20.0f);
    const render::View far = render::lookAtView({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, glm::radians(40.0f), 1.0f, 0.1f, 20.0f);
    using shared::EnvironmentData;
    auto frame = [&](const render::View& view) {
        renderer.render(view, settings);
        return renderer.stats().environmentBytesUploaded;
    };
    auto centre = [&] { return renderer.readRadiance().pixels[(16 * 32 + 16) * 4]; };

    EXPECT_EQ(frame(near), sizeof(EnvironmentData)); // every field differs from the zeroed block
    const float first = centre();
    EXPECT_EQ(frame(near), 0u);
    EXPECT_EQ(frame(far), sizeof(glm::mat4)); // inverseViewProjection
    settings.environment.rotationDegrees = 30.0f;
    EXPECT_EQ(frame(far), sizeof(glm::mat4)); // worldToEnvironment
    settings.environment.intensity = 2.0f;
    EXPECT_EQ(frame(far), sizeof(glm::vec4)); // params
    EXPECT_NEAR(centre(), 2.0f * first, 0.01f * first);
    renderer.setEnvironment(render::constantEnvironment(glm::vec3(0.25f)));
    // The SH (the brightest parts are constants of the programs, made again).
    EXPECT_EQ(frame(far), sizeof(EnvironmentData::sh));
    EXPECT_NEAR(centre(), first, 0.01f * first);
}

// The environment's bright sources are constants of the forward programs (ibl/ibl.glsl,
// IBL_SOURCE_*): a new environment must make the programs again. Two black maps, each with one
// bright patch (11 × 11 texels, 7.7°) in its own direction, one after the other in the same
// renderer: a Lambertian sphere (specularFactor 0) reflects albedo/π · E(n), E summed on the
// CPU over the patch's texels (radiance × solid angle × n·d). Bound 3 % where n·d > 0.3 (no
// patch texel below the horizon there), away from the rim; measured within 0.4 %. Stale
// constants light the second sphere from the first patch's direction.
TEST_F(GlTest, DiffuseLightFollowsEachNewEnvironmentsBrightSources)
{
    constexpr int W = 512, H = 256;
    constexpr float kRadiance = 50.0f, kAlbedo = 0.8f;
    render::Renderer renderer;
    scene::Material lambert;
    lambert.specularFactor = 0.0f;
    lambert.baseColorFactor = glm::vec4(glm::vec3(kAlbedo), 1.0f);
    lambert.metallicFactor = 0.0f;
    lambert.roughnessFactor = 1.0f;
    setSpheres(renderer, {lambert}); // once: the second environment finds the first's programs
    for (const glm::vec3 d : {glm::normalize(glm::vec3(0.5f, 0.4f, 0.6f)), glm::normalize(glm::vec3(-0.6f, -0.3f, 0.7f))}) {
        render::EnvironmentMap map;
        map.width = W;
        map.height = H;
        map.texels.assign(size_t(W * H), glm::vec3(0.0f));
        const glm::vec2 uv = render::directionToEquirect(d);
        const int cx = int(uv.x * W), cy = int(uv.y * H);
        std::vector<std::pair<glm::vec3, float>> patch; // texel direction, solid angle
        for (int y = cy - 5; y <= cy + 5; ++y)
            for (int x = cx - 5; x <= cx + 5; ++x) {
                map.texels[size_t(y * W + x)] = glm::vec3(kRadiance);
                const glm::vec3 t = render::equirectToDirection({(float(x) + 0.5f) / W, (float(y) + 0.5f) / H});
                patch.push_back({t, float(2.0 * M_PI / W * M_PI / H) * std::sqrt(std::max(0.0f, 1.0f - t.y * t.y))});
            }
        map.key = fmt::format("test-patch-{}-{}", cx, cy);
        renderer.setEnvironment(map);
        render::FrameSettings settings;
        settings.environment.skybox = false;
        // Twice, the second frame checked: a renderer's first frame draws without the light
        // clusters (another program), so the second environment's frames find the programs
        // the first one's second frame made.
        renderSphereTiles(renderer, 1, settings);
        const SphereRender r = renderSphereTiles(renderer, 1, settings);
        int tested = 0;
        double worst = 0.0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                glm::vec3 n;
                // Not at the rim, where the tessellated sphere's normals leave the exact ones.
                if (!sphereNormal(x, y, n) || n.z < 0.2f || glm::dot(n, d) < 0.3f) continue;
                double e = 0.0;
                for (const auto& [t, omega] : patch) e += kRadiance * omega * std::max(0.0f, glm::dot(n, t));
                const double expected = kAlbedo / M_PI * e;
                const double got = pixel(r.image, x, y).g;
                worst = std::max(worst, std::abs(got - expected) / expected);
                ASSERT_NEAR(got, expected, 0.03 * expected) << "patch towards " << d.x << ", " << d.y << ", " << d.z << ": pixel " << x << ", " << y;
                ++tested;
            }
        EXPECT_GT(tested, 1000);
        std::printf("Lambert under a bright patch towards (%.2f, %.2f, %.2f): worst deviation %.2f%%\n", d.x, d.y, d.z, 100.0 * worst);
    }
}

// The irradiance bake on the GPU (ibl/irradiance.comp) against its CPU twin
// (shading/EnvironmentMap: irradianceCube of the same sources), every texel, under a map with
// a sun far beyond half-float range (park, peak 222,000 cd/m²: the sources stay 32-bit) and one
// without, with the bright sources the cube can hold folded into it. Tolerance: half-float rounding and float summation order, 0.3 % of the texel plus
// 1e-4 of the map's mean irradiance. (The CPU twin's own accuracy against brute-force
// integration: Environment.IrradianceMatchesBruteForceOnEveryHdr.) Fails when the bake reads
// the wrong face convention or drops sources.
TEST_F(GlTest, IrradianceBakeMatchesItsCpuTwin)
{
    for (const char* name : {"park_1k.hdr", "venice_1k.hdr"}) {
        SCOPED_TRACE(name);
        const render::EnvironmentMap map = render::loadEnvironmentMap(std::string(SPECULA_ASSETS_DIR) + "/env/" + name);
        gl::State state;
        render::ImageBasedLighting ibl;
        ibl.setEnvironment(state, map, render::BakeSettings{});
        // The bright sources the cube can hold folded into it, as the bake does (keeping those
        // the specular lobe takes): park's sun stays exact, venice's sources all fold.
        render::IrradianceSplit split = render::splitIrradiance(map);
        const size_t exact = render::foldSmoothSources(split, size_t(ibl.specularSourceCount()));
        const std::vector<glm::vec3> expected = render::irradianceCube(split.cube, render::kIrradianceSize);
        const std::vector<float> gpu = ibl.irradiance().readFloat(0, 4);
        ASSERT_EQ(gpu.size(), expected.size() * 4);
        double mean = 0.0;
        for (const glm::vec3& e : expected) mean += (e.x + e.y + e.z) / 3.0;
        mean /= double(expected.size());
        int wrong = 0;
        std::string first;
        for (size_t i = 0; i < expected.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                const double want = expected[i][c], got = gpu[i * 4 + size_t(c)];
                if (std::abs(got - want) > 0.003 * std::abs(want) + 1e-4 * mean && ++wrong == 1)
                    first = "texel " + std::to_string(i) + ": " + std::to_string(got) + " vs " + std::to_string(want);
            }
        EXPECT_EQ(wrong, 0) << first;
        EXPECT_EQ(ibl.brightSources().size(), exact);
        if (std::string(name) == "park_1k.hdr") {
            EXPECT_GE(exact, 10u);
        } else {
            EXPECT_EQ(exact, 0u);
        }
    }
}

// A mirror under image-based light: a white metal sphere of roughness 0 (F = 1, energy
// compensation making the split sum's albedo exactly 1) reflects the map itself. Expected at
// each pixel centre: the map's radiance in the reflected direction, read bilinearly from the
// full-resolution equirectangular map on the CPU (the mirror's integral is that one sample).
// Bound: mean relative error (RGB length) over pixels with n·v ≥ 0.5 below 2 %, on venice_1k
// and studio_1k. Measured: 1.56 % and 1.91 % with 512² faces (the default for a 1k map); with
// 256² faces (the map's own texel density) 3.71 % and 4.43 %, which fail: resampled twice,
// the reflection blurs.
TEST_F(GlTest, MirrorReflectsTheMapAtItsOwnResolution)
{
    for (const char* name : {"venice_1k.hdr", "studio_1k.hdr"}) {
        SCOPED_TRACE(name);
        const render::EnvironmentMap map = render::loadEnvironmentMap(std::string(SPECULA_ASSETS_DIR) + "/env/" + name);
        render::Renderer renderer;
        renderer.setEnvironment(map);
        const SphereRender r = renderSphere(renderer, 1.0f, 0.0f, glm::vec3(1.0f));
        double sum = 0.0;
        int count = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                glm::vec3 n;
                if (!sphereNormal(x, y, n) || n.z < 0.5f) continue;
                const glm::dvec3 v = viewVector(0, 1, glm::dvec3(n));
                const glm::dvec3 reflected = 2.0 * glm::dot(glm::dvec3(n), v) * glm::dvec3(n) - v;
                const glm::dvec3 expected(map.sample(glm::vec3(reflected)));
                const glm::dvec3 got(pixel(r.image, x, y));
                sum += glm::length(got - expected) / std::max(glm::length(expected), 1e-6);
                ++count;
            }
        const double mean = sum / count;
        std::printf("mirror sphere vs the map, %s: mean relative error %.2f%% over %d pixels\n", name, 100.0 * mean, count);
        EXPECT_LT(mean, 0.02);
    }
}

// Each prefiltered level against a converged convolution of the same level (issue 14: no
// sample pattern may show). The reference is the same GGX-weighted integral at 8192 samples per
// texel, on every texel of a sparse grid (32² a face), the baked level read at the same texels.
// Relative error per texel and channel, against the texel plus 2 % of the level's mean (dark
// texels next to bright sources would otherwise weigh the most). `SPECULA_PREFILTER_SAMPLES=N`
// bakes with N samples at every level, for measuring (docs/ibl.md has the table).
// Measured with the default 256 samples: sunset_1k (soft) mean 0.5–1.6 %, p99 3–7.6 % per
// level; studio_1k (small softboxes 2,000× the mean) mean 10.7–18 %, p99 69–139 %, and still
// 4.3–6.6 % with 1,024 samples: filtered importance sampling of the GGX lobe alone does not
// converge under compact bright sources (issue 14's target, 1 %, is not met there). Bounds: the
// measured figures with a margin, so that a broken filter (the wrong source mip, roughness or
// weights) fails: sunset mean < 2.5 %, p99 < 10 %; studio mean < 22 %, p99 < 160 %.
TEST_F(GlTest, PrefilteredLevelsMatchAConvergedConvolution)
{
    struct Case {
        const char* name;
        double mean, p99;
    };
    for (const Case& test : {Case{"studio_1k.hdr", 0.22, 1.6}, Case{"sunset_1k.hdr", 0.025, 0.10}}) {
        const char* name = test.name;
        SCOPED_TRACE(name);
        const render::EnvironmentMap map = render::loadEnvironmentMap(std::string(SPECULA_ASSETS_DIR) + "/env/" + name);
        gl::State state;
        render::ImageBasedLighting ibl;
        render::BakeSettings settings;
        if (const char* n = std::getenv("SPECULA_PREFILTER_SAMPLES")) settings.prefilterSamples = std::atoi(n);
        ibl.setEnvironment(state, map, settings);
        const gl::Texture& cube = ibl.cube();
        const gl::Texture& baked = ibl.prefiltered();
        gl::Program reference({.compute = "ibl/prefilter.comp", .label = "converged prefilter"});
        state.useProgram(reference);
        state.bindTexture(0, cube);
        state.bindSampler(0, nullptr);
        reference.set(reference.uniformLocation("uSamples"), uint32_t(8192));
        reference.set(reference.uniformLocation("uSourceSize"), float(cube.width()));
        reference.set(reference.uniformLocation("uSourceLevels"), float(cube.levels()));
        for (int level = 1; level < baked.levels(); ++level) {
            const int size = baked.width(level);
            const int stride = std::max(1, size / 32), grid = size / stride;
            gl::TextureDesc desc;
            desc.type = gl::TextureType::Cube;
            desc.format = gl::Format::RGBA16F;
            desc.width = desc.height = grid;
            desc.label = "converged level";
            gl::Texture converged(desc);
            reference.set(reference.uniformLocation("uPerceptualRoughness"), float(level) / float(baked.levels() - 1));
            reference.set(reference.uniformLocation("uStride"), stride);
            reference.set(reference.uniformLocation("uLevelSize"), size);
            state.bindImage(0, converged, 0, gl::ImageAccess::WriteOnly, /*layered*/ true);
            state.dispatchCompute(uint32_t((grid + 7) / 8), uint32_t((grid + 7) / 8), 6);
            state.memoryBarrier(gl::Barrier::TextureUpdate);
            const std::vector<float> want = converged.readFloat(0, 4);
            const std::vector<float> got = baked.readFloat(level, 4);
            double mean = 0.0;
            for (size_t i = 0; i < want.size(); ++i)
                if (i % 4 != 3) mean += want[i];
            mean /= double(want.size()) * 0.75;
            std::vector<double> errors;
            for (int face = 0; face < 6; ++face)
                for (int y = 0; y < grid; ++y)
                    for (int x = 0; x < grid; ++x) {
                        const size_t r = (size_t(face) * grid * grid + size_t(y) * grid + size_t(x)) * 4;
                        const size_t b = (size_t(face) * size * size + size_t(y * stride + stride / 2) * size +
                                          size_t(x * stride + stride / 2)) * 4;
                        for (int c = 0; c < 3; ++c)
                            errors.push_back(std::abs(got[b + size_t(c)] - want[r + size_t(c)]) / (want[r + size_t(c)] + 0.02 * mean));
                    }
            double sum = 0.0;
            for (double e : errors) sum += e;
            std::sort(errors.begin(), errors.end());
            const double meanError = sum / double(errors.size()), p99 = errors[errors.size() * 99 / 100];
            std::printf("%s prefiltered level %d (%d², roughness %.3f): mean %.3f%%, p99 %.3f%%, max %.3f%%\n", name, level, size,
                        double(level) / double(baked.levels() - 1), 100.0 * meanError, 100.0 * p99, 100.0 * errors.back());
            EXPECT_LT(meanError, test.mean) << "level " << level;
            EXPECT_LT(p99, test.p99) << "level " << level;
        }
    }
}

namespace {

// A smooth ramp of radiance, L(d) = exp(2 x + 1.5 y), that a cube's filter follows closely, and
// an equirect map of it, `width` × width / 2, each texel L at its centre's direction.
float rampRadiance(const glm::vec3& d)
{
    return std::exp(2.0f * d.x + 1.5f * d.y);
}

render::EnvironmentMap rampMap(int width, const std::string& key)
{
    render::EnvironmentMap map;
    map.width = width;
    map.height = width / 2;
    map.key = key;
    map.texels.resize(size_t(map.width) * size_t(map.height));
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            map.texels[size_t(y) * size_t(map.width) + size_t(x)] =
                glm::vec3(rampRadiance(render::equirectToDirection({(x + 0.5f) / float(map.width), (y + 0.5f) / float(map.height)})));
    return map;
}

} // namespace

TEST_F(GlTest, SkyboxShowsTheMapAcrossCubeFaceEdges)
{
    // The sharp sky against the radiance it stands for, in each pixel's direction, looking at
    // the edges and the corner where +X, +Y and +Z meet: seamless cube filtering
    // (gl::State enables it) carries the bilinear filter across face edges. The map: a smooth
    // ramp L(d) = exp(2 x + 1.5 y), which the cube's filter follows closely everywhere but where
    // filtering within a face would hold it flat. 1024 × 512 makes a 512² cube, 128 × 64 a 64²
    // one. Bound: the pixels within one texel of a face's edge no further from L than 1.5 × the
    // rest + 0.05 %. Measured 2026-12-06 (mean relative error): 512² edge 0.072 %, rest 0.071 %;
    // 64² edge 0.102 %, rest 0.089 %. With seamless filtering off for the sky on purpose, the 64²
    // cube's edge pixels are 0.221 % off and this test fails. (Filtering a 256² or larger cube
    // within each face could not be seen here, 0.076 % at 512², and was tried as a saving on
    // llvmpipe: it saved nothing measurable, docs/performance.md.)
    const auto ramp = [](const glm::vec3& d) { return glm::vec3(rampRadiance(d)); };
    for (int width : {1024, 128}) {
        render::Renderer renderer;
        renderer.setEnvironment(rampMap(width, "test-ramp-" + std::to_string(width)));
        renderer.setScene(scene::Scene{});
        const int size = 192;
        const render::View view =
            render::lookAtView(glm::vec3(0.0f), glm::vec3(1.0f, 0.8f, 1.0f), glm::vec3(0, 1, 0), glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
        render::FrameSettings settings = test::radianceFrame(size, size);
        renderer.render(view, settings);
        const ImageFloat image = renderer.readRadiance();
        const int face = width / 2; // the cube's face size (BakeSettings: half the map's width)
        const glm::mat4 inverse = glm::inverse(view.projection * view.view);
        double edgeSum = 0.0, restSum = 0.0;
        int edgeCount = 0, restCount = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const glm::vec4 ndc((x + 0.5f) / size * 2.0f - 1.0f, 1.0f - (y + 0.5f) / size * 2.0f, 1.0f, 1.0f);
                const glm::vec4 far = inverse * ndc;
                const glm::vec3 d = glm::normalize(glm::vec3(far) / far.w);
                const glm::vec3 a = glm::abs(d);
                const float major = std::max({a.x, a.y, a.z});
                // The larger of the two other coordinates on the face, 1 at its edge.
                const float minor = a.x == major ? std::max(a.y, a.z) : a.y == major ? std::max(a.x, a.z) : std::max(a.x, a.y);
                const float texelsFromEdge = (1.0f - minor / major) * 0.5f * float(face);
                const double expected = ramp(d).x;
                const double error = std::abs(double(pixel(image, x, y).x) - expected) / expected;
                if (texelsFromEdge < 1.0f) edgeSum += error, ++edgeCount;
                else restSum += error, ++restCount;
            }
        const double edge = edgeSum / edgeCount, rest = restSum / restCount;
        std::printf("sky vs the map, %d² cube: mean relative error %.3f%% within a texel of a face edge (%d pixels), %.3f%% "
                    "elsewhere\n",
                    face, 100.0 * edge, edgeCount, 100.0 * rest);
        EXPECT_GT(edgeCount, 50);
        EXPECT_LT(rest, 0.01);
        EXPECT_LT(edge, 1.5 * rest + 0.0005) << face << "² cube";
    }
}

// The sky and a mirror sphere follow the environment's rotation, turned and back in one
// renderer: an unturned map compiles the rotation out of the programs (ibl/ibl.glsl's
// IBL_UNROTATED), so turning it must make them again. The map: the smooth ramp above,
// L(d) = exp(2 x + 1.5 y), 128 × 64; expected: L(R(−θ) d) along each sky pixel's direction d
// (the world-to-map rotation ForwardPass uploads), mean relative error within 0.5 % (measured
// 0.08-0.10 %); with the programs kept unturned the sky is 101 % off at 40° and this fails. The
// mirror sphere's turned reflections: BrightPatchReflectsWhereTheConventionSays.
TEST_F(GlTest, SkyFollowsTheEnvironmentsRotationBothWays)
{
    render::Renderer renderer;
    renderer.setEnvironment(rampMap(128, "test-ramp-turned"));
    renderer.setScene(scene::Scene{});
    const int size = 64;
    const render::View view =
        render::lookAtView(glm::vec3(0.0f), glm::vec3(1.0f, 0.3f, 0.2f), glm::vec3(0, 1, 0), glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
    const glm::mat4 inverse = glm::inverse(view.projection * view.view);
    for (float degrees : {0.0f, 40.0f, 0.0f, -120.0f, 360.0f}) {
        render::FrameSettings settings = test::radianceFrame(size, size);
        settings.environment.rotationDegrees = degrees;
        renderer.render(view, settings);
        const ImageFloat image = renderer.readRadiance();
        const glm::mat3 worldToMap = render::environmentRotation(-degrees);
        double sum = 0.0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const glm::vec4 ndc((x + 0.5f) / size * 2.0f - 1.0f, 1.0f - (y + 0.5f) / size * 2.0f, 1.0f, 1.0f);
                const glm::vec4 far = inverse * ndc;
                const double expected = rampRadiance(worldToMap * glm::normalize(glm::vec3(far) / far.w));
                sum += std::abs(double(pixel(image, x, y).x) - expected) / expected;
            }
        const double error = sum / double(size * size);
        std::printf("sky turned %.0f°: mean relative error %.3f%%\n", double(degrees), 100.0 * error);
        EXPECT_LT(error, 0.005) << degrees << "°";
    }
}

// --env-sun extract takes the sun out of the map that lights the scene, but the sky still shows
// it. sky_1k's real sun, extracted; a 10° view centred on it (the sun and the bright haze
// around it, every texel extraction changed, fill the view). Expected: the radiance of the map
// as loaded, bilinear in each pixel's direction (EnvironmentMap::sample, half-float range),
// mean relative error (RGB summed) within 3 %: the cube's resampling of a steep sun. Measured
// 2026-12-07: extract and keep both 1.41 %, and their skies' cubes equal bit for bit (made from
// the same texels). With the sky drawn from the lighting's cube, as before, extract is 45 % off
// and this fails. Lighting still reads the map less its sun (cube() is not the sky's),
// and the sky's cube and chain survive the bake cache and come out of a progressive bake the same.
TEST_F(GlTest, SkyShowsTheExtractedSun)
{
    namespace fs = std::filesystem;
    const std::string file = std::string(SPECULA_ASSETS_DIR) + "/env/sky_1k.hdr";
    ASSERT_TRUE(fs::exists(file)) << "shared assets missing";
    const render::EnvironmentMap original = render::loadEnvironmentMap(file);
    render::EnvironmentMap extracted = original;
    const auto sun = render::extractSun(extracted);
    ASSERT_TRUE(sun.has_value());
    ASSERT_GT(extracted.skyOnly.size(), 100u);
    render::BakeSettings bake;
    bake.prefilterSamples = 16; // the sky reads the cube, not the prefiltered chain
    const int size = 64;
    const render::View view = render::lookAtView(glm::vec3(0.0f), sun->direction, std::abs(sun->direction.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0),
                                                 glm::radians(10.0f), 1.0f, 0.1f, 100.0f);
    const glm::mat4 inverse = glm::inverse(view.projection * view.view);
    render::FrameSettings settings = test::radianceFrame(size, size);
    const auto renderSky = [&](const render::EnvironmentMap& map) {
        render::Renderer renderer;
        renderer.setEnvironment(map, bake);
        renderer.setScene(scene::Scene{});
        renderer.render(view, settings);
        return renderer.readRadiance();
    };
    const auto error = [&](const ImageFloat& image) {
        double sum = 0.0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const glm::vec4 ndc((x + 0.5f) / size * 2.0f - 1.0f, 1.0f - (y + 0.5f) / size * 2.0f, 1.0f, 1.0f);
                const glm::vec4 far = inverse * ndc;
                const glm::vec3 expected = glm::min(original.sample(glm::normalize(glm::vec3(far) / far.w)), glm::vec3(65504.0f));
                const glm::vec3 got = glm::vec3(pixel(image, x, y));
                const float e = expected.x + expected.y + expected.z;
                sum += std::abs(double(got.x + got.y + got.z - e)) / double(e);
            }
        return sum / double(size * size);
    };
    const ImageFloat keep = renderSky(original), withoutSun = renderSky(extracted);
    const double keepError = error(keep), extractError = error(withoutSun);
    std::printf("sky at sky_1k's sun (%zu texels taken out): mean relative error %.2f%% with --env-sun keep, %.2f%% with extract\n",
                extracted.skyOnly.size(), 100.0 * keepError, 100.0 * extractError);
    EXPECT_LT(keepError, 0.03);
    EXPECT_LT(extractError, 0.03);
    // The blurred sky (a level of the prefiltered chain): the map as loaded, blurred, shows the
    // sun's glow; with extract it must show the same, within 0.5 % (the chains are made from
    // the same texels). Measured: identical. From the lighting's chain it is 95.7 % off.
    settings.environment.skyboxBlur = 0.3f;
    const ImageFloat keepBlurred = renderSky(original), extractBlurred = renderSky(extracted);
    double blurSum = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::vec3 a = pixel(keepBlurred, x, y), b = pixel(extractBlurred, x, y);
            blurSum += std::abs(double(b.x + b.y + b.z) - double(a.x + a.y + a.z)) / double(a.x + a.y + a.z);
        }
    const double blurDifference = blurSum / double(size * size);
    std::printf("blurred sky (0.3) at the sun: extract against keep, mean relative difference %.3f%%\n", 100.0 * blurDifference);
    EXPECT_LT(blurDifference, 0.005);
    settings.environment.skyboxBlur = 0.0f;

    // Lighting reads the map less its sun; the cache gives back both cubes.
    const fs::path cache = fs::temp_directory_path() / ("specula-sky-" + std::to_string(::getpid()));
    fs::remove_all(cache);
    gl::State state;
    render::ImageBasedLighting baked, reread;
    baked.setEnvironment(state, extracted, bake, cache);
    ASSERT_NE(&baked.sky(), &baked.cube());
    ASSERT_TRUE(reread.setEnvironment(state, extracted, bake, cache).fromCache);
    ASSERT_NE(&reread.sky(), &reread.cube());
    EXPECT_TRUE(reread.sky().readFloat(0) == baked.sky().readFloat(0));
    EXPECT_TRUE(reread.cube().readFloat(0) == baked.cube().readFloat(0));
    EXPECT_FALSE(baked.sky().readFloat(0) == baked.cube().readFloat(0));
    // The viewer's progressive bake ends with the same sky (the preview's is smaller).
    render::ImageBasedLighting progressive;
    ASSERT_TRUE(progressive.setEnvironment(state, extracted, bake, {}, render::BakeMode::Progressive).progressive);
    ASSERT_NE(&progressive.sky(), &progressive.cube());
    while (progressive.advanceBake(state, 1e9).pending) {
    }
    EXPECT_TRUE(progressive.sky().readFloat(0) == baked.sky().readFloat(0));
    EXPECT_TRUE(progressive.skyPrefiltered().readFloat(2) == baked.skyPrefiltered().readFloat(2));
    render::ImageBasedLighting plain;
    plain.setEnvironment(state, original, bake);
    EXPECT_EQ(&plain.sky(), &plain.cube()); // nothing taken out: one cube and chain
    EXPECT_EQ(&plain.skyPrefiltered(), &plain.prefiltered());
    EXPECT_TRUE(plain.cube().readFloat(0) == baked.sky().readFloat(0));
    EXPECT_TRUE(reread.skyPrefiltered().readFloat(2) == baked.skyPrefiltered().readFloat(2));
    fs::remove_all(cache);
}

// The viewer's progressive bake: a preview (a 256² cube, 32 samples) before the first frame,
// then the full bake a band of rows of a face at a time, one step per advanceBake with no
// budget. Expected, independently of the bake's quality (the tests above measure that): the
// full bake's texels bit for bit as the bake at once makes them (each texel is the same
// invocation's in both; the bands only split the dispatches), the residual chain of studio's
// softboxes included; progress that grows with every step; the cache file written only when the
// last step is done (by a thread: waited for). Fails if the shaders ignore uOffset (every band
// lands on the first rows).
TEST_F(GlTest, ProgressiveBakeEndsWithTheBakeAtOnce)
{
    namespace fs = std::filesystem;
    const render::EnvironmentMap map = render::loadEnvironmentMap(std::string(SPECULA_ASSETS_DIR) + "/env/studio_1k.hdr");
    render::BakeSettings settings;
    settings.prefilterSamples = 64; // the test's time; the steps are sized by their reads
    const fs::path cache = fs::temp_directory_path() / ("specula-progressive-" + std::to_string(::getpid()));
    fs::remove_all(cache);
    const auto cached = [&] {
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(cache, ec))
            if (entry.path().filename().string().rfind("env-", 0) == 0) return true;
        return false;
    };
    gl::State state;
    render::ImageBasedLighting now;
    now.setEnvironment(state, map, settings);
    ASSERT_GT(now.cube().width(), render::kPreviewCubeSize);
    ASSERT_GT(now.specularSourceCount(), 0); // the residual chain is baked too

    render::ImageBasedLighting progressive;
    const render::BakeReport report = progressive.setEnvironment(state, map, settings, cache, render::BakeMode::Progressive);
    ASSERT_TRUE(report.progressive);
    ASSERT_TRUE(progressive.hasEnvironment());
    EXPECT_EQ(progressive.cube().width(), render::kPreviewCubeSize);
    EXPECT_FALSE(cached()); // a preview is never cached
    int steps = 0;
    double last = 0.0;
    render::BakeProgress progress;
    do {
        progress = progressive.advanceBake(state, 0.0);
        ++steps;
        EXPECT_GT(progress.fraction, last);
        last = progress.fraction;
        if (progress.pending) {
            ASSERT_FALSE(cached()) << "step " << steps;
        }
    } while (progress.pending && steps < 100000);
    EXPECT_TRUE(progress.finished);
    EXPECT_DOUBLE_EQ(progress.fraction, 1.0);
    EXPECT_GT(steps, 20);
    progressive.waitForCacheWrite();
    EXPECT_TRUE(cached());
    EXPECT_FALSE(progressive.advanceBake(state, 0.0).pending);

    EXPECT_EQ(progressive.specularSourceCount(), now.specularSourceCount());
    const auto same = [](const gl::Texture& a, const gl::Texture& b, const char* what) {
        SCOPED_TRACE(what);
        ASSERT_EQ(a.width(), b.width());
        ASSERT_EQ(a.levels(), b.levels());
        for (int level = 0; level < a.levels(); ++level) {
            const std::vector<float> x = a.readFloat(level), y = b.readFloat(level);
            size_t differ = 0, first = x.size();
            for (size_t i = 0; i < x.size(); ++i)
                if (x[i] != y[i] && differ++ == 0) first = i;
            EXPECT_EQ(differ, 0u) << "level " << level << ", first at float " << first << " of " << x.size();
        }
    };
    same(progressive.cube(), now.cube(), "cube");
    same(progressive.prefiltered(), now.prefiltered(), "prefiltered");
    same(progressive.residualCube(), now.residualCube(), "residual cube");
    same(progressive.residualPrefiltered(), now.residualPrefiltered(), "residual prefiltered");
    same(progressive.irradiance(), now.irradiance(), "irradiance");

    // The cache holds the full bake.
    render::ImageBasedLighting reread;
    EXPECT_TRUE(reread.setEnvironment(state, map, settings, cache, render::BakeMode::Progressive).fromCache);
    same(reread.prefiltered(), now.prefiltered(), "prefiltered from the cache");
    fs::remove_all(cache);
}

// The bake's cube mips (ibl/downsample.comp, in place of glGenerateMipmap): each texel of level
// L is the mean of the 2 × 2 texels of level L − 1 under it, on every face and level of
// venice_1k's 512² cube. Expected: that mean computed on the CPU from the level above as read
// back, within half-float rounding (relative 1e-3). Fails with the mips left empty or taken
// from the wrong texels.
TEST_F(GlTest, BakedCubeMipsAreBoxMeansOfTheLevelAbove)
{
    const render::EnvironmentMap map = render::loadEnvironmentMap(std::string(SPECULA_ASSETS_DIR) + "/env/venice_1k.hdr");
    render::BakeSettings settings;
    settings.prefilterSamples = 16; // the chain is not what this test reads
    gl::State state;
    render::ImageBasedLighting ibl;
    ibl.setEnvironment(state, map, settings);
    const gl::Texture& cube = ibl.cube();
    ASSERT_EQ(cube.width(), 512);
    ASSERT_EQ(cube.levels(), 10);
    std::vector<float> above = cube.readFloat(0);
    for (int level = 1; level < cube.levels(); ++level) {
        SCOPED_TRACE("level " + std::to_string(level));
        const std::vector<float> got = cube.readFloat(level);
        const size_t size = size_t(cube.width(level)), from = size * 2;
        ASSERT_EQ(got.size(), 6 * size * size * 4);
        size_t wrong = 0;
        double largest = 0.0;
        std::string first;
        for (size_t face = 0; face < 6; ++face)
            for (size_t y = 0; y < size; ++y)
                for (size_t x = 0; x < size; ++x)
                    for (size_t c = 0; c < 3; ++c) {
                        const auto at = [&](size_t n, size_t fx, size_t fy) { return ((face * n + fy) * n + fx) * 4 + c; };
                        const double want = 0.25 * (double(above[at(from, 2 * x, 2 * y)]) + above[at(from, 2 * x + 1, 2 * y)] +
                                                    above[at(from, 2 * x, 2 * y + 1)] + above[at(from, 2 * x + 1, 2 * y + 1)]);
                        const double value = got[at(size, x, y)];
                        largest = std::max(largest, want);
                        if (std::abs(value - want) > 1e-3 * std::abs(want) + 1e-6 && wrong++ == 0)
                            first = "face " + std::to_string(face) + " (" + std::to_string(x) + ", " + std::to_string(y) + "): " +
                                    std::to_string(value) + " vs " + std::to_string(want);
                    }
        EXPECT_EQ(wrong, 0u) << first;
        EXPECT_GT(largest, 0.0);
        above = got;
    }
}
