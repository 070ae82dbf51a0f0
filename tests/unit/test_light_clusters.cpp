// The cluster grid, its boxes, the culling test and the cutoff's effective range, without GL
// (shading/LightClusters.h, shaders/shared/ClusterData.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/LightClusters.h"

using namespace specula;
using render::ClusterGrid;

namespace {

glm::mat4 perspective(float aspect)
{
    return glm::perspective(glm::radians(50.0f), aspect, 0.1f, 100.0f);
}

bool contains(const shared::ClusterBounds& b, glm::vec3 p)
{
    return p.x >= b.lo.x && p.y >= b.lo.y && p.z >= b.lo.z && p.x <= b.hi.x && p.y <= b.hi.y && p.z <= b.hi.z;
}

} // namespace

// Tiles of whole pixels, at most 16 × 9 of them, covering the target exactly; 24 slices.
TEST(LightClusters, GridAdaptsToTheTarget)
{
    const ClusterGrid hd = ClusterGrid::make(1280, 720, perspective(16.0f / 9.0f));
    EXPECT_EQ(hd.tilesX, 16);
    EXPECT_EQ(hd.tilesY, 9);
    EXPECT_EQ(hd.tileWidth, 80);
    EXPECT_EQ(hd.tileHeight, 80);
    EXPECT_EQ(hd.slices, 24);
    EXPECT_EQ(hd.count(), 16 * 9 * 24);
    EXPECT_NEAR(hd.near, 0.1f, 1e-5f);
    EXPECT_NEAR(hd.far, 100.0f, 1e-2f);
    for (const auto& [w, h] : {std::pair{333, 197}, {1, 1}, {17, 1000}, {4000, 3}, {97, 61}}) {
        const ClusterGrid g = ClusterGrid::make(w, h, perspective(float(w) / float(h)));
        EXPECT_LE(g.tilesX, 16);
        EXPECT_LE(g.tilesY, 9);
        EXPECT_GE(g.tilesX * g.tileWidth, w);
        EXPECT_LT((g.tilesX - 1) * g.tileWidth, w) << "no empty tile column";
        EXPECT_GE(g.tilesY * g.tileHeight, h);
        EXPECT_LT((g.tilesY - 1) * g.tileHeight, h) << "no empty tile row";
    }
    // Slices: the first from near to 5 m, then exponential to far, and a depth's slice is the
    // one that spans it.
    EXPECT_FLOAT_EQ(hd.sliceDepth(1), 5.0f);
    EXPECT_EQ(hd.clusterAt({0.5f, 0.5f}, 0.2f), hd.index(0, 0, 0));
    EXPECT_EQ(hd.clusterAt({0.5f, 0.5f}, 4.9f), hd.index(0, 0, 0));
    for (int k = 1; k < hd.slices; ++k) {
        EXPECT_LT(hd.sliceDepth(k), hd.sliceDepth(k + 1));
        const float middle = std::sqrt(hd.sliceDepth(k) * hd.sliceDepth(k + 1));
        EXPECT_EQ(hd.clusterAt({0.5f, 0.5f}, middle), hd.index(0, 0, k)) << "slice " << k;
    }
    EXPECT_NEAR(hd.sliceDepth(12), 5.0f * std::pow(20.0f, 11.0f / 23.0f), 1e-3f);
    EXPECT_NEAR(ClusterGrid::make(64, 64, glm::perspective(1.0f, 1.0f, 0.1f, 10.0f)).first, 1.0f, 1e-4f) << "far / 10 when nearer";
}

// Every point of the view lies in the box of the cluster the shaders find for it.
TEST(LightClusters, BoxesHoldTheirFroxels)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (const auto& [w, h] : {std::pair{1280, 720}, {333, 197}, {50, 90}}) {
        const glm::mat4 projection = perspective(float(w) / float(h));
        const ClusterGrid grid = ClusterGrid::make(w, h, projection);
        const std::vector<shared::ClusterBounds> bounds = render::clusterBounds(grid, projection);
        ASSERT_EQ(bounds.size(), size_t(grid.count()));
        const glm::mat4 inverse = glm::inverse(projection);
        for (int i = 0; i < 20000; ++i) {
            const glm::vec2 window(u(rng) * float(w), u(rng) * float(h));
            const float depth = grid.near * std::pow(grid.far / grid.near, u(rng));
            // The view-space point at that window position and depth.
            const glm::vec2 ndc = window / glm::vec2(float(w), float(h)) * 2.0f - 1.0f;
            const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f), b = inverse * glm::vec4(ndc, 0.0f, 1.0f);
            const glm::vec3 pa = glm::vec3(a) / a.w, pb = glm::vec3(b) / b.w;
            const glm::vec3 p = pa + (-depth - pa.z) / (pb.z - pa.z) * (pb - pa);
            const int cluster = grid.clusterAt(window, depth);
            EXPECT_TRUE(contains(bounds[size_t(cluster)], p)) << w << "x" << h << ": window " << window.x << ", " << window.y
                                                              << " depth " << depth << " outside cluster " << cluster;
        }
    }
}

