// Billboards on the GPU against the CPU: the quad the vertex shader builds covers the screen
// rectangle render::billboardMatrix predicts, from many cameras and for every kind; 10,000
// instances take one draw call; cutout, blending order, HDR tint, pixel sizes and gizmos.
#include "GlTestContext.h"
#include "RadianceFrame.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <filesystem>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/Program.h"
#include "shading/Billboard.h"
#include "render/passes/BillboardPass.h"
#include "render/LightBuffer.h"
#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"
#include "shaders/shared/BillboardData.h"

using namespace specula;
using specula::test::GlTest;
using scene::BillboardKind;

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

/// Pixel bounds, inclusive, in image coordinates (row 0 at the top).
struct PixelBox {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    int count = 0;
    bool empty() const { return count == 0; }
};

scene::Image whiteImage()
{
    scene::Image image;
    image.name = "white";
    image.width = image.height = 4;
    image.pixels.assign(4 * 4 * 4, 255);
    return image;
}

/// One opaque white billboard (a fully opaque image, so it covers its whole quad).
scene::Scene oneBillboard(BillboardKind kind, glm::vec3 position, glm::vec2 size, glm::vec2 anchor, glm::vec3 axis)
{
    scene::Scene s;
    s.images.push_back(whiteImage());
    scene::BillboardGroup group;
    group.kind = kind;
    group.size = size;
    group.anchor = anchor;
    group.image = 0;
    group.alphaMode = scene::AlphaMode::Opaque;
    group.billboards.push_back({position, 1.0f, glm::vec3(1.0f), axis});
    s.billboards.push_back(group);
    return s;
}

PixelBox coveredPixels(const ImageFloat& image, float threshold = 0.5f)
{
    PixelBox box;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (image.pixels[(size_t(y) * image.width + x) * 4] <= threshold) continue;
            box.x0 = std::min(box.x0, x);
            box.x1 = std::max(box.x1, x);
            box.y0 = std::min(box.y0, y);
            box.y1 = std::max(box.y1, y);
            ++box.count;
        }
    }
    return box;
}

/// The pixels whose centres fall inside the bounding box of the projected corners.
PixelBox predictedPixels(const std::array<glm::vec3, 4>& corners, const render::View& view, int width, int height)
{
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& corner : corners) {
        const glm::vec4 clip = view.projection * view.view * glm::vec4(corner, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        // Window coordinates with y down (image rows).
        const glm::vec2 window((ndc.x * 0.5f + 0.5f) * float(width), (0.5f - ndc.y * 0.5f) * float(height));
        lo = glm::min(lo, window);
        hi = glm::max(hi, window);
    }
    // Pixel i's centre is at i + 0.5.
    PixelBox box;
    box.x0 = int(std::ceil(lo.x - 0.5f));
    box.x1 = int(std::floor(hi.x - 0.5f));
    box.y0 = int(std::ceil(lo.y - 0.5f));
    box.y1 = int(std::floor(hi.y - 0.5f));
    box.count = 1;
    return box;
}

glm::vec3 centrePixel(const ImageFloat& image, int x, int y)
{
    const float* p = &image.pixels[(size_t(y) * image.width + x) * 4];
    return {p[0], p[1], p[2]};
}

/// Window position (image rows, y down) of a world point.
glm::vec2 project(glm::vec3 point, const render::View& view, int width, int height)
{
    const glm::vec4 clip = view.projection * view.view * glm::vec4(point, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * float(width), (0.5f - ndc.y * 0.5f) * float(height)};
}

} // namespace

