// Scene data: node transforms, append, bounds, procedural meshes, the default rig, look rotations.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "render/View.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"

using namespace specula::scene;

namespace {

void expectVec(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

void checkMesh(const Primitive& p)
{
    ASSERT_TRUE(p.hasTangents);
    for (const Vertex& v : p.vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-4f);
        EXPECT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-4f);
        EXPECT_EQ(std::abs(v.tangent.w), 1.0f);
    }
    // Counter-clockwise seen from outside: the face normal agrees with the vertex normals.
    for (size_t i = 0; i + 2 < p.indices.size(); i += 3) {
        const Vertex& a = p.vertices[p.indices[i]];
        const Vertex& b = p.vertices[p.indices[i + 1]];
        const Vertex& c = p.vertices[p.indices[i + 2]];
        const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        EXPECT_GT(glm::dot(face, a.normal + b.normal + c.normal), 0.0f);
    }
}

// glTF convention: bitangent = cross(n, t) * w points up the image, i.e. towards decreasing v.
void checkTangentFrame(const Primitive& p)
{
    for (size_t i = 0; i + 2 < p.indices.size(); i += 3) {
        const Vertex& a = p.vertices[p.indices[i]];
        const Vertex& b = p.vertices[p.indices[i + 1]];
        const Vertex& c = p.vertices[p.indices[i + 2]];
        const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
        const glm::vec2 d1 = b.uv0 - a.uv0, d2 = c.uv0 - a.uv0;
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-12f) continue;
        const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
        const glm::vec3 bitangent = glm::cross(a.normal, glm::vec3(a.tangent)) * a.tangent.w;
        EXPECT_GT(glm::dot(glm::vec3(a.tangent), dPdu), 0.0f);
        EXPECT_GT(glm::dot(bitangent, -dPdv), 0.0f);
    }
}

} // namespace

TEST(Scene, ProceduralMeshesAreConsistent)
{
    const Primitive sphere = makeUvSphere(2.0f, 16, 8);
    checkMesh(sphere);
    checkTangentFrame(sphere);
    for (const Vertex& v : sphere.vertices) EXPECT_NEAR(glm::length(v.position), 2.0f, 1e-4f);
    EXPECT_EQ(sphere.indices.size(), size_t(16 * (8 - 1) * 2 * 3));
    const Primitive cube = makeCube(0.5f);
    checkMesh(cube);
    checkTangentFrame(cube);
    const Primitive plane = makePlane(2.0f);
    checkMesh(plane);
    checkTangentFrame(plane);
    expectVec(plane.bounds.min, {-1, 0, -1});
}

TEST(Scene, WorldTransformsComposeDownTheTree)
{
    Scene scene;
    Node parent;
    parent.translation = {1, 0, 0};
    parent.scale = glm::vec3(2.0f);
    const int p = scene.addNode(parent);
    Node child;
    child.translation = {0, 1, 0};
    child.mesh = 0;
    scene.addNode(child, p);
    scene.meshes.push_back({"m", {makeCube(1.0f)}});
    const auto instances = scene.meshInstances();
    ASSERT_EQ(instances.size(), 1u);
    expectVec(glm::vec3(instances[0].world[3]), {1, 2, 0});
    const Bounds bounds = scene.worldBounds();
    expectVec(bounds.min, {-1, 0, -2});
    expectVec(bounds.max, {3, 4, 2});
    EXPECT_EQ(scene.triangleCount(), 12u);
}

TEST(Scene, AppendShiftsIndices)
{
    Scene a = makeDemoScene();
    Scene b = makeLearnOpenGlScene();
    const size_t meshes = a.meshes.size() + b.meshes.size();
    const size_t lights = a.lights.size() + b.lights.size();
    const size_t instancesA = a.meshInstances().size(), instancesB = b.meshInstances().size();
    a.append(std::move(b), glm::translate(glm::mat4(1.0f), {100, 0, 0}));
    EXPECT_EQ(a.meshes.size(), meshes);
    EXPECT_EQ(a.lights.size(), lights);
    EXPECT_EQ(a.lightInstances().size(), lights);
    EXPECT_EQ(a.meshInstances().size(), instancesA + instancesB);
    for (const auto& p : a.meshInstances()) {
        const int material = a.meshes[size_t(p.mesh)].primitives[0].material;
        EXPECT_GE(material, 0);
        EXPECT_LT(size_t(material), a.materials.size());
    }
}

