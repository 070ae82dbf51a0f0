#include "render/passes/BloomPass.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "render/graph/GlGraphBackend.h"
#include "shaders/shared/Bindings.h"

namespace specula::render {
namespace {

constexpr int kMaxLevels = 8;
constexpr int kGroupSize = 8; // local_size of the bloom shaders

uint32_t groups(int size)
{
    return uint32_t((size + kGroupSize - 1) / kGroupSize);
}

struct DownsampleProgram {
    gl::Program program;
    int targetSize = -1, sourceTexel = -1, sourceExtent = -1, threshold = -1;
};

struct UpsampleProgram {
    gl::Program program;
    int targetSize = -1, lowerTexel = -1, lowerExtent = -1, radius = -1, keep = -1, scale = -1;
};

} // namespace

struct BloomPass::Impl {
    std::map<std::string, DownsampleProgram> downsample; ///< by variant: "first", "first karis", "rest"
    UpsampleProgram upsample;
    // Bilinear; the shaders reflect every tap into the frame first (shaders/post/bloom.glsl),
    // so the wrap mode only matters within half a texel of a level's edge.
    gl::Sampler linearClamp{{.mipFilter = gl::MipFilter::None, .wrapS = gl::Wrap::ClampToEdge,
                             .wrapT = gl::Wrap::ClampToEdge, .wrapR = gl::Wrap::ClampToEdge},
                            "bloom bilinear clamp"};

    DownsampleProgram& downsampleProgram(bool first, bool karis)
    {
        const std::string key = !first ? "rest" : karis ? "first karis" : "first";
        DownsampleProgram& p = downsample[key];
        if (!p.program) {
            std::vector<std::string> defines;
            if (first) defines.push_back("FIRST_LEVEL");
            if (first && karis) defines.push_back("KARIS_AVERAGE");
            p.program = gl::Program({.compute = "post/bloom_downsample.comp", .defines = defines, .label = "bloom down " + key});
            p.targetSize = p.program.uniformLocation("uTargetSize");
            p.sourceTexel = p.program.uniformLocation("uSourceTexel");
            p.sourceExtent = p.program.uniformLocation("uSourceExtent");
            p.threshold = p.program.uniformLocation("uThreshold");
        }
        return p;
    }

    UpsampleProgram& upsampleProgram()
    {
        if (!upsample.program) {
            upsample.program = gl::Program({.compute = "post/bloom_upsample.comp", .label = "bloom up"});
            upsample.targetSize = upsample.program.uniformLocation("uTargetSize");
            upsample.lowerTexel = upsample.program.uniformLocation("uLowerTexel");
            upsample.lowerExtent = upsample.program.uniformLocation("uLowerExtent");
            upsample.radius = upsample.program.uniformLocation("uRadius");
            upsample.keep = upsample.program.uniformLocation("uKeep");
            upsample.scale = upsample.program.uniformLocation("uScale");
        }
        return upsample;
    }