TEST_F(GlTest, BillboardCoversTheRectanglePredictedOnTheCpu)
{
    const glm::vec3 position(0.3f, 0.2f, -0.4f);
    const glm::vec3 axis = glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f));
    const glm::vec3 cameras[] = {{0, 0, 5}, {4, 1, 3}, {-3, 2.5f, 2}, {0.5f, -2, 4}, {2, 6, 1.5f}, {-5, 0.5f, -3}, {1, 1, -6}};
    const struct {
        BillboardKind kind;
        glm::vec2 size, anchor;
    } kinds[] = {
        // Anchors off the centre line, so a mirrored basis (right negated) would show.
        {BillboardKind::PointSprite, {1.2f, 0.8f}, {0.2f, 0.5f}},
        {BillboardKind::AxisAligned, {0.9f, 1.6f}, {0.8f, 0.0f}},
        {BillboardKind::ArbitraryAxis, {0.5f, 1.8f}, {0.3f, 0.6f}},
    };
    render::Renderer renderer;
    int compared = 0;
    for (const auto& k : kinds) {
        renderer.setScene(oneBillboard(k.kind, position, k.size, k.anchor, axis));
        for (const glm::vec3& eye : cameras) {
            // Look slightly past the billboard so it is not at the exact centre of the view.
            const render::View view = render::lookAtView(eye, position + glm::vec3(0.2f, -0.1f, 0.0f), {0, 1, 0},
                                                         glm::radians(40.0f), float(kWidth) / kHeight, 0.1f, 50.0f);
            renderer.render(view, test::radianceFrame(kWidth, kHeight));
            const ImageFloat image = renderer.readRadiance();
            const glm::mat4 basis = render::billboardMatrix(k.kind, position, eye, render::cameraUpFromView(view.view), axis);
            const PixelBox expected = predictedPixels(render::billboardCorners(basis, k.size, k.anchor), view, kWidth, kHeight);
            const PixelBox got = coveredPixels(image);
            const std::string what = "kind " + std::to_string(int(k.kind)) + " from (" + std::to_string(eye.x) + ", " +
                                     std::to_string(eye.y) + ", " + std::to_string(eye.z) + ")";
            ASSERT_GT(got.count, 30) << what; // big enough on screen for the comparison to mean something
            // Within one pixel: a corner's tip may stop short of the next pixel centre.
            EXPECT_NEAR(got.x0, expected.x0, 1) << what;
            EXPECT_NEAR(got.x1, expected.x1, 1) << what;
            EXPECT_NEAR(got.y0, expected.y0, 1) << what;
            EXPECT_NEAR(got.y1, expected.y1, 1) << what;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 21);
}

TEST_F(GlTest, PixelSizedBillboardKeepsItsSizeOnScreen)
{
    render::Renderer renderer;
    for (float distance : {1.5f, 6.0f, 40.0f}) {
        scene::Scene s = oneBillboard(BillboardKind::PointSprite, {0, 0, 0}, {20.0f, 12.0f}, {0.5f, 0.5f}, {0, 1, 0});
        s.billboards[0].sizeInPixels = true;
        renderer.setScene(s);
        const render::View view = render::lookAtView({0, 0, distance}, {0, 0, 0}, {0, 1, 0}, glm::radians(50.0f),
                                                     float(kWidth) / kHeight, 0.1f, 100.0f);
        renderer.render(view, test::radianceFrame(kWidth, kHeight));
        const PixelBox got = coveredPixels(renderer.readRadiance());
        EXPECT_NEAR(got.x1 - got.x0 + 1, 20, 1) << "distance " << distance;
        EXPECT_NEAR(got.y1 - got.y0 + 1, 12, 1) << "distance " << distance;
    }
}

