// Tangent generation and flat normals. The convention: t = dP/du, the bitangent points along
// -dP/dv (glTF's v runs down the image), w = sign(dot(cross(n, t), b)).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "scene/GltfImporter.h"
#include "scene/Procedural.h"
#include "scene/Tangents.h"

using namespace specula::scene;

namespace {

Vertex vertex(glm::vec3 position, glm::vec2 uv, glm::vec3 normal = {0, 0, 1})
{
    Vertex v;
    v.position = position;
    v.normal = normal;
    v.uv0 = uv;
    v.uv1 = uv;
    v.tangent = glm::vec4(0.0f); // so a vertex the generator forgot shows up
    return v;
}

/// A unit quad facing +Z (counter-clockwise seen from +Z), u to the right and glTF v going
/// down the screen, as an image is laid on it.
Primitive frontQuad()
{
    Primitive p;
    p.vertices = {vertex({0, 0, 0}, {0, 1}), vertex({1, 0, 0}, {1, 1}), vertex({1, 1, 0}, {1, 0}),
                  vertex({0, 1, 0}, {0, 0})};
    p.indices = {0, 1, 2, 0, 2, 3};
    return p;
}

bool finite(const glm::vec4& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

/// Every tangent finite, unit length, orthogonal to its normal, with w = ±1.
void expectWellFormed(const Primitive& p)
{
    ASSERT_TRUE(p.hasTangents);
    for (size_t i = 0; i < p.vertices.size(); ++i) {
        const Vertex& v = p.vertices[i];
        ASSERT_TRUE(finite(v.tangent)) << "vertex " << i;
        const glm::vec3 t(v.tangent);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f) << "vertex " << i;
        if (glm::length(v.normal) > 0.5f) {
            EXPECT_NEAR(glm::dot(t, glm::normalize(v.normal)), 0.0f, 1e-5f) << "vertex " << i;
        }
        EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f) << "vertex " << i;
    }
}

} // namespace

