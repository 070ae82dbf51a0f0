#pragma once
// Doom's 8-bit frame (docs/materials.md, "Doom-era lighting"). In a frame whose override is the
// Doom model (the Doom pipeline), the forward and billboard passes draw per pixel a palette
// index and a colour-map level (RG8UI), as Doom's frame buffer held palette indices; the
// colour-map pass (addTo) then turns each into its palette colour. The colour tables of
// scene/DoomPalette.h live here as textures (shaders/doom/palette.glsl reads them), bound for
// per-material Doom materials of normal frames too, which look them up inline.
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "render/graph/FrameGraph.h"

namespace specula::gl {
class State;
} // namespace specula::gl

namespace specula::render {

struct FrameContext;

class DoomPass {
public:
    /// Uploads the colour tables (scene::doom::colorTables()).
    DoomPass();
    ~DoomPass();
    DoomPass(const DoomPass&) = delete;
    DoomPass& operator=(const DoomPass&) = delete;

    /// Compiles the colour-map program now rather than on first use.
    void prepare();
    /// Binds the nearest-index table, the colour map and the palette to their units.
    void bindTables(gl::State& state) const;

    /// The palette index a Doom frame is cleared to: the one nearest `background` (linear) at
    /// full bright.
    static uint32_t clearIndex(glm::vec3 background);
    /// Adds "colour map": each pixel of `indexed` (palette index, colour-map level; written by
    /// the forward pass of a Doom frame) as its palette colour into `hdr` as linear radiance and
    /// into `ldr` (an sRGB texture, written without encoding) as the sRGB bytes themselves.
    void addTo(FrameGraph& graph, const FrameContext& frame, GraphTexture indexed, GraphTexture hdr, GraphTexture ldr);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
