#pragma once
// The multisample resolve: the MSAA frame averaged into a single-sampled one (a blit), for the
// passes that read the HDR frame (bloom, exposure). Without them the tone mapper resolves as it
// reads and this pass is not in the frame.
#include "render/graph/FrameGraph.h"

namespace specula::render {

class GlGraphBackend;

/// Adds "resolve": `multisampled` into `resolved`, colour attachment 0, nearest.
void addResolvePass(FrameGraph& graph, GlGraphBackend& backend, GraphTexture multisampled, GraphTexture resolved);

} // namespace specula::render