// Every texture of an appended material (the clearcoat layer's too) follows its images, and
// material variants of the same name become one, their mappings following their materials.
// (The anisotropy and iridescence textures were missed once: a scene file's second model drew
// the first model's images there.)
TEST(Scene, AppendShiftsTexturesAndMergesVariantsByName)
{
    auto model = [](std::vector<std::string> variants) {
        Scene s;
        s.images.resize(2);
        Material m;
        m.baseColorTexture.image = 0;
        m.clearcoatNormalTexture.image = 1;
        m.anisotropyTexture.image = 1;
        m.iridescenceThicknessTexture.image = 0;
        s.materials = {m, Material{}};
        Primitive p;
        p.vertices.resize(3);
        p.material = 0;
        for (int v = 0; v < int(variants.size()); ++v) p.variants.push_back({v, 1});
        s.meshes.push_back({"mesh", {p}, {}});
        s.variants = std::move(variants);
        return s;
    };
    Scene a = model({"red", "blue"});
    a.append(model({"blue", "green"}));
    EXPECT_EQ(a.variants, (std::vector<std::string>{"red", "blue", "green"}));
    const Material& second = a.materials.at(2);
    EXPECT_EQ(second.baseColorTexture.image, 2);
    EXPECT_EQ(second.clearcoatNormalTexture.image, 3);
    EXPECT_EQ(second.anisotropyTexture.image, 3);
    EXPECT_EQ(second.iridescenceThicknessTexture.image, 2);
    const Primitive& appended = a.meshes.at(1).primitives.at(0);
    EXPECT_EQ(appended.material, 2);
    ASSERT_EQ(appended.variants.size(), 2u);
    EXPECT_EQ(appended.variants[0].variant, 1); // its "blue" is the first model's
    EXPECT_EQ(appended.variants[0].material, 3);
    EXPECT_EQ(appended.variants[1].variant, 2); // "green" is new
}

TEST(Scene, LookRotationMapsMinusZToDirection)
{
    for (const glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), glm::vec3(0.3f, -0.5f, 0.8f)}) {
        const glm::quat q = lookRotation(d);
        expectVec(q * glm::vec3(0, 0, -1), glm::normalize(d));
        EXPECT_FALSE(glm::any(glm::isnan(q * glm::vec3(0, 1, 0))));
    }
}

TEST(Scene, DemoScenesHaveWhatTheyPromise)
{
    const Scene demo = makeDemoScene();
    int point = 0, spot = 0, directional = 0;
    for (const Light& l : demo.lights) {
        point += l.type == Light::Type::Point;
        spot += l.type == Light::Type::Spot;
        directional += l.type == Light::Type::Directional;
    }
    EXPECT_EQ(point, 3);
    EXPECT_EQ(spot, 1);
    EXPECT_EQ(directional, 1);
    EXPECT_EQ(demo.meshInstances().size(), 27u); // 25 spheres, the glass sphere and the floor
    ASSERT_FALSE(demo.cameraInstances().empty());

    const Scene learn = makeLearnOpenGlScene();
    EXPECT_EQ(learn.meshInstances().size(), 49u + 4u);
    EXPECT_EQ(learn.lights.size(), 4u);
    const auto camera = learn.cameraInstances().at(0);
    expectVec(glm::vec3(camera.world[3]), {0, 0, 3});
    expectVec(glm::vec3(camera.world * glm::vec4(0, 0, -1, 0)), {0, 0, -1});
    // Sphere (row 6, col 0): metallic 6/7, roughness clamped to 0.05.
    bool found = false;
    for (const auto& instance : learn.meshInstances()) {
        if (glm::distance(glm::vec3(instance.world[3]), glm::vec3(-7.5f, 7.5f, 0.0f)) < 1e-4f) {
            const Material& m = learn.materials[size_t(learn.meshes[size_t(instance.mesh)].primitives[0].material)];
            EXPECT_NEAR(m.metallicFactor, 6.0f / 7.0f, 1e-6f);
            EXPECT_NEAR(m.roughnessFactor, 0.05f, 1e-6f);
            found = true;
        }
    }
    EXPECT_TRUE(found);
}

TEST(Scene, DefaultRigLightsTheSideFacingTheViewer)
{
    Scene scene;
    EXPECT_EQ(addDefaultLightRig(scene, {0, 0, 1}), 3);
    const auto lights = scene.lightInstances();
    ASSERT_EQ(lights.size(), 3u);
    // The key light (first) comes from the viewer's side and from above.
    EXPECT_LT(lights[0].direction.z, 0.0f);
    EXPECT_LT(lights[0].direction.y, 0.0f);
    float total = 0.0f;
    for (const Light& l : scene.lights) {
        EXPECT_EQ(l.type, Light::Type::Directional);
        total += l.intensity;
    }
    EXPECT_FLOAT_EQ(total, 6.0f);
}

TEST(View, FramingKeepsTheBoundsInView)
{
    Bounds b;
    b.extend({-1, -2, -3});
    b.extend({4, 5, 6});
    const specula::render::View v = specula::render::frameBounds(b, 16.0f / 9.0f);
    const glm::mat4 vp = v.projection * v.view;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        const glm::vec4 clip = vp * glm::vec4(corner, 1.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        EXPECT_LE(std::abs(ndc.x), 1.0f);
        EXPECT_LE(std::abs(ndc.y), 1.0f);
        EXPECT_LE(std::abs(ndc.z), 1.0f);
    }
}
