// JSON scene files (docs/scene-format.md): values parsed exactly, the file's camera first,
// models placed, and every error one line naming the file and the offending value.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "TestFiles.h"
#include "core/Error.h"
#include "scene/SceneFile.h"

namespace fs = std::filesystem;
using namespace specula;
using namespace specula::scene;
using test::errorOf;
using test::sceneError;
using test::TempDir;

namespace {

const fs::path kBox = fs::path(SPECULA_ASSETS_DIR) / "models" / "Box" / "Box.glb";

void expectVec3(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

glm::vec3 column(const glm::mat4& m, int i) { return glm::vec3(m[i]); }

const char* kFullScene = R"({
  // Comments are allowed.
  "shapes": [
    {"type": "sphere", "name": "ball", "radius": 0.5, "segments": 16, "rings": 8, "translation": [1, 2, 3],
     "material": {"baseColor": [0.5, 0.25, 0.125, 0.75], "metallic": 1, "roughness": 0.3,
                  "emissive": [1, 0.5, 0], "emissiveStrength": 4, "doubleSided": true,
                  "alphaMode": "mask", "alphaCutoff": 0.25}},
    {"type": "cube", "halfExtent": 2, "rotationDegrees": [0, 90, 0], "scale": [1, 2, 3]},
    {"type": "plane", "size": 10, "uvRepeat": 4, "scale": 2}
  ],
  "lights": [
    {"type": "point", "name": "bulb", "position": [0, 3, 0], "color": [1, 0.9, 0.8], "intensity": 100, "range": 20},
    {"type": "spot", "position": [0, 4, 4], "target": [0, 0, 0], "intensity": 500,
     "innerConeAngle": 10, "outerConeAngle": 30},
    {"type": "directional", "direction": [0, -1, 0], "intensity": 3}
  ],
  "camera": {"position": [0, 1, 5], "target": [0, 1, 0], "yfov": 60, "znear": 0.05, "zfar": 200},
  "environment": {"color": [0.1, 0.2, 0.3], "intensity": 2, "rotation": 90},
  "render": {"width": 640, "height": 360, "msaa": 8, "exposure": -1.5, "tonemap": "aces",
             "brdfG": "schlick-ggx", "defaultLights": false}
})";

} // namespace

