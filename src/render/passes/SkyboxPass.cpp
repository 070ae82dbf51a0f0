#include "render/passes/SkyboxPass.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/Debug.h"
#include "render/FrameContext.h"

namespace specula::render {

bool SkyboxPass::blurred(const FrameContext& frame)
{
    return std::clamp(frame.settings.environment.skyboxBlur, 0.0f, 1.0f) > 0.0f;
}

bool SkyboxPass::unrotated(const FrameContext& frame)
{
    return std::fmod(frame.settings.environment.rotationDegrees, 360.0f) == 0.0f;
}

gl::Program& SkyboxPass::program(const FrameContext& frame)
{
    // Programs, not branches on uniforms: gallivm (llvmpipe) would read both cubes, and the
    // rotation's matrix in every pixel of an unturned map.
    const bool blurred = SkyboxPass::blurred(frame), turned = !unrotated(frame);
    gl::Program& program = mPrograms[(blurred ? 1 : 0) + (turned ? 2 : 0)];
    if (!program) {
        std::vector<std::string> defines;
        if (blurred) defines.push_back("SKYBOX_BLURRED");
        if (!turned) defines.push_back("IBL_UNROTATED");
        program = gl::Program({.vertex = "ibl/skybox.vert", .fragment = "ibl/skybox.frag", .defines = defines,
                               .label = std::string(blurred ? "skybox (blurred)" : "skybox") + (turned ? " turned" : "")});
    }
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
    // The sky's own cube and chain: with an extracted sun they still show it (lighting's do not).
    state.bindTexture(0, blurred(frame) ? ibl.skyPrefiltered() : ibl.sky());
    state.bindSampler(0, nullptr);
    state.bindVertexArray(frame.stores.emptyVertexArray);
    state.drawTriangles(3, false);
}

} // namespace specula::render
