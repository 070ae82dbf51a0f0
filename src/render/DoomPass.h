#pragma once
// Doom's 8-bit frame (docs/materials.md, "Doom-era lighting"). In a frame whose override is the
// Doom model, the forward and billboard passes draw into target(): per pixel a palette index
// and a colour-map level (RG8UI), as Doom's frame buffer held palette indices; the colour-map
// pass (resolve) then turns each into its palette colour. The colour tables of
// scene/DoomPalette.h live here as textures (shaders/doom/palette.glsl reads them), bound for
// per-material Doom materials of normal frames too, which look them up inline.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

namespace specula::gl {
class Framebuffer;
class State;
} // namespace specula::gl

namespace specula::render {

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

    /// Binds the indexed target of a width × height frame (index, level, and a depth buffer of
    /// its own; remade when the size changes) and clears it: every pixel to the palette index
    /// nearest `background` (linear) at full bright, depth to 1.
    void beginFrame(gl::State& state, int width, int height, glm::vec3 background);
    /// The colour-map pass: writes each pixel's palette colour to `output`'s colour 0 as linear
    /// radiance and to its colour 1 as the sRGB bytes themselves (an sRGB texture, written
    /// without encoding).
    void resolve(gl::State& state, const gl::Framebuffer& output);
    /// The last frame's (index, level) per pixel, bottom row first.
    std::vector<uint8_t> readIndexed() const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
