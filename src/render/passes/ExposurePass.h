#pragma once
// Automatic exposure: a log2-luminance histogram of the HDR frame (compute), its average
// between two percentiles turned into EV100 like a reflected-light meter, adapted over time,
// and left on the GPU for the tone mapper (no read-back, no stall).
#include <memory>

#include "render/graph/FrameGraph.h"
#include "settings/PassSettings.h"

namespace specula::gl {
class State;
class Texture;
} // namespace specula::gl

namespace specula::render {

class GlGraphBackend;

/// What the auto-exposure pass last decided (read back from the GPU).
struct ExposureReading {
    float ev100 = 0.0f;
    float exposure = 1.0f;         ///< 1 / (1.2 × 2^EV100)
    float averageLuminance = 0.0f; ///< cd/m², the last frame's measured average (0 = all black)
    bool measured = false;
};

class ExposurePass {
public:
    ExposurePass();
    ~ExposurePass();
    ExposurePass(const ExposurePass&) = delete;
    ExposurePass& operator=(const ExposurePass&) = delete;

    /// Adds "exposure": measures `hdr` (single-sampled, before exposure) and adapts the exposure
    /// state, which it returns for the tone mapper to read (bind()).
    GraphBuffer addTo(FrameGraph& graph, GlGraphBackend& backend, GraphTexture hdr, const AutoExposureSettings& settings);
    /// The same at once, outside a graph (the caller places barriers before reading the state).
    void apply(gl::State& state, const gl::Texture& hdr, const AutoExposureSettings& settings);
    /// Binds the exposure state for the tone mapper (SPECULA_BINDING_EXPOSURE).
    void bind() const;
    /// Reads the state back (stalls until the GPU is done).
    ExposureReading read() const;
    /// Forgets the adaptation: the next frame converges at once.
    void reset();
    void prepare();

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
