#include "scene/DemoScenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Hash.h"
#include "scene/Procedural.h"

namespace specula::scene {

Scene makeLearnOpenGlScene(float sphereZ, const char* name);

glm::quat lookRotation(glm::vec3 direction, glm::vec3 up)
{
    const glm::vec3 forward = glm::normalize(direction);
    glm::vec3 right = glm::cross(forward, up);
    if (glm::dot(right, right) < 1e-10f) {
        // Looking along up: any up perpendicular to forward will do, chosen stably.
        const glm::vec3 alternative = std::abs(forward.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
        right = glm::cross(forward, alternative);
    }
    right = glm::normalize(right);
    const glm::vec3 trueUp = glm::cross(right, forward);
    // Columns: local +X -> right, +Y -> up, +Z -> -forward.
    return glm::quat_cast(glm::mat3(right, trueUp, -forward));
}

int addLight(Scene& scene, const Light& light, glm::vec3 position, glm::vec3 direction)
{
    scene.lights.push_back(light);
    Node node;
    node.name = light.name;
    node.light = int(scene.lights.size() - 1);
    node.translation = position;
    node.rotation = lookRotation(direction);
    return scene.addNode(std::move(node));
}

int addCamera(Scene& scene, const Camera& camera, glm::vec3 position, glm::vec3 target, glm::vec3 up)
{
    scene.cameras.push_back(camera);
    Node node;
    node.name = camera.name;
    node.camera = int(scene.cameras.size() - 1);
    node.translation = position;
    node.rotation = lookRotation(target - position, up);
    return scene.addNode(std::move(node));
}

int addDefaultLightRig(Scene& scene, glm::vec3 viewDirection)
{
    // Build a frame around the view direction so the rig follows the camera.
    const glm::vec3 back = glm::normalize(viewDirection);
    const glm::quat frame = lookRotation(-back);
    const glm::vec3 right = frame * glm::vec3(1, 0, 0);
    const glm::vec3 up = frame * glm::vec3(0, 1, 0);
    struct Rig {
        const char* name;
        glm::vec3 from; // direction from the scene towards the light
        float lux;
    };
    const Rig rig[] = {
        {"default key", glm::normalize(-0.6f * right + 0.8f * up + 0.7f * back), 3.0f},
        {"default fill", glm::normalize(0.9f * right + 0.1f * up + 0.4f * back), 1.0f},
        {"default rim", glm::normalize(0.3f * right + 0.6f * up - 0.8f * back), 2.0f},
    };
    for (const Rig& r : rig) {
        Light light;
        light.name = r.name;
        light.type = Light::Type::Directional;
        light.intensity = r.lux;
        addLight(scene, light, glm::vec3(0.0f), -r.from);
    }
    return 3;
}

Scene makeDemoScene()
{
    Scene scene;
    scene.name = "demo";
    const int n = 5;
    const float spacing = 1.2f;
    const Primitive sphere = makeUvSphere(0.5f, 64, 32);
    for (int row = 0; row < n; ++row) {
        for (int col = 0; col < n; ++col) {
            Material material;
            material.name = "sphere";
            // Gold-ish for metals, a warm white for dielectrics, so both lobes read clearly.
            const float metallic = float(row) / float(n - 1);
            material.baseColorFactor = glm::mix(glm::vec4(0.8f, 0.8f, 0.8f, 1.0f), glm::vec4(1.0f, 0.78f, 0.34f, 1.0f), metallic);
            material.metallicFactor = metallic;
            material.roughnessFactor = std::clamp(float(col) / float(n - 1), 0.05f, 1.0f);
            const glm::vec3 position((float(col) - 2.0f) * spacing, 0.6f + float(row) * spacing, 0.0f);
            addShape(scene, sphere, material, glm::translate(glm::mat4(1.0f), position), "sphere");
        }
    }
    // A clear glass sphere right of the grid, before the trees: alpha 0.1, blended "transparent", so its diffuse light is a
    // tenth and its highlights are whole (Newell, Newell and Sancha 1972; docs/transparency.md).
    // The gallery's fade tile shows it as alpha coverage would: highlights a tenth too.
    Material glass;
    glass.name = "glass";
    glass.baseColorFactor = glm::vec4(0.92f, 0.96f, 1.0f, 0.1f);
    glass.metallicFactor = 0.0f;
    glass.roughnessFactor = 0.05f;
    glass.alphaMode = AlphaMode::Blend;
    glass.blendMode = BlendMode::Transparent;
    addShape(scene, sphere, glass, glm::translate(glm::mat4(1.0f), glm::vec3(3.4f, 2.1f, 1.0f)), "glass sphere");

    Material floor;
    floor.name = "floor";
    floor.baseColorFactor = glm::vec4(0.35f, 0.35f, 0.38f, 1.0f);
    floor.metallicFactor = 0.0f;
    floor.roughnessFactor = 0.6f;
    addShape(scene, makePlane(14.0f, 7.0f), floor, glm::mat4(1.0f), "floor");

    const struct {
        glm::vec3 color;
        glm::vec3 position;
    } points[] = {
        {{1.0f, 0.25f, 0.2f}, {-3.5f, 1.0f, 2.0f}},
        {{0.25f, 0.5f, 1.0f}, {3.5f, 1.0f, 2.0f}},
        {{0.3f, 1.0f, 0.35f}, {0.0f, 5.6f, 1.5f}},
    };
    int index = 0;
    for (const auto& p : points) {
        Light light;
        light.name = "point " + std::to_string(++index);
        light.type = Light::Type::Point;
        light.color = p.color;
        light.intensity = 8.0f; // cd
        light.range = 12.0f;
        addLight(scene, light, p.position, {0, 0, -1});
    }
    Light spot;
    spot.name = "spot";
    spot.type = Light::Type::Spot;
    spot.color = {1.0f, 0.95f, 0.85f};
    spot.intensity = 120.0f; // cd
    spot.innerConeAngle = glm::radians(12.0f);
    spot.outerConeAngle = glm::radians(22.0f);
    const glm::vec3 spotPosition(0.0f, 6.5f, 5.0f);
    addLight(scene, spot, spotPosition, glm::vec3(0.0f, 0.0f, 2.2f) - spotPosition);
    Light sun;
    sun.name = "sun";
    sun.type = Light::Type::Directional;
    sun.color = {1.0f, 0.97f, 0.92f};
    sun.intensity = 2.0f; // lux
    addLight(scene, sun, glm::vec3(0.0f), glm::normalize(glm::vec3(0.4f, -1.0f, -0.6f)));

    // Billboards, one group per kind (unlit: tints are radiance in cd/m²). A row of cut-out
    // trees behind the spheres turns about +Y only; glowing lanterns in front face the camera
    // (HDR, blended, so they can bloom); two leaning neon rods turn about their own axes.
    BillboardGroup trees;
    trees.name = "trees";
    trees.kind = BillboardKind::AxisAligned;
    trees.sprite = BuiltinSprite::Tree;
    trees.size = {1.6f, 3.2f};
    trees.anchor = {0.5f, 0.0f}; // the trunk's foot stands on the floor
    trees.alphaMode = AlphaMode::Mask;
    trees.tint = glm::vec3(1.0f);
    for (int i = 0; i < 9; ++i) {
        // A fixed, irregular pattern of heights and depths so the row does not look stamped.
        const float jitter = float((i * 7) % 5) / 4.0f; // 0..1
        trees.billboards.push_back({{-6.0f + 1.5f * float(i), 0.0f, -4.5f - 0.8f * jitter}, 0.8f + 0.4f * jitter, glm::vec3(1.0f)});
    }
    scene.billboards.push_back(std::move(trees));

    BillboardGroup lanterns;
    lanterns.name = "lanterns";
    lanterns.kind = BillboardKind::PointSprite;
    lanterns.sprite = BuiltinSprite::Disc;
    lanterns.size = glm::vec2(0.45f);
    lanterns.alphaMode = AlphaMode::Blend;
    lanterns.tint = {6.0f, 3.2f, 1.2f};
    for (int i = 0; i < 4; ++i)
        lanterns.billboards.push_back({{-4.5f + 3.0f * float(i), 0.35f, 2.6f}, 1.0f, glm::vec3(1.0f)});
    scene.billboards.push_back(std::move(lanterns));

    BillboardGroup rods;
    rods.name = "neon rods";
    rods.kind = BillboardKind::ArbitraryAxis;
    rods.sprite = BuiltinSprite::Disc; // stretched along the axis: a tube with soft ends
    rods.alphaMode = AlphaMode::Blend;
    rods.size = {0.16f, 2.6f};
    rods.tint = {5.0f, 0.6f, 3.5f};
    for (float side : {-1.0f, 1.0f}) {
        // Leaning outwards; each turns about its own axis only, so it stays a rod from any side.
        rods.billboards.push_back({{5.0f * side, 1.4f, 1.0f}, 1.0f, glm::vec3(1.0f), {0.35f * side, 1.0f, 0.0f}});
    }
    scene.billboards.push_back(std::move(rods));

    Camera camera;
    camera.name = "demo camera";
    camera.yfov = glm::radians(40.0f);
    camera.znear = 0.1f;
    camera.zfar = 100.0f;
    const int node = addCamera(scene, camera, {0.0f, 3.6f, 11.0f}, {0.0f, 2.7f, 0.0f});
    // The scene's first camera is the one first met walking the roots: move it to the front.
    scene.roots.pop_back();
    scene.roots.insert(scene.roots.begin(), node);
    return scene;
}

ScatteredLight scatteredLight(uint32_t index, const glm::vec3& center, float side)
{
    const uint32_t k = index * 4u;
    ScatteredLight s;
    s.light.type = Light::Type::Point;
    s.light.range = 4.0f;
    s.light.intensity = 8.0f; // cd: 8 lux at 1 m
    s.light.castShadows = false;
    const float hue = unitHash(k + 3u) * 6.0f;
    s.light.color = glm::clamp(glm::vec3(std::abs(hue - 3.0f) - 1.0f, 2.0f - std::abs(hue - 2.0f), 2.0f - std::abs(hue - 4.0f)),
                               0.0f, 1.0f) * 0.7f + 0.3f;
    s.position = center + glm::vec3((unitHash(k) - 0.5f) * side, 0.3f + 1.2f * unitHash(k + 1u), (unitHash(k + 2u) - 0.5f) * side);
    return s;
}

Scene makeManyLightsScene(int lights)
{
    Scene scene;
    scene.name = "many-lights";
    Material floor;
    floor.baseColorFactor = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f);
    floor.metallicFactor = 0.0f;
    floor.roughnessFactor = 0.7f;
    addShape(scene, makePlane(400.0f), floor, glm::mat4(1.0f), "floor");
    const Primitive sphere = makeUvSphere(0.8f, 32, 32);
    for (int row = 0; row < 7; ++row) {
        for (int col = 0; col < 7; ++col) {
            Material material;
            material.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
            material.metallicFactor = float(row) / 6.0f;
            material.roughnessFactor = std::clamp(float(col) / 6.0f, 0.1f, 1.0f);
            const glm::vec3 position((float(col) - 3.0f) * 2.5f, 0.8f, (float(row) - 3.0f) * 2.5f);
            addShape(scene, sphere, material, glm::translate(glm::mat4(1.0f), position), "sphere");
        }
    }
    // One light per 16 m² over a square of side max(20, 4 √n) m; a fixed hash of the light's
    // number places it, so a count always gives the same scene.
    const float side = std::max(20.0f, 4.0f * std::sqrt(float(std::max(lights, 0))));
    for (int i = 0; i < lights; ++i) {
        const ScatteredLight s = scatteredLight(uint32_t(i), glm::vec3(0.0f), side);
        addLight(scene, s.light, s.position, {0.0f, -1.0f, 0.0f});
    }
    Camera camera;
    camera.yfov = glm::radians(50.0f);
    camera.znear = 0.1f;
    camera.zfar = 150.0f;
    const int node = addCamera(scene, camera, {0.0f, 7.0f, 16.0f}, {0.0f, 0.0f, 0.0f});
    scene.roots.pop_back();
    scene.roots.insert(scene.roots.begin(), node);
    return scene;
}

Scene makeLearnOpenGlIblScene()
{
    return makeLearnOpenGlScene(-2.0f, "learnopengl-ibl");
}

Scene makeLearnOpenGlScene()
{
    return makeLearnOpenGlScene(0.0f, "learnopengl");
}

Scene makeLearnOpenGlScene(float sphereZ, const char* name)
{
    Scene scene;
    scene.name = name;
    const Primitive sphere = makeUvSphere(1.0f, 64, 64);
    for (int row = 0; row < 7; ++row) {
        for (int col = 0; col < 7; ++col) {
            Material material;
            material.baseColorFactor = glm::vec4(0.5f, 0.0f, 0.0f, 1.0f);
            material.metallicFactor = float(row) / 7.0f;
            material.roughnessFactor = std::clamp(float(col) / 7.0f, 0.05f, 1.0f);
            const glm::vec3 position((float(col) - 3.0f) * 2.5f, (float(row) - 3.0f) * 2.5f, sphereZ);
            addShape(scene, sphere, material, glm::translate(glm::mat4(1.0f), position), "sphere");
        }
    }
    const glm::vec3 lightPositions[] = {{-10, 10, 10}, {10, 10, 10}, {-10, -10, 10}, {10, -10, 10}};
    for (const glm::vec3& p : lightPositions) {
        Light light;
        light.type = Light::Type::Point;
        light.color = glm::vec3(1.0f);
        light.intensity = 300.0f; // the tutorial's colour (300, 300, 300) with 1/d^2 falloff
        // The tutorial's lights cast no shadows; its scene here is the same frame, so that
        // side-by-side timings compare equal work (docs/performance.md).
        light.castShadows = false;
        addLight(scene, light, p, {0, 0, -1});
        Material lamp;
        lamp.baseColorFactor = glm::vec4(1.0f);
        lamp.metallicFactor = 0.0f;
        lamp.roughnessFactor = 0.5f;
        const int lampNode = addShape(scene, sphere, lamp, glm::scale(glm::translate(glm::mat4(1.0f), p), glm::vec3(0.5f)), "light sphere");
        // A marker around the light, as in the tutorial: it must not hide its own light.
        scene.nodes[size_t(lampNode)].castShadows = false;
    }
    Camera camera;
    camera.yfov = glm::radians(45.0f);
    camera.znear = 0.1f;
    camera.zfar = 100.0f;
    const int node = addCamera(scene, camera, {0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f});
    scene.roots.pop_back();
    scene.roots.insert(scene.roots.begin(), node);
    return scene;
}

} // namespace specula::scene
