// Shadows against an exact ray test: scenes of analytic primitives (a floor, spheres, boxes)
// rendered by the GPU with shadow maps, and on the CPU by casting each pixel's ray, finding
// the nearest hit and testing the segment from it to the light against every primitive — lit
// or not — times the same BRDF the GPU-vs-CPU shading tests use (shading/Brdf.h).
//
// Pixels within a band of any change of what the CPU sees (another primitive, lit against
// shadowed) are not compared: the shadow filter's width, a tessellated sphere's silhouette and
// the shadow map's texels all live there. Elsewhere, inside the umbra, the GPU's radiance must
// be at most 2% of the unshadowed value; in the light, within the shading tests' tolerance.
// Each case also runs with shadows off and must then fail (the test can tell).
#include "GlTestContext.h"
#include "ImageProbe.h"
#include "ShadowScenes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <filesystem>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/ImageIO.h"
#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"
#include "shading/Brdf.h"
#include "shading/ShadowMaps.h"
#include "settings/PassSettings.h"

using namespace specula;
using specula::test::GlTest;
using glm::dvec3;

namespace {

using specula::test::Box;
using specula::test::Sphere;

// A scene of primitives and the camera that sees it.
struct ShadowScene : specula::test::ShadowPrimitives {
    glm::vec3 eye{0.0f, 8.0f, 10.0f};
    glm::vec3 target{0.0f};
    float yfov = glm::radians(50.0f);
    float far = 100.0f;
    int width = 160, height = 120;
};

const glm::vec3 kBaseColor = specula::test::kShadowBaseColor;
constexpr float kRoughness = specula::test::kShadowRoughness;

// The nearest hit of a ray: t, the primitive (0 floor, then spheres, then boxes), the normal.
struct Hit {
    double t = std::numeric_limits<double>::infinity();
    int object = -1;
    dvec3 normal{0.0};
};

void hitSphere(const Sphere& s, const dvec3& o, const dvec3& d, int id, Hit& hit)
{
    const dvec3 oc = o - dvec3(s.center);
    const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - double(s.radius) * s.radius;
    const double disc = b * b - c;
    if (disc <= 0.0) return;
    const double t = -b - std::sqrt(disc);
    if (t > 1e-6 && t < hit.t) hit = {t, id, glm::normalize(o + d * t - dvec3(s.center))};
}

void hitBox(const Box& box, const dvec3& o, const dvec3& d, int id, Hit& hit)
{
    double t0 = -1e300, t1 = 1e300;
    int axis = -1;
    double sign = 1.0;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-12) {
            if (o[a] < box.min[a] || o[a] > box.max[a]) return;
            continue;
        }
        double ta = (box.min[a] - o[a]) / d[a], tb = (box.max[a] - o[a]) / d[a];
        double s = -1.0;
        if (ta > tb) {
            std::swap(ta, tb);
            s = 1.0;
        }
        if (ta > t0) {
            t0 = ta;
            axis = a;
            sign = s;
        }
        t1 = std::min(t1, tb);
    }
    if (t0 > t1 || t0 <= 1e-6 || t0 >= hit.t || axis < 0) return;
    dvec3 n(0.0);
    n[axis] = sign;
    hit = {t0, id, n};
}

Hit intersect(const ShadowScene& sc, const dvec3& o, const dvec3& d)
{
    Hit hit;
    if (std::abs(d.y) > 1e-12) {
        const double t = -o.y / d.y;
        const dvec3 p = o + d * t;
        const double h = 0.5 * sc.floorSize;
        if (t > 1e-6 && std::abs(p.x) <= h && std::abs(p.z) <= h) hit = {t, 0, dvec3(0, 1, 0)};
    }
    for (size_t i = 0; i < sc.spheres.size(); ++i) hitSphere(sc.spheres[i], o, d, int(1 + i), hit);
    for (size_t i = 0; i < sc.boxes.size(); ++i) hitBox(sc.boxes[i], o, d, int(1 + sc.spheres.size() + i), hit);
    return hit;
}

scene::Scene buildScene(const ShadowScene& sc) { return specula::test::buildShadowScene(sc); }

// A frame whose pixels are radiance, one sample at each pixel's centre (the exact ray test's),
// with hard shadows: no tone map, no energy compensation.
render::FrameSettings radianceSettings(int width, int height)
{
    render::FrameSettings settings;
    settings.width = width;
    settings.height = height;
    settings.msaa = 1;
    settings.tonemap = render::Tonemap::None;
    settings.energyCompensation = false;
    settings.shadows.filter = ShadowFilter::Hard;
    return settings;
}

// Whether every pixel within `band` of (x, y) is in the same category as it: not near a change of
// what the exact test sees (callers keep `band` pixels from the image's edges).
bool interior(const std::vector<int>& category, int width, int x, int y, int band)
{
    const int c = category[size_t(y * width + x)];
    for (int dy = -band; dy <= band; ++dy)
        for (int dx = -band; dx <= band; ++dx)
            if (category[size_t((y + dy) * width + x + dx)] != c) return false;
    return true;
}