TEST(SceneFile, ParsesEveryField)
{
    TempDir dir;
    const fs::path path = dir.write("full.json", kFullScene);
    const SceneDocument document = loadSceneFile(path, test::kAllowExternal);
    const Scene& scene = document.scene;
    EXPECT_EQ(document.source, path);
    EXPECT_EQ(scene.name, "full");

    ASSERT_EQ(scene.meshes.size(), 3u);
    ASSERT_EQ(scene.materials.size(), 3u);
    const Material& ball = scene.materials[size_t(scene.meshes[0].primitives[0].material)];
    EXPECT_EQ(scene.meshes[0].name, "ball");
    EXPECT_EQ(ball.baseColorFactor, glm::vec4(0.5f, 0.25f, 0.125f, 0.75f));
    EXPECT_EQ(ball.metallicFactor, 1.0f);
    EXPECT_EQ(ball.roughnessFactor, 0.3f);
    EXPECT_EQ(ball.emissiveFactor, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_EQ(ball.emissiveStrength, 4.0f);
    EXPECT_TRUE(ball.doubleSided);
    EXPECT_EQ(ball.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(ball.alphaCutoff, 0.25f);
    // A 16 x 8 sphere: (16 + 1) * (8 + 1) vertices, radius 0.5.
    EXPECT_EQ(scene.meshes[0].primitives[0].vertices.size(), 17u * 9u);
    EXPECT_EQ(scene.meshes[0].primitives[0].bounds.max, glm::vec3(0.5f));

    // Unset material fields: a white dielectric of roughness 0.5.
    const Material& plain = scene.materials[size_t(scene.meshes[1].primitives[0].material)];
    EXPECT_EQ(plain.baseColorFactor, glm::vec4(1.0f));
    EXPECT_EQ(plain.metallicFactor, 0.0f);
    EXPECT_EQ(plain.roughnessFactor, 0.5f);
    EXPECT_EQ(plain.alphaMode, AlphaMode::Opaque);
    EXPECT_FALSE(plain.doubleSided);
    EXPECT_EQ(scene.meshes[1].name, "cube1");
    EXPECT_EQ(scene.meshes[1].primitives[0].bounds.max, glm::vec3(2.0f));
    EXPECT_EQ(scene.meshes[2].primitives[0].bounds.max, glm::vec3(5.0f, 0.0f, 5.0f));
    EXPECT_EQ(scene.meshes[2].primitives[0].vertices[1].uv0, glm::vec2(4.0f));

    const auto meshes = scene.meshInstances();
    ASSERT_EQ(meshes.size(), 3u);
    EXPECT_EQ(meshes[0].world, glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)));
    // The cube: scale (1, 2, 3), then 90° about +Y, which takes +X to −Z and +Z to +X.
    expectVec3(column(meshes[1].world, 0), glm::vec3(0, 0, -1));
    expectVec3(column(meshes[1].world, 1), glm::vec3(0, 2, 0));
    expectVec3(column(meshes[1].world, 2), glm::vec3(3, 0, 0));
    EXPECT_EQ(meshes[2].world, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)));

    ASSERT_EQ(scene.lights.size(), 3u);
    const Light& bulb = scene.lights[0];
    EXPECT_EQ(bulb.name, "bulb");
    EXPECT_EQ(bulb.type, Light::Type::Point);
    EXPECT_EQ(bulb.color, glm::vec3(1.0f, 0.9f, 0.8f));
    EXPECT_EQ(bulb.intensity, 100.0f);
    EXPECT_EQ(bulb.range, 20.0f);
    const Light& spot = scene.lights[1];
    EXPECT_EQ(spot.type, Light::Type::Spot);
    EXPECT_EQ(spot.name, "light1");
    EXPECT_EQ(spot.intensity, 500.0f);
    EXPECT_EQ(spot.range, 0.0f) << "absent range = infinite";
    EXPECT_FLOAT_EQ(spot.innerConeAngle, glm::radians(10.0f));
    EXPECT_FLOAT_EQ(spot.outerConeAngle, glm::radians(30.0f));
    EXPECT_EQ(scene.lights[2].type, Light::Type::Directional);
    EXPECT_EQ(scene.lights[2].intensity, 3.0f);
    EXPECT_EQ(scene.lights[2].color, glm::vec3(1.0f));

    const auto lights = scene.lightInstances();
    ASSERT_EQ(lights.size(), 3u);
    EXPECT_EQ(lights[0].light, 0);
    expectVec3(lights[0].position, glm::vec3(0, 3, 0));
    EXPECT_EQ(lights[1].light, 1);
    expectVec3(lights[1].position, glm::vec3(0, 4, 4));
    expectVec3(lights[1].direction, glm::normalize(glm::vec3(0, -4, -4)));
    EXPECT_EQ(lights[2].light, 2);
    // Straight down, parallel to the default up: still a proper rotation.
    expectVec3(lights[2].direction, glm::vec3(0, -1, 0));

    ASSERT_EQ(scene.cameras.size(), 1u);
    const Camera& camera = scene.cameras[0];
    EXPECT_EQ(camera.type, Camera::Type::Perspective);
    EXPECT_FLOAT_EQ(camera.yfov, glm::radians(60.0f));
    EXPECT_EQ(camera.znear, 0.05f);
    EXPECT_EQ(camera.zfar, 200.0f);
    EXPECT_EQ(camera.aspectRatio, 0.0f);
    const auto cameras = scene.cameraInstances();
    ASSERT_EQ(cameras.size(), 1u);
    expectVec3(column(cameras[0].world, 3), glm::vec3(0, 1, 5));
    expectVec3(-column(cameras[0].world, 2), glm::vec3(0, 0, -1)); // looks at the target
    expectVec3(column(cameras[0].world, 1), glm::vec3(0, 1, 0));

    ASSERT_TRUE(document.environment.color);
    EXPECT_EQ(*document.environment.color, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(document.environment.intensity, 2.0f);
    EXPECT_EQ(document.environment.rotationDegrees, 90.0f);
    EXPECT_TRUE(document.environment.file.empty());

    EXPECT_EQ(document.render.width, 640);
    EXPECT_EQ(document.render.height, 360);
    EXPECT_EQ(document.render.msaa, 8);
    EXPECT_EQ(document.render.exposure, -1.5f);
    EXPECT_EQ(document.render.tonemap, "aces");
    EXPECT_EQ(document.render.brdfG, "schlick-ggx");
    EXPECT_EQ(document.render.defaultLights, false);
}

