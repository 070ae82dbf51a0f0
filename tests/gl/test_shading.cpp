// GPU against CPU: a sphere lit by one light, read back as floats, each pixel compared with
// shading/Brdf.h evaluated at that pixel's analytic ray-sphere hit.
#include "GlTestContext.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"

#include <algorithm>
#include <optional>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/Brdf.h"
#include "render/LightBuffer.h"
#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;
using glm::dvec3;
using specula::test::hitUnitSphere;
using specula::test::pixelRay;

namespace {

struct Case {
    const char* name;
    scene::Light light;
    glm::vec3 lightPosition;
    glm::vec3 lightTarget;
    glm::vec3 baseColor;
    float metallic;
    float roughness;
    render::BrdfGeometry geometry = render::BrdfGeometry::SmithGGX;
    scene::MaterialShading shading{}; ///< the material's model and BRDF terms (scene file)
    std::optional<float> ior{};
    /// More lights in the same frame, each with its position and target; the CPU sums them all.
    struct Placed {
        scene::Light light;
        glm::vec3 position, target;
    };
    std::vector<Placed> more{};
    /// LightCulling::None: every light everywhere, LIGHTS_ALL with their count a constant
    /// (LIGHT_COUNT); the first frame is otherwise clustered, its count read from the buffer.
    render::LightCulling culling = render::LightCulling::Clustered;
};

struct Result {
    int tested = 0;
    int lit = 0;
    double maxRelativeError = 0.0;
};

// Tolerance: 1.5% relative plus 2e-3 cd/m² absolute. The GPU stores half floats (0.05%),
// evaluates in single precision, and shades a 256x128-facet sphere whose interpolated normals
// differ from the analytic ones by < 1e-4 rad; 1.5% leaves room for that, not for a wrong term.
constexpr double kRelative = 0.015;
constexpr double kAbsolute = 2e-3;

scene::Scene caseScene(const Case& c)
{
    scene::Scene s;
    scene::Material material;
    material.baseColorFactor = glm::vec4(c.baseColor, 1.0f);
    material.metallicFactor = c.metallic;
    material.roughnessFactor = c.roughness;
    material.shading = c.shading;
    material.ior = c.ior;
    scene::addShape(s, scene::makeUvSphere(1.0f, 256, 128), material, glm::mat4(1.0f), "sphere");
    std::vector<Case::Placed> lights{{c.light, c.lightPosition, c.lightTarget}};
    lights.insert(lights.end(), c.more.begin(), c.more.end());
    for (const Case::Placed& l : lights) scene::addLight(s, l.light, l.position, l.target - l.position);
    return s;
}

render::FrameSettings caseSettings(const Case& c)
{
    render::FrameSettings settings = test::radianceFrame(96, 96);
    settings.brdfGeometry = c.geometry;
    settings.energyCompensation = false; // exactly the glTF BRDF, as shading/Brdf.cpp evaluates it
    settings.lightCulling = c.culling;
    return settings;
}

const glm::vec3 kEye(0.0f, 0.0f, 4.0f);
const render::View kView = render::lookAtView(kEye, {0, 0, 0}, {0, 1, 0}, glm::radians(40.0f), 1.0f, 0.1f, 20.0f);

// Renders the case's frame, in its own renderer or in `existing` (whose scene and lights the
// caller has set to the case's), and compares every pixel with the CPU.
Result renderAndCompare(const Case& c, render::Renderer* existing = nullptr)
{
    std::vector<Case::Placed> lights{{c.light, c.lightPosition, c.lightTarget}};
    lights.insert(lights.end(), c.more.begin(), c.more.end());
    std::optional<render::Renderer> own;
    if (!existing) {
        own.emplace();
        own->setScene(caseScene(c));
    }
    render::Renderer& renderer = existing ? *existing : *own;
    renderer.render(kView, caseSettings(c));
    const ImageFloat image = renderer.readRadiance();
    const glm::vec3 eye = kEye;
    const render::View view = kView;

    render::brdf::Surface surface;
    surface.baseColor = dvec3(c.baseColor);
    surface.metallic = c.metallic;
    surface.perceptualRoughness = c.roughness;
    surface.geometry = c.shading.geometry.value_or(c.geometry);
    surface.distribution = c.shading.distribution.value_or(render::brdf::Distribution::GGX);
    surface.fresnel = c.shading.fresnel.value_or(render::brdf::Fresnel::Schlick);
    surface.diffuse = c.shading.diffuse.value_or(render::brdf::Diffuse::Lambert);
    if (c.ior) surface.f0Dielectric = double(scene::f0FromIor(*c.ior));
    const scene::ShadingModel model = c.shading.model.value_or(scene::ShadingModel::Pbr);
    // The classic models (classic_lighting.glsl): kd, ks = mix(0.5, base colour, metallic).
    const dvec3 kd = surface.baseColor * (1.0 - surface.metallic);
    const dvec3 ks = glm::mix(dvec3(0.5), surface.baseColor, surface.metallic);
    const double shininess = render::brdf::classicShininess(std::clamp(double(c.roughness), render::brdf::kMinPerceptualRoughness, 1.0));

    const glm::dmat4 inverse = test::inverseViewProjection(view);
    Result result;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            dvec3 p;
            if (!hitUnitSphere(pixelRay(inverse, x, y, image.width, image.height), p)) continue;
            const dvec3 n = glm::normalize(p);
            const dvec3 v = glm::normalize(dvec3(eye) - p);
            if (glm::dot(n, v) < 0.25) continue; // silhouette pixels straddle facets and background

            dvec3 expected(0.0);
            for (const Case::Placed& placed : lights) {
                const scene::Light& light = placed.light;
                const dvec3 lightPosition(placed.position);
                const dvec3 lightDirection = glm::normalize(dvec3(placed.target - placed.position));
                dvec3 l;
                double illuminance = light.intensity;
                if (light.type == scene::Light::Type::Directional) {
                    l = -lightDirection;
                } else {
                    const dvec3 toLight = lightPosition - p;
                    const double distance = glm::length(toLight);
                    l = toLight / distance;
                    illuminance *= render::brdf::rangeAttenuation(light.range, distance);
                    if (light.type == scene::Light::Type::Spot)
                        illuminance *= render::brdf::spotAttenuation(lightDirection, l, light.innerConeAngle, light.outerConeAngle);
                }
                const double NoL = glm::dot(n, l);
                if (model == scene::ShadingModel::Phong || model == scene::ShadingModel::BlinnPhong)
                    expected += render::brdf::evaluateClassic(kd, ks, shininess, model == scene::ShadingModel::BlinnPhong, n, v, l) *
                                dvec3(light.color) * illuminance;
                else if (NoL > 0.0)
                    expected += render::brdf::evaluate(surface, n, v, l) * dvec3(light.color) * illuminance * NoL;
            }
            ++result.tested;
            if (expected.x > 0.01) ++result.lit;
            for (int ch = 0; ch < 3; ++ch) {
                const double got = image.pixels[(size_t(y) * image.width + x) * 4 + ch];
                const double error = std::abs(got - expected[ch]);
                EXPECT_LE(error, kRelative * expected[ch] + kAbsolute)
                    << c.name << " pixel (" << x << ", " << y << ") channel " << ch << ": GPU " << got << " CPU " << expected[ch];
                if (expected[ch] > 0.05) result.maxRelativeError = std::max(result.maxRelativeError, error / expected[ch]);
            }
        }
    }
    return result;
}

} // namespace

