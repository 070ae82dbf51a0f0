#pragma once
// The full-screen triangle every image pass draws (tone map, FXAA, colour map, debug view).
#include "gl/State.h"

namespace specula::gl {
class Framebuffer;
class Program;
class Sampler;
class Texture;
class VertexArray;
} // namespace specula::gl

namespace specula::render {

/// What a full-screen pass reads and writes.
struct FullscreenDraw {
    const gl::Framebuffer* target = nullptr;
    int width = 0;
    int height = 0;
    gl::PipelineDesc pipeline{.noDepthTest = true, .noDepthWrite = true};
    const gl::Program* program = nullptr;
    const gl::Texture* input = nullptr;    ///< on SPECULA_UNIT_POST_INPUT
    const gl::Sampler* sampler = nullptr;  ///< null: the texture's own sampling
    const gl::VertexArray* triangle = nullptr;
};

/// Binds the target, viewport, pipeline, program and input, and draws three vertices.
void drawFullscreen(gl::State& state, const FullscreenDraw& draw);

} // namespace specula::render
