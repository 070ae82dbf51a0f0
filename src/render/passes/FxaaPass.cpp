#include "render/passes/FxaaPass.h"

#include <glm/glm.hpp>

#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "render/graph/GlGraphBackend.h"
#include "render/passes/Fullscreen.h"
#include "shaders/shared/Bindings.h"

namespace specula::render {

struct FxaaPass::Impl {
    gl::Program program;
    int texel = -1;
    // FXAA re-samples between pixels: bilinear, and clamped so edges do not wrap around.
    gl::Sampler linearClamp{{.mipFilter = gl::MipFilter::None, .wrapS = gl::Wrap::ClampToEdge,
                             .wrapT = gl::Wrap::ClampToEdge, .wrapR = gl::Wrap::ClampToEdge},
                            "fxaa bilinear clamp"};
    gl::VertexArray emptyVertexArray{"fxaa fullscreen triangle"};

    void ensureProgram()
    {
        if (program) return;
        program = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "post/fxaa.frag", .label = "fxaa"});
        texel = program.uniformLocation("uTexel");
    }
};

FxaaPass::FxaaPass() : mImpl(std::make_unique<Impl>()) {}
FxaaPass::~FxaaPass() = default;

void FxaaPass::prepare()
{
    mImpl->ensureProgram();
}

void FxaaPass::addTo(FrameGraph& graph, GlGraphBackend& backend, GraphTexture input, GraphTexture target)
{
    prepare();
    graph.addPass(
        "fxaa",
        [&](FrameGraph::Builder& b) {
            b.read(input, Use::Sample);
            b.write(target, Use::ColorAttachment);
        },
        [this, &backend, input, target] {
            apply(backend.state(), backend.texture(input), backend.framebuffer({target}));
        });
}

void FxaaPass::apply(gl::State& state, const gl::Texture& input, const gl::Framebuffer& target)
{
    Impl& r = *mImpl;
    r.ensureProgram();
    r.program.set(r.texel, glm::vec2(1.0f / float(input.width()), 1.0f / float(input.height())));
    // The values are encoded already: stored as they are.
    drawFullscreen(state, {.target = &target,
                           .width = input.width(),
                           .height = input.height(),
                           .program = &r.program,
                           .input = &input,
                           .sampler = &r.linearClamp,
                           .triangle = &r.emptyVertexArray});
}

} // namespace specula::render
