#pragma once
// Which surface of a scene a ray meets first: for clicking on an object to select it.
#include <optional>

#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace specula::scene {

struct PickHit {
    int node = -1;
    int mesh = -1;
    int primitive = -1;
    int material = -1;     ///< the primitive's material; -1 = the default material
    float distance = 0.0f; ///< along the ray, in units of |direction|
    glm::vec3 position{0.0f};
};

/// The nearest triangle (either side) the ray origin + t × direction, t > 0, meets; nullopt if
/// none. Brute force over every triangle of every mesh instance, skipping primitives whose
/// bounds the ray misses: fast enough for one click on scenes of a few hundred thousand triangles.
std::optional<PickHit> pick(const Scene& scene, const glm::vec3& origin, const glm::vec3& direction);

} // namespace specula::scene
