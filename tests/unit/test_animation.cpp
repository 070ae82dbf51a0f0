// glTF animation on the CPU: samplers (STEP, LINEAR with slerp, CUBICSPLINE) against values
// worked out by hand from the glTF 2.0 spec's formulas (Appendix C), joint matrices against a
// world transform composed here from axis-angle matrices (not through Pose's quaternions),
// morph weights, the deformation of vertices, and the import of the test assets and its errors.
//
// Broken on purpose (2026-12-03, each restored): normalised lerp in place of slerp fails
// LinearRotationIsSlerp; dropping the keyframe delta td from the cubic tangents fails
// CubicSplineIsTheSpecsHermite; skipping the inverse bind matrix fails
// JointMatricesAreWorldTimesInverseBind and ImportsTheSkinnedBar; ignoring the morph weights in
// deformPrimitive fails DeformMorphsThenSkins; reading only JOINTS_0/WEIGHTS_0 fails
// ImportsTheSkinnedBar and BadFilesAreOneLineErrors (the out-of-range joint goes unseen).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "TestFiles.h"
#include "scene/Animation.h"
#include "scene/GltfImporter.h"
#include "scene/Pose.h"
#include "render/View.h"

using namespace specula;
using namespace specula::scene;

namespace {

const std::string kAssets = std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/";

AnimationSampler sampler(Interpolation interpolation, std::vector<float> times, std::vector<float> values, int components)
{
    return {interpolation, std::move(times), std::move(values), components};
}

float at1(const AnimationSampler& s, float t)
{
    float v = 0.0f;
    evaluateSampler(s, t, false, &v);
    return v;
}

glm::vec4 rotationAt(const AnimationSampler& s, float t)
{
    glm::vec4 q;
    evaluateSampler(s, t, true, &q.x);
    return q;
}

/// (x, y, z, w) of a rotation by `degrees` about the unit `axis`.
glm::vec4 axisAngle(glm::vec3 axis, float degrees)
{
    const float h = glm::radians(degrees) / 2.0f;
    return {axis * std::sin(h), std::cos(h)};
}

void expectNear(const glm::vec4& got, const glm::vec4& want, float tolerance)
{
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << "component " << c;
}

std::string readText(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The bar asset with `edit` applied to its JSON, loaded from memory.
/// Test asset `name` with `edit` applied to its JSON, loaded from memory.
Scene loadEdited(const std::string& name, const std::function<void(nlohmann::json&)>& edit)
{
    nlohmann::json doc = nlohmann::json::parse(readText(kAssets + name));
    edit(doc);
    const std::string text = doc.dump();
    return loadGltfFromMemory(std::vector<unsigned char>(text.begin(), text.end()), kAssets + "edited.gltf");
}

Scene loadEditedBar(const std::function<void(nlohmann::json&)>& edit)
{
    return loadEdited("skinned_bar.gltf", edit);
}

} // namespace

TEST(AnimationSampler, StepHoldsEachKeyUntilTheNext)
{
    const auto s = sampler(Interpolation::Step, {0.0f, 1.0f, 3.0f}, {10.0f, 20.0f, 40.0f}, 1);
    EXPECT_EQ(at1(s, -1.0f), 10.0f); // before the first key: the first value
    EXPECT_EQ(at1(s, 0.0f), 10.0f);
    EXPECT_EQ(at1(s, 0.999f), 10.0f);
    EXPECT_EQ(at1(s, 1.0f), 20.0f);
    EXPECT_EQ(at1(s, 2.9f), 20.0f);
    EXPECT_EQ(at1(s, 3.0f), 40.0f);
    EXPECT_EQ(at1(s, 9.0f), 40.0f); // after the last: the last
}

TEST(AnimationSampler, LinearInterpolatesEachComponent)
{
    const auto s = sampler(Interpolation::Linear, {1.0f, 3.0f}, {0, 0, 0, 2, 4, -6}, 3);
    glm::vec3 v;
    evaluateSampler(s, 1.5f, false, &v.x); // a quarter of the way
    EXPECT_NEAR(v.x, 0.5f, 1e-6f);
    EXPECT_NEAR(v.y, 1.0f, 1e-6f);
    EXPECT_NEAR(v.z, -1.5f, 1e-6f);
    evaluateSampler(s, 0.0f, false, &v.x);
    EXPECT_EQ(v, glm::vec3(0.0f));
    evaluateSampler(s, 4.0f, false, &v.x);
    EXPECT_EQ(v, glm::vec3(2, 4, -6));
}

TEST(AnimationSampler, LinearRotationIsSlerp)
{
    // Between rotations about one axis, slerp turns at a constant rate: at u the angle is
    // u × 160°. Normalised linear interpolation would give 52.6° at u = 0.25, not 40°.
    const glm::vec4 a = axisAngle({0, 0, 1}, 0.0f), b = axisAngle({0, 0, 1}, 160.0f);
    const auto s = sampler(Interpolation::Linear, {0.0f, 1.0f}, {a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w}, 4);
    for (float u : {0.1f, 0.25f, 0.5f, 0.8f}) {
        SCOPED_TRACE(u);
        const glm::vec4 q = rotationAt(s, u);
        expectNear(q, axisAngle({0, 0, 1}, 160.0f * u), 1e-5f);
        EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
    }
}

TEST(AnimationSampler, LinearRotationTakesTheShorterArcAndIsNormalised)
{
    // b stored as -q (the same rotation as +90° about Z): the way from a is 90°, not 270°.
    const glm::vec4 a = axisAngle({0, 0, 1}, 0.0f), b = -axisAngle({0, 0, 1}, 90.0f);
    const auto s = sampler(Interpolation::Linear, {0.0f, 1.0f}, {a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w}, 4);
    expectNear(rotationAt(s, 0.5f), axisAngle({0, 0, 1}, 45.0f), 1e-5f);
    // Keys that are not unit length come out normalised (STEP and at the keys too).
    const auto scaled = sampler(Interpolation::Step, {0.0f}, {0, 0, 0, 3}, 4);
    expectNear(rotationAt(scaled, 0.0f), {0, 0, 0, 1}, 1e-6f);
}

TEST(AnimationSampler, CubicSplineIsTheSpecsHermite)
{
    // Keys at 0 s and 2 s (td = 2): key 0 value 1, out-tangent 3; key 1 in-tangent -1, value 5.
    // p(s) = (2s³-3s²+1)v0 + td(s³-2s²+s)b0 + (-2s³+3s²)v1 + td(s³-s²)a1, worked by hand:
    // t = 0.5 (s = 0.25): 0.84375 + 2(0.140625)(3) + 0.15625(5) + 2(-0.046875)(-1) = 2.5625;
    // t = 1.5 (s = 0.75): 0.15625 + 2(0.046875)(3) + 0.84375(5) + 2(-0.140625)(-1) = 4.9375.
    const auto s = sampler(Interpolation::CubicSpline, {0.0f, 2.0f}, {0.0f, 1.0f, 3.0f, -1.0f, 5.0f, 0.0f}, 1);
    EXPECT_NEAR(at1(s, 0.5f), 2.5625f, 1e-5f);
    EXPECT_NEAR(at1(s, 1.5f), 4.9375f, 1e-5f);
    EXPECT_EQ(at1(s, 0.0f), 1.0f);
    EXPECT_EQ(at1(s, 2.0f), 5.0f);
    EXPECT_EQ(at1(s, 7.0f), 5.0f);
    // A cubic rotation comes out normalised.
    const auto r = sampler(Interpolation::CubicSpline, {0.0f, 1.0f},
                           {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0}, 4);
    EXPECT_NEAR(glm::length(rotationAt(r, 0.3f)), 1.0f, 1e-6f);
}

TEST(AnimationPose, JointMatricesAreWorldTimesInverseBind)
{
    // root (T(1, 0, 0) R_y(30°)) > upper (T(0, 2, 0), rotation animated about X from 0° to
    // 90° over 2 s) > lower (T(0, 1, 0) S(2)); joints upper and lower.
    Scene s;
    Node root;
    root.translation = {1, 0, 0};
    root.rotation = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0));
    const int r = s.addNode(root);
    Node upper;
    upper.translation = {0, 2, 0};
    const int u = s.addNode(upper, r);
    Node lower;
    lower.translation = {0, 1, 0};
    lower.scale = glm::vec3(2.0f);
    const int l = s.addNode(lower, u);
    Skin skin;
    skin.joints = {u, l};
    const glm::mat4 ibm0 = glm::translate(glm::mat4(1.0f), {0.0f, -2.0f, 0.3f});
    const glm::mat4 ibm1 = glm::scale(glm::translate(glm::mat4(1.0f), {0.5f, -3.0f, 0.0f}), glm::vec3(0.5f, 0.25f, 1.0f));
    skin.inverseBindMatrices = {ibm0, ibm1};
    s.skins.push_back(skin);
    Animation a;
    const glm::vec4 q0 = axisAngle({1, 0, 0}, 0.0f), q1 = axisAngle({1, 0, 0}, 90.0f);
    a.samplers.push_back(sampler(Interpolation::Linear, {0.0f, 2.0f}, {q0.x, q0.y, q0.z, q0.w, q1.x, q1.y, q1.z, q1.w}, 4));
    a.channels.push_back({0, u, AnimationPath::Rotation});
    s.animations.push_back(a);

    for (float t : {0.0f, 0.5f, 2.0f}) {
        SCOPED_TRACE(t);
        // The same transforms from axis-angle matrices, composed by hand.
        const glm::mat4 rootWorld = glm::rotate(glm::translate(glm::mat4(1.0f), {1, 0, 0}), glm::radians(30.0f), {0, 1, 0});
        const glm::mat4 upperWorld =
            rootWorld * glm::rotate(glm::translate(glm::mat4(1.0f), {0, 2, 0}), glm::radians(45.0f * t), {1, 0, 0});
        const glm::mat4 lowerWorld = upperWorld * glm::scale(glm::translate(glm::mat4(1.0f), {0, 1, 0}), glm::vec3(2.0f));
        const glm::mat4 want[2] = {upperWorld * ibm0, lowerWorld * ibm1};
        const auto joints = jointMatrices(s.skins[0], worldMatrices(s, poseAt(s, 0, t)));
        ASSERT_EQ(joints.size(), 2u);
        for (int j = 0; j < 2; ++j)
            for (int c = 0; c < 4; ++c)
                for (int k = 0; k < 4; ++k) EXPECT_NEAR(joints[size_t(j)][c][k], want[j][c][k], 1e-5f) << j << " " << c << k;
    }
}

