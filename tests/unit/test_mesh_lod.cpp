// Levels of detail (scene/MeshLod.h): the chain of a tessellated sphere against the sphere it
// approximates, and the choice of a level against the projection's own arithmetic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/MeshLod.h"
#include "scene/Procedural.h"

using namespace specula::scene;

namespace {

/// The largest distance from the unit sphere of the points of `count` indices from `first`:
/// each triangle's centroid and edge midpoints (a triangle's vertices lie on the sphere, so it
/// strays most inside it, towards its middle).
float deviationFromUnitSphere(const Primitive& p, const std::vector<uint32_t>& indices, uint32_t first, uint32_t count)
{
    float worst = 0.0f;
    for (uint32_t i = first; i < first + count; i += 3) {
        const glm::vec3 a = p.vertices[indices[i]].position, b = p.vertices[indices[i + 1]].position,
                        c = p.vertices[indices[i + 2]].position;
        for (const glm::vec3 q : {(a + b + c) / 3.0f, (a + b) * 0.5f, (b + c) * 0.5f, (c + a) * 0.5f})
            worst = std::max(worst, 1.0f - glm::length(q));
    }
    return worst;
}

} // namespace

TEST(MeshLod, SphereChainHalvesTrianglesWithinItsStatedError)
{
    const Primitive sphere = makeUvSphere(1.0f, 64, 64);
    const LodChain chain = buildLodChain(sphere);
    ASSERT_GE(chain.levels.size(), 3u);
    // Level 0 is the mesh itself, in its own order.
    ASSERT_EQ(chain.levels[0].first, 0u);
    ASSERT_EQ(chain.levels[0].count, sphere.indices.size());
    EXPECT_TRUE(std::equal(sphere.indices.begin(), sphere.indices.end(), chain.indices.begin()));
    EXPECT_EQ(chain.levels[0].error, 0.0f);
    const float ownDeviation = deviationFromUnitSphere(sphere, chain.indices, 0, chain.levels[0].count);
    for (size_t i = 1; i < chain.levels.size(); ++i) {
        const LodLevel& l = chain.levels[i];
        SCOPED_TRACE("level " + std::to_string(i));
        ASSERT_EQ(l.count % 3, 0u);
        ASSERT_LE(size_t(l.first) + l.count, chain.indices.size());
        // At least a fifth fewer triangles than the level before, errors never shrinking.
        EXPECT_LE(l.count * 5, chain.levels[i - 1].count * 4);
        EXPECT_GE(l.error, chain.levels[i - 1].error);
        for (uint32_t k = l.first; k < l.first + l.count; ++k) ASSERT_LT(chain.indices[k], sphere.vertices.size());
        // The stated error bounds how far the level strays from the full mesh: measured against
        // the true sphere, at most the full mesh's own deviation plus the level's error.
        const float deviation = deviationFromUnitSphere(sphere, chain.indices, l.first, l.count);
        EXPECT_LE(deviation, ownDeviation + l.error) << "deviation " << deviation << ", error " << l.error;
        // And it is not wildly pessimistic either (else the choice would never take the level).
        EXPECT_GE(deviation, 0.25f * l.error) << "deviation " << deviation << ", error " << l.error;
    }
}

TEST(MeshLod, SmallMeshesKeepOneLevel)
{
    const Primitive sphere = makeUvSphere(1.0f, 16, 16); // 480 triangles
    const LodChain chain = buildLodChain(sphere);
    ASSERT_EQ(chain.levels.size(), 1u);
    EXPECT_EQ(chain.levels[0].count, sphere.indices.size());
}

TEST(MeshLod, ViewScaleIsThePerspectivesPixelsPerMetre)
{
    const glm::mat4 projection = glm::perspective(glm::radians(45.0f), 16.0f / 9.0f, 0.1f, 100.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(1, 2, 3), glm::vec3(0), glm::vec3(0, 1, 0));
    const LodView v = lodView(view, projection, 720, 0.5f);
    EXPECT_TRUE(v.perspective);
    // A metre at distance d covers 720 / (2 d tan 22.5°) pixels.
    EXPECT_NEAR(v.pixelsPerMetre, 720.0f / (2.0f * std::tan(glm::radians(22.5f))), 1e-2f);
    EXPECT_NEAR(glm::length(v.eye - glm::vec3(1, 2, 3)), 0.0f, 1e-5f);
    const LodView o = lodView(view, glm::ortho(-2.0f, 2.0f, -1.0f, 1.0f, 0.1f, 10.0f), 720, 0.5f);
    EXPECT_FALSE(o.perspective);
    EXPECT_NEAR(o.pixelsPerMetre, 360.0f, 1e-3f); // 2 m over 720 pixels
}

TEST(MeshLod, ChoosesTheCoarsestLevelWithinThePixelBound)
{
    const std::vector<LodLevel> levels = {{0, 300, 0.0f}, {300, 150, 0.001f}, {450, 75, 0.004f}, {525, 36, 0.02f}};
    LodView v;
    v.pixelsPerMetre = 1000.0f; // at 1 m
    v.maxPixels = 1.0f;
    const glm::vec3 center(0, 0, -11);
    // Nearest point 10 m away: 100 px/m, so errors of 1, 4 and 20 mm are 0.1, 0.4 and 2 px.
    EXPECT_EQ(selectLod(levels, 1.0f, center, 1.0f, v), 2);
    v.maxPixels = 0.3f;
    EXPECT_EQ(selectLod(levels, 1.0f, center, 1.0f, v), 1);
    // Twice the scale doubles the error.
    v.maxPixels = 1.0f;
    EXPECT_EQ(selectLod(levels, 3.0f, center, 1.0f, v), 1);
    // Farther away, coarser; the eye inside the bounds or no bound: full detail.
    EXPECT_EQ(selectLod(levels, 1.0f, glm::vec3(0, 0, -101), 1.0f, v), 3);
    EXPECT_EQ(selectLod(levels, 1.0f, glm::vec3(0, 0, -0.5f), 1.0f, v), 0);
    v.maxPixels = 0.0f;
    EXPECT_EQ(selectLod(levels, 1.0f, glm::vec3(0, 0, -101), 1.0f, v), 0);
    // Orthographic: no distance; 100 px/m everywhere.
    LodView o;
    o.perspective = false;
    o.pixelsPerMetre = 100.0f;
    o.maxPixels = 1.0f;
    EXPECT_EQ(selectLod(levels, 1.0f, glm::vec3(0, 0, -1000), 1.0f, o), 2);
}
