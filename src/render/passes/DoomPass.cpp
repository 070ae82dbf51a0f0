#include "render/passes/DoomPass.h"

#include <algorithm>
#include <cmath>

#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "render/FrameContext.h"
#include "shading/Tonemap.h"
#include "render/graph/GlGraphBackend.h"
#include "render/passes/Fullscreen.h"
#include "scene/DoomPalette.h"
#include "shaders/shared/Bindings.h"

namespace specula::render {

namespace doom = scene::doom;

struct DoomPass::Impl {
    gl::Texture nearest, colormap, palette;
    gl::Program program;

    Impl()
    {
        const doom::ColorTables& tables = doom::colorTables();
        gl::TextureDesc desc;
        desc.type = gl::TextureType::Texture3D;
        desc.format = gl::Format::R8UI;
        desc.width = desc.height = desc.layers = doom::kNearestCells;
        desc.label = "doom nearest-index table";
        nearest = gl::Texture(desc);
        // Entry (b · N + g) · N + r: red along x, green along y, blue along z, as uploaded.
        nearest.upload(0, 0, 1, gl::PixelType::UnsignedByte, tables.nearest.data());

        desc = {};
        desc.format = gl::Format::R8UI;
        desc.width = 256;
        desc.height = doom::kColormaps;
        desc.label = "doom colour map";
        colormap = gl::Texture(desc);
        // Level k is row k: x = palette index, y = level.
        colormap.upload(0, 0, 1, gl::PixelType::UnsignedByte, tables.colormap.data());

        desc = {};
        desc.format = gl::Format::RGBA8; // UNORM: a texel fetch returns the sRGB byte / 255 exactly
        desc.width = 256;
        desc.height = 1;
        desc.label = "doom palette";
        palette = gl::Texture(desc);
        std::vector<uint8_t> rgba(256 * 4, 255);
        for (size_t i = 0; i < 256; ++i) std::copy_n(tables.palette[i].begin(), 3, rgba.begin() + ptrdiff_t(4 * i));
        palette.upload(0, 0, 4, gl::PixelType::UnsignedByte, rgba.data());
    }

    void ensureProgram()
    {
        if (!program)
            program = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "doom/colormap.frag", .label = "doom colour map"});
    }
};

static_assert(sizeof(scene::doom::ColormapLevel) == 256, "colour map levels are uploaded as rows of 256 bytes");

DoomPass::DoomPass() : mImpl(std::make_unique<Impl>()) {}
DoomPass::~DoomPass() = default;

void DoomPass::prepare()
{
    mImpl->ensureProgram();
}

void DoomPass::bindTables(gl::State& state) const
{
    const Impl& p = *mImpl;
    // No sampler objects: the tables' own nearest filtering (integer textures need it).
    state.bindTexture(SPECULA_UNIT_DOOM_NEAREST, p.nearest);
    state.bindSampler(SPECULA_UNIT_DOOM_NEAREST, nullptr);
    state.bindTexture(SPECULA_UNIT_DOOM_COLORMAP, p.colormap);
    state.bindSampler(SPECULA_UNIT_DOOM_COLORMAP, nullptr);
    state.bindTexture(SPECULA_UNIT_DOOM_PALETTE, p.palette);
    state.bindSampler(SPECULA_UNIT_DOOM_PALETTE, nullptr);
}

uint32_t DoomPass::clearIndex(glm::vec3 background)
{
    doom::Rgb srgb;
    for (int c = 0; c < 3; ++c)
        srgb[size_t(c)] = uint8_t(std::lround(std::clamp(linearToSrgb(std::max(background[c], 0.0f)), 0.0f, 1.0f) * 255.0f));
    return doom::colorTables().lookUp(srgb);
}

void DoomPass::addTo(FrameGraph& graph, const FrameContext& frame, GraphTexture indexed, GraphTexture hdr, GraphTexture ldr)
{
    Impl& p = *mImpl;
    p.ensureProgram();
    graph.addPass(
        "colour map",
        [&](FrameGraph::Builder& b) {
            b.read(indexed, Use::Sample);
            b.write(hdr, Use::ColorAttachment);
            b.write(ldr, Use::ColorAttachment);
        },
        [this, &frame, &p, indexed, hdr, ldr] {
            bindTables(frame.state());
            // No sRGB encoding: colour 1 receives the palette's bytes as they are.
            drawFullscreen(frame.state(), {.target = &frame.backend.framebuffer({hdr, ldr}),
                                           .width = frame.width,
                                           .height = frame.height,
                                           .program = &p.program,
                                           .input = &frame.backend.texture(indexed),
                                           .triangle = &frame.stores.emptyVertexArray});
        });
}

} // namespace specula::render
