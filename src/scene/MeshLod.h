#pragma once
// Levels of detail for triangle meshes: coarser index lists over the same vertices
// (meshoptimizer's edge-collapse simplification), each with the geometric error it makes, and
// the choice of the coarsest level whose error, projected onto the screen, stays under a
// bound in pixels (docs/performance.md#levels-of-detail).
//
// Why a renderer on a CPU rasteriser needs them: llvmpipe shades 4×4 pixel blocks, so a
// triangle of a dozen pixels costs two to four blocks' worth of shading. A 64 × 64 sphere
// 150 pixels across is made of such triangles; the same sphere in 2,000 triangles looks the
// same (its silhouette moves by less than half a pixel) and shades in half the time.
#include <cstdint>
#include <vector>

#include "scene/Scene.h"

namespace specula::scene {

struct LodLevel {
    uint32_t first = 0; ///< first index in LodChain::indices
    uint32_t count = 0; ///< indices (a multiple of 3)
    /// Object-space distance (metres, before the node's scale) by which this level's surface
    /// may leave the full mesh's; 0 for level 0.
    float error = 0.0f;
};

/// Level 0 (the primitive's own indices) followed by the coarser levels, all in one index list.
struct LodChain {
    std::vector<uint32_t> indices;
    std::vector<LodLevel> levels;
};

/// Meshes below this many triangles keep one level: their draws cost little whatever their size.
constexpr size_t kLodMinTriangles = 1024;

/// The chain of `primitive` (indexed; else a chain of its implicit indices): each level aims at
/// half the triangles of the one before, until the simplifier stalls (less than a fifth fewer),
/// a level would have fewer than 128 triangles, or the error reaches a tenth of the mesh's size.
/// Borders (open edges) stay where they are, so a mesh cut along uv seams keeps no cracks.
LodChain buildLodChain(const Primitive& primitive);

/// Screen scale of a view: pixels per metre at unit distance for a perspective projection
/// (height / (2 tan(fovy / 2)) = projection[1][1] × height / 2), or pixels per metre for an
/// orthographic one.
struct LodView {
    glm::vec3 eye{0.0f};
    float pixelsPerMetre = 0.0f; ///< 0: always level 0
    bool perspective = true;
    float maxPixels = 0.5f;      ///< largest error allowed on screen; ≤ 0: always level 0
};

/// The view's LodView for a projection matrix and a viewport height in pixels.
LodView lodView(const glm::mat4& view, const glm::mat4& projection, int heightPixels, float maxPixels);

/// The coarsest level of `levels` whose error, scaled by `worldScale` (the node's largest axis
/// scale) and seen from `view` at the nearest point of a sphere (`center`, `radius`), is at
/// most view.maxPixels. Inside the sphere, level 0.
int selectLod(const std::vector<LodLevel>& levels, float worldScale, const glm::vec3& center, float radius, const LodView& view);

} // namespace specula::scene