struct Comparison {
    int umbra = 0, umbraWrong = 0; ///< interior shadowed pixels, and those brighter than 2% of lit
    std::vector<int> umbraByCaster; ///< interior shadowed pixels by the primitive that casts them
    int lit = 0, litWrong = 0;     ///< interior lit pixels, and those off by more than the tolerance
    std::string firstUmbraFailure, firstLitFailure;
};

// Renders `sc` and compares every interior pixel with the CPU's exact answer.
Comparison compare(const ShadowScene& sc, const render::FrameSettings& base, int band, const std::string& name)
{
    render::FrameSettings settings = base;
    settings.width = sc.width;
    settings.height = sc.height;
    settings.msaa = 1;
    settings.tonemap = render::Tonemap::None;
    settings.energyCompensation = false;
    const render::View view = render::lookAtView(sc.eye, sc.target, {0, 1, 0}, sc.yfov, float(sc.width) / float(sc.height), 0.1f, sc.far);
    render::Renderer renderer;
    renderer.setScene(buildScene(sc));
    renderer.render(view, settings);
    const ImageFloat image = renderer.readRadiance();
    // For review by eye: the GPU's image and what the CPU tests where (green lit, red umbra).
    const std::filesystem::path out = std::filesystem::path(SPECULA_TEST_OUTPUT_DIR) / "shadows";
    std::filesystem::create_directories(out);
    writePng(out / (name + "-gpu.png"), renderer.readImage());
    ImageRGBA8 tested;
    tested.width = sc.width;
    tested.height = sc.height;
    tested.pixels.assign(size_t(sc.width * sc.height) * 4, 0);

    const glm::dmat4 inverse = test::inverseViewProjection(view);
    render::brdf::Surface surface;
    surface.baseColor = dvec3(kBaseColor);
    surface.metallic = 0.0;
    surface.perceptualRoughness = kRoughness;
    const int w = sc.width, h = sc.height;
    std::vector<int> category(size_t(w * h), -1); // object * 2 + lit, -1 background
    std::vector<dvec3> unshadowed(size_t(w * h), dvec3(0.0));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const test::Ray ray = test::pixelRay(inverse, x, y, w, h);
            const dvec3 o = ray.origin, d = ray.direction;
            const Hit hit = intersect(sc, o, d);
            if (hit.object < 0) continue;
            const dvec3 p = o + d * hit.t;
            dvec3 l;
            double illuminance = sc.light.intensity, maxT = 1e300;
            if (sc.light.type == scene::Light::Type::Directional) {
                l = -glm::normalize(dvec3(sc.lightDirection));
            } else {
                const dvec3 toLight = dvec3(sc.lightPosition) - p;
                maxT = glm::length(toLight);
                l = toLight / maxT;
                illuminance *= render::brdf::rangeAttenuation(sc.light.range, maxT);
                if (sc.light.type == scene::Light::Type::Spot)
                    illuminance *= render::brdf::spotAttenuation(glm::normalize(dvec3(sc.lightDirection)), l, sc.light.innerConeAngle,
                                                                 sc.light.outerConeAngle);
            }
            const double NoL = glm::dot(hit.normal, l);
            const dvec3 v = -d;
            const dvec3 value = NoL > 0.0 ? render::brdf::evaluate(surface, hit.normal, v, l) * illuminance * NoL : dvec3(0.0);
            const Hit blocker = intersect(sc, p + hit.normal * 1e-5, l);
            const bool lit = NoL > 0.0 && blocker.t >= maxT;
            // Shadowed pixels also by their caster (self-shadowed ones: the primitive itself).
            const int caster = lit ? 0 : blocker.t < maxT ? blocker.object : hit.object;
            category[size_t(y * w + x)] = (hit.object * 256 + caster) * 2 + (lit ? 1 : 0);
            unshadowed[size_t(y * w + x)] = value;
        }
    }
    Comparison result;
    result.umbraByCaster.assign(1 + sc.spheres.size() + sc.boxes.size(), 0);
    for (int y = band; y < h - band; ++y) {
        for (int x = band; x < w - band; ++x) {
            const int c = category[size_t(y * w + x)];
            if (c < 0 || !interior(category, w, x, y, band)) continue;
            const dvec3 expected = unshadowed[size_t(y * w + x)];
            if (expected.r < 1e-3) continue; // facing away: nothing to tell lit from shadowed
            const float* px = &image.pixels[(size_t(y) * size_t(w) + size_t(x)) * 4];
            const double got = px[0];
            uint8_t* mark = &tested.pixels[(size_t(y) * size_t(w) + size_t(x)) * 4];
            mark[c % 2 == 0 ? 0 : 1] = 255;
            mark[3] = 255;
            if (c % 2 == 0) {
                ++result.umbra;
                ++result.umbraByCaster[size_t((c / 2) % 256)];
                if (got > 0.02 * expected.r) {
                    if (result.umbraWrong++ == 0)
                        result.firstUmbraFailure = "umbra pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): GPU " +
                                              std::to_string(got) + ", lit would be " + std::to_string(expected.r);
                }
            } else {
                ++result.lit;
                if (std::abs(got - expected.r) > 0.015 * expected.r + 2e-3) {
                    if (result.litWrong++ == 0)
                        result.firstLitFailure = "lit pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): GPU " +
                                              std::to_string(got) + ", CPU " + std::to_string(expected.r);
                }
            }
        }
    }
    writePng(out / (name + "-tested.png"), tested);
    return result;
}

