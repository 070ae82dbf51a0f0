// Billboard math (shading/Billboard.h): each kind's basis is orthonormal and right-handed and
// turns the way it should; degenerate views give finite, steady bases; quads, pixel sizes and
// the built-in sprites.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/Billboard.h"
#include "render/passes/BillboardPass.h"

using namespace specula;
using scene::BillboardKind;

namespace {

constexpr BillboardKind kKinds[] = {BillboardKind::PointSprite, BillboardKind::AxisAligned, BillboardKind::ArbitraryAxis};

glm::vec3 column(const glm::mat4& m, int i)
{
    return glm::vec3(m[i]);
}

bool finite(const glm::mat4& m)
{
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

/// Unit columns, pairwise perpendicular, right × up = look, position in column 3 with w = 1.
void expectBasis(const glm::mat4& m, glm::vec3 position, const std::string& what)
{
    ASSERT_TRUE(finite(m)) << what;
    const glm::vec3 right = column(m, 0), up = column(m, 1), look = column(m, 2);
    EXPECT_NEAR(glm::length(right), 1.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::length(up), 1.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::length(look), 1.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::dot(right, up), 0.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::dot(right, look), 0.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::dot(up, look), 0.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::distance(glm::cross(right, up), look), 0.0f, 1e-5f) << what << ": not right-handed";
    EXPECT_NEAR(glm::determinant(glm::mat3(m)), 1.0f, 1e-5f) << what;
    EXPECT_EQ(glm::vec4(m[3]), glm::vec4(position, 1.0f)) << what;
    EXPECT_EQ(m[0][3], 0.0f);
    EXPECT_EQ(m[1][3], 0.0f);
    EXPECT_EQ(m[2][3], 0.0f);
}

struct ViewCase {
    glm::vec3 position, camera, cameraUp, axis;
};

/// Random billboards seen by random cameras that look at them (cameraUp from a real view).
std::vector<ViewCase> randomSetups(int count)
{
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f);
    std::vector<ViewCase> setups;
    while (int(setups.size()) < count) {
        const glm::vec3 position(u(rng), u(rng), u(rng));
        const glm::vec3 camera(u(rng), u(rng), u(rng));
        const glm::vec3 axis(u(rng), u(rng), u(rng));
        if (glm::length(camera - position) < 0.1f || glm::length(axis) < 0.1f) continue;
        // A camera looking near (not at) the billboard, as in a real frame.
        const glm::vec3 target = position + glm::vec3(u(rng), u(rng), u(rng)) * 0.05f;
        const glm::vec3 forward = glm::normalize(target - camera);
        if (std::abs(forward.y) > 0.99f) continue; // lookAt with +Y up is undefined there
        setups.push_back({position, camera, render::cameraUpFromView(glm::lookAt(camera, target, {0, 1, 0})), axis});
    }
    return setups;
}

} // namespace

