#include "scene/Picking.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace specula::scene {

namespace {

/// Slab test (Kay & Kajiya 1986): does the ray meet the box before `tMax`?
bool hitsBounds(const Bounds& b, const glm::vec3& origin, const glm::vec3& direction, float tMax)
{
    float t0 = 0.0f, t1 = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        // 1/0 = ±inf keeps the slab test right for rays parallel to a face.
        const float inverse = 1.0f / direction[axis];
        float tNear = (b.min[axis] - origin[axis]) * inverse;
        float tFar = (b.max[axis] - origin[axis]) * inverse;
        if (tNear > tFar) std::swap(tNear, tFar);
        t0 = std::max(t0, tNear);
        t1 = std::min(t1, tFar);
        if (t0 > t1) return false;
    }
    return true;
}

/// Möller & Trumbore 1997, "Fast, Minimum Storage Ray/Triangle Intersection": t of the hit, or
/// a negative number.
float intersect(const glm::vec3& origin, const glm::vec3& direction, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c)
{
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(direction, e2);
    const float det = glm::dot(e1, p);
    // Degenerate triangles and rays in the triangle's plane: no hit.
    if (std::abs(det) < 1e-12f) return -1.0f;
    const float inverse = 1.0f / det;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) * inverse;
    if (u < 0.0f || u > 1.0f) return -1.0f;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(direction, q) * inverse;
    if (v < 0.0f || u + v > 1.0f) return -1.0f;
    return glm::dot(e2, q) * inverse;
}

} // namespace

std::optional<PickHit> pick(const Scene& scene, const glm::vec3& origin, const glm::vec3& direction)
{
    std::optional<PickHit> best;
    float bestT = std::numeric_limits<float>::max();
    for (const MeshInstance& instance : scene.meshInstances()) {
        // In the mesh's own space t is the same: the ray is transformed, not renormalised.
        const glm::mat4 toLocal = glm::inverse(instance.world);
        const glm::vec3 o = glm::vec3(toLocal * glm::vec4(origin, 1.0f));
        const glm::vec3 d = glm::vec3(toLocal * glm::vec4(direction, 0.0f));
        const Mesh& mesh = scene.meshes[size_t(instance.mesh)];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const Primitive& primitive = mesh.primitives[p];
            if (primitive.topology != Topology::Triangles) continue; // a line or a point has no area to hit
            if (!primitive.bounds.empty() && !hitsBounds(primitive.bounds, o, d, bestT)) continue;
            const size_t count = primitive.indices.empty() ? primitive.vertices.size() : primitive.indices.size();
            auto vertex = [&](size_t i) -> const glm::vec3& {
                return primitive.vertices[primitive.indices.empty() ? i : size_t(primitive.indices[i])].position;
            };
            for (size_t i = 0; i + 2 < count; i += 3) {
                const float t = intersect(o, d, vertex(i), vertex(i + 1), vertex(i + 2));
                if (t > 0.0f && t < bestT) {
                    bestT = t;
                    best = PickHit{instance.node, instance.mesh, int(p), primitive.material, t, origin + t * direction};
                }
            }
        }
    }
    return best;
}

} // namespace specula::scene