// The standard casters: a sphere above the floor, a box on it, a thin tall box.
ShadowScene casters()
{
    ShadowScene sc;
    sc.spheres = {{{-2.0f, 1.6f, 0.0f}, 1.0f}};
    sc.boxes = {{{1.0f, 0.0f, -1.0f}, {2.6f, 1.2f, 0.6f}}, {{-0.3f, 0.0f, 2.0f}, {0.0f, 3.0f, 2.3f}}};
    return sc;
}

void expectShadowsMatch(const char* name, const ShadowScene& sc, int band = 3, int minUmbra = 100)
{
    SCOPED_TRACE(name);
    render::FrameSettings settings;
    settings.shadows.filter = ShadowFilter::Hard; // the exact test has hard edges
    const Comparison on = compare(sc, settings, band, name);
    EXPECT_GE(on.umbra, minUmbra) << "too few umbra pixels to tell";
    EXPECT_GE(on.lit, 100) << "too few lit pixels to tell";
    EXPECT_EQ(on.umbraWrong, 0) << on.firstUmbraFailure << " (" << on.umbraWrong << " of " << on.umbra << " umbra pixels)";
    EXPECT_EQ(on.litWrong, 0) << on.firstLitFailure << " (" << on.litWrong << " of " << on.lit << " lit pixels)";
    // The same comparison without shadows must fail: every umbra pixel is then fully lit.
    settings.shadows.enabled = false;
    const Comparison off = compare(sc, settings, band, std::string(name) + "-off");
    EXPECT_GT(off.umbraWrong, off.umbra / 2) << "with shadows off the comparison should fail";
}

} // namespace

TEST_F(GlTest, PointLightShadowsMatchRayTest)
{
    ShadowScene sc = casters();
    sc.light.type = scene::Light::Type::Point;
    sc.light.intensity = 300.0f;
    sc.lightPosition = {0.5f, 5.0f, -3.0f};
    expectShadowsMatch("point", sc);
}

TEST_F(GlTest, SpotLightShadowsMatchRayTest)
{
    ShadowScene sc = casters();
    sc.light.type = scene::Light::Type::Spot;
    sc.light.intensity = 400.0f;
    sc.light.innerConeAngle = glm::radians(40.0f);
    sc.light.outerConeAngle = glm::radians(55.0f);
    sc.lightPosition = {-1.0f, 6.0f, -4.0f};
    sc.lightDirection = glm::normalize(glm::vec3(0.0f, 0.0f, 1.0f) - sc.lightPosition);
    expectShadowsMatch("spot", sc);
}

TEST_F(GlTest, SunShadowsMatchRayTestAt35And10Degrees)
{
    for (const float elevation : {35.0f, 10.0f}) {
        ShadowScene sc = casters();
        sc.floorSize = 60.0f;
        sc.light.type = scene::Light::Type::Directional;
        sc.light.intensity = 3.0f;
        const float e = glm::radians(elevation), azimuth = glm::radians(30.0f);
        // The sun behind the casters: their shadows fall towards the camera.
        sc.lightDirection = -glm::vec3(std::cos(e) * std::sin(azimuth), std::sin(e), -std::cos(e) * std::cos(azimuth));
        sc.eye = {0.0f, 10.0f, 14.0f};
        sc.width = 240;
        sc.height = 180;
        // At 10° a texel of the map stretches 1/sin 10° = 5.8 times along the floor: a wider band.
        if (elevation > 20.0f) expectShadowsMatch("sun at 35 degrees", sc);
        else expectShadowsMatch("sun at 10 degrees", sc, 8, 40);
    }
}

