#pragma once
// FXAA 3.11 (Lottes 2011) on the tone-mapped image: an alternative to MSAA (with --msaa 1) or a
// complement to it (it also smooths edges MSAA cannot see: alpha-tested and shading aliasing).
#include <memory>

#include "render/graph/FrameGraph.h"

namespace specula::gl {
class Framebuffer;
class State;
class Texture;
} // namespace specula::gl

namespace specula::render {

class GlGraphBackend;

class FxaaPass {
public:
    FxaaPass();
    ~FxaaPass();
    FxaaPass(const FxaaPass&) = delete;
    FxaaPass& operator=(const FxaaPass&) = delete;

    /// Adds "fxaa": `input` anti-aliased into `target`, as apply().
    void addTo(FrameGraph& graph, GlGraphBackend& backend, GraphTexture input, GraphTexture target);
    /// Anti-aliases `input` (the tone-mapped frame, sRGB-encoded values in an RGBA8 UNORM
    /// texture) into `target` (an sRGB texture, written without encoding again) at the same size.
    void apply(gl::State& state, const gl::Texture& input, const gl::Framebuffer& target);
    void prepare();

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
