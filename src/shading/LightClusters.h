#pragma once
// Clustered shading without GL: the cluster grid of a view (shaders/shared/ClusterData.h),
// each cluster's bounds, the effective range of lights without one, and the CPU twin of the
// GPU culling (render/passes/LightCullPass) that the tests compare it with.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/ImageIO.h"
#include "shaders/shared/ClusterData.h"
#include "shaders/shared/LightData.h"

namespace specula::render {

/// The froxel grid of a target and projection: tiles of whole pixels, exponential depth slices.
struct ClusterGrid {
    int width = 1, height = 1; ///< the target, pixels
    int tilesX = 1, tilesY = 1, slices = SPECULA_CLUSTER_SLICES;
    int tileWidth = 1, tileHeight = 1; ///< pixels
    float near = 0.1f, far = 100.0f;   ///< view depths (metres along -z) of the first and last slice's outer faces
    float first = 5.0f;                ///< where slice 1 begins: slice 0 is [near, first], the others exponential to far

    /// ceil(width / 16) × ceil(height / 9)-pixel tiles (so at most 16 × 9 of them) and 24
    /// slices: the first from the near plane to min(5 m, far / 10) (as Bevy's first_slice_depth:
    /// nothing much is nearer, and exponential slices from a 0.1 m near plane would spend a
    /// third of themselves on the first metre), the other 23 exponential from there to the far
    /// plane (an infinite far plane: 10⁶ × that).
    static ClusterGrid make(int width, int height, const glm::mat4& projection);

    int count() const { return tilesX * tilesY * slices; }
    int index(int x, int y, int slice) const { return x + tilesX * (y + tilesY * slice); }
    /// slice = floor(log(depth) × sliceScale() + sliceBias()), clamped to [0, slices): as the
    /// shaders find it (depths below `first` give slice 0).
    float sliceScale() const;
    float sliceBias() const;
    /// The view depth where slice k begins (k = slices: the far plane).
    float sliceDepth(int k) const;
    /// The cluster of a window position (pixels, y up) at a view depth, as lights/light_list.glsl finds it.
    int clusterAt(glm::vec2 window, float depth) const;
    bool operator==(const ClusterGrid&) const = default;
};

/// Every cluster's view-space box (the eight corners of its froxel, padded by 10⁻⁴ of its far
/// depth so that the rounding of a fragment's position never puts it outside its cluster).
std::vector<shared::ClusterBounds> clusterBounds(const ClusterGrid& grid, const glm::mat4& projection);

/// The view frustum's six planes in view space (xyz inward unit normal, w offset: inside where
/// dot(n, p) + w ≥ 0), from the projection (Gribb & Hartmann 2001).
std::array<glm::vec4, 6> viewFrustumPlanes(const glm::mat4& projection);
/// Whether a sphere (xyz centre, w radius; w < 0 = infinite) is not wholly outside a plane.
bool sphereInFrustum(const std::array<glm::vec4, 6>& planes, glm::vec4 sphere);

/// Light `index` as the culling tests it (lights/lights_in_view.comp does the same on the GPU).
shared::CullLight cullLight(const shared::GpuLight& light, const glm::mat4& view, uint32_t index);

/// The range a light is culled and shaded with: its own when it has one (> 0), else the
/// distance at which its illuminance falls to `cutoff` × its illuminance at 1 m, 1 m / √cutoff
/// (docs/clustered-shading.md: the window of KHR_lights_punctual at that range then changes the
/// illuminance anywhere by less than `cutoff` × the 1 m illuminance); cutoff 0: infinite (0).
float effectiveRange(float range, float cutoff);

/// The light lists of every cluster, as the GPU passes make them.
struct ClusterLists {
    std::vector<uint32_t> directional;           ///< every directional light, in order
    std::vector<std::vector<uint32_t>> clusters; ///< per cluster, light indices ascending
    uint32_t visible = 0;                        ///< point and spot lights that give light, in the frustum
    size_t entries() const;
    size_t longest() const;
};

/// The CPU twin of the GPU culling: every point and spot light that gives light
/// (shared::lightIsDark) and is in the frustum tested against every cluster with
/// shared::lightTouchesCluster, directional lights apart.
ClusterLists cullLights(const ClusterGrid& grid, const std::vector<shared::ClusterBounds>& bounds, const glm::mat4& view,
                        const glm::mat4& projection, const std::vector<shared::GpuLight>& lights);

/// The light-count view's legend: each bin's colour (shared/ClusterData.h, lightCountColor)
/// over its lower bound (0, 1, 2, 4 ... 256+), on a dark band; sRGB bytes, top row first.
ImageRGBA8 makeLightCountLegend();

} // namespace specula::render