TEST_F(GlTest, TenThousandBillboardsInOneDrawCall)
{
    auto grid = [](int count, scene::AlphaMode mode) {
        scene::Scene s;
        scene::BillboardGroup group;
        group.kind = BillboardKind::PointSprite;
        group.sprite = scene::BuiltinSprite::Disc;
        group.alphaMode = mode;
        group.size = glm::vec2(0.09f);
        for (int i = 0; i < count; ++i)
            group.billboards.push_back({{(float(i % 100) - 49.5f) * 0.1f, (float(i / 100) - 49.5f) * 0.1f, 0.0f}, 1.0f, glm::vec3(1.0f)});
        s.billboards.push_back(group);
        return s;
    };
    const render::View view = render::lookAtView({0, 0, 12}, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 50.0f);
    const render::FrameSettings settings = test::radianceFrame(400, 400);
    render::Renderer renderer;
    for (scene::AlphaMode mode : {scene::AlphaMode::Mask, scene::AlphaMode::Blend}) {
        renderer.setScene(grid(0, mode));
        renderer.render(view, settings);
        const int baseline = renderer.stats().drawCalls; // the tone mapper's
        renderer.setScene(grid(10000, mode));
        renderer.render(view, settings);
        EXPECT_EQ(renderer.stats().drawCalls, baseline + 1) << "alpha mode " << int(mode);
        EXPECT_EQ(renderer.stats().triangles, 20000u);
        // And they were drawn: each covers about 3.5 x 3.5 pixels, so most of the grid is lit.
        const PixelBox box = coveredPixels(renderer.readRadiance(), 0.25f);
        EXPECT_GT(box.count, 10000 * 4) << "alpha mode " << int(mode);
        EXPECT_LT(box.x0, 60);
        EXPECT_GT(box.x1, 340);
    }
}

TEST_F(GlTest, BillboardCutoutBlendingAndHdr)
{
    const render::View view = render::lookAtView({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, glm::radians(40.0f), 1.0f, 0.1f, 20.0f);
    const render::FrameSettings settings = test::radianceFrame(64, 64);
    render::Renderer renderer;
    auto disc = [](glm::vec3 position, glm::vec3 tint, scene::AlphaMode mode) {
        scene::BillboardGroup group;
        group.sprite = scene::BuiltinSprite::Disc;
        group.alphaMode = mode;
        group.tint = tint;
        group.size = glm::vec2(1.0f);
        group.billboards.push_back({position, 1.0f, glm::vec3(1.0f)});
        return group;
    };

    // Cutout, HDR: the centre emits the tint unclamped; a corner of the quad is cut away.
    scene::Scene s;
    s.billboards.push_back(disc({0, 0, 0}, {40.0f, 20.0f, 5.0f}, scene::AlphaMode::Mask));
    renderer.setScene(s);
    renderer.render(view, settings);
    ImageFloat image = renderer.readRadiance();
    glm::vec3 centre = centrePixel(image, 32, 32);
    EXPECT_NEAR(centre.x, 40.0f, 0.05f);
    EXPECT_NEAR(centre.y, 20.0f, 0.02f);
    EXPECT_NEAR(centre.z, 5.0f, 0.01f);
    const glm::vec2 corner = project({0.45f, 0.45f, 0.0f}, view, 64, 64); // outside the disc, inside the quad
    EXPECT_EQ(centrePixel(image, int(corner.x), int(corner.y)), glm::vec3(0.0f));
    // Cut-out sprites write depth: one behind an opaque plane is hidden.
    scene::Material black;
    black.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    black.metallicFactor = 0.0f;
    black.emissiveFactor = glm::vec3(0.25f);
    scene::addShape(s, scene::makePlane(0.4f), black,
                    glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, 0.5f}), glm::radians(90.0f), glm::vec3(1, 0, 0)));
    renderer.setScene(s);
    renderer.render(view, settings);
    image = renderer.readRadiance();
    EXPECT_NEAR(centrePixel(image, 32, 32).x, 0.25f, 1e-3f);
    EXPECT_NEAR(centrePixel(image, 32, 25).x, 40.0f, 0.05f); // just above the plane, the sprite shows

    // Blended, two groups: the nearer one covers the farther one whatever order the groups come in.
    for (bool redNearer : {true, false}) {
        scene::Scene blend;
        blend.billboards.push_back(disc({0, 0, redNearer ? 0.5f : -0.5f}, {1, 0, 0}, scene::AlphaMode::Blend));
        blend.billboards.push_back(disc({0.1f, 0, redNearer ? -0.5f : 0.5f}, {0, 0, 1}, scene::AlphaMode::Blend));
        renderer.setScene(blend);
        renderer.render(view, settings);
        image = renderer.readRadiance();
        centre = centrePixel(image, 32, 32); // inside both discs' solid cores
        EXPECT_NEAR(centre.x, redNearer ? 1.0f : 0.0f, 1e-3f) << "red nearer " << redNearer;
        EXPECT_NEAR(centre.z, redNearer ? 0.0f : 1.0f, 1e-3f) << "red nearer " << redNearer;
        EXPECT_EQ(renderer.stats().drawCalls, 3); // two runs of one group each, and the tone mapper
    }
    // Blended edges are partial: between the solid core and the rim, alpha is strictly between 0 and 1.
    scene::Scene soft;
    soft.billboards.push_back(disc({0, 0, 0}, {1, 1, 1}, scene::AlphaMode::Blend));
    renderer.setScene(soft);
    renderer.render(view, settings);
    image = renderer.readRadiance();
    const glm::vec2 rim = project({0.37f, 0.0f, 0.0f}, view, 64, 64);
    const float value = centrePixel(image, int(rim.x), int(rim.y)).x;
    EXPECT_GT(value, 0.02f);
    EXPECT_LT(value, 0.98f);
}

