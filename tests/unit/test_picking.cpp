// Ray picking against plain scene data (clicking on an object in the viewer).
#include <gtest/gtest.h>

#include "scene/Picking.h"

using namespace specula;

namespace {

/// Two unit quads facing +Z at z = 0 (material 0) and z = -2 (material 1), the far one moved by
/// its node.
scene::Scene twoQuads()
{
    scene::Scene s;
    for (int m = 0; m < 2; ++m) {
        scene::Primitive quad;
        for (glm::vec2 p : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            scene::Vertex v;
            v.position = glm::vec3(p, 0.0f);
            quad.vertices.push_back(v);
            quad.bounds.extend(v.position);
        }
        quad.indices = {0, 1, 2, 0, 2, 3};
        quad.material = m;
        s.meshes.push_back({"quad", {quad}});
        s.materials.emplace_back();
        scene::Node node;
        node.mesh = m;
        node.translation = glm::vec3(0.0f, 0.0f, -2.0f * float(m));
        s.addNode(node);
    }
    return s;
}

} // namespace

TEST(Picking, NearestSurfaceWins)
{
    const scene::Scene s = twoQuads();
    const auto hit = scene::pick(s, glm::vec3(0.2f, 0.3f, 5.0f), glm::vec3(0, 0, -1));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->material, 0);
    EXPECT_NEAR(hit->distance, 5.0f, 1e-5f);
    EXPECT_NEAR(hit->position.z, 0.0f, 1e-5f);
    // From behind, the far quad (moved by its node) is the nearer one.
    const auto back = scene::pick(s, glm::vec3(0.2f, 0.3f, -5.0f), glm::vec3(0, 0, 1));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->material, 1);
    EXPECT_NEAR(back->position.z, -2.0f, 1e-5f);
}

TEST(Picking, MissesReturnNothing)
{
    const scene::Scene s = twoQuads();
    EXPECT_FALSE(scene::pick(s, glm::vec3(3.0f, 0.0f, 5.0f), glm::vec3(0, 0, -1)));
    EXPECT_FALSE(scene::pick(s, glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0, 0, 1))); // pointing away
    EXPECT_FALSE(scene::pick(s, glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(1, 0, 0))); // parallel
}
