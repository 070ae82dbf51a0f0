#pragma once
// View-frustum culling of world-space bounding boxes (the forward pass and the SSAO pre-pass).
#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace specula::render {

/// Six planes of the view frustum (Gribb & Hartmann 2001), normals pointing inwards.
struct Frustum {
    glm::vec4 planes[6];
    explicit Frustum(const glm::mat4& viewProjection)
    {
        const glm::mat4 t = glm::transpose(viewProjection);
        planes[0] = t[3] + t[0];
        planes[1] = t[3] - t[0];
        planes[2] = t[3] + t[1];
        planes[3] = t[3] - t[1];
        planes[4] = t[3] + t[2];
        planes[5] = t[3] - t[2];
    }
    bool intersects(const scene::Bounds& b) const
    {
        if (b.empty()) return false;
        for (const glm::vec4& p : planes) {
            // The box corner furthest along the plane normal.
            const glm::vec3 corner(p.x >= 0 ? b.max.x : b.min.x, p.y >= 0 ? b.max.y : b.min.y, p.z >= 0 ? b.max.z : b.min.z);
            if (glm::dot(glm::vec3(p), corner) + p.w < 0.0f) return false;
        }
        return true;
    }
};

} // namespace specula::render
