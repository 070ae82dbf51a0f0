#pragma once
// The frame's pipelines: each a composition of passes into a frame graph, not a branch inside
// one function. Adding a pass to a frame is its own files (render/passes/) plus its line here.
//
//   forward: light culling → [shadows: cascades, spot, point] [ssao prepass → ssao → ssao blur] → forward → [resolve] → [bloom] → [exposure]
//            → tonemap | resolve+tonemap → [fxaa] → [debug view]
//   doom:    [ssao …] → forward (palette indices) → colour map → [debug view]
#include <memory>

#include "render/graph/FrameGraph.h"
#include "render/passes/BillboardPass.h"
#include "render/passes/BloomPass.h"
#include "render/passes/DebugViewPass.h"
#include "render/passes/DoomPass.h"
#include "render/passes/ExposurePass.h"
#include "render/passes/ForwardPass.h"
#include "render/passes/FxaaPass.h"
#include "render/passes/LightCullPass.h"
#include "render/passes/ShadowPass.h"
#include "render/passes/SsaoPass.h"
#include "render/passes/TonemapPass.h"

namespace specula::render {

struct FrameContext;

/// The passes a renderer keeps (what persists of each), made on first use: a pass that is off
/// costs nothing.
struct FramePasses {
    BillboardPass billboards; ///< holds the scene's billboard groups
    ShadowPass shadows;       ///< holds the shadow atlas (maps are kept while nothing changes)
    LightCullPass lightCull;  ///< holds the cluster grid and the lists' buffers
    ForwardPass forward;
    TonemapPass tonemap;
    SsaoPass& ssao() { return get(mSsao); }
    BloomPass& bloom() { return get(mBloom); }
    ExposurePass& exposure() { return get(mExposure); }
    FxaaPass& fxaa() { return get(mFxaa); }
    DoomPass& doom() { return get(mDoom); }
    DebugViewPass& debugView() { return get(mDebugView); }
    /// The exposure pass if a frame ever made it (its state is the automatic exposure).
    ExposurePass* exposureIfMade() const { return mExposure.get(); }

private:
    template <typename T>
    static T& get(std::unique_ptr<T>& pass)
    {
        if (!pass) pass = std::make_unique<T>();
        return *pass;
    }
    std::unique_ptr<SsaoPass> mSsao;
    std::unique_ptr<BloomPass> mBloom;
    std::unique_ptr<ExposurePass> mExposure;
    std::unique_ptr<FxaaPass> mFxaa;
    std::unique_ptr<DoomPass> mDoom;
    std::unique_ptr<DebugViewPass> mDebugView;
};

/// What a frame leaves to be read after it (the graph exports them).
struct FrameOutputs {
    GraphBuffer clusters;   ///< the cluster light lists (imported), when the frame culled lights
    bool everyLight = false; ///< the forward pass shades every light (LIGHTS_ALL)
    GraphTexture shadows;   ///< the shadow atlas (imported), when some light has a map
    GraphTexture ldr;       ///< the sRGB image (readImage, present)
    GraphTexture hdr;       ///< single-sampled radiance, when the frame made one
    GraphTexture msaaColor; ///< multisampled radiance, when the frame has MSAA
    GraphTexture occlusion; ///< SSAO's blurred occlusion, with the SSAO debug view
};

/// A frame in the making: its graph, the draw lists its passes read, what it exports.
struct Frame {
    FrameGraph graph;
    FrameDrawLists lists;
    FrameOutputs outputs;
};

/// Builds the frame for `context` into `frame`: the Doom pipeline for a Doom frame, else the
/// forward one. Programs are compiled and DFG tables baked here, not when the graph executes.
void buildFrame(Frame& frame, FramePasses& passes, const FrameContext& context);

} // namespace specula::render
