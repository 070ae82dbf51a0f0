// The geometry of shadow maps (shading/ShadowMaps.h), without GL: cascade splits, texel
// snapping (a moving camera never moves the texel grid), the atlas allocator, the budget.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/ShadowMaps.h"

using namespace specula;
using namespace specula::render;

TEST(ShadowMaps, PracticalSplitsBlendLogarithmicAndUniform)
{
    const float n = 0.1f, f = 100.0f;
    const auto uniform = cascadeSplits(n, f, 4, 0.0f);
    const auto logarithmic = cascadeSplits(n, f, 4, 1.0f);
    const auto practical = cascadeSplits(n, f, 4, 0.5f);
    ASSERT_EQ(uniform.size(), 4u);
    for (int i = 0; i < 4; ++i) {
        const float t = float(i + 1) / 4.0f;
        EXPECT_NEAR(uniform[size_t(i)], n + (f - n) * t, 1e-3f);
        EXPECT_NEAR(logarithmic[size_t(i)], n * std::pow(f / n, t), 1e-3f * logarithmic[size_t(i)]);
        EXPECT_NEAR(practical[size_t(i)], 0.5f * (uniform[size_t(i)] + logarithmic[size_t(i)]), 1e-3f * practical[size_t(i)]);
    }
    EXPECT_EQ(practical.back(), f) << "the last cascade reaches the far distance exactly";
}

namespace {

// The texel coordinates of world point p in a cascade's map (before the atlas mapping).
glm::dvec2 texelOf(const ShadowView& v, const glm::vec3& p, int tile)
{
    const glm::dvec4 c = glm::dmat4(v.viewProjection) * glm::dvec4(glm::dvec3(p), 1.0);
    return (glm::dvec2(c) / c.w * 0.5 + 0.5) * double(tile);
}

} // namespace

// Moving or turning the camera changes a cascade's window only by whole texels: every world
// point keeps its position within a texel, so the map's texels do not crawl (no shimmering).
// Without the snap (the window centred on the slice's sphere) the fractions change.
TEST(ShadowMaps, CascadesSnapToWholeTexelsAsTheCameraMoves)
{
    const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 200.0f);
    const glm::vec3 sun = glm::normalize(glm::vec3(-0.4f, -0.7f, -0.3f));
    scene::Bounds casters;
    casters.extend(glm::vec3(-100, 0, -100));
    casters.extend(glm::vec3(100, 20, 100));
    constexpr int kTile = 1024;
    const glm::vec3 probes[] = {{1.3f, 0.0f, -7.1f}, {-12.0f, 2.0f, -30.0f}, {40.0f, 0.5f, -80.0f}};
    const auto splits = cascadeSplits(0.1f, 200.0f, 4, 0.8f);
    const glm::mat4 start = glm::lookAt(glm::vec3(0, 5, 0), glm::vec3(0, 4, -10), glm::vec3(0, 1, 0));
    const ShadowView reference = cascadeView(start, projection, 0.1f, splits[0], sun, casters, kTile);
    double maxFractionChange = 0.0;
    for (int step = 1; step <= 20; ++step) {
        // Small moves (fractions of a texel), then turns.
        const glm::vec3 eye = glm::vec3(0, 5, 0) + glm::vec3(0.0137f, 0.0021f, -0.0093f) * float(step);
        const glm::mat4 view = glm::lookAt(eye, eye + glm::vec3(0.02f * float(step), -0.1f, -1.0f), glm::vec3(0, 1, 0));
        for (int c = 0; c < 4; ++c) {
            const ShadowView a = cascadeView(start, projection, c == 0 ? 0.1f : splits[size_t(c - 1)], splits[size_t(c)], sun, casters, kTile);
            const ShadowView b = cascadeView(view, projection, c == 0 ? 0.1f : splits[size_t(c - 1)], splits[size_t(c)], sun, casters, kTile);
            EXPECT_EQ(a.texelWorld, b.texelWorld) << "the window's size does not change with the camera";
            for (const glm::vec3& p : probes) {
                const glm::dvec2 ta = texelOf(a, p, kTile), tb = texelOf(b, p, kTile);
                const glm::dvec2 shift = tb - ta;
                const glm::dvec2 fraction = shift - glm::round(shift);
                maxFractionChange = std::max({maxFractionChange, std::abs(fraction.x), std::abs(fraction.y)});
            }
        }
    }
    EXPECT_LT(maxFractionChange, 2e-3) << "texel fractions changed: the grid moved with the camera";
    EXPECT_GT(reference.texelWorld, 0.0f);
}