TEST_F(GlTest, DegenerateViewsRenderFinite)
{
    // The camera straight above each kind of billboard, its up along −Z: finite pixels, no GL error.
    render::Renderer renderer;
    for (BillboardKind kind : {BillboardKind::PointSprite, BillboardKind::AxisAligned, BillboardKind::ArbitraryAxis}) {
        renderer.setScene(oneBillboard(kind, {0, 0, 0}, {1.0f, 1.0f}, {0.5f, 0.5f}, {0, 1, 0}));
        const render::View view = render::lookAtView({0, 5, 0}, {0, 0, 0}, {0, 0, -1}, glm::radians(40.0f), 1.0f, 0.1f, 20.0f);
        renderer.render(view, test::radianceFrame(32, 32));
        const ImageFloat image = renderer.readRadiance();
        for (float v : image.pixels) ASSERT_TRUE(std::isfinite(v)) << "kind " << int(kind);
        // A point sprite faces the camera even from above; the others are edge-on and vanish.
        const PixelBox box = coveredPixels(image);
        if (kind == BillboardKind::PointSprite) EXPECT_GT(box.count, 16);
        else EXPECT_EQ(box.count, 0) << "kind " << int(kind);
    }
}

TEST_F(GlTest, LightGizmosAreDiscsOfTheLightColour)
{
    scene::Scene s;
    scene::Light point;
    point.type = scene::Light::Type::Point;
    point.color = {1.0f, 0.5f, 0.25f};
    point.intensity = 10.0f;
    const glm::vec3 lightPosition(0.6f, 0.3f, 0.0f);
    scene::addLight(s, point, lightPosition, {0, 0, -1});
    // An opaque wall between the camera and the light: gizmos show through it.
    scene::Material wall;
    wall.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    wall.metallicFactor = 0.0f;
    scene::addShape(s, scene::makePlane(10.0f), wall,
                    glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, 1}), glm::radians(90.0f), glm::vec3(1, 0, 0)));

    const render::View view = render::lookAtView({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, glm::radians(40.0f), 1.0f, 0.1f, 20.0f);
    render::FrameSettings settings = test::radianceFrame(128, 128);
    settings.shadows.enabled = false; // counts draw calls: the gizmos' alone
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, settings);
    const int drawsWithout = renderer.stats().drawCalls;
    EXPECT_TRUE(coveredPixels(renderer.readRadiance(), 1e-3f).empty());

    settings.gizmos = true;
    renderer.render(view, settings);
    EXPECT_EQ(renderer.stats().drawCalls, drawsWithout + 1);
    const ImageFloat image = renderer.readRadiance();
    const glm::vec2 at = project(lightPosition, view, 128, 128);
    const glm::vec3 centre = centrePixel(image, int(at.x), int(at.y));
    const glm::vec3 expected = point.color * render::kGizmoRadiance;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], expected[c], expected[c] * 2e-3f) << "channel " << c;
    // kGizmoSizePixels across, centred on the light (the disc fades out towards the quad's rim).
    // One pixel more is allowed: off the view axis perspective stretches the quad by 1/cos²θ
    // radially (2% at this light's 8.5°), and pixel sizes are exact only at the centre.
    const PixelBox box = coveredPixels(image, 1e-3f);
    EXPECT_LE(box.x1 - box.x0 + 1, int(render::kGizmoSizePixels) + 1);
    EXPECT_GE(box.x1 - box.x0 + 1, int(render::kGizmoSizePixels) - 4);
    EXPECT_NEAR(0.5f * float(box.x0 + box.x1 + 1), at.x, 1.0f);
    EXPECT_NEAR(0.5f * float(box.y0 + box.y1 + 1), at.y, 1.0f);

    // The gizmos follow edits to the light buffer.
    render::PlacedLight moved = renderer.light(0);
    moved.position = {-0.6f, -0.3f, 0.0f};
    renderer.setLight(0, moved);
    renderer.render(view, settings);
    const glm::vec2 movedAt = project(moved.position, view, 128, 128);
    EXPECT_NEAR(centrePixel(renderer.readRadiance(), int(movedAt.x), int(movedAt.y)).x, expected.x, expected.x * 2e-3f);
}