TEST(AnimationPose, MorphWeightsFollowTheAnimation)
{
    Scene s;
    Mesh mesh;
    Primitive p;
    p.vertices.resize(1);
    p.targets.resize(2);
    mesh.primitives.push_back(p);
    mesh.weights = {0.25f, 0.0f};
    s.meshes.push_back(mesh);
    Node node;
    node.mesh = 0;
    const int n = s.addNode(node);
    Animation a;
    a.samplers.push_back(sampler(Interpolation::Linear, {0.0f, 1.0f}, {0.0f, 0.0f, 1.0f, 0.5f}, 2));
    a.channels.push_back({0, n, AnimationPath::Weights});
    s.animations.push_back(a);

    EXPECT_EQ(morphWeights(s, poseAt(s, -1, 0.0f), n, 2), (std::vector<float>{0.25f, 0.0f})); // the mesh's
    const auto w = morphWeights(s, poseAt(s, 0, 0.25f), n, 2);
    EXPECT_NEAR(w[0], 0.25f, 1e-6f);
    EXPECT_NEAR(w[1], 0.125f, 1e-6f);
    EXPECT_EQ(morphWeights(s, poseAt(s, 0, 3.0f), n, 2), (std::vector<float>{1.0f, 0.5f}));
    s.nodes[size_t(n)].weights = {0.5f, 0.75f}; // the node's own weights win over the mesh's
    EXPECT_EQ(morphWeights(s, poseAt(s, -1, 0.0f), n, 2), (std::vector<float>{0.5f, 0.75f}));
}

