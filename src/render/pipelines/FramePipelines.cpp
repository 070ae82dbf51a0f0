#include "render/pipelines/FramePipelines.h"

#include "core/Log.h"
#include "gl/Framebuffer.h"
#include "render/FrameContext.h"
#include "render/GpuScene.h"
#include "render/passes/ResolvePass.h"

namespace specula::render {
namespace {

GraphTextureDesc target(const FrameContext& frame, gl::Format format, int samples = 1)
{
    GraphTextureDesc d;
    d.width = frame.width;
    d.height = frame.height;
    d.format = format;
    if (samples > 1) {
        d.type = gl::TextureType::Texture2DMultisample;
        d.samples = samples;
    }
    return d;
}

/// SSAO's passes, when on: the occlusion the forward pass samples.
GraphTexture addSsao(Frame& f, FramePasses& passes, const FrameContext& frame)
{
    return frame.settings.ssao.enabled ? passes.ssao().addTo(f.graph, frame, f.lists.opaque) : GraphTexture{};
}

/// The SSAO view over the finished image, and what the renderer reads after the frame.
void finish(Frame& f, FramePasses& passes, const FrameContext& frame)
{
    FrameOutputs& out = f.outputs;
    if (frame.settings.debugView == DebugView::Ssao) {
        passes.debugView().addTo(f.graph, frame, out.occlusion, out.ldr);
        f.graph.exportTexture(out.occlusion);
    } else {
        out.occlusion = {};
    }
    if (frame.settings.debugView == DebugView::LightCount) passes.debugView().addLightCountLegend(f.graph, frame, out.ldr);
    if (frame.settings.debugView == DebugView::ShadowAtlas && out.shadows)
        passes.debugView().addShadowAtlas(f.graph, frame, out.shadows, out.ldr);
    if (out.ldr) f.graph.exportTexture(out.ldr);
    if (out.hdr) f.graph.exportTexture(out.hdr);
    if (out.msaaColor) f.graph.exportTexture(out.msaaColor);
}

/// The frame's kinds of light, and their count when every light is evaluated everywhere.
LightVariant lightVariant(const LightBuffer& buffer, bool everyLight)
{
    LightVariant v{.all = everyLight, .directional = false, .point = false, .spot = false};
    if (everyLight && buffer.count() <= LightVariant::kMaxConstantCount) v.count = buffer.count();
    v.directional = buffer.countOf(scene::Light::Type::Directional) > 0;
    v.point = buffer.countOf(scene::Light::Type::Point) > 0;
    v.spot = buffer.countOf(scene::Light::Type::Spot) > 0;
    return v;
}

/// ssao → forward → resolve → bloom → exposure → tone map → FXAA → debug view.
void buildForward(Frame& f, FramePasses& passes, const FrameContext& frame)
{
    const FrameSettings& s = frame.settings;
    FrameGraph& graph = f.graph;
    FrameOutputs& out = f.outputs;
    out.occlusion = addSsao(f, passes, frame);

    const bool multisampled = frame.samples > 1;
    const GraphTexture color = graph.createTexture(multisampled ? "msaa colour" : "hdr colour",
                                                   target(frame, gl::Format::RGBA16F, frame.samples));
    const GraphTexture depth = graph.createTexture(multisampled ? "msaa depth" : "depth",
                                                   target(frame, gl::Format::Depth32F, frame.samples));
    DoomPass* doomTables = ForwardPass::anyDoomMaterial(frame) ? &passes.doom() : nullptr;
    passes.forward.addTo(graph, frame, f.lists, {color, depth, out.occlusion, out.shadows, out.clusters}, passes.billboards,
                         doomTables, &passes.shadows, &passes.lightCull);
    if (multisampled) {
        out.msaaColor = color;
    } else {
        out.hdr = color;
    }

    // Passes on the HDR frame need it resolved. Without them the tone mapper resolves as it
    // reads (one pass instead of a blit and a pass), and the resolved HDR image is made only
    // when someone asks (Renderer::readRadiance): with every post pass off the frame costs what
    // it did before post-processing existed.
    if ((s.bloom.enabled || s.autoExposure.enabled) && multisampled) {
        out.hdr = graph.createTexture("hdr colour", target(frame, gl::Format::RGBA16F));
        addResolvePass(graph, frame.backend, color, out.hdr);
    }
    if (s.bloom.enabled)
        passes.bloom().addTo(graph, frame.backend, out.hdr, s.bloom, frame.exposureScale, s.debugView == DebugView::Bloom);
    GraphBuffer exposure;
    if (s.autoExposure.enabled) exposure = passes.exposure().addTo(graph, frame.backend, out.hdr, s.autoExposure);

    // Straight into the window when the tone map is the last pass and the window's back
    // buffer is sRGB-capable: GL encodes there as into the 8-bit image, so the bytes are the
    // same, and there is no image to copy. Else the image, which present() copies.
    bool toWindow = s.toWindow && !s.fxaa.enabled && s.debugView == DebugView::None;
    if (toWindow && !frame.stores.windowSrgb) {
        frame.stores.windowSrgb = gl::defaultFramebufferIsSrgb();
        log::debug("{}", *frame.stores.windowSrgb ? "the tone map draws straight into the window's sRGB back buffer"
                                                   : "the window's back buffer is not sRGB: frames are copied into it");
    }
    toWindow = toWindow && *frame.stores.windowSrgb;
    if (!toWindow) out.ldr = graph.createTexture("ldr colour", target(frame, gl::Format::SRGB8_ALPHA8));
    const GraphTexture toneMapped = s.fxaa.enabled ? graph.createTexture("fxaa input", target(frame, gl::Format::RGBA8)) : out.ldr;
    passes.tonemap.addTo(graph, frame, out.hdr ? out.hdr : color, out.hdr ? 1 : frame.samples, exposure, toneMapped,
                         s.fxaa.enabled);
    if (s.fxaa.enabled) passes.fxaa().addTo(graph, frame.backend, toneMapped, out.ldr);
    finish(f, passes, frame);
}

/// Doom's 8-bit frame: palette indices and levels, then the colour-map pass writes the palette
/// colours to both the HDR and the 8-bit target. Nothing else touches them (no tone curve,
/// exposure, bloom or FXAA: the renderer's effective settings), so the image is the palette's bytes.
void buildDoom(Frame& f, FramePasses& passes, const FrameContext& frame)
{
    FrameGraph& graph = f.graph;
    FrameOutputs& out = f.outputs;
    out.occlusion = addSsao(f, passes, frame);
    const GraphTexture indexed = graph.createTexture("doom indexed frame", target(frame, gl::Format::RG8UI));
    const GraphTexture depth = graph.createTexture("doom depth", target(frame, gl::Format::Depth32F));
    DoomPass& doom = passes.doom();
    passes.forward.addTo(graph, frame, f.lists, {indexed, depth, out.occlusion}, passes.billboards, &doom);
    out.hdr = graph.createTexture("hdr colour", target(frame, gl::Format::RGBA16F));
    out.ldr = graph.createTexture("ldr colour", target(frame, gl::Format::SRGB8_ALPHA8));
    doom.addTo(graph, frame, indexed, out.hdr, out.ldr);
    finish(f, passes, frame);
}

} // namespace

void buildFrame(Frame& f, FramePasses& passes, const FrameContext& frame)
{
    // The lights each cluster lists, for every shading path; a Doom frame shades with none.
    const bool culled = !isDoomFrame(frame.settings) && frame.settings.lightCulling == LightCulling::Clustered;
    // When the last culling listed nearly every light in nearly every cluster (a few lights
    // that reach most of the view), shade with every light: a few more evaluations, no index
    // each (LightCullPass::listsAreNearlyEveryLight). The culling still runs, to say when that
    // stops holding.
    const LightBuffer& lights = frame.stores.lights;
    const bool everyLight = frame.settings.lightCulling == LightCulling::None ||
                            (culled && passes.lightCull.listsAreNearlyEveryLight(lights.count() - lights.directionalCount()));
    if (culled) f.outputs.clusters = passes.lightCull.addTo(f.graph, frame);
    f.outputs.everyLight = everyLight;
    // Shadows first: whether any light has a map picks the forward programs.
    f.outputs.shadows = passes.shadows.addTo(f.graph, frame);
    passes.forward.prepareMaterials(frame, passes.shadows.variant(), lightVariant(lights, everyLight));
    if (frame.settings.lodPixels > 0.0f && frame.stores.scene && !frame.stores.scene->hasLevelsOfDetail())
        frame.stores.scene->buildLevelsOfDetail();
    f.lists = passes.forward.drawLists(frame);
    if (isDoomFrame(frame.settings)) {
        buildDoom(f, passes, frame);
    } else {
        buildForward(f, passes, frame);
    }
}

} // namespace specula::render