// The test of a light against a box: the sphere's reach, and a spot light's cone.
TEST(LightClusters, SphereAndConeTests)
{
    const shared::ClusterBounds box{{-1.0f, -1.0f, -11.0f, 0.0f}, {1.0f, 1.0f, -9.0f, 0.0f}};
    shared::CullLight l{};
    l.cone.w = -2.0f; // a point light
    l.sphere = {3.0f, 0.0f, -10.0f, 2.01f};
    EXPECT_TRUE(shared::lightTouchesCluster(l, box));
    l.sphere.w = 1.99f;
    EXPECT_FALSE(shared::lightTouchesCluster(l, box));
    l.sphere = {2.0f, 2.0f, -10.0f, 1.4f}; // the corner is √2 away
    EXPECT_FALSE(shared::lightTouchesCluster(l, box));
    l.sphere.w = 1.42f;
    EXPECT_TRUE(shared::lightTouchesCluster(l, box));
    l.sphere = {50.0f, 0.0f, 0.0f, -1.0f}; // infinite
    EXPECT_TRUE(shared::lightTouchesCluster(l, box));

    // A spot 5 m in front of the box with a 20° cone: towards the box it reaches, away it does not.
    l.sphere = {0.0f, 0.0f, -4.0f, 10.0f};
    l.cone = {0.0f, 0.0f, -1.0f, std::cos(glm::radians(20.0f))};
    EXPECT_TRUE(shared::lightTouchesCluster(l, box));
    l.cone = {0.0f, 0.0f, 1.0f, std::cos(glm::radians(20.0f))};
    EXPECT_FALSE(shared::lightTouchesCluster(l, box));
    // Sideways, 90° off: the sphere reaches, a narrow cone does not, a 90° cone does.
    l.cone = {1.0f, 0.0f, 0.0f, std::cos(glm::radians(20.0f))};
    EXPECT_FALSE(shared::lightTouchesCluster(l, box));
    l.cone.w = 0.0f;
    EXPECT_TRUE(shared::lightTouchesCluster(l, box));
    // Beyond its range along the axis.
    l.cone = {0.0f, 0.0f, -1.0f, std::cos(glm::radians(20.0f))};
    l.sphere.w = 4.5f;
    EXPECT_FALSE(shared::lightTouchesCluster(l, box)) << "the box starts 5 m away, the range is 4.5 m";
}

// The effective range of a light without one, and the error it makes: the window of
// KHR_lights_punctual, clamp(1 − (d/r)⁴, 0, 1) / d², differs from 1 / d² by d² / r⁴ below r and
// by 1 / d² beyond, both at most 1 / r² = cutoff (times the illuminance at 1 m). Checked
// numerically; the bound is tight (reached at d = r), so a range any shorter breaks it.
TEST(LightClusters, CutoffErrorIsBelowTheCutoff)
{
    EXPECT_EQ(render::effectiveRange(3.0f, 1e-4f), 3.0f) << "a light's own range wins";
    EXPECT_EQ(render::effectiveRange(0.0f, 0.0f), 0.0f) << "cutoff 0: infinite";
    for (const float cutoff : {1e-1f, 1e-2f, 1e-4f, 1e-6f}) {
        const double r = render::effectiveRange(0.0f, cutoff);
        EXPECT_NEAR(r, 1.0 / std::sqrt(double(cutoff)), 1e-3 * r);
        double worst = 0.0;
        for (int i = 1; i <= 100000; ++i) {
            const double d = 3.0 * r * double(i) / 100000.0;
            const double ratio = d / r;
            const double windowed = std::clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0) / (d * d);
            worst = std::max(worst, 1.0 / (d * d) - windowed);
        }
        EXPECT_LE(worst, double(cutoff) * (1.0 + 1e-5)) << "cutoff " << cutoff;
        EXPECT_GT(worst, double(cutoff) * 0.99) << "the bound is reached at the range";
        // A range 5% shorter than 1 / √cutoff would break it.
        const double shorter = 0.95 * r;
        EXPECT_GT(1.0 / (shorter * shorter), double(cutoff));
    }
}
