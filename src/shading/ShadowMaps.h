#pragma once
// The geometry of shadow maps, free of GL: cascade splits and their fitted, texel-snapped
// orthographic views for directional lights, the perspective views of spot lights and of a
// point light's six cube faces, the atlas the maps share, and which lights get a map when a
// scene has more than the budget. render/passes/ShadowPass renders what this decides.
//
// Every view maps a world position to the shadow atlas: uv in [0, 1]² of the whole atlas
// (already inside the view's tile) and depth in [0, 1] (GL window depth), so one matrix
// multiply and a divide by w give what the shadow sampler compares.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace specula::render {

/// Far distances of `count` cascades between `near` and `far` (view depth, metres) by the
/// practical split scheme (Zhang et al. 2006): λ·logarithmic + (1 − λ)·uniform.
std::vector<float> cascadeSplits(float near, float far, int count, float lambda);

/// A square tile of the atlas, in texels.
struct AtlasTile {
    int x = 0, y = 0, size = 0;
    bool operator==(const AtlasTile&) const = default;
};

/// One shadow view: what the shadow pass renders into its tile and what shading reads back.
struct ShadowView {
    glm::mat4 viewProjection{1.0f}; ///< world → clip of the light's camera (GL clip space)
    glm::mat4 worldToAtlas{1.0f};   ///< world → (atlas uv, window depth, w)
    AtlasTile tile;
    bool orthographic = false;
    float near = 0.0f, far = 1.0f; ///< of the light's camera, metres
    /// World size of one texel: orthographic views at any depth, perspective ones at depth 1
    /// (times the view depth elsewhere).
    float texelWorld = 0.0f;
};

/// The view of a cascade: the bounding sphere of the camera frustum's slice [sliceNear,
/// sliceFar] (view depth), seen along `lightDirection` (where the light points) by an
/// orthographic camera whose window is the sphere's square, its centre snapped to whole
/// texels of `tileSize` in a light-space basis that depends on the light only, so that the
/// map's texels do not crawl when the camera moves or turns. The depth range reaches back to
/// `casters` (world bounds of everything that may cast) so that casters outside the slice
/// still cast into it.
ShadowView cascadeView(const glm::mat4& cameraView, const glm::mat4& cameraProjection, float sliceNear, float sliceFar,
                       const glm::vec3& lightDirection, const scene::Bounds& casters, int tileSize);

/// The perspective view of a spot light: its cone (outer angle, plus a texel's margin for the
/// filter), from near = 5 cm (or less for short ranges) to `far`.
ShadowView spotView(const glm::vec3& position, const glm::vec3& direction, float outerConeAngle, float far, int tileSize);

/// The six 90° faces of a point light, in the order +X, −X, +Y, −Y, +Z, −Z (the face of a
/// direction d is its major axis: shadowFace(d)).
std::vector<ShadowView> pointViews(const glm::vec3& position, float far, int tileSize);
/// 0..5, as pointViews orders them.
int shadowFace(const glm::vec3& direction);

/// Maps a light camera's clip space into `tile` of an atlas of `atlasSize` texels: clip →
/// (uv in the atlas, depth in [0, 1]).
glm::mat4 clipToAtlas(const AtlasTile& tile, int atlasSize);

/// Square tiles of power-of-two sizes in a square atlas (a quadtree buddy allocator).
class ShadowAtlas {
public:
    explicit ShadowAtlas(int size, int minTile = 32);
    int size() const { return mSize; }
    /// A free tile of `tileSize` (a power of two ≤ size()), or none when the atlas is full.
    std::optional<AtlasTile> allocate(int tileSize);
    void clear();

private:
    int mSize, mMinTile;
    std::vector<std::vector<AtlasTile>> mFree; ///< free tiles by level (0 = the whole atlas)
};

/// A light asking for a shadow map: how much of the screen it matters to.
struct ShadowCandidate {
    int light = 0;
    scene::Light::Type type = scene::Light::Type::Point;
    /// Screen importance in [0, 1]: the fraction of the view's height its sphere of influence
    /// covers (1 for lights around or in front of the camera, and for directional lights).
    float importance = 0.0f;
};

/// The fraction of the view's height a sphere of `radius` at `center` covers (1 when the
/// camera is inside it; 0 behind the camera and out of the frustum).
float screenImportance(const glm::vec3& center, float radius, const glm::mat4& view, const glm::mat4& projection);

/// Tile size of a spot or point light's map (of each cube face) from its importance: the
/// largest tile for a light that fills the view, halving as it shrinks, at least `minTile`.
int tileSizeFor(float importance, int maxTile, int minTile);

/// The lights that get a map: every candidate by decreasing importance until `budget` spot
/// and point lights (directional lights are outside the budget, at most `maxDirectional`);
/// ties by light index. The rest are returned in `dropped`.
std::vector<ShadowCandidate> chooseShadowed(std::vector<ShadowCandidate> candidates, int budget, int maxDirectional,
                                            std::vector<int>* dropped);

} // namespace specula::render