TEST_F(GlTest, PointLitSphereMatchesCpu)
{
    Case c{"point, dielectric", {}, {2.0f, 2.5f, 3.0f}, {0, 0, 0}, {0.8f, 0.3f, 0.2f}, 0.0f, 0.5f};
    c.light.type = scene::Light::Type::Point;
    c.light.intensity = 30.0f;
    c.light.color = {1.0f, 0.9f, 0.8f};
    c.light.range = 8.0f;
    const Result r = renderAndCompare(c);
    EXPECT_GT(r.tested, 2000);
    EXPECT_GT(r.lit, 1000);
    RecordProperty("maxRelativeError", std::to_string(r.maxRelativeError));

    Case metal{"point, rough metal", c.light, {-2.0f, 1.0f, 3.0f}, {0, 0, 0}, {0.95f, 0.64f, 0.54f}, 1.0f, 0.3f};
    renderAndCompare(metal);
    Case schlick = metal;
    schlick.name = "point, schlick-ggx";
    schlick.geometry = render::BrdfGeometry::SchlickGGX;
    renderAndCompare(schlick);
}

TEST_F(GlTest, SpotLitSphereMatchesCpu)
{
    Case c{"spot", {}, {0.0f, 3.0f, 2.5f}, {0.3f, 0.0f, 0.0f}, {0.5f, 0.7f, 0.9f}, 0.3f, 0.6f};
    c.light.type = scene::Light::Type::Spot;
    c.light.intensity = 60.0f;
    c.light.innerConeAngle = glm::radians(8.0f);
    c.light.outerConeAngle = glm::radians(16.0f);
    const Result r = renderAndCompare(c);
    // The cone edge crosses the sphere: some of it lit, some not.
    EXPECT_GT(r.lit, 200);
    EXPECT_LT(r.lit, r.tested - 200);
}

