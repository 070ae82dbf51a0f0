// KHR_materials_diffuse_transmission on the GPU against the extension's BSDF, ported here from
// its text (not from the shader): the dielectric's base is mix(diffuse_brdf(baseColor),
// diffuse_btdf(colour), fraction) under Appendix B's Fresnel mix, so a light in front gives
// ((1 - F)(1 - fraction) c_diff / pi + F D V) n.l and a light behind (1 - F) fraction colour
// (1 - metallic) / pi |n.l| — F Schlick's at v.h of the light mirrored through the surface (the
// weight the diffuse lobe has for a light there; docs/materials.md) — with fraction =
// diffuseTransmissionFactor x diffuseTransmissionTexture's A and colour =
// diffuseTransmissionColorFactor x diffuseTransmissionColorTexture's RGB (sRGB); under
// image-based light the BTDF sees the irradiance from -n.
#include "GlTestContext.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"
#include "GltfBrdfTerms.h"

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

// tests/assets/gltf/diffuse_transmission_quad.gltf (make_diffuse_transmission.py).
const dvec3 kBaseColor(0.3, 0.6, 0.2);
constexpr double kMetallic = 0.2, kRoughness = 0.5;
// Per texel (0: the quad's left half, 1: its right): the fraction and the colour.
const double kFraction[2] = {0.8 * 96.0 / 255.0, 0.8};
const dvec3 kColorFactor(1.0, 0.9, 0.7);
dvec3 texelColour(int texel)
{
    return texel == 0 ? kColorFactor * dvec3(srgbToLinear(1.0), srgbToLinear(64 / 255.0), srgbToLinear(32 / 255.0))
                      : kColorFactor * dvec3(srgbToLinear(128 / 255.0), srgbToLinear(1.0), srgbToLinear(96 / 255.0));
}

/// Radiance towards v per unit illuminance from l (the extension's BSDF, Appendix B's mix).
dvec3 leafRadiance(double fraction, const dvec3& colour, const dvec3& n, const dvec3& v, const dvec3& l)
{
    const dvec3 f0 = glm::mix(dvec3(0.04), kBaseColor, kMetallic);
    const double NoL = glm::dot(n, l), NoV = std::max(glm::dot(n, v), 1e-4);
    if (NoL >= 0.0) {
        const dvec3 h = glm::normalize(v + l);
        const dvec3 F = schlick(f0, 1.0, glm::dot(v, h));
        const double alpha = kRoughness * kRoughness;
        const dvec3 diffuse = (1.0 - F) * (1.0 - fraction) * kBaseColor * (1.0 - kMetallic) / kPi;
        return (diffuse + F * D_GGX(std::clamp(glm::dot(n, h), 0.0, 1.0), alpha) * V_GGX(NoL, NoV, alpha)) * NoL;
    }
    const dvec3 mirrored = l - 2.0 * NoL * n;
    const dvec3 F = schlick(f0, 1.0, glm::dot(v, glm::normalize(v + mirrored)));
    return (1.0 - F) * fraction * colour * (1.0 - kMetallic) / kPi * -NoL;
}

// The tolerance of tests/gl/test_shading.cpp: 1.5% relative plus 2e-3 cd/m² absolute.
constexpr double kRelative = 0.015;
constexpr double kAbsolute = 2e-3;
constexpr int kSize = 128;

render::FrameSettings exactSettings()
{
    render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
    settings.environment.skybox = false;
    return settings;
}

scene::Scene loadLeaf()
{
    return scene::loadGltf(std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/diffuse_transmission_quad.gltf");
}

/// The quad's point seen through pixel (x, y), if it is inside the quad away from its edges and
/// the seam between the texels.
bool quadPoint(const glm::dmat4& inverse, int x, int y, dvec3& p)
{
    const test::Ray ray = pixelRay(inverse, x, y, kSize, kSize);
    p = ray.origin + ray.direction * (-ray.origin.z / ray.direction.z);
    return std::abs(p.x) < 0.97 && std::abs(p.y) < 0.97 && std::abs(p.x) > 0.03;
}

} // namespace