TEST(SceneFile, EmptyFileGivesDefaults)
{
    TempDir dir;
    const SceneDocument document = loadSceneFile(dir.write("empty.json", "{}"));
    EXPECT_TRUE(document.scene.nodes.empty());
    EXPECT_FALSE(document.render.width);
    EXPECT_FALSE(document.render.tonemap);
    EXPECT_FALSE(document.render.defaultLights);
    EXPECT_FALSE(document.environment.color);
    EXPECT_EQ(document.environment.intensity, 1.0f);
}

TEST(SceneFile, RotationsAgree)
{
    TempDir dir;
    const SceneDocument document = loadSceneFile(dir.write("r.json", R"({"shapes": [
        {"type": "cube", "rotationDegrees": [90, 0, 0]},
        {"type": "cube", "rotation": [0.70710678, 0, 0, 0.70710678]},
        {"type": "cube", "rotation": [2, 0, 0, 2]},
        {"type": "cube", "rotationDegrees": [90, 90, 0]}
    ]})"));
    const auto meshes = document.scene.meshInstances();
    ASSERT_EQ(meshes.size(), 4u);
    // Euler angles, a unit quaternion and an unnormalised one give the same rotation.
    for (int c = 0; c < 4; ++c) {
        expectVec3(column(meshes[1].world, c), column(meshes[0].world, c));
        expectVec3(column(meshes[2].world, c), column(meshes[0].world, c));
    }
    // X first, then Y: +Y goes to +Z about X, then +Z goes to +X about Y.
    expectVec3(glm::vec3(meshes[3].world * glm::vec4(0, 1, 0, 0)), glm::vec3(1, 0, 0));
    expectVec3(glm::vec3(meshes[0].world * glm::vec4(0, 1, 0, 0)), glm::vec3(0, 0, 1));
}

TEST(SceneFile, LookingAlongUp)
{
    // Straight down and straight up: the right-hand side stays +X (the view tilted over the pole).
    TempDir dir;
    for (const float y : {-1.0f, 1.0f}) {
        const SceneDocument document = loadSceneFile(dir.write(
            "c.json", fmt::format(R"({{"camera": {{"position": [0, 0, 0], "direction": [0, {}, 0]}}}})", y)));
        const glm::mat4 world = document.scene.cameraInstances().at(0).world;
        expectVec3(-column(world, 2), glm::vec3(0, y, 0));
        expectVec3(column(world, 0), glm::vec3(1, 0, 0));
        expectVec3(column(world, 1), glm::vec3(0, 0, y < 0 ? -1 : 1));
    }
    // A custom up vector.
    const SceneDocument document = loadSceneFile(dir.write(
        "u.json", R"({"camera": {"type": "orthographic", "xmag": 2, "ymag": 1, "position": [0, 0, 0],
                      "direction": [1, 0, 0], "up": [0, 0, 1]}})"));
    const glm::mat4 world = document.scene.cameraInstances().at(0).world;
    expectVec3(-column(world, 2), glm::vec3(1, 0, 0));
    expectVec3(column(world, 1), glm::vec3(0, 0, 1));
    const Camera& camera = document.scene.cameras.at(0);
    EXPECT_EQ(camera.type, Camera::Type::Orthographic);
    EXPECT_EQ(camera.xmag, 2.0f);
    EXPECT_EQ(camera.ymag, 1.0f);
}

