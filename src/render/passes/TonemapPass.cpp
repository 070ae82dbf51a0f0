#include "render/passes/TonemapPass.h"

#include <string>
#include <vector>

#include "render/FrameContext.h"
#include "render/graph/GlGraphBackend.h"
#include "render/passes/Fullscreen.h"
#include "shaders/shared/Bindings.h"
#include "shaders/shared/FrameData.h"

namespace specula::render {

uint32_t tonemapId(Tonemap t)
{
    switch (t) {
    case Tonemap::None: return SPECULA_TONEMAP_NONE;
    case Tonemap::Reinhard: return SPECULA_TONEMAP_REINHARD;
    case Tonemap::ReinhardExtended: return SPECULA_TONEMAP_REINHARD_EXT;
    case Tonemap::Aces: return SPECULA_TONEMAP_ACES;
    case Tonemap::Neutral: return SPECULA_TONEMAP_NEUTRAL;
    case Tonemap::Agx: return SPECULA_TONEMAP_AGX;
    }
    return SPECULA_TONEMAP_NONE;
}

gl::Program& TonemapPass::program(int samples, bool automaticExposure, bool encodeSrgb, uint32_t tonemap)
{
    gl::Program& program = mPrograms[(int(tonemap) * 64 + samples) * 4 + (automaticExposure ? 1 : 0) + (encodeSrgb ? 2 : 0)];
    if (!program) {
        // The operator as a constant: gallivm (llvmpipe) runs every operator of a branch on a
        // uniform, a third of this pass there (docs/performance.md).
        std::vector<std::string> defines{"TONEMAP_OPERATOR " + std::to_string(tonemap) + "u"};
        if (samples > 1) defines.push_back("MSAA_SAMPLES " + std::to_string(samples));
        if (automaticExposure) defines.push_back("AUTO_EXPOSURE");
        if (encodeSrgb) defines.push_back("ENCODE_SRGB");
        program = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "post/tonemap.frag", .defines = defines,
                               .label = "tonemap"});
    }
    return program;
}

void TonemapPass::addTo(FrameGraph& graph, const FrameContext& frame, GraphTexture input, int samples, GraphBuffer exposure,
                        GraphTexture target, bool encodeSrgb)
{
    gl::Program& tonemap = program(samples, bool(exposure), encodeSrgb, tonemapId(frame.settings.tonemap));
    graph.addPass(
        samples > 1 ? "resolve+tonemap" : "tonemap",
        [&](FrameGraph::Builder& b) {
            b.read(input, Use::Sample);
            if (exposure) b.read(exposure, Use::StorageRead);
            if (target) b.write(target, Use::ColorAttachment);
            else b.sideEffect(); // the window
        },
        [&frame, &tonemap, input, exposure, target, encodeSrgb] {
            gl::State& state = frame.state();
            frame.stores.frame.bind(SPECULA_BINDING_FRAME);
            if (exposure) gl::bindStorageBuffer(SPECULA_BINDING_EXPOSURE, frame.backend.buffer(exposure));
            // Into FXAA's UNORM input the shader encodes; into the sRGB target (or window) GL does.
            drawFullscreen(state, {.target = target ? &frame.backend.framebuffer({target}) : nullptr,
                                   .width = frame.width,
                                   .height = frame.height,
                                   .pipeline = {.noDepthTest = true, .noDepthWrite = true, .framebufferSrgb = !encodeSrgb},
                                   .program = &tonemap,
                                   .input = &frame.backend.texture(input),
                                   .triangle = &frame.stores.emptyVertexArray});
        });
}

} // namespace specula::render
