#pragma once
// A light placed in the world, as the renderer's light buffer holds it (no GL: for
// Renderer.h and the apps).
#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace specula::render {

/// A light placed in the world.
struct PlacedLight {
    scene::Light light;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; ///< where it points
};

} // namespace specula::render
