#include "scene/Tangents.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace specula::scene {

namespace {

// Below this squared length a vector has no usable direction. Inputs are in metres and
// uv units, so anything this small is a degenerate triangle, not real geometry.
constexpr float kTinyLengthSquared = 1e-20f;

bool isFinite(const glm::vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// `v` normalised, or `fallback` when `v` has no direction (zero, denormal, NaN, infinite).
glm::vec3 normalizeOr(const glm::vec3& v, const glm::vec3& fallback)
{
    const float lengthSquared = glm::dot(v, v);
    if (!(lengthSquared > kTinyLengthSquared) || !std::isfinite(lengthSquared)) return fallback;
    return v / std::sqrt(lengthSquared);
}

/// Some unit vector perpendicular to `n` (any will do: it is only used where uvs give no direction).
glm::vec3 anyPerpendicular(const glm::vec3& n)
{
    // Project the axis least aligned with n, so the projection cannot vanish.
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return normalizeOr(axis - n * glm::dot(n, axis), glm::vec3(1, 0, 0));
}

/// The triangles of a primitive as corner vertex indices; triangles referring to a vertex that
/// does not exist are left out rather than read out of bounds.
std::vector<std::array<uint32_t, 3>> triangles(const Primitive& primitive)
{
    std::vector<std::array<uint32_t, 3>> out;
    const size_t vertexCount = primitive.vertices.size();
    if (primitive.indices.empty()) {
        out.reserve(vertexCount / 3);
        for (uint32_t i = 0; i + 2 < vertexCount; i += 3) out.push_back({i, i + 1, i + 2});
        return out;
    }
    out.reserve(primitive.indices.size() / 3);
    for (size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
        const std::array<uint32_t, 3> t{primitive.indices[i], primitive.indices[i + 1], primitive.indices[i + 2]};
        if (t[0] < vertexCount && t[1] < vertexCount && t[2] < vertexCount) out.push_back(t);
    }
    return out;
}

/// The interior angle of a triangle at corner `p` (edges to `a` and `b`); 0 when an edge is degenerate.
float cornerAngle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b)
{
    const glm::vec3 ea = normalizeOr(a - p, glm::vec3(0.0f));
    const glm::vec3 eb = normalizeOr(b - p, glm::vec3(0.0f));
    if (ea == glm::vec3(0.0f) || eb == glm::vec3(0.0f)) return 0.0f;
    return std::acos(std::clamp(glm::dot(ea, eb), -1.0f, 1.0f));
}

/// Tangent-frame sums of one vertex for the triangles of one handedness.
struct FrameSum {
    glm::vec3 tangent{0.0f};   ///< Σ angle × (dP/du projected on the vertex's tangent plane)
    glm::vec3 bitangent{0.0f}; ///< Σ angle × (-dP/dv projected likewise)
    float weight = 0.0f;
};

// Handedness groups: triangles whose uv mapping preserves the orientation of the surface
// (w = +1) and mirrored ones (w = -1).
constexpr int kPreserving = 0;
constexpr int kMirrored = 1;

} // namespace

namespace {

/// The skin and morph data that run alongside the vertices, re-gathered after the vertices
/// changed: new vertex i copies old vertex source[i].
void remapVertexData(Primitive& primitive, const std::vector<uint32_t>& source)
{
    const size_t n = size_t(primitive.influences);
    if (n > 0) {
        std::vector<uint16_t> joints(source.size() * n);
        std::vector<float> weights(source.size() * n);
        for (size_t i = 0; i < source.size(); ++i)
            for (size_t k = 0; k < n; ++k) {
                joints[i * n + k] = primitive.joints[size_t(source[i]) * n + k];
                weights[i * n + k] = primitive.weights[size_t(source[i]) * n + k];
            }
        primitive.joints = std::move(joints);
        primitive.weights = std::move(weights);
    }
    for (MorphTarget& target : primitive.targets) {
        for (std::vector<glm::vec3>* list : {&target.positions, &target.normals, &target.tangents}) {
            if (list->empty()) continue;
            std::vector<glm::vec3> moved(source.size());
            for (size_t i = 0; i < source.size(); ++i) moved[i] = (*list)[source[i]];
            *list = std::move(moved);
        }
    }
}

} // namespace

