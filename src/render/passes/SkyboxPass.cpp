#include "render/passes/SkyboxPass.h"

#include "gl/Debug.h"
#include "render/FrameContext.h"

namespace specula::render {

void SkyboxPass::prepare()
{
    if (!mProgram) mProgram = gl::Program({.vertex = "ibl/skybox.vert", .fragment = "ibl/skybox.frag", .label = "skybox"});
}

void SkyboxPass::draw(const FrameContext& frame)
{
    const ImageBasedLighting& ibl = frame.stores.ibl;
    if (!ibl.hasEnvironment() || !frame.settings.environment.skybox) return;
    gl::DebugGroup group("skybox");
    prepare();
    gl::State& state = frame.state();
    state.useProgram(mProgram);
    // Depth 1 passes only where nothing was drawn (the clear value), and writes nothing.
    state.apply({.noDepthWrite = true, .depthCompare = gl::CompareOp::LessEqual, .cull = gl::CullMode::None});
    state.bindTexture(0, ibl.cube());
    state.bindSampler(0, nullptr);
    state.bindVertexArray(frame.stores.emptyVertexArray);
    state.drawTriangles(3, false);
}

} // namespace specula::render
