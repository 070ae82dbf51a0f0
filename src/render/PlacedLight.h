#pragma once
// A light placed in the world, as the renderer's light buffer holds it (no GL: for
// Renderer.h and the apps).
#include <cstddef>

#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace specula::render {

/// A light placed in the world.
struct PlacedLight {
    scene::Light light;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; ///< where it points
    /// KHR_node_visibility: a hidden light's node (an animation may show it) gives no light,
    /// casts no shadow and has no gizmo; its other fields are kept.
    bool visible = true;
};

/// What one light edit (Renderer::setLight) uploaded to the light buffer: to check that it
/// touched that light's bytes and no others.
struct LightWrite {
    size_t offset = 0;      ///< the last upload's byte range
    size_t size = 0;
    size_t bytes = 0;       ///< bytes uploaded by the whole edit
    size_t lightOffset = 0; ///< where the light lives in the buffer
    size_t lightSize = 0;
};

} // namespace specula::render