    /// Adds the glow of `hdr` to it; levels[k] is level k + 1 (level 0 is the frame).
    void run(gl::State& state, gl::Texture& hdr, const std::vector<gl::Texture*>& levels, const BloomSettings& settings,
             float exposure, bool glowOnly);
};

namespace {

/// Level k's size: rounded up, so that level k + 1 covers all of level k.
GraphTextureDesc levelDesc(int w, int h, int k)
{
    GraphTextureDesc desc;
    desc.width = std::max(1, (w + (1 << k) - 1) >> k);
    desc.height = std::max(1, (h + (1 << k) - 1) >> k);
    // Half floats: the glow of a 65504 pixel must not become Inf, and an 11-bit float's 6-bit
    // mantissa would cost the 1% energy accuracy.
    desc.format = gl::Format::RGBA16F;
    return desc;
}

} // namespace

BloomPass::BloomPass() : mImpl(std::make_unique<Impl>()) {}
BloomPass::~BloomPass() = default;

int BloomPass::levelsFor(int width, int height, int requested)
{
    int halvings = 0;
    for (int size = std::max(width, height); size > 1; size = (size + 1) / 2) ++halvings;
    return std::clamp(requested, 0, std::min(kMaxLevels, halvings));
}

void BloomPass::prepare(const BloomSettings& settings)
{
    mImpl->downsampleProgram(true, settings.fireflyFilter);
    mImpl->downsampleProgram(false, false);
    mImpl->upsampleProgram();
}

void BloomPass::addTo(FrameGraph& graph, GlGraphBackend& backend, GraphTexture hdr, const BloomSettings& settings,
                      float exposure, bool glowOnly)
{
    prepare(settings);
    // A copy: createTexture below grows the graph's resources, which a reference would outlive
    // (AddressSanitizer: heap-use-after-free, found on branch wt-hard).
    const GraphTextureDesc frame = graph.desc(hdr);
    const int levels = levelsFor(frame.width, frame.height, settings.levels);
    // Made before the pass: its execute step captures the handles.
    std::vector<GraphTexture> handles;
    for (int k = 1; k <= levels; ++k)
        handles.push_back(graph.createTexture("bloom level " + std::to_string(k), levelDesc(frame.width, frame.height, k)));
    graph.addPass(
        "bloom",
        [&](FrameGraph::Builder& b) {
            b.write(hdr, Use::ImageReadWrite);
            // Written first (down-sampled into), then read and written (up-sampled into).
            for (GraphTexture level : handles) b.write(level, Use::ImageStore);
        },
        [this, &backend, hdr, handles, settings, exposure, glowOnly] {
            std::vector<gl::Texture*> textures;
            for (GraphTexture h : handles) textures.push_back(&backend.texture(h));
            mImpl->run(backend.state(), backend.texture(hdr), textures, settings, exposure, glowOnly);
        });
}

void BloomPass::apply(gl::State& state, gl::Texture& hdr, const BloomSettings& settings, float exposure, bool glowOnly)
{
    // A graph of this one pass, its levels from a pool of its own.
    GlGraphBackend backend(state);
    FrameGraph graph;
    GraphTextureDesc desc;
    desc.width = hdr.width();
    desc.height = hdr.height();
    desc.format = hdr.desc().format;
    const GraphTexture frame = graph.importTexture("hdr", desc, backend.importTexture(hdr));
    addTo(graph, backend, frame, settings, exposure, glowOnly);
    backend.beginFrame(graph);
    graph.execute(backend);
}

void BloomPass::Impl::run(gl::State& state, gl::Texture& hdr, const std::vector<gl::Texture*>& levelTextures,
                          const BloomSettings& settings, float exposure, bool glowOnly)
{
    Impl& r = *this;
    const int w = hdr.width(), h = hdr.height();
    const int levels = levelsFor(w, h, settings.levels);
    if (levels == 0) {
        // A 1×1 frame has nowhere to spread light: no glow.
        if (glowOnly) hdr.clear();
        return;
    }

    // Where the frame ends in level k, in its texels: not a texel edge once a size was odd.
    auto extent = [&](int k) { return glm::vec2(float(w), float(h)) / float(1 << k); };

    // Down: frame → level 1 → … → level `levels`.
    for (int k = 1; k <= levels; ++k) {
        const gl::Texture& source = k == 1 ? hdr : *levelTextures[size_t(k - 2)];
        const gl::Texture& target = *levelTextures[size_t(k - 1)];
        DownsampleProgram& p = r.downsampleProgram(k == 1, settings.fireflyFilter);
        state.useProgram(p.program);
        p.program.set(p.targetSize, glm::ivec2(target.width(), target.height()));
        p.program.set(p.sourceTexel, glm::vec2(1.0f / float(source.width()), 1.0f / float(source.height())));
        p.program.set(p.sourceExtent, extent(k - 1));
        if (k == 1)
            p.program.set(p.threshold, glm::vec4(settings.threshold, settings.knee * settings.threshold, exposure, 0.0f));
        state.bindTexture(SPECULA_UNIT_POST_INPUT, source);
        state.bindSampler(SPECULA_UNIT_POST_INPUT, &r.linearClamp);
        state.bindImage(SPECULA_IMAGE_POST_OUTPUT, target, 0, gl::ImageAccess::WriteOnly);
        state.dispatchCompute(groups(target.width()), groups(target.height()));
        state.memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::Image);
    }

    // Up: level `levels` → … → level 1, each adding the magnified level below; then the frame.
    UpsampleProgram& p = r.upsampleProgram();
    state.useProgram(p.program);
    p.program.set(p.radius, std::max(settings.radius, 0.0f));
    for (int k = levels - 1; k >= 0; --k) {
        const gl::Texture& lower = *levelTextures[size_t(k)];
        const gl::Texture& target = k == 0 ? hdr : *levelTextures[size_t(k - 1)];
        const bool frame = k == 0;
        p.program.set(p.targetSize, glm::ivec2(target.width(), target.height()));
        p.program.set(p.lowerTexel, glm::vec2(1.0f / float(lower.width()), 1.0f / float(lower.height())));
        p.program.set(p.lowerExtent, extent(k + 1));
        p.program.set(p.keep, frame && glowOnly ? 0.0f : 1.0f);
        // Level 1 now holds the sum of `levels` blurred copies of the frame.
        p.program.set(p.scale, frame ? std::max(settings.intensity, 0.0f) / float(levels) : 1.0f);
        state.bindTexture(SPECULA_UNIT_POST_INPUT, lower);
        state.bindSampler(SPECULA_UNIT_POST_INPUT, &r.linearClamp);
        state.bindImage(SPECULA_IMAGE_POST_OUTPUT, target, 0, gl::ImageAccess::ReadWrite);
        state.dispatchCompute(groups(target.width()), groups(target.height()));
        // Between dispatches; after the last one the frame graph places what its readers need.
        if (k > 0) state.memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::Image);
    }
}

} // namespace specula::render