TEST(AnimationPose, DeformMorphsThenSkins)
{
    Primitive p;
    Vertex v;
    v.position = {1, 0, 0};
    v.normal = {0, 0, 1};
    v.tangent = {1, 0, 0, -1};
    p.vertices = {v};
    MorphTarget target;
    target.positions = {{0, 2, 0}};
    target.normals = {{0, 1, -1}};   // at weight 1 the normal is (0, 1, 0)
    target.tangents = {{-1, 0, 1}};  // at weight 1 the tangent is (0, 0, 1)
    p.targets = {target};
    p.influences = 8; // both sets: weight 0.25 on joint 0 (first set), 0.75 on joint 1 (second)
    p.joints = {0, 0, 0, 0, 1, 0, 0, 0};
    p.weights = {0.25f, 0, 0, 0, 0.75f, 0, 0, 0};
    const glm::mat4 j0 = glm::translate(glm::mat4(1.0f), {0, 0, 4});
    const glm::mat4 j1 = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), {0, 0, 1}); // x -> y, y -> -x
    std::vector<Vertex> out;
    Bounds bounds;
    deformPrimitive(p, {j0, j1}, {1.0f}, out, bounds);
    ASSERT_EQ(out.size(), 1u);
    // Morphed: p = (1, 2, 0), n = (0, 1, 0), t = (0, 0, 1). Skinned by 0.25 j0 + 0.75 j1:
    // 0.25 (1, 2, 4) + 0.75 (-2, 1, 0) = (-1.25, 1.25, 1).
    EXPECT_NEAR(out[0].position.x, -1.25f, 1e-5f);
    EXPECT_NEAR(out[0].position.y, 1.25f, 1e-5f);
    EXPECT_NEAR(out[0].position.z, 1.0f, 1e-5f);
    // The blended 3x3 is 0.25 I + 0.75 R: n = (0, 1, 0) goes to (-0.75, 0.25, 0) / |…| by the
    // inverse transpose (this matrix is a scaled rotation, so the same direction).
    const glm::vec3 n = glm::normalize(glm::vec3(-0.75f, 0.25f, 0.0f));
    EXPECT_NEAR(glm::dot(out[0].normal, n), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::vec3(out[0].tangent), glm::vec3(0, 0, 1)), 1.0f, 1e-5f);
    EXPECT_EQ(out[0].tangent.w, -1.0f);
    EXPECT_EQ(bounds.min, out[0].position);
    // With weight 0 the target does nothing, and without joints there is no skinning.
    deformPrimitive(p, {}, {0.0f}, out, bounds);
    EXPECT_EQ(out[0].position, v.position);
}