TEST(SceneFile, LoadsModelByAbsolutePath)
{
    TempDir dir;
    const SceneDocument document = loadSceneFile(dir.write(
        "m.json", R"({"models": [{"path": ")" + kBox.string() + R"(", "name": "box", "translation": [10, 0, 0], "scale": 2}]})"), test::kAllowExternal);
    const Scene& scene = document.scene;
    ASSERT_FALSE(scene.meshes.empty());
    ASSERT_EQ(scene.roots.size(), 1u);
    EXPECT_EQ(scene.nodes[size_t(scene.roots[0])].name, "box");
    // Box.glb is the unit cube centred at the origin.
    const Bounds bounds = scene.worldBounds();
    expectVec3(bounds.center(), glm::vec3(10, 0, 0));
    expectVec3(bounds.max - bounds.min, glm::vec3(2.0f));
}

TEST(SceneFile, LoadsModelByRelativePath)
{
    TempDir dir;
    const fs::path relative = fs::relative(kBox, dir.path());
    ASSERT_TRUE(relative.is_relative());
    const SceneDocument document =
        loadSceneFile(dir.write("m.json", R"({"models": [{"path": ")" + relative.string() + R"("}]})"), test::kAllowExternal);
    EXPECT_FALSE(document.scene.meshes.empty());
    expectVec3(document.scene.worldBounds().max, glm::vec3(0.5f));
}

TEST(SceneFile, FileCameraComesFirst)
{
    // A model with its own camera, listed before the scene file's camera.
    TempDir dir;
    dir.write("cam.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"camera": 0, "translation": [7, 7, 7]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.3, "znear": 0.01}}]})");
    const SceneDocument document = loadSceneFile(dir.write("s.json", R"({
        "models": [{"path": "cam.gltf"}],
        "shapes": [{"type": "sphere"}],
        "camera": {"position": [1, 2, 3], "yfov": 50}})"));
    const auto cameras = document.scene.cameraInstances();
    ASSERT_EQ(cameras.size(), 2u);
    EXPECT_FLOAT_EQ(document.scene.cameras[size_t(cameras[0].camera)].yfov, glm::radians(50.0f));
    expectVec3(column(cameras[0].world, 3), glm::vec3(1, 2, 3));
    expectVec3(column(cameras[1].world, 3), glm::vec3(7, 7, 7));
}

TEST(SceneFile, EnvironmentFileResolvedAgainstSceneDirectory)
{
    TempDir dir;
    fs::create_directory(dir / "env");
    dir.write("env/sky.hdr", "not really an image; only its existence is checked here");
    const SceneDocument document =
        loadSceneFile(dir.write("e.json", R"({"environment": {"file": "env/sky.hdr", "intensity": 0.5}})"));
    EXPECT_EQ(fs::path(document.environment.file), dir / "env" / "sky.hdr");
    EXPECT_EQ(document.environment.intensity, 0.5f);
    EXPECT_FALSE(document.environment.color);
}

TEST(SceneFile, LoadSceneDispatchesOnExtension)
{
    TempDir dir;
    const SceneDocument gltf = loadScene(kBox);
    EXPECT_FALSE(gltf.scene.meshes.empty());
    EXPECT_EQ(gltf.source, kBox);
    EXPECT_FALSE(gltf.render.width);

    const SceneDocument json = loadScene(dir.write("s.JSON", R"({"render": {"width": 3}})"));
    EXPECT_EQ(json.render.width, 3);

    const fs::path text = dir.write("scene.txt", "{}");
    EXPECT_EQ(errorOf([&] { loadScene(text); }), text.string() + ": unknown scene format (use .gltf, .glb or .json)");
    const fs::path missing = dir / "missing.json";
    EXPECT_EQ(errorOf([&] { loadScene(missing); }), missing.string() + ": no such file");
    EXPECT_EQ(errorOf([&] { loadSceneFile(missing); }), missing.string() + ": no such file");
    EXPECT_EQ(errorOf([&] { loadScene(dir / "missing.glb"); }), (dir / "missing.glb").string() + ": no such file");
}

