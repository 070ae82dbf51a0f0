#pragma once
// What the passes of a frame share: the stores the renderer keeps from frame to frame (scene,
// lights, environment, frame constants, default textures) and this frame's view and settings.
// A pass adds itself to a frame graph with `addTo(graph, frame, inputs...)`, keeping only
// what persists (programs, kernels, tables) in its own object.
#include <optional>

#include "gl/State.h"
#include "gl/Texture.h"
#include "gl/UniformBuffer.h"
#include "gl/VertexArray.h"
#include "render/ImageBasedLighting.h"
#include "render/LightBuffer.h"
#include "render/Renderer.h"
#include "render/View.h"
#include "shaders/shared/EnvironmentData.h"
#include "shaders/shared/FrameData.h"

namespace specula::render {

class BillboardPass;
class DoomTables;
class GlGraphBackend;
class GpuScene;

/// Persistent GPU stores shared by the passes.
struct FrameStores {
    gl::State state;
    gl::UniformBuffer<shared::FrameData> frame{"frame"};
    LightBuffer lights;
    std::unique_ptr<GpuScene> scene;
    ImageBasedLighting ibl;
    gl::UniformBuffer<shared::EnvironmentData> environment{"environment"};
    gl::VertexArray emptyVertexArray{"fullscreen triangle"};
    gl::Texture white;
    gl::Texture flatNormal;
    /// Changes whenever what casts shadows may have changed (a new scene, an edited material):
    /// shadow maps drawn before it are stale.
    uint64_t casterVersion = 0;
    /// Whether the default framebuffer encodes sRGB itself (GL_FRAMEBUFFER_SRGB applies to it):
    /// asked by the first frame drawn straight into a window (FrameSettings::toWindow).
    std::optional<bool> windowSrgb;
    FrameStores();
    ~FrameStores();
};

/// One frame: what it shows and with what.
struct FrameContext {
    const View& view;
    const FrameSettings& settings; ///< as the frame runs them (debug views and Doom frames adjust)
    int width;
    int height;
    int samples;
    float exposureScale; ///< 2^EV × camera exposure (manual), before automatic exposure
    FrameStores& stores;
    GlGraphBackend& backend;
    FrameStats& stats;
    gl::State& state() const { return stores.state; }
};

/// A Doom frame: the Doom model overrides every material and no material view replaces it.
bool isDoomFrame(const FrameSettings& settings);

} // namespace specula::render