TEST(GltfAnimation, ImportsTheSkinnedBar)
{
    const Scene s = loadGltf(kAssets + "skinned_bar.gltf");
    ASSERT_EQ(s.skins.size(), 1u);
    EXPECT_EQ(s.skins[0].joints, (std::vector<int>{1, 2}));
    EXPECT_EQ(s.skins[0].inverseBindMatrices[1], glm::translate(glm::mat4(1.0f), {0, -1, 0}));
    EXPECT_EQ(s.nodes[0].skin, 0);
    const Primitive& bar = s.meshes[0].primitives[0];
    EXPECT_EQ(bar.influences, 8); // JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1
    ASSERT_EQ(bar.joints.size(), bar.vertices.size() * 8);
    ASSERT_EQ(s.animations.size(), 2u);
    EXPECT_EQ(s.animations[0].name, "bend");
    EXPECT_EQ(s.animations[1].name, "lift");
    EXPECT_EQ(s.animations[0].duration(), 1.0f);
    EXPECT_EQ(s.animations[1].samplers[0].interpolation, Interpolation::Step);
    // At t = 1 the top of the bar, (±0.1, 2, ±0.1) at rest, is turned 90° about the bend
    // joint at (0, 1, 0): x = -1, y in 0.9..1.1.
    const Pose pose = poseAt(s, 0, 1.0f);
    const auto joints = jointMatrices(s.skins[0], worldMatrices(s, pose));
    std::vector<Vertex> out;
    Bounds bounds;
    deformPrimitive(bar, joints, {}, out, bounds);
    EXPECT_NEAR(bounds.min.x, -1.0f, 1e-5f);
    EXPECT_NEAR(bounds.max.y, 1.1f, 1e-5f);
}

TEST(GltfAnimation, ImportsTheMorphQuad)
{
    const Scene s = loadGltf(kAssets + "morph_quad.gltf");
    ASSERT_EQ(s.meshes[0].primitives[0].targets.size(), 2u);
    EXPECT_EQ(s.meshes[0].weights, (std::vector<float>{0.25f, 0.0f}));
    ASSERT_EQ(s.animations.size(), 1u);
    EXPECT_EQ(s.animations[0].samplers[0].components, 2);
    EXPECT_EQ(s.animations[0].channels[0].path, AnimationPath::Weights);
}

