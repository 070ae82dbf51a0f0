#pragma once
// Screen-space ambient occlusion: a depth/normal pre-pass of the scene's opaque and masked
// surfaces, the occlusion of a normal-oriented hemisphere kernel (compute), and a depth-aware
// 4×4 blur (compute). The forward pass (SSAO variant) multiplies the result into the ambient
// occlusion of each pixel; direct light is never darkened.
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "render/graph/FrameGraph.h"

namespace specula::render {

class DrawList;
struct FrameContext;

class SsaoPass {
public:
    SsaoPass();
    ~SsaoPass();
    SsaoPass(const SsaoPass&) = delete;
    SsaoPass& operator=(const SsaoPass&) = delete;

    /// Adds the three passes to `graph` and returns the blurred occlusion (R16F, 1 =
    /// unoccluded) for the forward pass to sample:
    ///  - "ssao prepass": depth and view-space face normals of `opaque` (the frame's opaque and
    ///    alpha-masked draws; blended surfaces do not occlude), one sample per pixel;
    ///  - "ssao": the occlusion of each pixel's hemisphere kernel (noisy: one kernel rotation
    ///    per pixel), compute;
    ///  - "ssao blur": a depth-aware 4×4 blur of it, compute.
    GraphTexture addTo(FrameGraph& graph, const FrameContext& frame, const DrawList& opaque);

    /// The hemisphere kernel: `count` offsets in tangent space (z along the normal), length
    /// ≤ 1, cosine-distributed in direction and denser near the centre. Deterministic.
    static std::vector<glm::vec4> makeKernel(int count);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