// A sun over a 200 m floor, casters 3, 8, 20, 45 and 90 m from the camera: each casts onto a
// wall behind it that faces the camera (so that far shadows are not foreshortened to nothing),
// every cascade is used, and every caster's shadow must be there (counted per caster).
TEST_F(GlTest, CascadesCoverCastersFrom3To90Metres)
{
    ShadowScene sc;
    sc.floorSize = 200.0f;
    sc.far = 150.0f;
    sc.width = 480;
    sc.height = 270;
    sc.yfov = glm::radians(45.0f);
    sc.eye = {0.0f, 1.5f, 0.0f};
    sc.target = {0.0f, 1.5f, -100.0f};
    sc.light.type = scene::Light::Type::Directional;
    sc.light.intensity = 3.0f;
    const glm::vec3 toSun = glm::normalize(glm::vec3(0.3f, 0.5f, 0.8f));
    sc.lightDirection = -toSun;
    const float distances[] = {3.0f, 8.0f, 20.0f, 45.0f, 90.0f};
    const float azimuths[] = {-24.0f, -12.0f, 0.0f, 12.0f, 24.0f};
    for (int i = 0; i < 5; ++i) {
        const float d = distances[i];
        const float x = d * std::tan(glm::radians(azimuths[i]));
        // The wall: 0.25 d wide, 0.3 d tall, its front face at z = -d.
        sc.boxes.push_back({{x - 0.125f * d, 0.0f, -d - 0.02f * d}, {x + 0.125f * d, 0.3f * d, -d}});
        // The caster: a cube of 0.06 d, 0.15 d in front of the wall.
        const glm::vec3 c(x + 0.03f * d, 0.2f * d, -d + 0.15f * d);
        sc.boxes.push_back({c - glm::vec3(0.03f * d), c + glm::vec3(0.03f * d)});
    }
    SCOPED_TRACE("cascades");
    render::FrameSettings settings;
    settings.shadows.filter = ShadowFilter::Hard;
    const Comparison on = compare(sc, settings, 2, "cascades");
    EXPECT_EQ(on.umbraWrong, 0) << on.firstUmbraFailure << " (" << on.umbraWrong << " of " << on.umbra << " umbra pixels)";
    EXPECT_EQ(on.litWrong, 0) << on.firstLitFailure << " (" << on.litWrong << " of " << on.lit << " lit pixels)";
    for (int i = 0; i < 5; ++i) {
        const int caster = 1 + 2 * i + 1; // after the floor, each wall then its caster
        EXPECT_GE(on.umbraByCaster[size_t(caster)], 20) << "the shadow of the caster at " << distances[i] << " m";
    }
    settings.shadows.enabled = false;
    const Comparison off = compare(sc, settings, 2, "cascades-off");
    EXPECT_GT(off.umbraWrong, off.umbra / 2) << "with shadows off the comparison should fail";
}

// No acne: a floor lit by a sun 10° above it, nothing above it, is uniformly lit (every pixel
// within the shading tolerance of the unshadowed value); the floor is its own caster.
TEST_F(GlTest, NoAcneOnAFloorLitAtTenDegrees)
{
    ShadowScene sc;
    sc.floorSize = 60.0f;
    sc.light.type = scene::Light::Type::Directional;
    sc.light.intensity = 3.0f;
    const float e = glm::radians(10.0f);
    sc.lightDirection = -glm::vec3(std::cos(e) * 0.6f, std::sin(e), std::cos(e) * 0.8f);
    sc.eye = {0.0f, 4.0f, 12.0f};
    for (const ShadowFilter filter : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss}) {
        SCOPED_TRACE(shadowFilterName(filter));
        render::FrameSettings settings;
        settings.shadows.filter = filter;
        const Comparison c = compare(sc, settings, 1, std::string("acne-") + shadowFilterName(filter));
        EXPECT_GT(c.lit, 5000);
        EXPECT_EQ(c.umbra, 0);
        EXPECT_EQ(c.litWrong, 0) << c.firstLitFailure << " (" << c.litWrong << " of " << c.lit << " lit pixels)";
    }
}

// Cached shadows: a still scene draws its maps once; moving the camera redraws the cascades
// (they follow the view) and nothing else; editing a light redraws only its views.
TEST_F(GlTest, StillScenesDrawTheirShadowMapsOnce)
{
    ShadowScene sc = casters();
    sc.light.type = scene::Light::Type::Spot;
    sc.light.intensity = 100.0f;
    sc.lightPosition = {-3.0f, 7.0f, 3.0f};
    sc.lightDirection = -sc.lightPosition;
    scene::Scene s = buildScene(sc);
    scene::Light point;
    point.intensity = 50.0f;
    scene::addLight(s, point, {2.0f, 4.0f, 0.0f}, {0, -1, 0});
    scene::Light sun;
    sun.type = scene::Light::Type::Directional;
    scene::addLight(s, sun, {0, 0, 0}, {0.3f, -1.0f, 0.2f});
    render::Renderer renderer;
    renderer.setScene(s);
    render::FrameSettings settings;
    settings.width = settings.height = 64;
    settings.msaa = 1;
    const render::View view = render::lookAtView(sc.eye, sc.target, {0, 1, 0}, sc.yfov, 1.0f, 0.1f, 100.0f);
    renderer.render(view, settings);
    const auto& stats = renderer.stats().shadows;
    EXPECT_EQ(stats.lights, 3);
    EXPECT_EQ(stats.views, 1 + 6 + 4) << "a spot's view, six cube faces, four cascades";
    EXPECT_EQ(stats.rendered, stats.views);
    for (int frame = 0; frame < 3; ++frame) {
        renderer.render(view, settings);
        EXPECT_EQ(renderer.stats().shadows.rendered, 0) << "frame " << frame + 2 << " of a still scene";
        EXPECT_EQ(renderer.stats().shadows.cached, 11);
    }
    const render::View moved = render::lookAtView(sc.eye + glm::vec3(0.5f, 0, 0), sc.target, {0, 1, 0}, sc.yfov, 1.0f, 0.1f, 100.0f);
    renderer.render(moved, settings);
    EXPECT_EQ(renderer.stats().shadows.rendered, 4) << "only the cascades follow the camera";
    render::PlacedLight spot = renderer.light(0);
    spot.position += glm::vec3(0.1f, 0, 0);
    renderer.setLight(0, spot);
    renderer.render(moved, settings);
    EXPECT_EQ(renderer.stats().shadows.rendered, 1) << "only the edited spot light's view";
    settings.shadows.cache = false;
    renderer.render(moved, settings);
    EXPECT_EQ(renderer.stats().shadows.rendered, 11) << "with the cache off every view, every frame";
}