// A directional light behind the leaf, one in front of it, and the leaf seen from behind (the
// double-sided back face: its normal turned to the viewer) with the light on the side the camera
// left. Shadows are on (the default): the leaf lit from behind must not shadow itself.
// Broken on purpose (2026-12-07), channels failing of 28,422 a case: no light through the
// surface (the lobe removed) 23,685 lit and 23,747 seen from behind; the front's diffuse not
// scaled by 1 - fraction 28,422 lit from the front; the textures not read 23,685, 14,211 and
// 23,443; the colour through texCoord 0 with its transform (textures 16 on reading their uv sets
// from flags.y), or through texCoord 1 without it, 28,422 and 28,314 from behind.
TEST_F(GlTest, DiffuseTransmissionFromGltf)
{
    scene::Scene s = loadLeaf();
    ASSERT_EQ(s.materials.size(), 1u);
    ASSERT_FLOAT_EQ(s.materials[0].diffuseTransmissionFactor, 0.8f);
    render::Renderer renderer;
    renderer.setScene(s);
    const render::FrameSettings settings = exactSettings();

    struct Case {
        const char* name;
        glm::vec3 eye;
        glm::vec3 travel; // where the light's rays go
    };
    const Case cases[] = {{"lit from behind", {0.0f, -0.3f, 3.0f}, glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f))},
                          {"lit from the front", {0.0f, -0.3f, 3.0f}, glm::normalize(glm::vec3(-0.2f, 0.4f, -1.0f))},
                          {"seen from behind", {0.2f, 0.3f, -3.0f}, glm::normalize(glm::vec3(-0.4f, 0.1f, -1.0f))}};
    const glm::vec3 colour(1.0f, 0.95f, 0.9f);
    constexpr float kLux = 3.0f;
    for (const Case& c : cases) {
        scene::Light sun;
        sun.type = scene::Light::Type::Directional;
        sun.intensity = kLux;
        sun.color = colour;
        renderer.setLights({render::PlacedLight{sun, glm::vec3(0.0f), c.travel}});
        const render::View view = render::lookAtView(c.eye, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 20.0f);
        renderer.render(view, settings);
        const ImageFloat image = renderer.readRadiance();
        const glm::dmat4 inverse = test::inverseViewProjection(view);
        const dvec3 l = -dvec3(c.travel);
        const dvec3 E = dvec3(colour) * double(kLux);
        int tested = 0, failures = 0;
        double worst = 0.0, textureMatters = 0.0, withoutExtension = 0.0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                dvec3 p;
                if (!quadPoint(inverse, x, y, p)) continue;
                const dvec3 v = glm::normalize(dvec3(c.eye) - p);
                const dvec3 n(0.0, 0.0, glm::dot(v, dvec3(0, 0, 1)) > 0.0 ? 1.0 : -1.0); // double-sided
                const int texel = p.x < 0.0 ? 0 : 1;
                const dvec3 expected = leafRadiance(kFraction[texel], texelColour(texel), n, v, l) * E;
                const dvec3 swapped = leafRadiance(kFraction[1 - texel], texelColour(1 - texel), n, v, l) * E;
                const dvec3 plain = leafRadiance(0.0, dvec3(0.0), n, v, l) * E;
                ++tested;
                for (int ch = 0; ch < 3; ++ch) {
                    const double got = image.pixels[(size_t(y) * kSize + x) * 4 + ch];
                    const double error = std::abs(got - expected[ch]);
                    const double tolerance = kRelative * expected[ch] + kAbsolute;
                    if (error > tolerance && failures++ < 5)
                        ADD_FAILURE() << c.name << ": pixel (" << x << ", " << y << ") channel " << ch << ": GPU " << got << " CPU "
                                      << expected[ch];
                    textureMatters = std::max(textureMatters, std::abs(swapped[ch] - expected[ch]) / tolerance);
                    withoutExtension = std::max(withoutExtension, std::abs(plain[ch] - expected[ch]) / tolerance);
                    if (expected[ch] > 0.02) worst = std::max(worst, error / expected[ch]);
                }
            }
        EXPECT_EQ(failures, 0) << c.name;
        EXPECT_GT(tested, 5000) << c.name;
        // The other half's texels, or the surface without the extension, would be far outside.
        EXPECT_GT(textureMatters, 3.0) << c.name;
        EXPECT_GT(withoutExtension, 3.0) << c.name;
        std::printf("diffuse transmission quad, %s: %d pixels, worst relative error %.3f%%, the texel swap %.1f tolerances, "
                    "no extension %.1f\n",
                    c.name, tested, 100.0 * worst, textureMatters, withoutExtension);
    }
}