namespace {

/// Linear radiance at a window position (image rows), 0 outside the image.
glm::vec3 radianceAt(const ImageFloat& image, glm::vec2 at)
{
    const int x = int(std::floor(at.x)), y = int(std::floor(at.y));
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return glm::vec3(0.0f);
    return centrePixel(image, x, y);
}

/// The brightest green radiance within `radius` pixels of `at` (a rod is thin: the segment's
/// exact pixel may sit half a pixel off its centre line).
float greenNear(const ImageFloat& image, glm::vec2 at, int radius)
{
    float best = 0.0f;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) best = std::max(best, radianceAt(image, at + glm::vec2(dx, dy)).g);
    return best;
}

/// Fraction of the points at t in [t0, t1] along the projected segment a → b with a lit pixel
/// (green radiance above `threshold`) within one pixel.
float litAlong(const ImageFloat& image, glm::vec2 a, glm::vec2 b, float t0, float t1, float threshold)
{
    int lit = 0, total = 0;
    for (float t = t0; t <= t1 + 1e-4f; t += 0.02f, ++total)
        if (greenNear(image, glm::mix(a, b, t), 1) > threshold) ++lit;
    return float(lit) / float(total);
}

/// Distance from `p` to the convex polygon `hull` (either winding): 0 inside.
float distanceToConvexHull(const std::vector<glm::vec2>& hull, glm::vec2 p)
{
    bool inside = true;
    float nearest = 1e30f;
    float sign = 0.0f;
    for (size_t i = 0; i < hull.size(); ++i) {
        const glm::vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
        const glm::vec2 e = b - a;
        const float cross = e.x * (p.y - a.y) - e.y * (p.x - a.x);
        if (sign == 0.0f && cross != 0.0f) sign = cross > 0.0f ? 1.0f : -1.0f;
        if (cross * sign < 0.0f) inside = false;
        const float t = std::clamp(glm::dot(p - a, e) / std::max(glm::dot(e, e), 1e-12f), 0.0f, 1.0f);
        nearest = std::min(nearest, glm::distance(p, a + t * e));
    }
    return inside ? 0.0f : nearest;
}