// The shadow-atlas view: a spot light 4 m straight above a floor sees the floor at view depth
// 4 m in every texel of its tile (the floor is perpendicular to its axis), so its tile is one
// grey, 1 − (1 − d)^¼ of the window depth d of a perspective view at 4 m — computed here from
// the view's near and far planes — and the rest of the atlas is white (cleared to the far
// plane). Around the atlas's square, dark blue. Fails when the view shows the frame instead,
// or a tile is never drawn (a black square: depth 0).
TEST_F(GlTest, ShadowAtlasViewShowsEachTileAtItsDepth)
{
    ShadowScene sc;
    sc.light.type = scene::Light::Type::Spot;
    sc.light.intensity = 100.0f;
    sc.light.range = 10.0f;
    sc.lightPosition = {0.0f, 4.0f, 0.0f};
    sc.lightDirection = {0.0f, -1.0f, 0.0f};
    render::Renderer renderer;
    renderer.setScene(buildScene(sc));
    render::FrameSettings settings;
    settings.width = 256;
    settings.height = 128;
    settings.msaa = 1;
    settings.debugView = DebugView::ShadowAtlas;
    renderer.render(render::lookAtView(sc.eye, sc.target, {0, 1, 0}, sc.yfov, 2.0f, 0.1f, 100.0f), settings);
    ASSERT_EQ(renderer.stats().shadows.lights, 1);
    const ImageRGBA8 image = renderer.readImage();
    writePng(std::filesystem::path(SPECULA_TEST_OUTPUT_DIR) / "shadows" / "atlas-view.png", image);

    const render::ShadowView view = render::spotView(sc.lightPosition, sc.lightDirection, sc.light.outerConeAngle, sc.light.range, 64);
    const double n = view.near, f = view.far, z = 4.0;
    const double ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * z);
    const double depth = 0.5 * ndc + 0.5;
    const double expected = 255.0 * (1.0 - std::pow(1.0 - depth, 0.25));
    int grey = 0, white = 0, other = 0;
    int minX = 1 << 30, maxX = -1, minY = 1 << 30, maxY = -1;
    std::string firstOther;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 256; ++x) {
            const uint8_t* p = &image.pixels[size_t(y * 256 + x) * 4];
            if (x < 64 || x >= 192) {
                EXPECT_TRUE(p[0] == 0 && p[1] == 0 && p[2] == 51) << "outside the atlas at " << x << "," << y;
                continue;
            }
            if (p[0] == 255 && p[1] == 255 && p[2] == 255) {
                ++white;
            } else if (std::abs(p[0] - expected) <= 1.5 && p[1] == p[0] && p[2] == p[0]) {
                ++grey;
                minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y), maxY = std::max(maxY, y);
            } else if (++other == 1) {
                firstOther = std::to_string(x) + "," + std::to_string(y) + ": " + std::to_string(p[0]) + " (tile grey " +
                             std::to_string(expected) + ")";
            }
        }
    EXPECT_EQ(other, 0) << firstOther;
    ASSERT_GT(grey, 16) << "the spot light's tile";
    EXPECT_GT(white, grey) << "the rest of the atlas is empty";
    EXPECT_EQ(grey, (maxX - minX + 1) * (maxY - minY + 1)) << "the tile is one square of one grey";
    EXPECT_EQ(maxX - minX, maxY - minY);
}