TEST(Billboard, CameraUpFromView)
{
    const glm::mat4 view = glm::lookAt(glm::vec3(1, 2, 3), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    const glm::vec3 up = render::cameraUpFromView(view);
    // The camera's up is world +Y made perpendicular to the view direction.
    const glm::vec3 forward = glm::normalize(glm::vec3(-1, -2, -3));
    const glm::vec3 expected = glm::normalize(glm::vec3(0, 1, 0) - forward * forward.y);
    EXPECT_NEAR(glm::distance(up, expected), 0.0f, 1e-5f);
}

TEST(Billboard, BasesAreOrthonormalAndRightHanded)
{
    for (const ViewCase& s : randomSetups(500))
        for (BillboardKind kind : kKinds)
            expectBasis(render::billboardMatrix(kind, s.position, s.camera, s.cameraUp, s.axis), s.position,
                        "kind " + std::to_string(int(kind)));
}

TEST(Billboard, PointSpriteFacesTheCamera)
{
    for (const ViewCase& s : randomSetups(300)) {
        const glm::mat4 m = render::billboardMatrix(BillboardKind::PointSprite, s.position, s.camera, s.cameraUp);
        const glm::vec3 toCamera = glm::normalize(s.camera - s.position);
        // look ∥ camera − position, pointing at the camera.
        EXPECT_NEAR(glm::dot(column(m, 2), toCamera), 1.0f, 1e-5f);
        // up' is the camera's up made perpendicular to look: same half-space, right ⟂ camera up.
        EXPECT_GT(glm::dot(column(m, 1), s.cameraUp), 0.0f);
        EXPECT_NEAR(glm::dot(column(m, 0), s.cameraUp), 0.0f, 1e-5f);
    }
    // Exactly the formulas.
    const glm::vec3 p(1, 2, 3), c(4, -1, 7), up(0.1f, 1.0f, 0.2f);
    const glm::vec3 look = glm::normalize(c - p);
    const glm::vec3 right = glm::normalize(glm::cross(up, look));
    const glm::mat4 m = render::billboardMatrix(BillboardKind::PointSprite, p, c, up);
    EXPECT_NEAR(glm::distance(column(m, 0), right), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(column(m, 1), glm::cross(look, right)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(column(m, 2), look), 0.0f, 1e-6f);
}

TEST(Billboard, AxisAlignedKeepsUpFromEveryCamera)
{
    for (const ViewCase& s : randomSetups(300)) {
        const glm::mat4 m = render::billboardMatrix(BillboardKind::AxisAligned, s.position, s.camera, s.cameraUp);
        EXPECT_EQ(column(m, 1), glm::vec3(0, 1, 0));
        // look is the flattened direction to the camera.
        glm::vec3 flat = s.camera - s.position;
        flat.y = 0.0f;
        EXPECT_NEAR(glm::dot(column(m, 2), glm::normalize(flat)), 1.0f, 1e-5f);
        EXPECT_EQ(column(m, 2).y, 0.0f);
    }
    // A camera circling the billboard at several heights: the sprite turns, up never tilts.
    for (float height : {-20.0f, -1.0f, 0.0f, 0.5f, 3.0f, 50.0f}) {
        for (int i = 0; i < 36; ++i) {
            const float angle = glm::radians(10.0f * float(i));
            const glm::vec3 camera(5.0f * std::cos(angle), height, 5.0f * std::sin(angle));
            const glm::mat4 m = render::billboardMatrix(BillboardKind::AxisAligned, glm::vec3(0.0f), camera, {0, 1, 0});
            expectBasis(m, glm::vec3(0.0f), "orbit");
            EXPECT_EQ(column(m, 1), glm::vec3(0, 1, 0));
            EXPECT_NEAR(glm::dot(column(m, 2), glm::normalize(glm::vec3(camera.x, 0.0f, camera.z))), 1.0f, 1e-5f);
        }
    }
}

TEST(Billboard, ArbitraryAxisKeepsItsAxis)
{
    for (const ViewCase& s : randomSetups(300)) {
        const glm::mat4 m = render::billboardMatrix(BillboardKind::ArbitraryAxis, s.position, s.camera, s.cameraUp, s.axis);
        const glm::vec3 a = glm::normalize(s.axis);
        EXPECT_NEAR(glm::distance(column(m, 1), a), 0.0f, 1e-5f);
        // It turns towards the camera as far as the axis allows: look is the direction to the
        // camera with its component along the axis removed.
        const glm::vec3 toCamera = s.camera - s.position;
        const glm::vec3 across = toCamera - a * glm::dot(toCamera, a);
        if (glm::length(across) > 1e-3f) {
            EXPECT_NEAR(glm::dot(column(m, 2), glm::normalize(across)), 1.0f, 1e-4f);
        }
        // right = normalize(cross(A, look₀)), look' = cross(right, A).
        const glm::vec3 right = glm::normalize(glm::cross(a, glm::normalize(toCamera)));
        EXPECT_NEAR(glm::distance(column(m, 0), right), 0.0f, 1e-4f);
        EXPECT_NEAR(glm::distance(column(m, 2), glm::cross(right, a)), 0.0f, 1e-4f);
    }
    // With A = +Y it is the axis-aligned billboard.
    for (const ViewCase& s : randomSetups(50)) {
        const glm::mat4 a = render::billboardMatrix(BillboardKind::ArbitraryAxis, s.position, s.camera, s.cameraUp, {0, 3, 0});
        const glm::mat4 b = render::billboardMatrix(BillboardKind::AxisAligned, s.position, s.camera, s.cameraUp);
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(glm::distance(a[c], b[c]), 0.0f, 1e-5f);
    }
}

TEST(Billboard, DegenerateCasesAreFinite)
{
    const glm::vec3 p(1.0f, 2.0f, -3.0f);
    struct Case {
        const char* name;
        BillboardKind kind;
        glm::vec3 camera, cameraUp, axis;
    };
    const Case cases[] = {
        // The camera straight above an axis-aligned billboard, looking down (its up is −Z or any horizontal).
        {"axis-aligned, camera above", BillboardKind::AxisAligned, p + glm::vec3(0, 10, 0), {0, 0, -1}, {0, 1, 0}},
        {"axis-aligned, camera below", BillboardKind::AxisAligned, p - glm::vec3(0, 10, 0), {1, 0, 0}, {0, 1, 0}},
        {"axis-aligned, above, up vertical too", BillboardKind::AxisAligned, p + glm::vec3(0, 10, 0), {0, 1, 0}, {0, 1, 0}},
        {"axis-aligned, above, zero up", BillboardKind::AxisAligned, p + glm::vec3(0, 10, 0), {0, 0, 0}, {0, 1, 0}},
        {"axis-aligned, nearly above", BillboardKind::AxisAligned, p + glm::vec3(1e-6f, 10, 0), {0, 0, -1}, {0, 1, 0}},
        // Look parallel to the camera's up.
        {"point sprite, look along up", BillboardKind::PointSprite, p + glm::vec3(0, 5, 0), {0, 1, 0}, {0, 1, 0}},
        {"point sprite, look against up", BillboardKind::PointSprite, p + glm::vec3(0, -5, 0), {0, 1, 0}, {0, 1, 0}},
        {"point sprite, zero up", BillboardKind::PointSprite, p + glm::vec3(0, 0, 5), {0, 0, 0}, {0, 1, 0}},
        // Look parallel to the axis.
        {"arbitrary, look along axis", BillboardKind::ArbitraryAxis, p + glm::vec3(2, 2, 2), {0, 1, 0}, {1, 1, 1}},
        {"arbitrary, look against axis", BillboardKind::ArbitraryAxis, p - glm::vec3(2, 2, 2), {0, 1, 0}, {1, 1, 1}},
        {"arbitrary, look and up along axis", BillboardKind::ArbitraryAxis, p + glm::vec3(0, 0, 4), {0, 0, 1}, {0, 0, 1}},
        {"arbitrary, zero axis", BillboardKind::ArbitraryAxis, p + glm::vec3(0, 0, 4), {0, 1, 0}, {0, 0, 0}},
    };
    for (const Case& c : cases) expectBasis(render::billboardMatrix(c.kind, p, c.camera, c.cameraUp, c.axis), p, c.name);
    // The camera exactly at the position, for every kind.
    for (BillboardKind kind : kKinds) expectBasis(render::billboardMatrix(kind, p, p, {0, 1, 0}, {0, 1, 0}), p, "camera at position");
    for (BillboardKind kind : kKinds) expectBasis(render::billboardMatrix(kind, p, p, {0, 0, 0}, {0, 0, 0}), p, "everything zero");
}

TEST(Billboard, AxisAlignedOverThePoleIsSteady)
{
    // An orbit camera tilting over the top of a tree: at (0, h, ε) looking at it, its up is −Z
    // and look is +Z. Straight above (ε = 0) the fallback picks the same basis, so the sprite
    // does not jump as the camera passes over the pole.
    const glm::vec3 p(0.0f);
    auto basisFrom = [&](float epsilon) {
        const glm::vec3 camera(0.0f, 10.0f, epsilon);
        const glm::mat4 view = glm::lookAt(camera, p, epsilon == 0.0f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0));
        return render::billboardMatrix(BillboardKind::AxisAligned, p, camera, render::cameraUpFromView(view));
    };
    const glm::mat4 near = basisFrom(1e-2f);
    const glm::mat4 above = basisFrom(0.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(glm::distance(near[c], above[c]), 0.0f, 1e-5f) << "column " << c;
    EXPECT_NEAR(glm::distance(column(above, 2), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(Billboard, CornersFollowSizeAndAnchor)
{
    const glm::mat4 basis = render::billboardMatrix(BillboardKind::PointSprite, {1, 2, 3}, {1, 2, 10}, {0, 1, 0});
    // Facing +Z: right = +X, up = +Y.
    const auto centred = render::billboardCorners(basis, {2.0f, 4.0f}, {0.5f, 0.5f});
    EXPECT_NEAR(glm::distance(centred[0], glm::vec3(0, 0, 3)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(centred[1], glm::vec3(2, 0, 3)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(centred[2], glm::vec3(2, 4, 3)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(centred[3], glm::vec3(0, 4, 3)), 0.0f, 1e-6f);
    // A tree stands on its anchor at the bottom centre.
    const auto standing = render::billboardCorners(basis, {2.0f, 4.0f}, {0.5f, 0.0f});
    EXPECT_NEAR(glm::distance(standing[0], glm::vec3(0, 2, 3)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(standing[2], glm::vec3(2, 6, 3)), 0.0f, 1e-6f);
}

TEST(Billboard, WorldUnitsPerPixel)
{
    // Perspective: at distance d a pixel spans 2 d tan(fov/2) / height.
    const float fov = glm::radians(60.0f);
    const glm::mat4 projection = glm::perspective(fov, 1.5f, 0.1f, 100.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    for (float z : {0.0f, -5.0f, 3.0f}) {
        const float d = 5.0f - z;
        EXPECT_NEAR(render::worldUnitsPerPixel(projection * view, projection, {0, 0, z}, 480),
                    2.0f * d * std::tan(fov / 2.0f) / 480.0f, 1e-6f);
    }
    // Behind the camera: zero, so a pixel-sized sprite there collapses.
    EXPECT_EQ(render::worldUnitsPerPixel(projection * view, projection, {0, 0, 10}, 480), 0.0f);
    // Orthographic: 2 ymag / height, whatever the distance.
    const glm::mat4 ortho = glm::ortho(-4.0f, 4.0f, -3.0f, 3.0f, 0.1f, 100.0f);
    EXPECT_NEAR(render::worldUnitsPerPixel(ortho * view, ortho, {0, 0, -20}, 300), 6.0f / 300.0f, 1e-6f);
}

TEST(Billboard, BuiltinSprites)
{
    const scene::Image disc = render::makeBuiltinSprite(scene::BuiltinSprite::Disc, 32);
    ASSERT_EQ(disc.width, 32);
    ASSERT_EQ(disc.height, 32);
    ASSERT_EQ(disc.pixels.size(), 32u * 32u * 4u);
    auto alpha = [](const scene::Image& image, int x, int y) { return image.pixels[(size_t(y) * image.width + x) * 4 + 3]; };
    EXPECT_EQ(alpha(disc, 16, 16), 255);
    EXPECT_EQ(alpha(disc, 0, 0), 0);
    EXPECT_EQ(alpha(disc, 31, 16), 0);
    // Round: the same alpha at the same radius in every direction.
    EXPECT_EQ(alpha(disc, 16 + 10, 16), alpha(disc, 16, 16 + 10));
    EXPECT_EQ(alpha(disc, 15 - 10, 15), alpha(disc, 15, 15 - 10));

    const scene::Image tree = render::makeBuiltinSprite(scene::BuiltinSprite::Tree, 32);
    ASSERT_EQ(tree.width, 32);
    ASSERT_EQ(tree.height, 64);
    // Trunk at the bottom centre (last rows), air in the corners, leaves in the middle.
    EXPECT_EQ(alpha(tree, 16, 63), 255);
    EXPECT_EQ(alpha(tree, 0, 63), 0);
    EXPECT_EQ(alpha(tree, 0, 0), 0);
    EXPECT_EQ(alpha(tree, 16, 32), 255);
    const uint8_t* leaf = &tree.pixels[(size_t(32) * 32 + 16) * 4];
    EXPECT_GT(leaf[1], leaf[0]); // green
    EXPECT_GT(leaf[1], leaf[2]);
    // Transparent texels carry a leaf or bark colour, never black, so filtering keeps edges clean.
    const uint8_t* air = &tree.pixels[(size_t(20) * 32 + 0) * 4];
    EXPECT_GT(int(air[0]) + air[1] + air[2], 0);
}

TEST(Billboard, LightGizmos)
{
    std::vector<render::PlacedLight> lights(3);
    lights[0].light.type = scene::Light::Type::Point;
    lights[0].light.color = {1.0f, 0.5f, 0.25f};
    lights[0].position = {1, 2, 3};
    lights[1].light.type = scene::Light::Type::Spot;
    lights[1].light.range = 2.5f;
    lights[1].light.innerConeAngle = glm::radians(10.0f);
    lights[1].light.outerConeAngle = glm::radians(30.0f);
    lights[1].position = {-1, 4, 0};
    lights[1].direction = {0, 0, -3}; // not unit: rods run along the unit direction
    lights[2].light.type = scene::Light::Type::Directional;
    lights[2].direction = {0, -2, 0}; // shining down: its gizmo sits above the scene
    scene::Bounds bounds;
    bounds.extend(glm::vec3(-1, 0, -1));
    bounds.extend(glm::vec3(3, 2, 1));
    const render::LightGizmos gizmos = render::makeLightGizmos(lights, bounds, 1);
    const scene::BillboardGroup& discs = gizmos.discs;
    EXPECT_EQ(discs.kind, BillboardKind::PointSprite);
    EXPECT_TRUE(discs.sizeInPixels);
    EXPECT_EQ(discs.size, glm::vec2(render::kGizmoSizePixels));
    EXPECT_EQ(discs.alphaMode, scene::AlphaMode::Blend);
    ASSERT_EQ(discs.billboards.size(), 3u);
    EXPECT_EQ(discs.billboards[0].position, glm::vec3(1, 2, 3));
    EXPECT_EQ(discs.billboards[0].tint, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(discs.tint, glm::vec3(render::kGizmoRadiance));
    EXPECT_EQ(discs.billboards[1].position, glm::vec3(-1, 4, 0));
    // centre − direction × radius: (1, 1, 0) + (0, 1, 0) × √6.
    const float radius = std::sqrt(6.0f);
    EXPECT_NEAR(glm::distance(discs.billboards[2].position, glm::vec3(1.0f, 1.0f + radius, 0.0f)), 0.0f, 1e-5f);
    // The selected light (1) is drawn larger, the others at their size.
    EXPECT_EQ(discs.billboards[0].scale, 1.0f);
    EXPECT_EQ(discs.billboards[1].scale, render::kGizmoSelectedScale);

    const scene::BillboardGroup& rods = gizmos.rods;
    EXPECT_EQ(rods.kind, BillboardKind::ArbitraryAxis);
    EXPECT_TRUE(rods.spanAxis);
    EXPECT_TRUE(rods.sizeInPixels);
    EXPECT_EQ(rods.size.x, render::kGizmoRodPixels);
    EXPECT_EQ(rods.anchor, glm::vec2(0.5f, 0.0f)); // each rod starts at its position
    EXPECT_EQ(rods.sprite, scene::BuiltinSprite::Bar);
    EXPECT_EQ(rods.tint, glm::vec3(render::kGizmoRodRadiance));
    // The point light has none; the spot light its cones and its direction; the directional one
    // its direction.
    ASSERT_EQ(rods.billboards.size(), size_t(render::kGizmoInnerConeRods + render::kGizmoOuterConeRods + 1 + 1));
    int inner = 0, outer = 0, along = 0;
    for (size_t i = 0; i + 1 < rods.billboards.size(); ++i) {
        const scene::Billboard& rod = rods.billboards[i];
        EXPECT_EQ(rod.position, glm::vec3(-1, 4, 0));
        EXPECT_EQ(rod.scale, render::kGizmoSelectedScale);
        EXPECT_NEAR(glm::length(rod.axis), 2.5f, 1e-5f) << "as long as the range";
        const float angle = std::acos(std::clamp(glm::dot(glm::normalize(rod.axis), glm::vec3(0, 0, -1)), -1.0f, 1.0f));
        if (std::abs(angle - glm::radians(10.0f)) < 1e-3f) {
            ++inner;
            EXPECT_EQ(rod.tint, glm::vec3(render::kGizmoInnerConeTint));
        } else if (std::abs(angle - glm::radians(30.0f)) < 1e-3f) {
            ++outer;
            EXPECT_EQ(rod.tint, glm::vec3(1.0f));
        } else if (angle < 1e-3f) {
            ++along;
        }
    }
    EXPECT_EQ(inner, render::kGizmoInnerConeRods);
    EXPECT_EQ(outer, render::kGizmoOuterConeRods);
    EXPECT_EQ(along, 1);
    // The directional light's rod: from its disc to the centre of the bounds.
    const scene::Billboard& sun = rods.billboards.back();
    EXPECT_EQ(sun.position, discs.billboards[2].position);
    EXPECT_NEAR(glm::distance(sun.position + sun.axis, glm::vec3(1, 1, 0)), 0.0f, 1e-5f);
    EXPECT_EQ(sun.scale, 1.0f);

    // Without a range a spot light's rods reach the centre of the bounds (at least the radius).
    lights[1].light.range = 0.0f;
    const render::LightGizmos unbounded = render::makeLightGizmos(lights, bounds);
    const float toCentre = glm::distance(glm::vec3(-1, 4, 0), glm::vec3(1, 1, 0));
    EXPECT_NEAR(glm::length(unbounded.rods.billboards[0].axis), std::max(toCentre, radius), 1e-5f);
}

TEST(Billboard, BarSpriteIsSolidAlongItsHeight)
{
    const scene::Image bar = render::makeBuiltinSprite(scene::BuiltinSprite::Bar, 32);
    ASSERT_EQ(bar.width, 32);
    ASSERT_EQ(bar.height, 32);
    auto alpha = [&](int x, int y) { return bar.pixels[(size_t(y) * 32 + size_t(x)) * 4 + 3]; };
    for (int y = 0; y < 32; ++y) {
        EXPECT_EQ(alpha(16, y), 255) << "row " << y; // the middle, top to bottom
        EXPECT_EQ(alpha(0, y), 0);                   // the sides fade to nothing
        EXPECT_EQ(alpha(31, y), 0);
        EXPECT_EQ(alpha(8, y), alpha(8, 0));         // the same profile on every row
    }
}

TEST(Billboard, SceneAppendPlacesBillboards)
{
    scene::Scene model;
    model.images.push_back({});
    scene::BillboardGroup group;
    group.kind = BillboardKind::ArbitraryAxis;
    group.image = 0;
    group.billboards.push_back({{1, 0, 0}, 1.0f, glm::vec3(1.0f), {1, 0, 0}});
    model.billboards.push_back(group);
    scene::Scene s;
    s.images.resize(2);
    const glm::mat4 transform = glm::rotate(glm::translate(glm::mat4(1.0f), {0, 5, 0}), glm::radians(90.0f), glm::vec3(0, 1, 0));
    s.append(model, transform);
    ASSERT_EQ(s.billboards.size(), 1u);
    EXPECT_EQ(s.billboards[0].image, 2) << "image index shifted past the scene's own images";
    // Billboards are world-space data: the transform moves them and turns their axes.
    EXPECT_NEAR(glm::distance(s.billboards[0].billboards[0].position, glm::vec3(0, 5, -1)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(s.billboards[0].billboards[0].axis, glm::vec3(0, 0, -1)), 0.0f, 1e-5f);
}