void generateFlatNormals(Primitive& primitive)
{
    std::vector<Vertex> flat;
    const auto tris = triangles(primitive);
    flat.reserve(tris.size() * 3);
    std::vector<uint32_t> source;
    source.reserve(tris.size() * 3);
    for (const auto& t : tris) source.insert(source.end(), t.begin(), t.end());
    for (const auto& t : tris) {
        const Vertex& v0 = primitive.vertices[t[0]];
        const Vertex& v1 = primitive.vertices[t[1]];
        const Vertex& v2 = primitive.vertices[t[2]];
        // Counter-clockwise triangles are front facing in glTF, so this normal faces the viewer.
        const glm::vec3 face = glm::cross(v1.position - v0.position, v2.position - v0.position);
        for (const Vertex* v : {&v0, &v1, &v2}) {
            Vertex copy = *v;
            // A zero-area triangle has no normal of its own; keep whatever the vertex had.
            copy.normal = normalizeOr(face, normalizeOr(v->normal, glm::vec3(0, 0, 1)));
            flat.push_back(copy);
        }
    }
    primitive.vertices = std::move(flat);
    primitive.indices.clear();
    primitive.flatNormals = true;
    if (primitive.deformable()) remapVertexData(primitive, source);
}

void generateTangents(Primitive& primitive, int uvSet)
{
    auto uv = [uvSet](const Vertex& v) { return uvSet == 1 ? v.uv1 : v.uv0; };
    auto normal = [](const Vertex& v) { return normalizeOr(v.normal, glm::vec3(0.0f)); };

    const auto tris = triangles(primitive);
    const size_t vertexCount = primitive.vertices.size();
    std::array<std::vector<FrameSum>, 2> sums{std::vector<FrameSum>(vertexCount), std::vector<FrameSum>(vertexCount)};
    // Per triangle: kPreserving, kMirrored, or -1 when its uvs (or positions) are degenerate.
    std::vector<int> group(tris.size(), -1);

    for (size_t ti = 0; ti < tris.size(); ++ti) {
        const auto& t = tris[ti];
        const Vertex* v[3] = {&primitive.vertices[t[0]], &primitive.vertices[t[1]], &primitive.vertices[t[2]]};
        const glm::vec3 e1 = v[1]->position - v[0]->position;
        const glm::vec3 e2 = v[2]->position - v[0]->position;
        const glm::vec2 d1 = uv(*v[1]) - uv(*v[0]);
        const glm::vec2 d2 = uv(*v[2]) - uv(*v[0]);
        // Solving e = dP/du du + dP/dv dv for both edges: dP/du = tu / det, dP/dv = tv / det.
        const float det = d1.x * d2.y - d2.x * d1.y;
        const glm::vec3 tu = e1 * d2.y - e2 * d1.y;
        const glm::vec3 tv = e2 * d1.x - e1 * d2.x;
        // Like MikkTSpace, take any uv area that is not (relatively) zero: tiny uv islands are valid.
        const float uvScale = std::max({std::abs(d1.x), std::abs(d1.y), std::abs(d2.x), std::abs(d2.y)});
        if (!std::isfinite(det) || !(std::abs(det) > 1e-12f * uvScale * uvScale) || !isFinite(tu) || !isFinite(tv)) {
            continue;
        }
        const float s = det > 0.0f ? 1.0f : -1.0f;
        const glm::vec3 dPdu = tu * s; // directions only: the 1/|det| scale cancels when normalised
        const glm::vec3 b = -tv * s;   // -dP/dv: glTF's v runs down the image, a normal map's green up
        // In MikkTSpace's (u, 1 - v) space the signed area is -det; a counter-clockwise (positive)
        // one means the uv mapping preserves the orientation of the front face, so w = +1.
        const int g = det < 0.0f ? kPreserving : kMirrored;
        group[ti] = g;
        for (int c = 0; c < 3; ++c) {
            const float angle = cornerAngle(v[c]->position, v[(c + 1) % 3]->position, v[(c + 2) % 3]->position);
            if (!(angle > 0.0f)) continue;
            // Project onto the vertex's tangent plane before summing (as MikkTSpace does), so
            // triangles at an angle to the vertex normal contribute only their in-plane part.
            const glm::vec3 n = normal(*v[c]);
            FrameSum& sum = sums[size_t(g)][t[size_t(c)]];
            sum.tangent += angle * normalizeOr(dPdu - n * glm::dot(n, dPdu), glm::vec3(0.0f));
            sum.bitangent += angle * normalizeOr(b - n * glm::dot(n, b), glm::vec3(0.0f));
            sum.weight += angle;
        }
    }

    // A vertex used by triangles of both handedness cannot carry one w: split it, the copy
    // taking the group with less weight.
    std::vector<uint32_t> splitCopy(vertexCount, UINT32_MAX);
    std::vector<int> vertexGroup(vertexCount, kPreserving);
    for (size_t i = 0; i < vertexCount; ++i) {
        const float wp = sums[kPreserving][i].weight, wm = sums[kMirrored][i].weight;
        if (wp > 0.0f && wm > 0.0f) {
            vertexGroup[i] = wp >= wm ? kPreserving : kMirrored;
            splitCopy[i] = uint32_t(primitive.vertices.size());
            primitive.vertices.push_back(primitive.vertices[i]);
        } else if (wm > 0.0f) {
            vertexGroup[i] = kMirrored;
        }
    }

    // Triangles whose group a corner's vertex lost now use the copy. Non-indexed primitives
    // never get here: each of their vertices belongs to one triangle.
    if (primitive.vertices.size() != vertexCount) {
        for (size_t ti = 0, k = 0; k + 2 < primitive.indices.size(); k += 3) {
            uint32_t* corner = &primitive.indices[k];
            if (corner[0] >= vertexCount || corner[1] >= vertexCount || corner[2] >= vertexCount) continue;
            const int g = group[ti++];
            if (g < 0) continue;
            for (int c = 0; c < 3; ++c)
                if (splitCopy[corner[c]] != UINT32_MAX && vertexGroup[corner[c]] != g)
                    corner[c] = splitCopy[corner[c]];
        }
    }

    auto finish = [&](Vertex& vertex, const FrameSum& sum, int g) {
        const glm::vec3 n = normal(vertex);
        // Gram-Schmidt against the vertex normal: the shader's TBN needs t ⟂ n.
        glm::vec3 t = normalizeOr(sum.tangent - n * glm::dot(n, sum.tangent), glm::vec3(0.0f));
        if (t == glm::vec3(0.0f)) {
            // No uv direction here (degenerate uvs, or the sums cancelled): any tangent is as
            // good as another, but the bitangent still tells which way round it goes.
            // cross(n, cross(b, n)) = b on the tangent plane, so this t gives w = +1; mirrored
            // triangles need the opposite tangent for the same bitangent.
            const float sign = g == kMirrored ? -1.0f : 1.0f;
            t = glm::dot(sum.bitangent, sum.bitangent) > kTinyLengthSquared
                    ? normalizeOr(sign * glm::cross(sum.bitangent, n), anyPerpendicular(n))
                    : anyPerpendicular(n);
        }
        float w = g == kMirrored ? -1.0f : 1.0f;
        const float side = glm::dot(glm::cross(n, t), sum.bitangent);
        if (side != 0.0f && std::isfinite(side)) w = side < 0.0f ? -1.0f : 1.0f;
        vertex.tangent = glm::vec4(t, w);
    };
    for (size_t i = 0; i < vertexCount; ++i) {
        finish(primitive.vertices[i], sums[size_t(vertexGroup[i])][i], vertexGroup[i]);
        if (splitCopy[i] != UINT32_MAX) {
            const int other = vertexGroup[i] == kPreserving ? kMirrored : kPreserving;
            finish(primitive.vertices[splitCopy[i]], sums[size_t(other)][i], other);
        }
    }
    primitive.hasTangents = true;
    if (primitive.deformable() && primitive.vertices.size() != vertexCount) {
        std::vector<uint32_t> source(primitive.vertices.size());
        for (size_t i = 0; i < vertexCount; ++i) {
            source[i] = uint32_t(i);
            if (splitCopy[i] != UINT32_MAX) source[splitCopy[i]] = uint32_t(i);
        }
        remapVertexData(primitive, source);
    }
}

} // namespace specula::scene
