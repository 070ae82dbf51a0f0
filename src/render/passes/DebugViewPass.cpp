#include "render/passes/DebugViewPass.h"

#include "render/FrameContext.h"
#include "render/graph/GlGraphBackend.h"
#include "shaders/shared/Bindings.h"

namespace specula::render {

void DebugViewPass::addTo(FrameGraph& graph, const FrameContext& frame, GraphTexture occlusion, GraphTexture target)
{
    if (!mProgram) mProgram = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "post/debug.frag", .label = "debug view"});
    graph.addPass(
        "debug view",
        [&](FrameGraph::Builder& b) {
            b.read(occlusion, Use::Sample);
            b.write(target, Use::ColorAttachment);
        },
        [this, &frame, occlusion, target] {
            gl::State& state = frame.state();
            state.bindFramebuffer(&frame.backend.framebuffer({target}));
            state.viewport(0, 0, frame.width, frame.height);
            // No sRGB encoding: the byte is the occlusion × 255.
            state.apply({.noDepthTest = true, .noDepthWrite = true});
            state.useProgram(mProgram);
            state.bindTexture(SPECULA_UNIT_POST_INPUT, frame.backend.texture(occlusion));
            state.bindSampler(SPECULA_UNIT_POST_INPUT, nullptr);
            state.bindVertexArray(frame.stores.emptyVertexArray);
            state.drawTriangles(3, false);
        });
}

} // namespace specula::render
