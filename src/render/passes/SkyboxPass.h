#pragma once
// The environment behind the scene, drawn inside the forward pass after the opaque surfaces
// (it fills only the pixels they left, at depth 1) and before anything blended.
#include "gl/Program.h"

namespace specula::render {

struct FrameContext;

class SkyboxPass {
public:
    /// The sky shows a prefiltered level (blurred) rather than the base cube.
    static bool blurred(const FrameContext& frame);
    /// The environment is not turned (its rotation a whole number of turns): the programs that
    /// read it then compile the rotation out (ibl/ibl.glsl's IBL_UNROTATED).
    static bool unrotated(const FrameContext& frame);
    /// Compiles this frame's program now rather than on first use.
    void prepare(const FrameContext& frame);
    /// Draws the sky into the bound target when the frame has an environment and shows it.
    void draw(const FrameContext& frame);

private:
    gl::Program& program(const FrameContext& frame);
    gl::Program mPrograms[4]; ///< sharp (the base cube), blurred (a prefiltered level); then both turned
};

} // namespace specula::render
