#include "render/passes/Fullscreen.h"

#include "shaders/shared/Bindings.h"

namespace specula::render {

void drawFullscreen(gl::State& state, const FullscreenDraw& d)
{
    state.bindFramebuffer(d.target);
    state.viewport(0, 0, d.width, d.height);
    state.apply(d.pipeline);
    state.useProgram(*d.program);
    state.bindTexture(SPECULA_UNIT_POST_INPUT, *d.input);
    state.bindSampler(SPECULA_UNIT_POST_INPUT, d.sampler);
    state.bindVertexArray(*d.triangle);
    state.drawTriangles(3, false);
}

} // namespace specula::render
