#pragma once
// The SSAO debug view: the blurred occlusion as grey in the 8-bit image, byte = occlusion × 255
// (no sRGB encoding), replacing the frame.
#include "gl/Program.h"
#include "render/graph/FrameGraph.h"

namespace specula::render {

struct FrameContext;

class DebugViewPass {
public:
    /// Adds "debug view": `occlusion` (R16F) into `target`.
    void addTo(FrameGraph& graph, const FrameContext& frame, GraphTexture occlusion, GraphTexture target);

private:
    gl::Program mProgram;
};

} // namespace specula::render