// KHR_materials_transmission's texture decides texel by texel where a surface casts (the shadow
// rule, render::transmissionCutout: where it stops at least half the light). A 3 m square 2 m
// above the floor, transmission factor 1 and a 2 × 1 texture read nearest, whose left texel lets
// nothing through (R 0) and whose right texel lets everything through (R 255), under a sun 60°
// up: by an exact ray test the floor is in shadow where the ray to the sun crosses the left
// half, and lit through its base colour where it crosses the right half (the tint map). Each
// floor pixel against the same frame with shadows off: in the umbra at most 2 % of it, in the
// light (times the glass's colour under the clear half) within 1.5 %; pixels within 3 of a
// change (the map's texels, the square's edges) are not compared. Broken on purpose
// (2026-12-07, shader copies): without the shadow pass's cutout the clear half casts too (all
// 490 pixels under it fail); with every texel cut out, as the rule before cast nothing from a
// factor of 0.5 up, the opaque half casts none (all 490 umbra pixels fail).
TEST_F(GlTest, TransmissionTextureDecidesWhereASurfaceCasts)
{
    test::ShadowPrimitives primitives;
    primitives.light.type = scene::Light::Type::Directional;
    primitives.light.intensity = 3.0f;
    const double elevation = glm::radians(60.0);
    const dvec3 toSun(0.0, std::sin(elevation), -std::cos(elevation)); // the shadow falls towards the camera
    primitives.lightDirection = -glm::vec3(toSun);
    scene::Scene s = test::buildShadowScene(primitives);
    s.images.push_back({"half clear", 2, 1, 4, {0, 0, 0, 255, 255, 255, 255, 255}});
    scene::Sampler nearest;
    nearest.magFilter = nearest.minFilter = scene::Filter::Nearest;
    nearest.mipmaps = false;
    s.samplers.push_back(nearest);
    scene::Material glass;
    glass.baseColorFactor = glm::vec4(kBaseColor, 1.0f);
    glass.roughnessFactor = 0.2f;
    glass.metallicFactor = 0.0f;
    glass.transmissionFactor = 1.0f;
    glass.transmissionTexture.image = int(s.images.size() - 1);
    glass.transmissionTexture.sampler = int(s.samplers.size() - 1);
    constexpr double kSquareHeight = 2.0, kHalf = 1.5;
    scene::addShape(s, scene::makePlane(float(2.0 * kHalf)), glass, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, float(kSquareHeight), 0.0f)),
                    "half-clear square");

    constexpr int kImageWidth = 240, kImageHeight = 180, kBand = 3;
    render::FrameSettings settings = radianceSettings(kImageWidth, kImageHeight);
    const render::View view = render::lookAtView({0.0f, 8.0f, 10.0f}, glm::vec3(0.0f), {0, 1, 0}, glm::radians(50.0f),
                                                 float(kImageWidth) / float(kImageHeight), 0.1f, 100.0f);
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, settings);
    const ImageFloat shadowed = renderer.readRadiance();
    writePng(std::filesystem::path(SPECULA_TEST_OUTPUT_DIR) / "shadows" / "transmission-cutout-gpu.png", renderer.readImage());
    settings.shadows.enabled = false;
    renderer.render(view, settings);
    const ImageFloat unshadowed = renderer.readRadiance();

    // Per pixel: -1 not the floor (the square, the sky); 0 floor in shadow; 1 floor lit through
    // the clear half; 2 floor lit past the square.
    const glm::dmat4 inverse = test::inverseViewProjection(view);
    std::vector<int> category(size_t(kImageWidth * kImageHeight), -1);
    for (int y = 0; y < kImageHeight; ++y)
        for (int x = 0; x < kImageWidth; ++x) {
            const test::Ray ray = test::pixelRay(inverse, x, y, kImageWidth, kImageHeight);
            if (ray.direction.y >= 0.0) continue;
            const dvec3 atSquare = ray.origin + ray.direction * ((kSquareHeight - ray.origin.y) / ray.direction.y);
            if (std::abs(atSquare.x) <= kHalf && std::abs(atSquare.z) <= kHalf) continue; // the square, seen first
            const dvec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
            if (std::abs(p.x) > 0.5 * primitives.floorSize || std::abs(p.z) > 0.5 * primitives.floorSize) continue;
            const dvec3 q = p + toSun * (kSquareHeight / toSun.y); // where the ray to the sun meets the square's plane
            const bool crosses = std::abs(q.x) <= kHalf && std::abs(q.z) <= kHalf;
            category[size_t(y * kImageWidth + x)] = !crosses ? 2 : q.x < 0.0 ? 0 : 1;
        }
    int counts[3] = {0, 0, 0}, wrong[3] = {0, 0, 0};
    for (int y = kBand; y < kImageHeight - kBand; ++y)
        for (int x = kBand; x < kImageWidth - kBand; ++x) {
            const int c = category[size_t(y * kImageWidth + x)];
            if (c < 0 || !interior(category, kImageWidth, x, y, kBand)) continue;
            const size_t at = (size_t(y) * kImageWidth + size_t(x)) * 4;
            const double got = shadowed.pixels[at], lit = unshadowed.pixels[at];
            ASSERT_GT(lit, 1e-3) << "the floor faces the sun";
            ++counts[c];
            // Under the clear half: the light the glass lets through, tinted by its base colour.
            const double expected = c == 1 ? lit * kBaseColor.r : lit;
            const bool ok = c == 0 ? got <= 0.02 * lit : std::abs(got - expected) <= 0.015 * expected + 2e-3;
            if (!ok && wrong[c]++ < 3)
                ADD_FAILURE() << (c == 0 ? "umbra" : c == 1 ? "under the clear half" : "lit") << " pixel (" << x << ", " << y
                              << "): " << got << ", unshadowed " << lit;
        }
    std::printf("transmission cutout: %d umbra, %d under the clear half, %d lit pixels compared; %d, %d, %d wrong\n", counts[0],
                counts[1], counts[2], wrong[0], wrong[1], wrong[2]);
    EXPECT_GT(counts[0], 100);
    EXPECT_GT(counts[1], 100);
    EXPECT_GT(counts[2], 100);
    EXPECT_EQ(wrong[0] + wrong[1] + wrong[2], 0);
}