/// Convex hull of 2D points (Andrew's monotone chain).
std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points)
{
    std::sort(points.begin(), points.end(), [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<glm::vec2> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0f) --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0f) --k;
        hull[k++] = points[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

} // namespace

// The expectation is the light itself, not the gizmo code: the rod along a spot light's
// direction covers the segment from its position to position + direction × range, projected
// with the camera on the CPU; the cone's rods stay inside the projected cone (out to the range)
// and reach out to its rim; all move when the light turns.
TEST_F(GlTest, LightGizmoRodsShowDirectionAndCone)
{
    constexpr int kW = 320, kH = 240;
    scene::Scene s; // no surfaces, no environment: every lit pixel is a gizmo's
    scene::Light spot;
    spot.type = scene::Light::Type::Spot;
    spot.color = {0.2f, 1.0f, 0.4f};
    spot.range = 1.6f;
    spot.innerConeAngle = glm::radians(10.0f);
    spot.outerConeAngle = glm::radians(30.0f);
    const glm::vec3 apex(-0.8f, -0.1f, 0.0f);
    // Tilted a little, so the rod crosses pixel rows at every sub-pixel offset along its length.
    const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, 0.1f, 0.0f));
    scene::addLight(s, spot, apex, direction);
    // From afar with a narrow field: little perspective, so the cone seen from the side is close
    // to the triangle an orthographic view would show.
    const render::View view = render::lookAtView({0, 0, 8}, {0, 0, 0}, {0, 1, 0}, glm::radians(22.0f), float(kW) / kH, 0.1f, 20.0f);
    render::FrameSettings settings = test::radianceFrame(kW, kH);
    settings.gizmos = true;
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, settings);
    const ImageFloat image = renderer.readRadiance();
    const std::filesystem::path out = std::filesystem::path(SPECULA_TEST_OUTPUT_DIR) / "billboards";
    std::filesystem::create_directories(out);
    writePng(out / "gizmo-rods.png", renderer.readImage()); // for review by eye

    // Lit = more than a third of the rod's radiance (the bar sprite's soft sides are fainter);
    // the inner cone's rods (kGizmoInnerConeTint) stay below that.
    const float threshold = render::kGizmoRodRadiance * spot.color.g / 3.0f;
    ASSERT_LT(render::kGizmoInnerConeTint, 1.0f / 3.0f);
    const float discRadius = 0.5f * render::kGizmoSizePixels + 1.0f;
    const glm::vec2 a = project(apex, view, kW, kH);
    const glm::vec2 end = project(apex + direction * spot.range, view, kW, kH);
    // From outside the disc to the rod's far end.
    const float t0 = discRadius / glm::distance(a, end);
    EXPECT_GT(litAlong(image, a, end, t0, 0.97f, threshold), 0.95f) << "no rod along the light's direction";
    EXPECT_LT(greenNear(image, glm::mix(a, end, 1.06f), 1), threshold) << "the direction rod is longer than the range";
    // Gizmo-coloured: the light's colour x kGizmoRodRadiance x the sprite's cover.
    const glm::vec3 mid = radianceAt(image, glm::mix(a, end, 0.5f));
    EXPECT_GT(mid.g, threshold);
    EXPECT_NEAR(mid.r / mid.g, spot.color.r / spot.color.g, 0.02f);
    EXPECT_NEAR(mid.b / mid.g, spot.color.b / spot.color.g, 0.02f);

    // The cone's outline on screen: the convex hull of the apex and the cap of the sphere of
    // radius range within the outer angle of the direction (where the rods end).
    auto coneOutline = [&](glm::vec3 d, float outer, float* rimReach) {
        const glm::vec3 u = glm::normalize(glm::cross(d, glm::vec3(0, 0, 1)));
        const glm::vec3 v = glm::cross(d, u);
        std::vector<glm::vec2> points{a};
        *rimReach = 0.0f; // largest screen distance of the cone's rim from the projected axis line
        const glm::vec2 axis = glm::normalize(project(apex + d * spot.range, view, kW, kH) - a);
        for (int i = 0; i <= 8; ++i) {
            const float angle = outer * float(i) / 8.0f;
            for (int k = 0; k < 360; k += 2) {
                const float phi = glm::radians(float(k));
                const glm::vec3 edge = std::cos(angle) * d + std::sin(angle) * (std::cos(phi) * u + std::sin(phi) * v);
                points.push_back(project(apex + edge * spot.range, view, kW, kH));
                const glm::vec2 off = points.back() - a;
                if (i == 8) *rimReach = std::max(*rimReach, std::abs(off.x * axis.y - off.y * axis.x));
            }
        }
        return convexHull(points);
    };
    // The rods' farthest reach from the projected axis line, outside the disc.
    auto farthestFromAxis = [&](const ImageFloat& im, glm::vec3 d) {
        const glm::vec2 axis = glm::normalize(project(apex + d * spot.range, view, kW, kH) - a);
        float farthest = 0.0f;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const glm::vec2 off = glm::vec2(x + 0.5f, y + 0.5f) - a;
                if (centrePixel(im, x, y).g > threshold && glm::length(off) > discRadius)
                    farthest = std::max(farthest, std::abs(off.x * axis.y - off.y * axis.x));
            }
        return farthest;
    };
    // Every lit pixel lies inside the outline give or take 2 pixels (a rod's half width and a
    // pixel of rasterisation), and the rods reach out to near the rim's projection: at least 80%
    // of the way, as 8 evenly spread rods leave at most 22.5° between the rim's top and the
    // nearest rod (cos 22.5° = 0.92; the rest is perspective). Which azimuths the rods take is
    // the implementation's choice.
    float rimReach = 0.0f;
    const std::vector<glm::vec2> hull = coneOutline(direction, spot.outerConeAngle, &rimReach);
    int outside = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            if (centrePixel(image, x, y).g <= threshold || glm::distance(p, a) <= discRadius) continue;
            if (distanceToConvexHull(hull, p) > 2.0f) ++outside;
        }
    }
    EXPECT_EQ(outside, 0) << "lit pixels outside the light's cone";
    const float reach = farthestFromAxis(image, direction);
    EXPECT_GT(reach, 0.8f * rimReach) << "the cone's rods do not reach its rim";
    EXPECT_LT(reach, rimReach + 2.0f);

    // Turning the light: the rod follows, and none is left along the old direction.
    render::PlacedLight turned = renderer.light(0);
    turned.direction = {0, 1, 0};
    renderer.setLight(0, turned);
    renderer.render(view, settings);
    const ImageFloat after = renderer.readRadiance();
    const glm::vec2 up = project(apex + glm::vec3(0, 1, 0) * spot.range, view, kW, kH);
    EXPECT_GT(litAlong(after, a, up, discRadius / glm::distance(a, up), 0.97f, threshold), 0.95f) << "no rod along the new direction";
    EXPECT_LT(litAlong(after, a, end, 0.6f, 0.97f, threshold), 0.05f) << "a rod stayed along the old direction";

    // A wider cone reaches further from the axis, as far as its own rim.
    turned.direction = direction;
    turned.light.outerConeAngle = glm::radians(45.0f);
    renderer.setLight(0, turned);
    renderer.render(view, settings);
    float widerRim = 0.0f;
    coneOutline(direction, turned.light.outerConeAngle, &widerRim);
    const float widerReach = farthestFromAxis(renderer.readRadiance(), direction);
    EXPECT_GT(widerReach, 0.8f * widerRim);
    EXPECT_GT(widerReach, reach + 10.0f) << "the cone's rods did not follow the cone angle";

    // The selected light's rod is wider: the radiance summed across the rod (its width in
    // pixels times the sprite's mean cover), averaged along it, grows by kGizmoSelectedScale.
    turned.light.outerConeAngle = spot.outerConeAngle;
    renderer.setLight(0, turned);
    auto across = [&](const ImageFloat& im) {
        float sum = 0.0f;
        for (float t = 0.55f; t <= 0.9f; t += 0.01f)
            for (int dy = -6; dy <= 6; ++dy) sum += radianceAt(im, glm::mix(a, end, t) + glm::vec2(0.0f, float(dy))).g;
        return sum;
    };
    renderer.render(view, settings);
    const float plain = across(renderer.readRadiance());
    settings.selectedLight = 0;
    renderer.render(view, settings);
    const float selected = across(renderer.readRadiance());
    EXPECT_NEAR(selected / plain, render::kGizmoSelectedScale, 0.2f);
}