TEST(SceneFile, UnknownKeys)
{
    EXPECT_EQ(sceneError(R"({"lihgts": []})"), "scene.json: unknown key 'lihgts' (did you mean 'lights'?)");
    EXPECT_EQ(sceneError(R"({"foo": 1})"), "scene.json: unknown key 'foo'");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "point", "position": [0, 0, 0]}, {"type": "point", "intensty": 2}]})"),
              "scene.json: unknown key 'intensty' in lights[1] (did you mean 'intensity'?)");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "material": {"color": [1, 1, 1]}}]})"),
              "scene.json: unknown key 'color' in shapes[0].material");
    EXPECT_EQ(sceneError(R"({"render": {"width": 1, "width": 2}})"), "scene.json: duplicate key 'width'");
    EXPECT_EQ(sceneError(R"({"a\nb": 1})"), "scene.json: unknown key 'a b'") << "stays one line";
    EXPECT_EQ(sceneError(R"({"camera": {"position": [0, 0, 0], "q": 1}})"), "scene.json: unknown key 'q' in camera")
        << "no guess for a one-letter key";
}

TEST(SceneFile, WrongTypes)
{
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "point", "position": [0, 0, 0]},
                                        {"type": "point", "position": [0, 0, 0]},
                                        {"type": "point", "position": [0, 0, 0], "intensity": "bright"}]})"),
              "scene.json: lights[2].intensity must be a number");
    EXPECT_EQ(sceneError(R"({"lights": {}})"), "scene.json: lights must be an array");
    EXPECT_EQ(sceneError(R"({"lights": [5]})"), "scene.json: lights[0] must be an object");
    EXPECT_EQ(sceneError(R"({"camera": {"position": [0, 0]}})"), "scene.json: camera.position must be an array of 3 numbers");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "material": {"baseColor": [1, 1]}}]})"),
              "scene.json: shapes[0].material.baseColor must be an array of 3 or 4 numbers");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "scale": "big"}]})"),
              "scene.json: shapes[0].scale must be a number or an array of 3 numbers");
    EXPECT_EQ(sceneError(R"({"render": {"width": 2.5}})"), "scene.json: render.width must be an integer");
    EXPECT_EQ(sceneError(R"({"render": {"defaultLights": 0}})"), "scene.json: render.defaultLights must be true or false");
    EXPECT_EQ(sceneError(R"({"models": [{"path": 3}]})"), "scene.json: models[0].path must be a string");
    EXPECT_EQ(sceneError("[1, 2]"), "scene.json: the file must contain a JSON object");
}