// Surfaces that let light through cast coloured and partial shadows (the tint map,
// render::tintsShadow). Over a floor, under a sun 60° up, three 2.4 m squares around 2 m up:
// clear coloured glass (a plane, transmission 1, base colour (0.9, 0.45, 0.15)): the light
// through it is that colour; a blended sheet of alpha 0.4: 0.6 of the light; a glass slab (a
// closed box 0.5 m thick, KHR_materials_volume thickness 1 at its scale, attenuation colour
// (0.5, 0.8, 1) at 1 m, base colour (0.64, 1, 0.81)): each of its two faces on the way lets
// through √base × the attenuation over half the thickness, so the floor receives base ×
// attenuation^(thickness / distance) — tinted once, as the forward pass tints the view through
// it. By an exact ray test, each floor pixel whose ray to the sun crosses a square is compared,
// per channel, with the frame with shadows off times what that square lets through, and every
// other floor pixel with it unchanged, within 2 % (pixels within 3 of a change, and those whose
// ray crosses a slab's edge, are not compared). With `--shadows-tint off` every floor pixel is
// the unshadowed one.
TEST_F(GlTest, SurfacesThatLetLightThroughTintTheirShadows)
{
    test::ShadowPrimitives primitives;
    primitives.light.type = scene::Light::Type::Directional;
    primitives.light.intensity = 3.0f;
    const double elevation = glm::radians(60.0);
    const dvec3 toSun(0.0, std::sin(elevation), -std::cos(elevation));
    primitives.lightDirection = -glm::vec3(toSun);
    scene::Scene s = test::buildShadowScene(primitives);
    constexpr double kHeight = 2.0, kHalf = 1.2, kSlab = 0.25; // the slab's half thickness
    struct Pane {
        double x;
        scene::Material material;
        dvec3 through;
    };
    std::vector<Pane> panes(3);
    panes[0].x = -3.0;
    panes[0].material.baseColorFactor = glm::vec4(0.9f, 0.45f, 0.15f, 1.0f);
    panes[0].material.transmissionFactor = 1.0f;
    panes[0].through = dvec3(0.9, 0.45, 0.15);
    panes[1].x = 0.0;
    panes[1].material.baseColorFactor = glm::vec4(0.3f, 0.6f, 0.9f, 0.4f);
    panes[1].material.alphaMode = scene::AlphaMode::Blend;
    panes[1].through = dvec3(0.6);
    panes[2].x = 3.0;
    panes[2].material.baseColorFactor = glm::vec4(0.64f, 1.0f, 0.81f, 1.0f);
    panes[2].material.transmissionFactor = 1.0f;
    panes[2].material.attenuationColor = glm::vec3(0.5f, 0.8f, 1.0f);
    panes[2].material.attenuationDistance = 1.0f;
    // The slab: makeCube(1) (2 m a side) scaled to 2.4 × 0.5 × 2.4; the shader scales the
    // thickness by the mean of the model's axes' lengths, so this factor means 0.5 m.
    const glm::vec3 slabScale{float(kHalf), float(kSlab), float(kHalf)};
    const double meanScale = (double(slabScale.x) + slabScale.y + slabScale.z) / 3.0;
    panes[2].material.thickness = float(2.0 * kSlab / meanScale);
    panes[2].through = dvec3(0.64 * std::pow(0.5, 2.0 * kSlab), 1.0 * std::pow(0.8, 2.0 * kSlab), 0.81);
    for (size_t k = 0; k < panes.size(); ++k) {
        Pane& pane = panes[k];
        pane.material.roughnessFactor = 0.3f;
        pane.material.metallicFactor = 0.0f; // a metal lets no light through
        const glm::mat4 at = glm::translate(glm::mat4(1.0f), glm::vec3(float(pane.x), float(kHeight), 0.0f));
        if (k == 2) {
            scene::addShape(s, scene::makeCube(1.0f), pane.material, glm::scale(at, slabScale), "slab");
        } else {
            pane.material.doubleSided = true;
            scene::addShape(s, scene::makePlane(float(2.0 * kHalf)), pane.material, at, "pane");
        }
    }

    // An opaque block standing on the blended sheet: nearer the sun than the sheet, so the sheet
    // under it tints nothing of it (the tint map's depth).
    const dvec3 kBlockMin(-0.6, kHeight, -0.6), kBlockMax(0.6, kHeight + 0.4, 0.6);
    {
        scene::Material block;
        block.baseColorFactor = glm::vec4(kBaseColor, 1.0f);
        block.metallicFactor = 0.0f;
        block.roughnessFactor = test::kShadowRoughness;
        const glm::vec3 centre(0.5 * (kBlockMin + kBlockMax)), half(0.5 * (kBlockMax - kBlockMin));
        scene::addShape(s, scene::makeCube(1.0f), block, glm::scale(glm::translate(glm::mat4(1.0f), centre), half), "block");
    }

    constexpr int kImageWidth = 480, kImageHeight = 270, kBand = 3;
    render::FrameSettings settings = radianceSettings(kImageWidth, kImageHeight);
    const render::View view = render::lookAtView({0.0f, 9.0f, 9.0f}, glm::vec3(0.0f, 0.0f, 1.0f), {0, 1, 0}, glm::radians(55.0f),
                                                 float(kImageWidth) / float(kImageHeight), 0.1f, 100.0f);
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, settings);
    const ImageFloat shadowed = renderer.readRadiance();
    writePng(std::filesystem::path(SPECULA_TEST_OUTPUT_DIR) / "shadows" / "tinted-gpu.png", renderer.readImage());
    settings.shadows.tint = false; // --shadows-tint off: they cast nothing
    renderer.render(view, settings);
    const ImageFloat untinted = renderer.readRadiance();
    settings.shadows.enabled = false;
    renderer.render(view, settings);
    const ImageFloat unshadowed = renderer.readRadiance();

    // Per pixel: -1 not the floor (a pane, the sky) or not compared; 0 the floor past the
    // panes; 1 + k the floor whose ray to the sun crosses pane k. A ray meets the panes'
    // footprints at the slab's top and bottom; crossing one and not the other, it is an edge.
    const glm::dmat4 inverse = test::inverseViewProjection(view);
    const auto paneAt = [&](const dvec3& origin, const dvec3& direction, double height) {
        const dvec3 at = origin + direction * ((height - origin.y) / direction.y);
        for (size_t k = 0; k < panes.size(); ++k)
            if (std::abs(at.x - panes[k].x) <= kHalf && std::abs(at.z) <= kHalf) return int(k);
        return -1;
    };
    const auto hitsBlock = [&](const dvec3& origin, const dvec3& direction) { // slab method
        double near = 0.0, far = 1e30;
        for (int a = 0; a < 3; ++a) {
            const double t0 = (kBlockMin[a] - origin[a]) / direction[a], t1 = (kBlockMax[a] - origin[a]) / direction[a];
            near = std::max(near, std::min(t0, t1));
            far = std::min(far, std::max(t0, t1));
        }
        return near <= far;
    };
    const int kBlockTop = int(panes.size()) + 1;
    std::vector<int> category(size_t(kImageWidth * kImageHeight), -1);
    for (int y = 0; y < kImageHeight; ++y)
        for (int x = 0; x < kImageWidth; ++x) {
            const test::Ray ray = test::pixelRay(inverse, x, y, kImageWidth, kImageHeight);
            if (ray.direction.y >= 0.0) continue;
            int& c = category[size_t(y * kImageWidth + x)];
            if (hitsBlock(ray.origin, ray.direction)) {
                const dvec3 top = ray.origin + ray.direction * ((kBlockMax.y - ray.origin.y) / ray.direction.y);
                if (std::abs(top.x - 0.5 * (kBlockMin.x + kBlockMax.x)) < 0.5 * (kBlockMax.x - kBlockMin.x) &&
                    std::abs(top.z - 0.5 * (kBlockMin.z + kBlockMax.z)) < 0.5 * (kBlockMax.z - kBlockMin.z))
                    c = kBlockTop;
                continue;
            }
            if (paneAt(ray.origin, ray.direction, kHeight + kSlab) >= 0 || paneAt(ray.origin, ray.direction, kHeight - kSlab) >= 0)
                continue; // a pane, seen first
            const dvec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
            if (std::abs(p.x) > 0.5 * primitives.floorSize || std::abs(p.z) > 0.5 * primitives.floorSize) continue;
            if (hitsBlock(p, toSun)) continue; // the block's own shadow
            const int top = paneAt(p, toSun, kHeight + kSlab), bottom = paneAt(p, toSun, kHeight - kSlab);
            if (top == bottom) c = 1 + top;
        }
    std::vector<int> counts(panes.size() + 2, 0), wrong(panes.size() + 2, 0);
    for (int y = kBand; y < kImageHeight - kBand; ++y)
        for (int x = kBand; x < kImageWidth - kBand; ++x) {
            const int c = category[size_t(y * kImageWidth + x)];
            if (c < 0 || !interior(category, kImageWidth, x, y, kBand)) continue;
            ++counts[size_t(c)];
            const dvec3 through = c == 0 || c == kBlockTop ? dvec3(1.0) : panes[size_t(c - 1)].through;
            bool ok = true;
            std::string detail;
            for (int channel = 0; channel < 3; ++channel) {
                const size_t at = (size_t(y) * kImageWidth + size_t(x)) * 4 + size_t(channel);
                const double got = shadowed.pixels[at], lit = unshadowed.pixels[at];
                ASSERT_GT(lit, 1e-3) << "the floor faces the sun";
                const double expected = lit * through[channel];
                if (std::abs(got - expected) > 0.02 * expected + 2e-3) ok = false;
                if (c != kBlockTop && std::abs(untinted.pixels[at] - lit) > 0.02 * lit + 2e-3) ok = false;
                detail += " " + std::to_string(got) + " (" + std::to_string(expected) + ")";
            }
            if (!ok && wrong[size_t(c)]++ < 3)
                ADD_FAILURE() << (c == 0           ? std::string("past the panes")
                                  : c == kBlockTop ? std::string("the block's top")
                                                   : "under pane " + std::to_string(c - 1))
                              << ", pixel (" << x
                              << ", " << y << "): rgb" << detail;
        }
    std::printf("tinted shadows: %d pixels past the panes, %d, %d, %d under them, %d on the block; %d, %d, %d, %d, %d wrong\n",
                counts[0], counts[1], counts[2], counts[3], counts[4], wrong[0], wrong[1], wrong[2], wrong[3], wrong[4]);
    for (size_t c = 0; c < counts.size(); ++c) {
        EXPECT_GT(counts[c], 100) << "category " << c;
        EXPECT_EQ(wrong[c], 0) << "category " << c;
    }
}