TEST(Tangents, FrontQuadIsPlusXRightHanded)
{
    Primitive p = frontQuad();
    generateTangents(p);
    expectWellFormed(p);
    ASSERT_EQ(p.vertices.size(), 4u);
    for (const Vertex& v : p.vertices) {
        EXPECT_NEAR(glm::distance(glm::vec3(v.tangent), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
        EXPECT_EQ(v.tangent.w, 1.0f);
        // glTF's bitangent, cross(n, t) * w, points up the image: +Y, where v decreases.
        EXPECT_NEAR(glm::distance(glm::cross(v.normal, glm::vec3(v.tangent)) * v.tangent.w, glm::vec3(0, 1, 0)), 0.0f,
                    1e-6f);
    }
}

TEST(Tangents, MirroredQuadIsLeftHanded)
{
    // The same quad with u running right to left: the image is mirrored on it.
    Primitive p = frontQuad();
    for (Vertex& v : p.vertices) v.uv0.x = 1.0f - v.uv0.x;
    generateTangents(p);
    expectWellFormed(p);
    for (const Vertex& v : p.vertices) {
        EXPECT_NEAR(glm::distance(glm::vec3(v.tangent), glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);
        EXPECT_EQ(v.tangent.w, -1.0f);
        EXPECT_NEAR(glm::distance(glm::cross(v.normal, glm::vec3(v.tangent)) * v.tangent.w, glm::vec3(0, 1, 0)), 0.0f,
                    1e-6f);
    }
}

TEST(Tangents, VFlippedQuadIsLeftHanded)
{
    // v running up the screen (an OpenGL-style layout) mirrors the image vertically.
    Primitive p = frontQuad();
    for (Vertex& v : p.vertices) v.uv0.y = 1.0f - v.uv0.y;
    generateTangents(p);
    expectWellFormed(p);
    for (const Vertex& v : p.vertices) {
        EXPECT_NEAR(glm::distance(glm::vec3(v.tangent), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
        EXPECT_EQ(v.tangent.w, -1.0f);
    }
}

TEST(Tangents, MatchesProceduralCube)
{
    // makeCube writes its tangents by hand with the same convention; regenerate and compare.
    Primitive cube = makeCube(1.0f);
    const Primitive reference = cube;
    for (Vertex& v : cube.vertices) v.tangent = glm::vec4(0.0f);
    generateTangents(cube);
    expectWellFormed(cube);
    ASSERT_EQ(cube.vertices.size(), reference.vertices.size());
    for (size_t i = 0; i < cube.vertices.size(); ++i)
        EXPECT_NEAR(glm::distance(cube.vertices[i].tangent, reference.vertices[i].tangent), 0.0f, 1e-5f) << i;
}

TEST(Tangents, SharedVertexOfOppositeHandednessIsSplit)
{
    // Two quads side by side sharing the edge x = 1; the right one's uvs mirror the left
    // one's about that edge (a mirrored uv island, as on a symmetric character).
    Primitive p;
    p.vertices = {vertex({0, 0, 0}, {0, 1}), vertex({1, 0, 0}, {1, 1}), vertex({1, 1, 0}, {1, 0}),
                  vertex({0, 1, 0}, {0, 0}), vertex({2, 0, 0}, {0, 1}), vertex({2, 1, 0}, {0, 0})};
    p.indices = {0, 1, 2, 0, 2, 3, 1, 4, 5, 1, 5, 2};
    generateTangents(p);
    expectWellFormed(p);
    EXPECT_EQ(p.vertices.size(), 8u); // vertices 1 and 2 each got a mirrored copy
    ASSERT_EQ(p.indices.size(), 12u);
    for (size_t k = 0; k < 6; ++k) {
        const Vertex& v = p.vertices[p.indices[k]];
        EXPECT_EQ(v.tangent.w, 1.0f) << "left corner " << k;
        EXPECT_NEAR(glm::distance(glm::vec3(v.tangent), glm::vec3(1, 0, 0)), 0.0f, 1e-6f) << k;
    }
    for (size_t k = 6; k < 12; ++k) {
        const Vertex& v = p.vertices[p.indices[k]];
        EXPECT_EQ(v.tangent.w, -1.0f) << "right corner " << k;
        EXPECT_NEAR(glm::distance(glm::vec3(v.tangent), glm::vec3(-1, 0, 0)), 0.0f, 1e-6f) << k;
    }
    // The copies keep everything else of the original.
    EXPECT_EQ(p.vertices[6].position, p.vertices[1].position);
    EXPECT_EQ(p.vertices[7].position, p.vertices[2].position);
}

TEST(Tangents, OrthogonalToSmoothNormals)
{
    // A bent strip with averaged normals: tangents must be re-orthogonalised per vertex.
    Primitive p;
    const glm::vec3 n0 = glm::normalize(glm::vec3(-0.3f, 0, 1)), n1 = glm::normalize(glm::vec3(0.3f, 0, 1));
    p.vertices = {vertex({0, 0, 0}, {0, 1}, n0), vertex({1, 0, 0.3f}, {1, 1}, n1), vertex({1, 1, 0.3f}, {1, 0}, n1),
                  vertex({0, 1, 0}, {0, 0}, n0)};
    p.indices = {0, 1, 2, 0, 2, 3};
    generateTangents(p);
    expectWellFormed(p);
    for (const Vertex& v : p.vertices) {
        EXPECT_GT(v.tangent.x, 0.9f);
        EXPECT_EQ(v.tangent.w, 1.0f);
    }
}

TEST(Tangents, DegenerateInputGivesNoNaN)
{
    // All uvs equal, a zero-area triangle, a zero normal, a NaN position, an unreferenced vertex.
    Primitive p;
    p.vertices = {vertex({0, 0, 0}, {0.5f, 0.5f}),
                  vertex({1, 0, 0}, {0.5f, 0.5f}),
                  vertex({0, 1, 0}, {0.5f, 0.5f}),
                  vertex({0, 0, 0}, {0, 0}),
                  vertex({0, 0, 0}, {1, 0}),
                  vertex({0, 0, 0}, {0, 1}),
                  vertex({0, 0, 0}, {0, 0}, {0, 0, 0}),
                  vertex({std::numeric_limits<float>::quiet_NaN(), 0, 0}, {1, 1}),
                  vertex({1, 1, 1}, {0, 0}, {0, 1, 0})};
    p.indices = {0, 1, 2, 3, 4, 5, 6, 7, 0, 99, 0, 1};
    generateTangents(p);
    ASSERT_TRUE(p.hasTangents);
    for (size_t i = 0; i < p.vertices.size(); ++i) {
        const Vertex& v = p.vertices[i];
        ASSERT_TRUE(finite(v.tangent)) << i;
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f) << i;
        EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f) << i;
        if (glm::length(v.normal) > 0.5f) {
            EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-5f) << i;
        }
    }
    EXPECT_EQ(p.vertices.size(), 9u); // nothing to split
}

TEST(Tangents, NonIndexedAndSecondUvSet)
{
    Primitive p;
    // Non-indexed; uv0 degenerate, uv1 the front-quad layout rotated: u runs up the screen.
    p.vertices = {vertex({0, 0, 0}, {0, 0}), vertex({1, 0, 0}, {0, 0}), vertex({1, 1, 0}, {0, 0})};
    p.vertices[0].uv1 = {0, 0};
    p.vertices[1].uv1 = {0, 1};
    p.vertices[2].uv1 = {1, 1};
    generateTangents(p, 1);
    expectWellFormed(p);
    EXPECT_TRUE(p.indices.empty());
    for (const Vertex& v : p.vertices)
        EXPECT_NEAR(glm::distance(glm::vec3(v.tangent), glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
}

TEST(Tangents, AgreeWithNormalTangentMirrorTestFile)
{
    // The sample's tangents were exported by Blender (MikkTSpace) and it has mirrored islands:
    // regenerating them must give the same handedness and nearly the same directions.
    const Scene scene = loadGltf(std::filesystem::path(SPECULA_ASSETS_DIR) /
                                 "models/NormalTangentMirrorTest/NormalTangentMirrorTest.glb");
    const Primitive& original = scene.meshes.at(0).primitives.at(0);
    Primitive regenerated = original;
    regenerated.hasTangents = false;
    generateTangents(regenerated);
    expectWellFormed(regenerated);
    ASSERT_EQ(regenerated.indices.size(), original.indices.size());
    size_t sameSign = 0, sameDirection = 0;
    const size_t corners = original.indices.size();
    for (size_t k = 0; k < corners; ++k) {
        const glm::vec4 a = original.vertices[original.indices[k]].tangent;
        const glm::vec4 b = regenerated.vertices[regenerated.indices[k]].tangent;
        sameSign += a.w == b.w;
        sameDirection += glm::dot(glm::normalize(glm::vec3(a)), glm::vec3(b)) > 0.99f;
    }
    EXPECT_EQ(sameSign, corners);
    // Measured: all 15720 corners within 8°; the margin allows for a different weighting.
    EXPECT_GE(double(sameDirection), 0.99 * double(corners));
}

TEST(TangentsFlatNormals, Triangle)
{
    Primitive p;
    p.vertices = {vertex({0, 0, 0}, {0, 0}, {0, 0, 0}), vertex({2, 0, 0}, {1, 0}, {0, 0, 0}),
                  vertex({0, 0, -2}, {0, 1}, {0, 0, 0})};
    p.vertices[1].color = {1, 0, 0, 1};
    p.indices = {0, 1, 2};
    generateFlatNormals(p);
    ASSERT_EQ(p.vertices.size(), 3u);
    EXPECT_TRUE(p.indices.empty());
    // Counter-clockwise seen from +Y: the face normal is +Y.
    for (const Vertex& v : p.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(p.vertices[1].position, glm::vec3(2, 0, 0));
    EXPECT_EQ(p.vertices[1].uv0, glm::vec2(1, 0));
    EXPECT_EQ(p.vertices[1].color, glm::vec4(1, 0, 0, 1));
}

TEST(TangentsFlatNormals, SharedVerticesAreUnsharedAndDegenerateKeepsNormal)
{
    Primitive p = frontQuad();
    p.vertices[0].normal = p.vertices[1].normal = p.vertices[2].normal = p.vertices[3].normal = {0, 0, -1};
    p.indices = {0, 1, 2, 0, 2, 3, 0, 0, 1, 2, 1}; // a degenerate triangle, then a partial one
    generateFlatNormals(p);
    ASSERT_EQ(p.vertices.size(), 9u);
    for (size_t i = 0; i < 6; ++i) EXPECT_EQ(p.vertices[i].normal, glm::vec3(0, 0, 1)) << i;
    for (size_t i = 6; i < 9; ++i) EXPECT_EQ(p.vertices[i].normal, glm::vec3(0, 0, -1)) << i; // zero area: kept
    EXPECT_EQ(p.vertices[3].position, glm::vec3(0, 0, 0));
    EXPECT_EQ(p.vertices[5].position, glm::vec3(0, 1, 0));
}
