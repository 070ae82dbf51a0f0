#include "render/passes/SkyboxPass.h"

#include <algorithm>
#include <string>
#include <vector>

#include "gl/Debug.h"
#include "render/FrameContext.h"

namespace specula::render {

bool SkyboxPass::blurred(const FrameContext& frame)
{
    return std::clamp(frame.settings.environment.skyboxBlur, 0.0f, 1.0f) > 0.0f;
}

gl::Program& SkyboxPass::program(const FrameContext& frame)
{
    // Two programs, not a branch on the uniform: gallivm (llvmpipe) would read both cubes.
    const bool blurred = SkyboxPass::blurred(frame);
    gl::Program& program = mPrograms[blurred ? 1 : 0];
    if (!program)
        program = gl::Program({.vertex = "ibl/skybox.vert", .fragment = "ibl/skybox.frag",
                               .defines = blurred ? std::vector<std::string>{"SKYBOX_BLURRED"} : std::vector<std::string>{},
                               .label = blurred ? "skybox (blurred)" : "skybox"});
    return program;
}

void SkyboxPass::prepare(const FrameContext& frame)
{
    program(frame);
}

void SkyboxPass::draw(const FrameContext& frame)
{
    const ImageBasedLighting& ibl = frame.stores.ibl;
    if (!ibl.hasEnvironment() || !frame.settings.environment.skybox) return;
    gl::DebugGroup group("skybox");
    gl::State& state = frame.state();
    state.useProgram(program(frame));
    // Depth 1 passes only where nothing was drawn (the clear value), and writes nothing.
    state.apply({.noDepthWrite = true, .depthCompare = gl::CompareOp::LessEqual, .cull = gl::CullMode::None});
    state.bindTexture(0, ibl.cube());
    state.bindSampler(0, nullptr);
    state.bindVertexArray(frame.stores.emptyVertexArray);
    state.drawTriangles(3, false);
}

} // namespace specula::render