TEST_F(GlTest, BillboardInstanceLayoutMatchesGlsl)
{
    const gl::Program program({.vertex = "billboard/billboard.vert", .fragment = "billboard/billboard.frag"});
    auto property = [&](const char* name, GLenum what) {
        const GLuint index = glGetProgramResourceIndex(program.id(), GL_BUFFER_VARIABLE, name);
        EXPECT_NE(index, GL_INVALID_INDEX) << name;
        GLint value = -1;
        glGetProgramResourceiv(program.id(), GL_BUFFER_VARIABLE, index, 1, &what, 1, nullptr, &value);
        return value;
    };
    using shared::GpuBillboard;
    EXPECT_EQ(property("billboards[0].positionScale", GL_OFFSET), GLint(offsetof(GpuBillboard, positionScale)));
    EXPECT_EQ(property("billboards[0].tint", GL_OFFSET), GLint(offsetof(GpuBillboard, tint)));
    EXPECT_EQ(property("billboards[0].axis", GL_OFFSET), GLint(offsetof(GpuBillboard, axis)));
    EXPECT_EQ(property("billboards[0].positionScale", GL_TOP_LEVEL_ARRAY_STRIDE), GLint(sizeof(GpuBillboard)));
}

TEST_F(GlTest, DemoBillboardsFromSeveralCameras)
{
    // For review by eye (build/test-output/billboards/): trees stay upright and turn about +Y,
    // lanterns and gizmos face the camera, the neon rods keep their leaning axes.
    scene::Scene s = scene::makeDemoScene();
    render::Renderer renderer;
    renderer.setScene(s);
    render::FrameSettings settings;
    settings.width = 480;
    settings.height = 270;
    settings.gizmos = true;
    const std::filesystem::path out = std::filesystem::path(SPECULA_TEST_OUTPUT_DIR) / "billboards";
    std::filesystem::create_directories(out);
    const struct {
        const char* name;
        glm::vec3 eye, target;
    } cameras[] = {
        {"front", {0.0f, 3.6f, 11.0f}, {0.0f, 2.7f, 0.0f}},
        {"left", {-10.0f, 2.0f, 5.0f}, {0.0f, 2.0f, -1.0f}},
        {"high-right", {8.0f, 9.0f, 6.0f}, {0.0f, 1.5f, -1.0f}},
        {"behind-low", {3.0f, 0.8f, -11.0f}, {0.0f, 2.0f, 0.0f}},
        {"above", {0.0f, 16.0f, 0.01f}, {0.0f, 0.0f, 0.0f}},
    };
    for (const auto& c : cameras) {
        const render::View view = render::lookAtView(c.eye, c.target, {0, 1, 0}, glm::radians(50.0f), 16.0f / 9.0f, 0.1f, 100.0f);
        renderer.render(view, settings);
        writePng(out / (std::string("demo-") + c.name + ".png"), renderer.readImage());
        const ImageFloat image = renderer.readRadiance();
        for (float v : image.pixels) ASSERT_TRUE(std::isfinite(v)) << c.name;
    }
}
