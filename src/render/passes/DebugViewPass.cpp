#include "render/passes/DebugViewPass.h"

#include "render/FrameContext.h"
#include "render/graph/GlGraphBackend.h"
#include "render/passes/Fullscreen.h"
#include "shading/LightClusters.h"

#include <glm/vec2.hpp>

#include <algorithm>
#include <vector>

namespace specula::render {

void DebugViewPass::addTo(FrameGraph& graph, const FrameContext& frame, GraphTexture occlusion, GraphTexture target)
{
    if (!mProgram) mProgram = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "post/debug.frag", .label = "debug view"});
    graph.addPass(
        "debug view",
        [&](FrameGraph::Builder& b) {
            b.read(occlusion, Use::Sample);
            b.write(target, Use::ColorAttachment);
        },
        [this, &frame, occlusion, target] {
            // No sRGB encoding: the byte is the occlusion × 255.
            drawFullscreen(frame.state(), {.target = &frame.backend.framebuffer({target}),
                                           .width = frame.width,
                                           .height = frame.height,
                                           .program = &mProgram,
                                           .input = &frame.backend.texture(occlusion),
                                           .triangle = &frame.stores.emptyVertexArray});
        });
}

void DebugViewPass::drawShadowAtlas(gl::State& state, const gl::Texture& atlas, const gl::Framebuffer& target, int width,
                                    int height, const gl::VertexArray& triangle)
{
    if (!mAtlasProgram) {
        mAtlasProgram = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "post/shadow_atlas.frag", .label = "shadow atlas view"});
        mFrameSize = mAtlasProgram.uniformLocation("uFrameSize");
    }
    mAtlasProgram.set(mFrameSize, glm::vec2(float(width), float(height)));
    drawFullscreen(state, {.target = &target, .width = width, .height = height, .program = &mAtlasProgram, .input = &atlas,
                           .sampler = &mNearest, .triangle = &triangle});
}

void DebugViewPass::addShadowAtlas(FrameGraph& graph, const FrameContext& frame, GraphTexture atlas, GraphTexture target)
{
    graph.addPass(
        "debug view: shadow atlas",
        [&](FrameGraph::Builder& b) {
            b.read(atlas, Use::Sample);
            b.write(target, Use::ColorAttachment);
        },
        [this, &frame, atlas, target] {
            drawShadowAtlas(frame.state(), frame.backend.texture(atlas), frame.backend.framebuffer({target}), frame.width,
                            frame.height, frame.stores.emptyVertexArray);
        });
}

void DebugViewPass::addLightCountLegend(FrameGraph& graph, const FrameContext& frame, GraphTexture target)
{
    if (!mLegendProgram)
        mLegendProgram = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "post/legend.frag", .label = "light-count legend"});
    if (!mLegend) {
        const ImageRGBA8 legend = makeLightCountLegend();
        mLegend = gl::Texture({.format = gl::Format::RGBA8, .width = legend.width, .height = legend.height, .label = "light-count legend"});
        // Bottom row first, as GL wants it.
        std::vector<uint8_t> rows(legend.pixels.size());
        const size_t row = size_t(legend.width) * 4;
        for (int y = 0; y < legend.height; ++y)
            std::copy_n(&legend.pixels[size_t(legend.height - 1 - y) * row], row, &rows[size_t(y) * row]);
        mLegend.upload(0, 0, 4, gl::PixelType::UnsignedByte, rows.data());
    }
    graph.addPass(
        "debug view: legend", [&](FrameGraph::Builder& b) { b.write(target, Use::ColorAttachment); },
        [this, &frame, target] {
            // The viewport is the legend's, in the corner: no sRGB encoding, the bytes as drawn.
            drawFullscreen(frame.state(), {.target = &frame.backend.framebuffer({target}),
                                           .width = std::min(mLegend.width(), frame.width),
                                           .height = std::min(mLegend.height(), frame.height),
                                           .program = &mLegendProgram,
                                           .input = &mLegend,
                                           .sampler = &mNearest,
                                           .triangle = &frame.stores.emptyVertexArray});
        });
}

} // namespace specula::render
