#pragma once
// The scenes the shadow tests are made of (test_shadows.cpp, test_shadow_quality.cpp): a
// square floor at y = 0, spheres and boxes of one grey material, and one light.
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/DemoScenes.h"
#include "scene/Procedural.h"
#include "scene/Scene.h"

namespace specula::test {

struct Sphere {
    glm::vec3 center;
    float radius;
};
struct Box {
    glm::vec3 min, max;
};

/// Every surface's material: grey, dielectric, rough (the CPU references use the same).
inline const glm::vec3 kShadowBaseColor(0.8f);
constexpr float kShadowRoughness = 0.8f;

struct ShadowPrimitives {
    float floorSize = 20.0f;
    std::vector<Sphere> spheres;
    std::vector<Box> boxes;
    scene::Light light;
    glm::vec3 lightPosition{0.0f};
    glm::vec3 lightDirection{0.0f, -1.0f, 0.0f};
};

inline scene::Scene buildShadowScene(const ShadowPrimitives& sc)
{
    scene::Scene s;
    scene::Material material;
    material.baseColorFactor = glm::vec4(kShadowBaseColor, 1.0f);
    material.metallicFactor = 0.0f;
    material.roughnessFactor = kShadowRoughness;
    scene::addShape(s, scene::makePlane(sc.floorSize), material, glm::mat4(1.0f), "floor");
    for (const Sphere& sp : sc.spheres)
        scene::addShape(s, scene::makeUvSphere(sp.radius, 128, 64), material, glm::translate(glm::mat4(1.0f), sp.center), "sphere");
    for (const Box& b : sc.boxes) {
        const glm::mat4 t = glm::scale(glm::translate(glm::mat4(1.0f), 0.5f * (b.min + b.max)), 0.5f * (b.max - b.min));
        scene::addShape(s, scene::makeCube(1.0f), material, t, "box");
    }
    scene::addLight(s, sc.light, sc.lightPosition, sc.lightDirection);
    return s;
}

} // namespace specula::test