TEST_F(GlTest, DirectionalLitSphereMatchesCpu)
{
    Case c{"directional", {}, {0, 0, 0}, {-1.0f, -1.0f, -1.0f}, {0.9f, 0.9f, 0.9f}, 0.0f, 0.8f};
    c.light.type = scene::Light::Type::Directional;
    c.light.intensity = 3.0f;
    renderAndCompare(c);
}

namespace {

// One light of each kind, for the frames that mix them.
struct MixedLights {
    scene::Light point, spot, sun;
};

MixedLights mixedLights()
{
    MixedLights m;
    m.point.type = scene::Light::Type::Point;
    m.point.intensity = 20.0f;
    m.point.color = {1.0f, 0.8f, 0.6f};
    m.spot.type = scene::Light::Type::Spot;
    m.spot.intensity = 50.0f;
    m.spot.color = {0.6f, 0.8f, 1.0f};
    m.spot.range = 9.0f;
    m.spot.innerConeAngle = glm::radians(10.0f);
    m.spot.outerConeAngle = glm::radians(20.0f);
    m.sun.type = scene::Light::Type::Directional;
    m.sun.intensity = 1.5f;
    return m;
}

} // namespace

// Every kind of light in one frame, and each pair of kinds: the forward programs compile in only
// the kinds a frame has (NO_*_LIGHTS) and, with every light evaluated everywhere, their count
// as a constant (LIGHT_COUNT). Each frame against the CPU's sum of its lights, clustered (the
// count read from the buffer) and brute force (the count a constant).
TEST_F(GlTest, MixedLightKindsMatchCpuWithAndWithoutAConstantCount)
{
    const auto [point, spot, sun] = mixedLights();
    const Case::Placed placedPoint{point, {2.0f, 2.5f, 3.0f}, {0, 0, 0}};
    const Case::Placed placedSpot{spot, {-1.0f, 3.0f, 2.5f}, {-0.3f, 0.2f, 0.0f}};
    const Case::Placed placedSun{sun, {0, 0, 0}, {1.0f, -0.5f, -1.0f}};
    const std::vector<std::vector<Case::Placed>> sets = {
        {placedPoint, placedSpot, placedSun}, {placedPoint, placedSpot}, {placedSpot, placedSun}, {placedSun, placedPoint},
        {placedPoint, placedPoint, placedSpot, placedSun, placedSpot}};
    for (const render::LightCulling culling : {render::LightCulling::Clustered, render::LightCulling::None}) {
        for (const std::vector<Case::Placed>& set : sets) {
            Case c{culling == render::LightCulling::None ? "mixed kinds, constant count" : "mixed kinds, clustered", set[0].light,
                   set[0].position, set[0].target, {0.7f, 0.6f, 0.5f}, 0.4f, 0.45f};
            c.more.assign(set.begin() + 1, set.end());
            c.culling = culling;
            const Result r = renderAndCompare(c);
            EXPECT_GT(r.lit, 1000) << set.size() << " lights";
        }
    }
}

// A few lights evaluated everywhere, without shadow maps, are constants of the forward programs
// while they stay still (LIGHT_CONSTANTS, render/passes/ForwardPass): from the first frame, not
// in the frames after an edit (those read the light buffer: a dragged light must not compile a
// program a frame), and again, with the edited values, once the lights have been still for
// 16 frames. Each frame against the CPU's sum of its lights. Fails with the constants kept
// after an edit (the frame shows the old lights), or never made again.
TEST_F(GlTest, LightsAsConstantsFollowEveryEdit)
{
    auto [point, spot, sun] = mixedLights();
    point.castShadows = spot.castShadows = false; // a frame with shadow maps reads its lights' records
    Case c{"constant lights", point, {2.0f, 2.5f, 3.0f}, {0, 0, 0}, {0.7f, 0.6f, 0.5f}, 0.4f, 0.45f};
    c.more = {{spot, {-1.0f, 3.0f, 2.5f}, {-0.3f, 0.2f, 0.0f}}};
    c.culling = render::LightCulling::None;
    render::Renderer renderer;
    renderer.setScene(caseScene(c));
    EXPECT_GT(renderAndCompare(c, &renderer).lit, 1000);
    EXPECT_TRUE(renderer.stats().lightConstants);

    // Move the point light and brighten it.
    Case moved = c;
    moved.lightPosition = {-2.5f, 1.0f, 3.0f};
    moved.light.intensity = 35.0f;
    render::PlacedLight placed = renderer.light(0);
    placed.light.intensity = moved.light.intensity;
    placed.position = moved.lightPosition;
    placed.direction = glm::normalize(moved.lightTarget - moved.lightPosition);
    renderer.setLight(0, placed);
    EXPECT_GT(renderAndCompare(moved, &renderer).lit, 1000);
    EXPECT_FALSE(renderer.stats().lightConstants);
    for (int frame = 0; frame < 16; ++frame) renderer.render(kView, caseSettings(moved));
    EXPECT_GT(renderAndCompare(moved, &renderer).lit, 1000);
    EXPECT_TRUE(renderer.stats().lightConstants);
}

