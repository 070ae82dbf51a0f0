#pragma once
// Built-in scenes that need no file, and the default light rig.
#include <cstdint>

#include "scene/Scene.h"

namespace specula::scene {

/// The demo: a 5x5 grid of spheres (metallic rising by row, roughness by column), a clear
/// glass sphere right of them (blended, "transparent": highlights kept), a floor,
/// three coloured point lights, a spot light and a directional light, a camera, and one
/// billboard group of each kind (axis-aligned trees, point-sprite lanterns, leaning
/// arbitrary-axis neon rods).
Scene makeDemoScene();

/// Equal to the LearnOpenGL "PBR lighting" demo: 7x7 spheres (radius 1, 64x64 segments) at
/// ((col-3)*2.5, (row-3)*2.5, 0), metallic = row/7, roughness = clamp(col/7, 0.05, 1),
/// albedo (0.5, 0, 0); four point lights of (300, 300, 300) at (+-10, +-10, 10), each also
/// drawn as a sphere scaled 0.5; camera at (0, 0, 3) looking down -Z, 45 degree fov, near 0.1, far 100.
Scene makeLearnOpenGlScene();

/// The LearnOpenGL "IBL specular" demo: the same spheres and lights with the spheres moved to
/// z = -2 (the environment is set by the caller and drawn as the skybox).
Scene makeLearnOpenGlIblScene();

/// The many-lights scene (clustered shading's benchmark, docs/clustered-shading.md): a 7×7
/// grid of spheres on a 400 m square floor, and `lights` coloured point lights of range 4 m,
/// 0.3–1.5 m above the floor, scattered over a square whose area grows with their number (one
/// light per 16 m², and at least 20 × 20 m): the same deterministic places for the same count.
/// Camera at (0, 7, 16) looking at the origin, 50° fov, near 0.1, far 150.
Scene makeManyLightsScene(int lights);

/// Light `index` of a deterministic scatter (the many-lights scene's, the viewer's scatter-lights):
/// a coloured point light of 8 cd and range 4 m that casts no shadow, placed in a square of side
/// `side` m around `center`, 0.3–1.5 m above it.
struct ScatteredLight {
    Light light;
    glm::vec3 position;
};
ScatteredLight scatteredLight(uint32_t index, const glm::vec3& center, float side);

/// Adds the default rig when a scene has no light: three directional lights (key 3 lux from
/// the upper left front, fill 1 lux from the right, rim 2 lux from behind), placed relative to
/// a viewer at `viewDirection` (from the scene towards the camera). Returns lights added.
int addDefaultLightRig(Scene& scene, glm::vec3 viewDirection = {0.0f, 0.0f, 1.0f});

/// Adds a node holding `light` at `position` pointing along `direction`; returns the node.
int addLight(Scene& scene, const Light& light, glm::vec3 position, glm::vec3 direction);
/// Adds a camera node at `position` looking at `target`; returns the node.
int addCamera(Scene& scene, const Camera& camera, glm::vec3 position, glm::vec3 target,
              glm::vec3 up = {0.0f, 1.0f, 0.0f});

/// Rotation that turns local -Z into `direction` with local +Y as close to `up` as possible
/// (any perpendicular up when `direction` is parallel to `up`).
glm::quat lookRotation(glm::vec3 direction, glm::vec3 up = {0.0f, 1.0f, 0.0f});

} // namespace specula::scene
