#pragma once
// Screen-space ambient occlusion: a depth/normal pre-pass of the scene's opaque and masked
// surfaces, the occlusion of a normal-oriented hemisphere kernel (compute), and a depth-aware
// 4×4 blur (compute). The forward pass (SSAO variant) multiplies the result into the ambient
// occlusion of each pixel; direct light is never darkened.
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "settings/PassSettings.h"
#include "render/View.h"

namespace specula::gl {
class State;
class Texture;
} // namespace specula::gl

namespace specula::render {

class GpuScene;

class SsaoPass {
public:
    SsaoPass();
    ~SsaoPass();
    SsaoPass(const SsaoPass&) = delete;
    SsaoPass& operator=(const SsaoPass&) = delete;

    /// Draws depth and view-space face normals of `scene`'s opaque and alpha-masked surfaces in
    /// `view` (frustum-culled) at width × height, one sample per pixel. Expects the frame
    /// uniform block (view, viewProjection) bound. Blended surfaces do not occlude; no scene
    /// leaves nothing to occlude.
    void drawDepthNormals(gl::State& state, const GpuScene* scene, const View& view, int width, int height);
    /// Occlusion of the last pre-pass (noisy: one kernel rotation per pixel).
    void computeOcclusion(gl::State& state, const View& view, const SsaoSettings& settings);
    /// The depth-aware blur of computeOcclusion()'s result; then occlusion() holds it.
    void blur(gl::State& state);
    /// R16F, width × height: 1 = unoccluded. Valid after blur().
    const gl::Texture& occlusion() const;

    /// Compiles the programs `scene` needs now rather than on first use.
    void prepare(const GpuScene* scene);

    /// The hemisphere kernel: `count` offsets in tangent space (z along the normal), length
    /// ≤ 1, cosine-distributed in direction and denser near the centre. Deterministic.
    static std::vector<glm::vec4> makeKernel(int count);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
