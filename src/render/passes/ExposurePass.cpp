#include "render/passes/ExposurePass.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "render/graph/GlGraphBackend.h"
#include "gl/Texture.h"
#include "gl/UniformBuffer.h"
#include "shaders/shared/Bindings.h"
#include "shaders/shared/PostData.h"

namespace specula::render {
namespace {

constexpr int kGroupSize = 16; // local_size of histogram.comp: one invocation per bin
static_assert(kGroupSize * kGroupSize == SPECULA_HISTOGRAM_BINS);

// EV100 = log2(L × 100 / 12.5) = log2(L) + 3, so the histogram spans the clamp range exactly.
constexpr float kLog2MeterScale = 3.0f;

// Buffer storage starts undefined: the histogram must start empty.
constexpr std::array<uint32_t, 2 * SPECULA_HISTOGRAM_BINS> kEmptyHistogram{};

} // namespace

struct ExposurePass::Impl {
    gl::Program histogram, adapt;
    int histogramSize = -1;
    gl::UniformBuffer<shared::ExposureParams> params{"exposure params"};
    // Zero-filled at creation; the adaptation pass clears the histogram after reading it.
    gl::Buffer bins{sizeof(kEmptyHistogram), kEmptyHistogram.data(), "luminance histogram"};
    gl::Buffer exposure{sizeof(shared::ExposureState), nullptr, "exposure state"};

    void ensurePrograms()
    {
        if (!histogram) {
            histogram = gl::Program({.compute = "post/histogram.comp", .label = "luminance histogram"});
            histogramSize = histogram.uniformLocation("uSize");
        }
        if (!adapt) adapt = gl::Program({.compute = "post/exposure_adapt.comp", .label = "exposure adaptation"});
    }
};

ExposurePass::ExposurePass() : mImpl(std::make_unique<Impl>())
{
    reset();
}

ExposurePass::~ExposurePass() = default;

void ExposurePass::prepare()
{
    mImpl->ensurePrograms();
}

void ExposurePass::reset()
{
    const shared::ExposureState initial{glm::vec4(0.0f, 1.0f, 0.0f, 0.0f)};
    mImpl->exposure.update(0, sizeof(initial), &initial);
}

void ExposurePass::bind() const
{
    gl::bindStorageBuffer(SPECULA_BINDING_EXPOSURE, mImpl->exposure);
}

ExposureReading ExposurePass::read() const
{
    gl::State::memoryBarrier(gl::Barrier::BufferUpdate);
    const auto bytes = mImpl->exposure.read(0, sizeof(shared::ExposureState));
    shared::ExposureState s;
    std::memcpy(&s, bytes.data(), sizeof(s));
    return {s.value.x, s.value.y, s.value.z, s.value.w > 0.0f};
}

void ExposurePass::apply(gl::State& state, const gl::Texture& hdr, const AutoExposureSettings& settings)
{
    Impl& r = *mImpl;
    r.ensurePrograms();
    const float minEv = std::min(settings.minEv100, settings.maxEv100);
    const float maxEv = std::max(std::max(settings.minEv100, settings.maxEv100), minEv + 1.0f); // a range, never a point
    const float low = std::clamp(settings.lowPercentile, 0.0f, 1.0f);
    const float high = std::clamp(settings.highPercentile, low, 1.0f);
    auto& p = r.params.data();
    p.histogram = glm::vec4(minEv - kLog2MeterScale, maxEv - kLog2MeterScale, low, high);
    p.adaptation = glm::vec4(std::max(settings.deltaTime, 0.0f), std::max(settings.speedUp, 0.0f),
                             std::max(settings.speedDown, 0.0f), 0.0f);
    p.clampEv = glm::vec4(minEv, maxEv, 0.0f, 0.0f);
    r.params.upload();
    r.params.bind(SPECULA_BINDING_EXPOSURE_PARAMS);
    gl::bindStorageBuffer(SPECULA_BINDING_HISTOGRAM, r.bins);
    gl::bindStorageBuffer(SPECULA_BINDING_EXPOSURE, r.exposure);

    state.useProgram(r.histogram);
    r.histogram.set(r.histogramSize, glm::ivec2(hdr.width(), hdr.height()));
    state.bindTexture(SPECULA_UNIT_POST_INPUT, hdr);
    state.bindSampler(SPECULA_UNIT_POST_INPUT, nullptr);
    state.dispatchCompute(uint32_t((hdr.width() + kGroupSize - 1) / kGroupSize),
                          uint32_t((hdr.height() + kGroupSize - 1) / kGroupSize));
    state.memoryBarrier(gl::Barrier::StorageBuffer);
    state.useProgram(r.adapt);
    state.dispatchCompute(1, 1);
    // The tone mapper reads the state next, the next frame's histogram the cleared bins: the
    // frame graph places their barriers.
}

GraphBuffer ExposurePass::addTo(FrameGraph& graph, GlGraphBackend& backend, GraphTexture hdr, const AutoExposureSettings& settings)
{
    prepare();
    const GraphBuffer state = graph.importBuffer("exposure state", backend.importBuffer(mImpl->exposure));
    const GraphBuffer bins = graph.importBuffer("luminance histogram", backend.importBuffer(mImpl->bins));
    graph.addPass(
        "exposure",
        [&](FrameGraph::Builder& b) {
            b.read(hdr, Use::Sample);
            b.write(bins, Use::StorageWrite);
            b.write(state, Use::StorageWrite);
        },
        [this, &backend, hdr, settings] { apply(backend.state(), backend.texture(hdr), settings); });
    return state;
}

} // namespace specula::render