// The light from behind is shadowed as any other: an opaque box between the back light and the
// leaf leaves its shadow on the light let through, against an exact ray test from each point of
// the leaf towards the light (a band around the shadow's edge, the filter's width, is not
// compared). Broken on purpose (2026-12-07): the shadow lookup offset along n instead of -n (away
// from the light behind) shadowed the leaf by itself: 20,826 channels failed (and 23,685 and
// 23,747 in DiffuseTransmissionFromGltf, whose shadows are on too).
TEST_F(GlTest, DiffuseTransmissionIsShadowedFromBehind)
{
    scene::Scene s = loadLeaf();
    scene::Material card;
    card.name = "card";
    card.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    const glm::vec3 boxCentre(-0.35f, -0.2f, -0.9f);
    constexpr float kHalf = 0.3f;
    scene::addShape(s, scene::makeCube(kHalf), card, glm::translate(glm::mat4(1.0f), boxCentre), "occluder");
    render::Renderer renderer;
    renderer.setScene(s);
    const glm::vec3 travel = glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f));
    scene::Light sun;
    sun.type = scene::Light::Type::Directional;
    sun.intensity = 3.0f;
    renderer.setLights({render::PlacedLight{sun, glm::vec3(0.0f), travel}});
    const glm::vec3 eye(0.0f, -0.3f, 3.0f);
    const render::View view = render::lookAtView(eye, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 20.0f);
    renderer.render(view, exactSettings());
    const ImageFloat image = renderer.readRadiance();

    const dvec3 l = -dvec3(travel);
    auto shadowed = [&](const dvec3& p) { // the slab test of the ray p + t l against the box
        double t0 = 0.0, t1 = 1e300;
        for (int a = 0; a < 3; ++a) {
            const double lo = (double(boxCentre[a]) - kHalf - p[a]) / l[a], hi = (double(boxCentre[a]) + kHalf - p[a]) / l[a];
            t0 = std::max(t0, std::min(lo, hi));
            t1 = std::min(t1, std::max(lo, hi));
        }
        return t0 <= t1;
    };
    const glm::dmat4 inverse = test::inverseViewProjection(view);
    int lit = 0, umbra = 0, failures = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            dvec3 p;
            if (!quadPoint(inverse, x, y, p)) continue;
            // Away from the shadow's edge: the points 0.08 m around agree.
            const bool inside = shadowed(p);
            bool edge = false;
            for (const dvec3 d : {dvec3(0.08, 0, 0), dvec3(-0.08, 0, 0), dvec3(0, 0.08, 0), dvec3(0, -0.08, 0)})
                edge = edge || shadowed(p + d) != inside;
            if (edge) continue;
            const dvec3 v = glm::normalize(dvec3(eye) - p);
            const int texel = p.x < 0.0 ? 0 : 1;
            const dvec3 unshadowed = leafRadiance(kFraction[texel], texelColour(texel), dvec3(0, 0, 1), v, l) * 3.0;
            for (int ch = 0; ch < 3; ++ch) {
                const double got = image.pixels[(size_t(y) * kSize + x) * 4 + ch];
                const bool wrong = inside ? got > 0.02 * unshadowed[ch] + kAbsolute
                                          : std::abs(got - unshadowed[ch]) > kRelative * unshadowed[ch] + kAbsolute;
                if (wrong && failures++ < 5)
                    ADD_FAILURE() << (inside ? "umbra" : "lit") << " pixel (" << x << ", " << y << ") channel " << ch << ": GPU "
                                  << got << ", unshadowed " << unshadowed[ch];
            }
            ++(inside ? umbra : lit);
        }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(umbra, 500);
    EXPECT_GT(lit, 3000);
    std::printf("diffuse transmission shadowed from behind: %d umbra and %d lit pixels compared\n", umbra, lit);
}