// EXT_mesh_gpu_instancing on the morphed quad (tests/assets/gltf/morph_quad.gltf, an instance at
// each of its four corners): the animation's weights channel targets the instanced node, and
// every instance is drawn with the weights it sets ((0, 0) to (1, 0.5) over 1 s), not the mesh's
// (0.25, 0). Before, the file was refused (the instanced node had no mesh of its own for the
// weights channel). Broken on purpose (2026-12-07): without Node::weightsFrom in morphWeights the
// instances kept (0.25, 0).
TEST(GltfAnimation, InstancesFollowTheirNodesMorphWeights)
{
    const Scene s = loadEdited("morph_quad.gltf", [](nlohmann::json& d) {
        d["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"] = {{"attributes", {{"TRANSLATION", 0}}}};
        d["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    });
    ASSERT_EQ(s.nodes.size(), 5u); // the quad's node and its four instances
    const Pose pose = poseAt(s, 0, 1.0f);
    for (int instance = 1; instance <= 4; ++instance) {
        EXPECT_EQ(s.nodes[size_t(instance)].weightsFrom, 0);
        EXPECT_EQ(morphWeights(s, pose, instance, 2), (std::vector<float>{1.0f, 0.5f})) << "instance " << instance;
        EXPECT_EQ(morphWeights(s, poseAt(s, -1, 0.0f), instance, 2), (std::vector<float>{0.25f, 0.0f})); // at rest: the mesh's
    }
}

TEST(GltfAnimation, BadFilesAreOneLineErrors)
{
    using test::errorOf;
    EXPECT_NE(errorOf([] { loadEditedBar([](nlohmann::json& d) { d["skins"][0]["joints"] = {1}; }); })
                  .find("uses joint 1 (the skin has 1)"),
              std::string::npos);
    EXPECT_NE(errorOf([] { loadEditedBar([](nlohmann::json& d) { d["skins"][0]["joints"] = {1, 17}; }); })
                  .find("refers to node 17"),
              std::string::npos);
    EXPECT_NE(errorOf([] { loadEditedBar([](nlohmann::json& d) { d["animations"][0]["channels"][0]["sampler"] = 3; }); })
                  .find("refers to sampler 3"),
              std::string::npos);
    EXPECT_NE(errorOf([] { loadEditedBar([](nlohmann::json& d) { d["animations"][0]["channels"][0]["target"]["node"] = 9; }); })
                  .find("refers to node 9"),
              std::string::npos);
    EXPECT_NE(errorOf([] {
                  loadEditedBar([](nlohmann::json& d) { d["animations"][0]["samplers"][0]["interpolation"] = "CUBICSPLINE"; });
              }).find("output numbers for 2 keyframes"),
              std::string::npos);
    EXPECT_NE(errorOf([] { loadEditedBar([](nlohmann::json& d) { d["animations"][0]["channels"][0]["target"]["path"] = "weights"; }); })
                  .find("whose mesh has no morph targets"),
              std::string::npos);
    // JOINTS as floats is not glTF.
    EXPECT_NE(errorOf([] {
                  loadEditedBar([](nlohmann::json& d) {
                      d["accessors"][2]["componentType"] = 5126;
                  });
              }).find("JOINTS_0"),
              std::string::npos);
    EXPECT_NE(errorOf([] { loadEditedBar([](nlohmann::json& d) { d["nodes"][0]["skin"] = 4; }); }).find("refers to skin 4"),
              std::string::npos);
    EXPECT_NE(errorOf([] { loadEditedBar([](nlohmann::json& d) { d["skins"][0]["inverseBindMatrices"] = 0; }); }).find("MAT4"),
              std::string::npos);
}

namespace {

Scene loadEditedPointers(const std::function<void(nlohmann::json&)>& edit)
{
    return loadEdited("animation_pointer.gltf", edit);
}

} // namespace

// tests/assets/gltf/animation_pointer.gltf (make_animation_pointer.py): KHR_animation_pointer's
// channels become node paths and material, texture-transform and light properties; the one
// Specula does not animate (an application's extras) is a warning naming its pointer.
TEST(GltfAnimation, AnimationPointerTargets)
{
    const Scene s = loadGltf(kAssets + "animation_pointer.gltf");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("'/materials/0/extras/glow', which is not supported"), std::string::npos) << s.warnings[0];
    ASSERT_EQ(s.animations.size(), 1u);
    const std::vector<AnimationChannel>& c = s.animations[0].channels;
    ASSERT_EQ(c.size(), 7u);
    EXPECT_EQ(c[0].path, AnimationPath::Property);
    EXPECT_EQ(c[0].property, (AnimatedProperty{AnimatedField::BaseColor, 0, -1}));
    EXPECT_EQ(c[1].property, (AnimatedProperty{AnimatedField::TextureOffset, 0, 0})); // the base colour texture
    EXPECT_EQ(c[2].path, AnimationPath::Translation);
    EXPECT_EQ(c[2].node, 1);
    EXPECT_EQ(c[3].property, (AnimatedProperty{AnimatedField::LightIntensity, 0, -1}));
    EXPECT_EQ(c[4].property, (AnimatedProperty{AnimatedField::LightColor, 0, -1}));
    EXPECT_EQ(c[5].path, AnimationPath::Translation); // the camera's node, a core channel
    EXPECT_EQ(c[6].property, (AnimatedProperty{AnimatedField::CameraYfov, 0, -1}));
    EXPECT_EQ(animatedProperties(s).size(), 5u);

    // The values at 0.25 s and 0.75 s, written into copies of the materials and lights.
    for (const float t : {0.25f, 0.75f}) {
        const Pose pose = poseAt(s, 0, t);
        std::vector<Material> materials = s.materials;
        std::vector<Light> lights = s.lights;
        applyProperties(pose, materials, lights);
        const glm::vec4 colour = glm::mix(glm::vec4(1, 0, 0, 1), glm::vec4(0, 0, 1, 1), t);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(materials[0].baseColorFactor[k], colour[k], 1e-6f) << "t " << t;
        EXPECT_EQ(materials[0].baseColorTexture.transform.offset, glm::vec2(t < 0.5f ? 0.0f : 0.5f, 0.0f));
        EXPECT_EQ(materials[1].baseColorFactor, s.materials[1].baseColorFactor); // not animated
        EXPECT_NEAR(lights[0].intensity, 2.0f + 4.0f * t, 1e-5f);
        EXPECT_EQ(lights[0].color, t < 0.5f ? glm::vec3(1.0f) : glm::vec3(1.0f, 0.5f, 0.25f));
        EXPECT_NEAR(pose.nodes[1].translation.y, 0.5f * t, 1e-6f);
    }
    // The rest pose sets nothing: the file's values stay.
    const Pose rest = poseAt(s, -1, 0.0f);
    EXPECT_TRUE(rest.properties.empty());
}

TEST(GltfAnimation, AnimationPointerErrors)
{
    using test::errorOf;
    const auto pointer = [](int channel) {
        return nlohmann::json::json_pointer("/animations/0/channels/" + std::to_string(channel) +
                                            "/target/extensions/KHR_animation_pointer/pointer");
    };
    // An index past the document's materials or lights.
    EXPECT_NE(errorOf([&] {
                  loadEditedPointers([&](nlohmann::json& d) { d[pointer(0)] = "/materials/7/pbrMetallicRoughness/baseColorFactor"; });
              }).find("but there are 2 materials"),
              std::string::npos);
    EXPECT_NE(errorOf([&] {
                  loadEditedPointers([&](nlohmann::json& d) { d[pointer(3)] = "/extensions/KHR_lights_punctual/lights/3/intensity"; });
              }).find("but there are 1 lights"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { loadEditedPointers([&](nlohmann::json& d) { d[pointer(2)] = "/nodes/9/translation"; }); })
                  .find("refers to node 9"),
              std::string::npos);
    // The path "pointer" without the extension's pointer.
    EXPECT_NE(errorOf([&] {
                  loadEditedPointers([](nlohmann::json& d) { d["animations"][0]["channels"][0]["target"].erase("extensions"); });
              }).find("no KHR_animation_pointer pointer"),
              std::string::npos);
    // Keyframes of the wrong size for the property (a VEC4 colour sampler on a scalar).
    EXPECT_NE(errorOf([&] {
                  loadEditedPointers([&](nlohmann::json& d) { d[pointer(0)] = "/materials/0/pbrMetallicRoughness/roughnessFactor"; });
              }).find("output numbers for 2 keyframes of 1 values"),
              std::string::npos);
    // A pointer Specula does not know is a warning, not an error.
    const Scene s = loadEditedPointers([&](nlohmann::json& d) { d[pointer(0)] = "/cameras/0/perspective/aspectRatio"; });
    EXPECT_EQ(s.warnings.size(), 2u);
}

// An animated camera (its node moved by a core channel, its yfov through a pointer) seen
// through render::cameraView with the pose: where the keyframes put it, against matrices built
// here from the file's numbers; without a pose, the rest camera.
TEST(GltfAnimation, AnimatedCameraFollowsItsNodeAndPointer)
{
    const Scene s = loadGltf(kAssets + "animation_pointer.gltf");
    const float aspect = 2.0f;
    for (const float t : {0.0f, 0.5f, 1.0f}) {
        const Pose pose = poseAt(s, 0, t);
        const render::View v = render::cameraView(s, 0, aspect, &pose);
        const glm::vec3 eye(0.5f * t, 0.0f, 6.0f);
        EXPECT_NEAR(glm::distance(v.position, eye), 0.0f, 1e-6f) << "t " << t;
        const glm::mat4 view = glm::inverse(glm::translate(glm::mat4(1.0f), eye));
        const glm::mat4 projection = glm::perspective(0.6f + 0.3f * t, aspect, 0.1f, 50.0f);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                EXPECT_NEAR(v.view[c][r], view[c][r], 1e-5f) << "t " << t;
                EXPECT_NEAR(v.projection[c][r], projection[c][r], 1e-5f) << "t " << t;
            }
    }
    const render::View rest = render::cameraView(s, 0, aspect);
    EXPECT_EQ(rest.position, glm::vec3(0.0f, 0.0f, 6.0f));
    EXPECT_NEAR(rest.projection[1][1], 1.0f / std::tan(0.3f), 1e-5f);
}

// Scene::append (scene files with several models) shifts a pointer's material and light as it
// shifts the primitives' and nodes'.
TEST(GltfAnimation, AppendShiftsAnimatedMaterialsAndLights)
{
    Scene s = loadGltf(kAssets + "animation_pointer.gltf");
    s.append(loadGltf(kAssets + "animation_pointer.gltf"));
    ASSERT_EQ(s.animations.size(), 2u);
    const std::vector<AnimationChannel>& c = s.animations[1].channels;
    EXPECT_EQ(c[0].property.index, 2); // material 0 of the second copy
    ASSERT_GT(c[2].node, 2); // the nodes shift as before: the second copy's card
    EXPECT_EQ(s.nodes[size_t(c[2].node)].name, "card");
    EXPECT_EQ(c[3].property.index, 1); // light 0 of the second copy
    EXPECT_EQ(c[4].property.index, 1);
    EXPECT_EQ(c[6].property.index, 1); // camera 0 of the second copy
}

// tests/assets/gltf/animation_pointer_surface.gltf (make_animation_pointer_surface.py): pointers
// on a normal map's scale, an occlusion map's strength, an alpha cutoff and KHR_node_visibility's
// `visible` (a bool: unsigned bytes, STEP). A hidden node's mesh and light are left out of the
// scene's instances unless asked for (the renderer keeps them for the animation that shows
// them); under a pose its subtree follows the animated flag. Broken on purpose (2026-12-07):
// nodeVisibility ignoring the pose's value failed at 0.25 s; the visibility not passed to the
// children in Scene's walk listed the hidden quad and light.
TEST(GltfAnimation, AnimationPointerSurfaceAndVisibilityTargets)
{
    const Scene s = loadGltf(kAssets + "animation_pointer_surface.gltf");
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    ASSERT_EQ(s.animations.size(), 1u);
    const std::vector<AnimationChannel>& c = s.animations[0].channels;
    ASSERT_EQ(c.size(), 4u);
    EXPECT_EQ(c[0].property, (AnimatedProperty{AnimatedField::NormalScale, 0, -1}));
    EXPECT_EQ(c[1].property, (AnimatedProperty{AnimatedField::OcclusionStrength, 1, -1}));
    EXPECT_EQ(c[2].property, (AnimatedProperty{AnimatedField::AlphaCutoff, 2, -1}));
    EXPECT_EQ(c[3].property, (AnimatedProperty{AnimatedField::NodeVisible, 3, -1}));
    EXPECT_FALSE(s.nodes[3].visible);
    EXPECT_TRUE(s.nodes[4].visible); // its own flag; its parent hides it

    const auto meshNodes = [](const std::vector<MeshInstance>& v) {
        std::vector<int> out;
        for (const MeshInstance& m : v) out.push_back(m.node);
        return out;
    };
    EXPECT_EQ(meshNodes(s.meshInstances()), (std::vector<int>{0, 1, 2}));
    const std::vector<MeshInstance> all = s.meshInstances(HiddenNodes::Include);
    ASSERT_EQ(meshNodes(all), (std::vector<int>{0, 1, 2, 4}));
    EXPECT_FALSE(all[3].visible);
    ASSERT_EQ(s.lightInstances().size(), 1u); // the sun
    ASSERT_EQ(s.lightInstances(HiddenNodes::Include).size(), 2u);
    EXPECT_FALSE(s.lightInstances(HiddenNodes::Include)[0].visible); // the bulb, under the group
    // A renderer keeps hidden nodes only where an animation may show them.
    EXPECT_EQ(s.hiddenNodesToKeep(), HiddenNodes::Include);
    Scene still = s;
    still.animations.clear();
    EXPECT_EQ(still.hiddenNodesToKeep(), HiddenNodes::Skip);

    for (const float t : {0.25f, 0.75f}) {
        const Pose pose = poseAt(s, 0, t);
        const std::vector<bool> visible = nodeVisibility(s, pose);
        for (int n : {3, 4, 5}) EXPECT_EQ(visible[size_t(n)], t < 0.5f) << "t " << t << " node " << n;
        for (int n : {0, 1, 2, 6}) EXPECT_TRUE(visible[size_t(n)]) << "t " << t << " node " << n;
        std::vector<Material> materials = s.materials;
        std::vector<Light> lights = s.lights;
        applyProperties(pose, materials, lights);
        EXPECT_NEAR(materials[0].normalScale, 2.0f * t, 1e-6f);
        EXPECT_NEAR(materials[1].occlusionStrength, t, 1e-6f);
        EXPECT_NEAR(materials[2].alphaCutoff, 0.1f + 0.8f * t, 1e-6f);
        EXPECT_EQ(lights[1].intensity, 8.0f); // visibility is not a light's property
    }
    const std::vector<bool> rest = nodeVisibility(s, poseAt(s, -1, 0.0f));
    EXPECT_FALSE(rest[4]);
}

// The volume's and transmission's pointers, and the clamps a pose applies as the importer does.
TEST(GltfAnimation, AnimationPointerTransmissionAndVolumeTargets)
{
    const auto pointer = [](int channel) {
        return nlohmann::json::json_pointer("/animations/0/channels/" + std::to_string(channel) +
                                            "/target/extensions/KHR_animation_pointer/pointer");
    };
    // Channel 5 has a scalar sampler (0.25 to 0.75 over 1 s), channel 4 a VEC3 one ((1, 1, 1)
    // STEP to (1, 0.5, 0.25) at 0.5 s).
    const std::pair<const char*, AnimatedField> scalars[] = {
        {"/materials/0/extensions/KHR_materials_transmission/transmissionFactor", AnimatedField::Transmission},
        {"/materials/0/extensions/KHR_materials_volume/thicknessFactor", AnimatedField::Thickness},
        {"/materials/0/extensions/KHR_materials_volume/attenuationDistance", AnimatedField::AttenuationDistance},
        {"/materials/0/extensions/KHR_materials_clearcoat/clearcoatNormalTexture/scale", AnimatedField::ClearcoatNormalScale},
        {"/materials/0/alphaCutoff", AnimatedField::AlphaCutoff},
        {"/materials/0/normalTexture/scale", AnimatedField::NormalScale},
        {"/materials/0/occlusionTexture/strength", AnimatedField::OcclusionStrength},
    };
    for (const auto& scalar : scalars) {
        const char* path = scalar.first; // named, not a structured binding: clang 15 cannot capture those
        const AnimatedField field = scalar.second;
        const Scene s = loadEditedPointers([&](nlohmann::json& d) { d[pointer(5)] = path; });
        EXPECT_TRUE(s.warnings.empty()) << path;
        ASSERT_EQ(s.animations[0].channels.size(), 8u) << path;
        EXPECT_EQ(s.animations[0].channels[5].property, (AnimatedProperty{field, 0, -1})) << path;
        std::vector<Material> materials = s.materials;
        std::vector<Light> lights = s.lights;
        applyProperties(poseAt(s, 0, 0.5f), materials, lights);
        const Material& m = materials[0];
        const float got = field == AnimatedField::Transmission          ? m.transmissionFactor
                          : field == AnimatedField::Thickness           ? m.thickness
                          : field == AnimatedField::AttenuationDistance ? m.attenuationDistance
                          : field == AnimatedField::ClearcoatNormalScale ? m.clearcoatNormalScale
                          : field == AnimatedField::AlphaCutoff         ? m.alphaCutoff
                          : field == AnimatedField::NormalScale         ? m.normalScale
                                                                        : m.occlusionStrength;
        EXPECT_NEAR(got, 0.5f, 1e-6f) << path;
    }
    const Scene s = loadEditedPointers([&](nlohmann::json& d) { d[pointer(4)] = "/materials/0/extensions/KHR_materials_volume/attenuationColor"; });
    EXPECT_EQ(s.animations[0].channels[4].property, (AnimatedProperty{AnimatedField::AttenuationColor, 0, -1}));
    std::vector<Material> materials = s.materials;
    std::vector<Light> lights = s.lights;
    applyProperties(poseAt(s, 0, 0.75f), materials, lights);
    EXPECT_EQ(materials[0].attenuationColor, glm::vec3(1.0f, 0.5f, 0.25f));

    // Clamped as the importer clamps the file's values.
    Pose pose = restPose(s);
    pose.properties = {{{AnimatedField::Transmission, 0, -1}, glm::vec4(1.5f)},
                       {{AnimatedField::Thickness, 0, -1}, glm::vec4(-1.0f)},
                       {{AnimatedField::AttenuationDistance, 0, -1}, glm::vec4(-2.0f)},
                       {{AnimatedField::OcclusionStrength, 0, -1}, glm::vec4(3.0f)},
                       {{AnimatedField::AttenuationColor, 0, -1}, glm::vec4(2.0f, -1.0f, 0.5f, 0.0f)}};
    materials = s.materials;
    applyProperties(pose, materials, lights);
    EXPECT_EQ(materials[0].transmissionFactor, 1.0f);
    EXPECT_EQ(materials[0].thickness, 0.0f);
    EXPECT_EQ(materials[0].attenuationDistance, 0.0f); // no attenuation
    EXPECT_EQ(materials[0].occlusionStrength, 1.0f);
    EXPECT_EQ(materials[0].attenuationColor, glm::vec3(1.0f, 0.0f, 0.5f));
}

// KHR_node_visibility's pointer is a bool: its keyframes unsigned bytes, its sampler STEP, its node
// in the document; each otherwise a one-line error. Scene::append shifts its node.
TEST(GltfAnimation, NodeVisibilityPointerErrorsAndAppend)
{
    using test::errorOf;
    const auto edited = [](const std::function<void(nlohmann::json&)>& edit) {
        return [edit] { loadEdited("animation_pointer_surface.gltf", edit); };
    };
    EXPECT_NE(errorOf(edited([](nlohmann::json& d) { d["animations"][0]["channels"][3]["sampler"] = 0; })) // floats, LINEAR
                  .find("a bool: its output must be unsigned bytes"),
              std::string::npos);
    EXPECT_NE(errorOf(edited([](nlohmann::json& d) { d["animations"][0]["samplers"][3]["interpolation"] = "LINEAR"; }))
                  .find("a bool: its sampler must use STEP interpolation, not LINEAR"),
              std::string::npos);
    EXPECT_NE(errorOf(edited([](nlohmann::json& d) {
                  d["animations"][0]["channels"][3]["target"]["extensions"]["KHR_animation_pointer"]["pointer"] =
                      "/nodes/9/extensions/KHR_node_visibility/visible";
              })).find("but there are 7 nodes"),
              std::string::npos);

    Scene s = loadGltf(kAssets + "animation_pointer.gltf");
    s.append(loadGltf(kAssets + "animation_pointer_surface.gltf"));
    const AnimationChannel& visibility = s.animations[1].channels[3];
    ASSERT_EQ(visibility.property.field, AnimatedField::NodeVisible);
    EXPECT_EQ(s.nodes[size_t(visibility.property.index)].name, "group");
    EXPECT_FALSE(s.nodes[size_t(visibility.property.index)].visible);
}
