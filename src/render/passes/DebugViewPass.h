#pragma once
// Debug views that replace the finished frame, in the 8-bit image without sRGB encoding:
//   - ssao: the blurred occlusion as grey, byte = occlusion × 255;
//   - shadow-atlas: the shadow atlas fitted into the frame (shaders/post/shadow_atlas.frag).
#include "gl/Program.h"
#include "gl/Texture.h"
#include "render/graph/FrameGraph.h"

namespace specula::gl {
class Framebuffer;
class State;
class VertexArray;
} // namespace specula::gl

namespace specula::render {

struct FrameContext;

class DebugViewPass {
public:
    /// Adds "debug view": `occlusion` (R16F) into `target`.
    void addTo(FrameGraph& graph, const FrameContext& frame, GraphTexture occlusion, GraphTexture target);
    /// Adds "debug view: shadow atlas": the depth atlas into `target`.
    void addShadowAtlas(FrameGraph& graph, const FrameContext& frame, GraphTexture atlas, GraphTexture target);
    /// Adds "debug view: legend": the light-count view's legend into `target`'s bottom-left corner.
    void addLightCountLegend(FrameGraph& graph, const FrameContext& frame, GraphTexture target);
    /// Draws the atlas view into `target` now (the viewer's picture of the atlas).
    void drawShadowAtlas(gl::State& state, const gl::Texture& atlas, const gl::Framebuffer& target, int width, int height,
                         const gl::VertexArray& triangle);

private:
    gl::Program mProgram;
    gl::Program mAtlasProgram;
    int mFrameSize = -1;
    gl::Program mLegendProgram;
    gl::Texture mLegend;
    gl::Sampler mNearest{{.minFilter = gl::Filter::Nearest, .magFilter = gl::Filter::Nearest, .mipFilter = gl::MipFilter::None,
                          .wrapS = gl::Wrap::ClampToEdge, .wrapT = gl::Wrap::ClampToEdge},
                         "debug view nearest"};
};

} // namespace specula::render