// Under image-based light the BTDF sees the irradiance of the hemisphere behind. An environment
// of radiance A over z > 0 and B over z < 0 gives irradiance pi A about +z and pi B about -z;
// with no specular lobe (metallic 0, KHR_materials_specular's factor 0: F = 0) the leaf seen from
// the front is (1 - fraction) baseColor A + fraction colour B, and from behind the same with A and
// B swapped. Tolerance 2% + 2e-3 (the irradiance cube's convolution, 1% by docs/ibl.md).
// Broken on purpose (2026-12-07): the BTDF's irradiance read about +n failed at 23,848 of the
// 28,524 channels on each side; the front's diffuse not scaled by 1 - fraction at all of them.
TEST_F(GlTest, DiffuseTransmissionUnderImageBasedLight)
{
    scene::Scene s = loadLeaf();
    s.materials[0].metallicFactor = 0.0f;
    s.materials[0].specularFactor = 0.0f; // F0 = F90 = 0: no specular lobe, the diffuse weight 1
    const glm::vec3 A(0.5f, 0.4f, 0.3f), B(2.0f, 1.5f, 1.0f);
    render::EnvironmentMap map;
    map.width = 256;
    map.height = 128;
    map.key = "test-two-hemispheres";
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const glm::vec3 d = render::equirectToDirection({(x + 0.5f) / map.width, (y + 0.5f) / map.height});
            map.texels.push_back(d.z > 0.0f ? A : B);
        }
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.setEnvironment(map);
    renderer.setLights({});
    for (const bool front : {true, false}) {
        const glm::vec3 eye(0.1f, -0.2f, front ? 3.0f : -3.0f);
        const render::View view = render::lookAtView(eye, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 20.0f);
        renderer.render(view, exactSettings());
        const ImageFloat image = renderer.readRadiance();
        const glm::dmat4 inverse = test::inverseViewProjection(view);
        const dvec3 facing = front ? dvec3(A) : dvec3(B), behind = front ? dvec3(B) : dvec3(A);
        int tested = 0, failures = 0;
        double worst = 0.0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                dvec3 p;
                if (!quadPoint(inverse, x, y, p)) continue;
                const int texel = p.x < 0.0 ? 0 : 1;
                const dvec3 expected = (1.0 - kFraction[texel]) * kBaseColor * facing + kFraction[texel] * texelColour(texel) * behind;
                ++tested;
                for (int ch = 0; ch < 3; ++ch) {
                    const double got = image.pixels[(size_t(y) * kSize + x) * 4 + ch];
                    const double error = std::abs(got - expected[ch]);
                    if (error > 0.02 * expected[ch] + kAbsolute && failures++ < 5)
                        ADD_FAILURE() << (front ? "front" : "back") << " pixel (" << x << ", " << y << ") channel " << ch << ": GPU "
                                      << got << " expected " << expected[ch];
                    worst = std::max(worst, error / expected[ch]);
                }
            }
        EXPECT_EQ(failures, 0);
        EXPECT_GT(tested, 5000);
        std::printf("diffuse transmission under two hemispheres, seen from the %s: %d pixels, worst relative error %.3f%%\n",
                    front ? "front" : "back", tested, 100.0 * worst);
    }
}
