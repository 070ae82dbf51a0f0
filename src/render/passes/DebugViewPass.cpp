#include "render/passes/DebugViewPass.h"

#include "render/FrameContext.h"
#include "render/graph/GlGraphBackend.h"
#include "render/passes/Fullscreen.h"

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
            // No sRGB encoding: the byte is the occlusion × 255.
            drawFullscreen(frame.state(), {.target = &frame.backend.framebuffer({target}),
                                           .width = frame.width,
                                           .height = frame.height,
                                           .program = &mProgram,
                                           .input = &frame.backend.texture(occlusion),
                                           .triangle = &frame.stores.emptyVertexArray});
        });
}

} // namespace specula::render
