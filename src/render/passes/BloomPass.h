#pragma once
// Physically based bloom in compute shaders (Jimenez 2014, "Next Generation Post Processing in
// Call of Duty: Advanced Warfare"): the HDR frame is down-sampled into up to 8 levels with the
// 13-tap filter (a Karis average on the first level), up-sampled back with a 3×3 tent, each
// level added on the way, and the sum blended into the frame:
//     frame += intensity / levels × Σ_levels blur_level(frame)
// Every filter's weights sum to 1 and each level conserves energy (value × texel area), so
// with the firefly filter off the glow adds intensity × the frame's energy. Level sizes are
// rounded up (1023 → 512 → 256 …) and each level maps exactly 2:1 onto the one above, so odd
// sizes lose no edge and stay centred; beyond the border the frame continues as its mirror
// image (shaders/post/bloom.glsl), so light near the border keeps its glow's energy too.
#include <memory>

#include "render/graph/FrameGraph.h"
#include "settings/PassSettings.h"

namespace specula::gl {
class State;
class Texture;
} // namespace specula::gl

namespace specula::render {

class GlGraphBackend;

class BloomPass {
public:
    BloomPass();
    ~BloomPass();
    BloomPass(const BloomPass&) = delete;
    BloomPass& operator=(const BloomPass&) = delete;

    /// Adds "bloom" to `graph`: the glow of `hdr` (RGBA16F, single-sampled, read and written in
    /// place) added to it, through levels the graph allocates. `exposure` is the frame's manual
    /// exposure scale (threshold and firefly weights are judged on exposed values). With
    /// `glowOnly` the frame is replaced by the glow it would get (debug view). Does nothing for
    /// a 1×1 frame or zero levels.
    void addTo(FrameGraph& graph, GlGraphBackend& backend, GraphTexture hdr, const BloomSettings& settings, float exposure,
               bool glowOnly = false);
    /// The same on a texture of the caller's, at once: a graph of this one pass.
    void apply(gl::State& state, gl::Texture& hdr, const BloomSettings& settings, float exposure,
               bool glowOnly = false);
    /// Compiles the programs now rather than on first use.
    void prepare(const BloomSettings& settings);

    /// The levels apply() uses for a frame of this size: `requested` clamped to 0–8 and to the
    /// halvings it takes to reach 1×1.
    static int levelsFor(int width, int height, int requested);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
