#pragma once
// The environment behind the scene, drawn inside the forward pass after the opaque surfaces
// (it fills only the pixels they left, at depth 1) and before anything blended.
#include "gl/Program.h"

namespace specula::render {

struct FrameContext;

class SkyboxPass {
public:
    /// Compiles the program now rather than on first use.
    void prepare();
    /// Draws the sky into the bound target when the frame has an environment and shows it.
    void draw(const FrameContext& frame);

private:
    gl::Program mProgram;
};

} // namespace specula::render
