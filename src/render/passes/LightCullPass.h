#pragma once
// Clustered light culling (docs/clustered-shading.md): every frame, on the GPU, the point and
// spot lights of the light buffer are tested against every cluster of the view
// (shaders/shared/ClusterData.h) and each cluster gets the compact list of those that reach
// it, which every shading path reads (shaders/lights/light_list.glsl). One pass, "light
// culling", of four dispatches:
//   1. lights in view (lights/lights_in_view.comp): the point and spot lights that touch the
//      frustum, in view space and in light order, and the directional lights' indices;
//   2. count (lights/cluster_cull.comp): each cluster counts the lights that touch its box;
//   3. scan (lights/cluster_scan.comp): each list's place, an exclusive prefix sum, and the totals;
//   4. fill (cluster_cull.comp, CLUSTER_FILL): each cluster writes its list.
// Between 3 and 4 the renderer reads the totals back (16 words): when the lists would not fit,
// the buffer grows (one line of warning) before they are written, so no list is ever cut short.
// The clusters' boxes are made on the CPU (shading/LightClusters) when the target size or the
// projection changes.
#include <cstdint>
#include <memory>
#include <vector>

#include "render/graph/FrameGraph.h"
#include "shading/LightClusters.h"

namespace specula::gl {
class Buffer;
class State;
} // namespace specula::gl

namespace specula::render {

struct FrameContext;

/// What the last culling found (read back between counting and filling).
struct ClusterCounts {
    uint32_t directional = 0; ///< directional lights (every cluster's)
    uint32_t visible = 0;     ///< point and spot lights that touch the frustum
    uint32_t entries = 0;     ///< entries of all cluster lists together
    uint32_t longest = 0;     ///< the longest cluster list (directional lights not counted)
};

class LightCullPass {
public:
    LightCullPass();
    ~LightCullPass();
    LightCullPass(const LightCullPass&) = delete;
    LightCullPass& operator=(const LightCullPass&) = delete;

    /// Adds "light culling" for the frame's view and target; returns the cluster lists'
    /// buffer, for the passes that shade to read (Use::Sample: they fetch its texel view).
    GraphBuffer addTo(FrameGraph& graph, const FrameContext& frame);
    /// Binds the lists' texel view (SPECULA_UNIT_CLUSTERS) for shading.
    void bind(gl::State& state) const;

    const ClusterGrid& grid() const;
    const std::vector<shared::ClusterBounds>& bounds() const;
    /// How many times the lists were made: a frame whose lights and view are those of the last
    /// lists keeps them (no dispatch, no read-back).
    int runs() const;
    ClusterCounts counts() const;
    /// Whether the next frame had better shade every light (LIGHTS_ALL) than read the lists:
    /// the last culling listed nearly every one of `pointAndSpotLights` in nearly every cluster
    /// (at least 90% of all cluster-light pairs) and they are few (at most 32). Then the lists
    /// would save a few evaluations and cost an index fetch for every light of every pixel
    /// (and per-pixel addresses where every pixel read the same light). Every light is a
    /// superset of any list, so this is never wrong, only faster; the next culling says
    /// whether it still holds.
    bool listsAreNearlyEveryLight(int pointAndSpotLights) const;
    /// Words the lists' buffer holds (header, records, indices).
    size_t capacityWords() const;
    /// The lists' buffer as the last frame left it (tests).
    std::vector<uint32_t> readWords() const;

    /// Tests only: shrinks every cluster's box about its centre by `fraction` of its size
    /// (0 = the true boxes), to show that the clustered frame then differs from brute force.
    void setShrinkForTesting(float fraction);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