TEST(ShadowMaps, AtlasHandsOutDisjointPowerOfTwoTiles)
{
    ShadowAtlas atlas(4096, 64);
    std::vector<AtlasTile> tiles;
    for (int i = 0; i < 4; ++i) tiles.push_back(*atlas.allocate(1024)); // cascades
    for (int i = 0; i < 6; ++i) tiles.push_back(*atlas.allocate(512));  // a point light
    for (int i = 0; i < 40; ++i) tiles.push_back(*atlas.allocate(256));
    for (size_t a = 0; a < tiles.size(); ++a) {
        EXPECT_LE(tiles[a].x + tiles[a].size, 4096);
        EXPECT_LE(tiles[a].y + tiles[a].size, 4096);
        for (size_t b = a + 1; b < tiles.size(); ++b) {
            const bool apart = tiles[a].x + tiles[a].size <= tiles[b].x || tiles[b].x + tiles[b].size <= tiles[a].x ||
                               tiles[a].y + tiles[a].size <= tiles[b].y || tiles[b].y + tiles[b].size <= tiles[a].y;
            EXPECT_TRUE(apart) << "tiles " << a << " and " << b << " overlap";
        }
    }
    // 4 × 1024² + 6 × 512² + 40 × 256² is half of 4096²: 32 more tiles of 512² fill it.
    int more = 0;
    while (atlas.allocate(512)) ++more;
    EXPECT_EQ(more, 32);
    EXPECT_FALSE(atlas.allocate(64).has_value()) << "the atlas is full";
    EXPECT_FALSE(ShadowAtlas(1024).allocate(300).has_value()) << "not a power of two";
    // The same requests give the same tiles (cached maps stay where they were).
    ShadowAtlas again(4096, 64);
    EXPECT_EQ(*again.allocate(1024), tiles[0]);
}

TEST(ShadowMaps, BudgetKeepsTheMostImportantAndReportsTheRest)
{
    std::vector<ShadowCandidate> candidates;
    for (int i = 0; i < 100; ++i) candidates.push_back({i, scene::Light::Type::Point, float(i % 10) / 10.0f + 0.01f});
    candidates.push_back({100, scene::Light::Type::Directional, 1.0f});
    std::vector<int> dropped;
    const auto chosen = chooseShadowed(candidates, 64, 4, &dropped);
    EXPECT_EQ(chosen.size(), 65u) << "64 spot/point lights and the directional one";
    EXPECT_EQ(dropped.size(), 36u);
    float least = 1.0f;
    for (const ShadowCandidate& c : chosen)
        if (c.type != scene::Light::Type::Directional) least = std::min(least, c.importance);
    for (int light : dropped) EXPECT_LE(candidates[size_t(light)].importance, least) << "a more important light was dropped";
}

TEST(ShadowMaps, ImportanceAndTileSizes)
{
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
    EXPECT_EQ(screenImportance({0, 0, 0}, 1.0f, view, projection), 1.0f) << "the camera inside the light's sphere";
    EXPECT_EQ(screenImportance({0, 0, 50}, 1.0f, view, projection), 0.0f) << "behind the camera";
    const float near = screenImportance({0, 0, -5}, 1.0f, view, projection), far = screenImportance({0, 0, -50}, 1.0f, view, projection);
    EXPECT_GT(near, far);
    EXPECT_NEAR(far, 1.0f / (50.0f * std::tan(glm::radians(30.0f))), 1e-3f);
    EXPECT_EQ(tileSizeFor(1.0f, 1024, 64), 1024);
    EXPECT_EQ(tileSizeFor(0.3f, 1024, 64), 512);
    EXPECT_EQ(tileSizeFor(0.001f, 1024, 64), 64);
}

TEST(ShadowMaps, PointFacesCoverEveryDirection)
{
    const auto views = pointViews({1, 2, 3}, 20.0f, 256);
    ASSERT_EQ(views.size(), 6u);
    // A direction's major-axis face sees it inside its window.
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 d = glm::normalize(glm::vec3(std::sin(1.7f * float(i)), std::cos(2.3f * float(i)), std::sin(0.7f * float(i) + 1.0f)));
        const int face = shadowFace(d);
        const glm::vec4 c = views[size_t(face)].viewProjection * glm::vec4(glm::vec3(1, 2, 3) + 5.0f * d, 1.0f);
        const glm::vec3 ndc = glm::vec3(c) / c.w;
        EXPECT_LE(std::abs(ndc.x), 1.0f);
        EXPECT_LE(std::abs(ndc.y), 1.0f);
        EXPECT_GT(c.w, 0.0f);
    }
}