TEST(SceneFile, BadValues)
{
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "point", "position": [0, 0, 0], "intensity": -1}]})"),
              "scene.json: lights[0].intensity must not be negative");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "sun", "direction": [0, -1, 0]}]})"),
              "scene.json: lights[0].type must be point, spot or directional (got 'sun')");
    EXPECT_EQ(sceneError(R"({"lights": [{"position": [0, 0, 0]}]})"), "scene.json: lights[0] needs 'type'");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "spot", "position": [0, 0, 0]}]})"),
              "scene.json: lights[0] needs 'direction' or 'target'");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "point", "position": [0, 0, 0], "innerConeAngle": 5}]})"),
              "scene.json: lights[0].innerConeAngle only applies to spot lights");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "directional", "direction": [0, -1, 0], "range": 5}]})"),
              "scene.json: lights[0].range only applies to point and spot lights");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "spot", "position": [0, 0, 0], "direction": [0, 0, 0]}]})"),
              "scene.json: lights[0].direction must not be the zero vector");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "spot", "position": [1, 1, 1], "target": [1, 1, 1]}]})"),
              "scene.json: lights[0].target must differ from position");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "spot", "position": [0, 0, 0], "direction": [0, -1, 0],
                                         "innerConeAngle": 30, "outerConeAngle": 30}]})"),
              "scene.json: lights[0].innerConeAngle must be at least 0 and less than outerConeAngle");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "spot", "position": [0, 0, 0], "direction": [0, -1, 0],
                                         "outerConeAngle": 120}]})"),
              "scene.json: lights[0].outerConeAngle must be in (0, 90] degrees");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "point", "position": [0, 0, 0], "color": [1, -1, 1]}]})"),
              "scene.json: lights[0].color must not have negative components");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "point", "position": [0, 0, 0], "intensity": 1e300}]})"),
              "scene.json: lights[0].intensity is out of range");
    EXPECT_EQ(sceneError(R"({"lights": [{"type": "point", "position": [0, 1e300, 0]}]})"),
              "scene.json: lights[0].position is out of range");

    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cone"}]})"),
              "scene.json: shapes[0].type must be sphere, cube or plane (got 'cone')");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "radius": 1}]})"),
              "scene.json: shapes[0].radius only applies to spheres");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "sphere", "radius": 0}]})"), "scene.json: shapes[0].radius must be positive");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "sphere", "segments": 2}]})"),
              "scene.json: shapes[0].segments must be between 3 and 4096");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "rotation": [0, 0, 0, 1], "rotationDegrees": [0, 0, 0]}]})"),
              "scene.json: shapes[0] has both 'rotation' and 'rotationDegrees'; give one");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "rotation": [0, 0, 0, 0]}]})"),
              "scene.json: shapes[0].rotation must be a non-zero quaternion [x, y, z, w]");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "scale": [1, 0, 1]}]})"), "scene.json: shapes[0].scale must not be zero");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "material": {"roughness": 1.5}}]})"),
              "scene.json: shapes[0].material.roughness must be between 0 and 1");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "material": {"alphaMode": "cutout"}}]})"),
              "scene.json: shapes[0].material.alphaMode must be opaque, mask or blend (got 'cutout')");
    EXPECT_EQ(sceneError(R"({"shapes": [{"type": "cube", "material": {"alphaCutoff": 0.3}}]})"),
              "scene.json: shapes[0].material.alphaCutoff only applies to alphaMode \"mask\"");

    EXPECT_EQ(sceneError(R"({"camera": {"yfov": 40}})"), "scene.json: camera needs 'position'");
    EXPECT_EQ(sceneError(R"({"camera": {"position": [0, 0, 0], "yfov": 180}})"),
              "scene.json: camera.yfov must be between 0 and 180 degrees");
    EXPECT_EQ(sceneError(R"({"camera": {"position": [0, 0, 0], "znear": 1, "zfar": 1}})"),
              "scene.json: camera.zfar must be greater than znear");
    EXPECT_EQ(sceneError(R"({"camera": {"type": "orthographic", "position": [0, 0, 0], "xmag": 1, "ymag": 1, "yfov": 40}})"),
              "scene.json: camera.yfov only applies to perspective cameras");

    EXPECT_EQ(sceneError(R"({"render": {"msaa": 3}})"), "scene.json: render.msaa must be 1, 2, 4 or 8");
    EXPECT_EQ(sceneError(R"({"render": {"width": 0}})"), "scene.json: render.width must be between 1 and 16384");
    EXPECT_EQ(sceneError(R"({"render": {"height": 4294967296}})"),
              "scene.json: render.height must be between 1 and 16384");
    EXPECT_EQ(sceneError(R"({"render": {"height": 99999999999999999999}})"), "scene.json: render.height must be an integer");
    EXPECT_EQ(sceneError(R"({"render": {"tonemap": "filmic"}})"),
              "scene.json: render.tonemap must be none, reinhard, reinhard-ext, aces, neutral or agx (got 'filmic')");
    EXPECT_EQ(sceneError(R"({"render": {"brdfG": "beckmann"}})"),
              "scene.json: render.brdfG must be smith-ggx, smith-ggx-correlated, schlick-ggx, neumann, kelemen, cook-torrance or "
              "implicit (got 'beckmann')");

    EXPECT_EQ(sceneError(R"({"environment": {"color": [1, 1, 1], "file": "a.hdr"}})"),
              "scene.json: environment has both 'color' and 'file'; give one");
    EXPECT_EQ(sceneError(R"({"environment": {"file": "a.png"}})"),
              "scene.json: environment.file must be a .hdr or .exr image");
    EXPECT_EQ(sceneError(R"({"environment": {"intensity": -2}})"), "scene.json: environment.intensity must not be negative");
}

