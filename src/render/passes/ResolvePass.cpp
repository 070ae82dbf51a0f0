#include "render/passes/ResolvePass.h"

#include "gl/Framebuffer.h"
#include "render/graph/GlGraphBackend.h"

namespace specula::render {

void addResolvePass(FrameGraph& graph, GlGraphBackend& backend, GraphTexture multisampled, GraphTexture resolved)
{
    const GraphTextureDesc size = graph.desc(resolved);
    graph.addPass(
        "resolve",
        [&](FrameGraph::Builder& b) {
            b.read(multisampled, Use::BlitSource);
            b.write(resolved, Use::BlitTarget);
        },
        [&backend, multisampled, resolved, size] {
            backend.framebuffer({multisampled}).blitColorTo(backend.framebuffer({resolved}), size.width, size.height);
        });
}

} // namespace specula::render