namespace {

Case variantBase(const char* name)
{
    Case c{name, {}, {2.0f, 2.5f, 3.0f}, {0, 0, 0}, {0.8f, 0.3f, 0.2f}, 0.0f, 0.45f};
    c.light.type = scene::Light::Type::Point;
    c.light.intensity = 30.0f;
    c.light.color = {1.0f, 0.9f, 0.8f};
    return c;
}

} // namespace

// Every physically based variant (one term changed at a time, on a dielectric and on a
// metal) against shading/Brdf.cpp, pixel by pixel, same tolerance as above.
TEST_F(GlTest, BrdfVariantsMatchCpu)
{
    std::vector<Case> cases;
    for (auto d : {scene::BrdfDistribution::Beckmann, scene::BrdfDistribution::BlinnPhong}) {
        Case c = variantBase(scene::brdfDistributionName(d));
        c.shading.distribution = d;
        cases.push_back(c);
    }
    for (auto g : {scene::BrdfGeometry::SmithGGXCorrelated, scene::BrdfGeometry::SchlickGGX, scene::BrdfGeometry::Neumann,
                   scene::BrdfGeometry::Kelemen, scene::BrdfGeometry::CookTorrance, scene::BrdfGeometry::Implicit}) {
        Case c = variantBase(scene::brdfGeometryName(g));
        c.shading.geometry = g;
        cases.push_back(c);
    }
    for (auto f : {scene::BrdfFresnel::SchlickSG, scene::BrdfFresnel::None}) {
        Case c = variantBase(scene::brdfFresnelName(f));
        c.shading.fresnel = f;
        cases.push_back(c);
    }
    for (auto d : {scene::BrdfDiffuse::OrenNayar, scene::BrdfDiffuse::Burley}) {
        Case c = variantBase(scene::brdfDiffuseName(d));
        c.shading.diffuse = d;
        c.roughness = 0.8f; // a rough surface, where the diffuse models differ most
        cases.push_back(c);
    }
    Case ior = variantBase("ior 2.0");
    ior.ior = 2.0f;
    cases.push_back(ior);
    for (Case c : cases) {
        const Result r = renderAndCompare(c);
        EXPECT_GT(r.lit, 1000) << c.name;
        // The same variant on a rough gold-like metal: F and the specular lobe alone.
        c.baseColor = {0.95f, 0.64f, 0.54f};
        c.metallic = 1.0f;
        c.lightPosition = {-2.0f, 1.0f, 3.0f};
        renderAndCompare(c);
        // Lit from behind: grazing light and view, where F, G and the diffuse models differ
        // most (VoH down to about 0.35).
        c.lightPosition = {3.0f, 0.5f, -1.5f};
        c.metallic = 0.0f;
        EXPECT_GT(renderAndCompare(c).lit, 30) << c.name;
    }
}

// The classic models per pixel: Phong (R·V)^n and Blinn-Phong (N·H)^n, shininess from
// roughness and given.
TEST_F(GlTest, PhongAndBlinnPhongMatchCpu)
{
    for (auto model : {scene::ShadingModel::Phong, scene::ShadingModel::BlinnPhong}) {
        Case c = variantBase(scene::shadingModelName(model));
        c.shading.model = model;
        const Result r = renderAndCompare(c);
        EXPECT_GT(r.lit, 1000);
        c.roughness = 0.2f; // shininess 1248: a small, bright highlight
        renderAndCompare(c);
        c.metallic = 1.0f; // ks = base colour, no diffuse
        renderAndCompare(c);
    }
}