TEST(SceneFile, MissingFilesNameTheEntry)
{
    TempDir dir;
    const fs::path path = dir.write("scene.json", R"({"models": [{"path": "nope.glb"}],
                                                      "environment": {"file": "nope.hdr"}})");
    const std::string error = errorOf([&] { loadSceneFile(path); });
    EXPECT_TRUE(error.starts_with(path.string() + ": models[0]: ")) << error;
    EXPECT_NE(error.find("nope.glb"), std::string::npos) << error;

    const fs::path env = dir.write("env.json", R"({"environment": {"file": "nope.hdr"}})");
    EXPECT_EQ(errorOf([&] { loadSceneFile(env); }),
              env.string() + ": environment.file: " + (dir / "nope.hdr").string() + ": no such file");
}

TEST(SceneFile, SyntaxErrorsGiveLineAndColumn)
{
    // A missing comma after "width": 1; nlohmann reports the end of the unexpected token.
    EXPECT_EQ(sceneError("{\"render\": {\n  \"width\": 1\n  \"height\": 2}}\n"),
              "scene.json:3:10: syntax error while parsing object - unexpected string literal; expected '}'");
    EXPECT_EQ(sceneError(""), "scene.json:1:1: syntax error while parsing value - unexpected end of input; "
                              "expected '[', '{', or a literal");
    // The newline inside the string is the error: the end of line 2 (nlohmann itself would say
    // "line 3, column 0").
    const std::string unterminated = sceneError("{\n\"a\": \"abc\n");
    EXPECT_TRUE(unterminated.starts_with("scene.json:2:10: syntax error while parsing value - invalid string"))
        << unterminated;
    EXPECT_TRUE(sceneError(R"({"render": {"exposure": 1e999}})").starts_with("scene.json:")) << "overflow";
}

TEST(SceneFile, DocumentedExampleLoads)
{
    // The example in docs/scene-format.md, next to an `assets` link to the shared assets.
    const std::string doc = test::readFile(fs::path(SPECULA_SOURCE_DIR) / "docs" / "scene-format.md");
    const size_t begin = doc.find("```json\n");
    ASSERT_NE(begin, std::string::npos);
    const size_t end = doc.find("```", begin + 8);
    ASSERT_NE(end, std::string::npos);

    TempDir dir;
    fs::create_directory_symlink(fs::absolute(SPECULA_ASSETS_DIR), dir / "assets");
    const SceneDocument document = loadSceneFile(dir.write("example.json", doc.substr(begin + 8, end - begin - 8)), test::kAllowExternal);
    const Scene& scene = document.scene;
    EXPECT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(scene.meshInstances().size(), 4u) << "the box and three shapes";
    EXPECT_EQ(scene.cameraInstances().at(0).camera, 0);
    EXPECT_EQ(document.render.width, 1280);
    EXPECT_EQ(document.render.defaultLights, false);
}
