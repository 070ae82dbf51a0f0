#include "scene/MeshLod.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <meshoptimizer.h>

namespace specula::scene {

namespace {

constexpr size_t kMinLevelTriangles = 128;
constexpr int kMaxLevels = 8;
constexpr float kMaxRelativeError = 0.1f; ///< of the mesh's extent (meshopt_simplifyScale)
/// meshoptimizer's error is a quadric estimate that undershoots: on a tessellated sphere the
/// levels stray 1.4–1.5× as far as it says (tests/unit/test_mesh_lod.cpp). Twice it is the
/// error each level states, so that the pixel bound holds.
constexpr float kErrorSafety = 2.0f;

} // namespace

LodChain buildLodChain(const Primitive& primitive)
{
    LodChain chain;
    if (primitive.indices.empty()) {
        chain.indices.resize(primitive.vertices.size() - primitive.vertices.size() % 3);
        std::iota(chain.indices.begin(), chain.indices.end(), 0u);
    } else {
        chain.indices = primitive.indices;
    }
    chain.levels.push_back({0, uint32_t(chain.indices.size()), 0.0f});
    if (chain.indices.size() / 3 < kLodMinTriangles || primitive.vertices.empty()) return chain;

    const float* positions = &primitive.vertices[0].position.x;
    const size_t vertexCount = primitive.vertices.size();
    const size_t stride = sizeof(Vertex);
    const float scale = meshopt_simplifyScale(positions, vertexCount, stride);
    std::vector<uint32_t> level(chain.indices.size());
    size_t previous = chain.indices.size();
    while (int(chain.levels.size()) < kMaxLevels) {
        const size_t target = (previous / 6) * 3;
        if (target / 3 < kMinLevelTriangles) break;
        float error = 0.0f;
        // Each level is simplified from the full mesh, so that its error is measured against
        // level 0, not accumulated level on level.
        const size_t count = meshopt_simplify(level.data(), chain.indices.data(), chain.levels[0].count, positions, vertexCount,
                                              stride, target, kMaxRelativeError, meshopt_SimplifyLockBorder, &error);
        if (count == 0 || count * 5 > previous * 4) break; // stalled: less than a fifth fewer
        const uint32_t first = uint32_t(chain.indices.size());
        chain.indices.insert(chain.indices.end(), level.begin(), level.begin() + std::ptrdiff_t(count));
        // Errors must grow with the level for the choice to be monotonic.
        const float absolute = std::max(kErrorSafety * error * scale, chain.levels.back().error);
        chain.levels.push_back({first, uint32_t(count), absolute});
        previous = count;
        if (error >= kMaxRelativeError) break;
    }
    // The coarser levels in vertex-cache order (meshoptimizer's optimiser): the rasteriser's
    // post-transform cache then transforms each vertex about once. Level 0 keeps the file's
    // order, which a blended mesh's look depends on.
    for (size_t i = 1; i < chain.levels.size(); ++i) {
        const LodLevel& l = chain.levels[i];
        meshopt_optimizeVertexCache(chain.indices.data() + l.first, chain.indices.data() + l.first, l.count, vertexCount);
    }
    return chain;
}

LodView lodView(const glm::mat4& view, const glm::mat4& projection, int heightPixels, float maxPixels)
{
    LodView v;
    v.eye = glm::vec3(glm::inverse(view)[3]);
    v.perspective = projection[3][3] == 0.0f;
    v.pixelsPerMetre = std::abs(projection[1][1]) * 0.5f * float(std::max(heightPixels, 0));
    v.maxPixels = maxPixels;
    return v;
}

int selectLod(const std::vector<LodLevel>& levels, float worldScale, const glm::vec3& center, float radius, const LodView& view)
{
    if (levels.size() < 2 || view.maxPixels <= 0.0f || !(view.pixelsPerMetre > 0.0f)) return 0;
    float pixelsPerMetre = view.pixelsPerMetre;
    if (view.perspective) {
        const float distance = glm::length(center - view.eye) - radius;
        if (!(distance > 0.0f)) return 0; // the eye is inside the bounds (or NaN)
        pixelsPerMetre /= distance;
    }
    int chosen = 0;
    for (size_t i = 1; i < levels.size(); ++i) {
        if (levels[i].error * worldScale * pixelsPerMetre > view.maxPixels) break;
        chosen = int(i);
    }
    return chosen;
}

} // namespace specula::scene
