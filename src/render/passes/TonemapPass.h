#pragma once
// Tone mapping: the exposed HDR frame through the frame's tone curve into the 8-bit image.
// Reading a multisampled frame it resolves as it reads ("resolve+tonemap": one pass instead of
// a blit and a pass); with automatic exposure it reads the exposure state the exposure pass left
// on the GPU. Into the sRGB target GL encodes; into FXAA's UNORM input the shader does.
#include <cstdint>
#include <map>

#include "gl/Program.h"
#include "render/graph/FrameGraph.h"
#include "shading/Tonemap.h"

namespace specula::render {

struct FrameContext;

/// The operator's SPECULA_TONEMAP_* id (shaders/shared/FrameData.h).
uint32_t tonemapId(Tonemap t);

class TonemapPass {
public:
    /// Adds the pass: `input` (RGBA16F, `samples` per pixel) into `target` (sRGB, or with
    /// `encodeSrgb` an RGBA8 UNORM texture the shader encodes into; an invalid `target`: the
    /// default framebuffer, sRGB-capable).
    void addTo(FrameGraph& graph, const FrameContext& frame, GraphTexture input, int samples, GraphBuffer exposure,
               GraphTexture target, bool encodeSrgb);

private:
    gl::Program& program(int samples, bool automaticExposure, bool encodeSrgb, uint32_t tonemap);
    std::map<int, gl::Program> mPrograms; ///< by operator, sample count, auto exposure, encoding
};

} // namespace specula::render
