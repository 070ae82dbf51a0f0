#include "render/passes/LightCullPass.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <string>
#include <utility>

#include "core/Log.h"
#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "render/FrameContext.h"
#include "render/graph/GlGraphBackend.h"
#include "shaders/shared/Bindings.h"

namespace specula::render {
namespace {

// The lists' first buffer: 4 MiB, a million light indices (288 per cluster of a 16 × 9 × 24
// grid); a frame that needs more grows it.
constexpr size_t kInitialWords = size_t(1) << 20;

uint32_t groups(uint32_t invocations, uint32_t size)
{
    return (invocations + size - 1) / size;
}

} // namespace

struct LightCullPass::Impl {
    gl::Program inView, count, scan, fill;
    int inViewView = -1, inViewBase = -1, countClusters = -1, scanClusters = -1, fillClusters = -1;
    std::array<int, 6> inViewFrustum{};

    gl::Buffer words;          // header, records, indices (shared/ClusterData.h)
    gl::Texture wordTexels;    // its R32UI view
    uint32_t retiredTexels = 0; // a view a growth deleted, for gl::State to forget
    size_t capacity = 0;        // words
    gl::Buffer cullLights;      // CullLight per light at most
    size_t cullCapacity = 0;    // lights
    gl::Buffer boundsBuffer;

    ClusterGrid grid;
    glm::mat4 projection{0.0f};
    bool haveGrid = false;
    std::vector<shared::ClusterBounds> bounds;
    float shrink = 0.0f;
    ClusterCounts last;
    bool haveCounts = false;
    // What the lists in `words` were made for: the lights' revision and the view.
    struct Culled {
        uint64_t lights = 0;
        glm::mat4 view{0.0f};
        bool operator==(const Culled&) const = default;
    };
    std::optional<Culled> culled;
    int runs = 0;

    void ensurePrograms()
    {
        if (inView) return;
        inView = gl::Program({.compute = "lights/lights_in_view.comp", .label = "lights in view"});
        inViewView = inView.uniformLocation("uView");
        inViewBase = inView.uniformLocation("uBase");
        for (int i = 0; i < 6; ++i) inViewFrustum[size_t(i)] = inView.uniformLocation(("uFrustum[" + std::to_string(i) + "]").c_str());
        count = gl::Program({.compute = "lights/cluster_cull.comp", .label = "cluster count"});
        countClusters = count.uniformLocation("uClusters");
        scan = gl::Program({.compute = "lights/cluster_scan.comp", .label = "cluster scan"});
        scanClusters = scan.uniformLocation("uClusters");
        fill = gl::Program({.compute = "lights/cluster_cull.comp", .defines = {"CLUSTER_FILL"}, .label = "cluster fill"});
        fillClusters = fill.uniformLocation("uClusters");
    }

    void allocateWords(size_t wordCount)
    {
        if (wordTexels) retiredTexels = wordTexels.id();
        wordTexels = {};
        culled.reset();
        // Only the header is read before the passes write it; the rest is written by the
        // culling before anything reads it (no 4 MiB of zeros made and copied at start-up).
        std::array<uint32_t, SPECULA_CLUSTER_HEADER_WORDS> header{};
        header[SPECULA_CLUSTER_WORD_CAPACITY] = uint32_t(wordCount);
        words = gl::Buffer(wordCount * sizeof(uint32_t), nullptr, "light clusters");
        words.update(0, sizeof(header), header.data());
        wordTexels = gl::Texture(words, gl::Format::R32UI, "light cluster texels");
        capacity = wordCount;
    }

    /// The grid and its boxes for this target and projection (kept while neither changes).
    void updateGrid(int width, int height, const glm::mat4& proj)
    {
        const ClusterGrid g = ClusterGrid::make(width, height, proj);
        if (haveGrid && g == grid && proj == projection) return;
        culled.reset(); // new boxes: the lists must be made again
        grid = g;
        projection = proj;
        haveGrid = true;
        bounds = clusterBounds(grid, projection);
        std::vector<shared::ClusterBounds> uploaded = bounds;
        if (shrink > 0.0f) {
            for (shared::ClusterBounds& b : uploaded) {
                const glm::vec4 centre = (b.lo + b.hi) * 0.5f, half = (b.hi - b.lo) * (0.5f * (1.0f - shrink));
                b = {centre - half, centre + half};
            }
        }
        const size_t bytes = uploaded.size() * sizeof(shared::ClusterBounds);
        if (boundsBuffer.size() != bytes) {
            boundsBuffer = gl::Buffer(bytes, uploaded.data(), "cluster bounds");
        } else {
            boundsBuffer.update(0, bytes, uploaded.data());
        }
        const size_t needed = SPECULA_CLUSTER_HEADER_WORDS + 2 * size_t(grid.count()) + 1024;
        if (capacity < needed) allocateWords(std::max(kInitialWords, needed));
    }

    /// Steps 1–3, then the totals read back.
    ClusterCounts countLists(gl::State& state, const glm::mat4& view, uint32_t base)
    {
        const uint32_t clusters = uint32_t(grid.count());
        gl::bindStorageBuffer(SPECULA_BINDING_CLUSTERS, words);
        gl::bindStorageBuffer(SPECULA_BINDING_CULL_LIGHTS, cullLights);
        gl::bindStorageBuffer(SPECULA_BINDING_CLUSTER_BOUNDS, boundsBuffer);
        state.useProgram(inView);
        inView.set(inViewView, view);
        inView.set(inViewBase, base);
        const std::array<glm::vec4, 6> planes = viewFrustumPlanes(projection);
        for (size_t i = 0; i < planes.size(); ++i) inView.set(inViewFrustum[i], planes[i]);
        state.dispatchCompute(1, 1);
        state.memoryBarrier(gl::Barrier::StorageBuffer);
        state.useProgram(count);
        count.set(countClusters, clusters);
        state.dispatchCompute(groups(clusters, SPECULA_CULL_GROUP), 1);
        state.memoryBarrier(gl::Barrier::StorageBuffer);
        state.useProgram(scan);
        scan.set(scanClusters, clusters);
        state.dispatchCompute(1, 1);
        state.memoryBarrier(gl::Barrier::BufferUpdate | gl::Barrier::StorageBuffer);
        uint32_t header[SPECULA_CLUSTER_HEADER_WORDS];
        const auto bytes = words.read(0, sizeof header);
        std::memcpy(header, bytes.data(), sizeof header);
        return {header[SPECULA_CLUSTER_WORD_DIRECTIONAL], header[SPECULA_CLUSTER_WORD_VISIBLE],
                header[SPECULA_CLUSTER_WORD_ENTRIES], header[SPECULA_CLUSTER_WORD_MAX]};
    }

    void run(FrameContext const& frame)
    {
        gl::State& state = frame.state();
        if (retiredTexels) state.forgetTexture(std::exchange(retiredTexels, 0u));
        LightBuffer& lights = frame.stores.lights;
        // The lists of the last run still hold while neither the lights nor the view (nor the
        // grid: updateGrid) changed: a still frame culls nothing, and reads nothing back.
        const Culled now{lights.revision(), frame.view.view};
        if (culled && *culled == now) return;
        const size_t lightCount = size_t(lights.count());
        if (cullCapacity < std::max<size_t>(lightCount, 1)) {
            cullCapacity = std::max<size_t>({64, lightCount, 2 * cullCapacity});
            cullLights = gl::Buffer(cullCapacity * sizeof(shared::CullLight), nullptr, "lights in view");
        }
        lights.bind(state);
        const uint32_t base = SPECULA_CLUSTER_HEADER_WORDS + 2u * uint32_t(grid.count());
        ClusterCounts c = countLists(state, frame.view.view, base);
        const size_t needed = size_t(base) + c.directional + c.entries;
        if (needed > capacity) {
            size_t grown = capacity;
            while (grown < needed) grown *= 2;
            log::warn("light clusters: {} light indices do not fit the {} the list buffer holds; grown to {}", needed - base,
                      capacity - base, grown - base);
            allocateWords(grown);
            c = countLists(state, frame.view.view, base); // into the new buffer
        }
        state.useProgram(fill);
        fill.set(fillClusters, uint32_t(grid.count()));
        state.dispatchCompute(groups(uint32_t(grid.count()), SPECULA_CULL_GROUP), 1);
        last = c;
        haveCounts = true;
        culled = now;
        ++runs;
        // The shading passes fetch the lists next: the frame graph places that barrier.
    }
};

LightCullPass::LightCullPass() : mImpl(std::make_unique<Impl>()) {}
LightCullPass::~LightCullPass() = default;

GraphBuffer LightCullPass::addTo(FrameGraph& graph, const FrameContext& frame)
{
    Impl& r = *mImpl;
    r.ensurePrograms();
    r.updateGrid(frame.width, frame.height, frame.view.projection);
    const GraphBuffer lists = graph.importBuffer("light clusters", frame.backend.importBuffer(r.words));
    graph.addPass(
        "light culling", [&](FrameGraph::Builder& b) { b.write(lists, Use::StorageWrite); }, [&r, &frame] { r.run(frame); });
    return lists;
}

void LightCullPass::bind(gl::State& state) const
{
    Impl& r = *mImpl;
    if (r.retiredTexels) state.forgetTexture(std::exchange(r.retiredTexels, 0u));
    state.bindTexture(SPECULA_UNIT_CLUSTERS, r.wordTexels);
    state.bindSampler(SPECULA_UNIT_CLUSTERS, nullptr);
}

const ClusterGrid& LightCullPass::grid() const
{
    return mImpl->grid;
}

const std::vector<shared::ClusterBounds>& LightCullPass::bounds() const
{
    return mImpl->bounds;
}

int LightCullPass::runs() const
{
    return mImpl->runs;
}

ClusterCounts LightCullPass::counts() const
{
    return mImpl->last;
}

bool LightCullPass::listsAreNearlyEveryLight(int pointAndSpotLights) const
{
    const Impl& r = *mImpl;
    constexpr int kFewLights = 32;
    if (!r.haveCounts || pointAndSpotLights > kFewLights) return false;
    const double pairs = double(r.grid.count()) * double(pointAndSpotLights);
    return double(r.last.entries) >= 0.9 * pairs;
}

size_t LightCullPass::capacityWords() const
{
    return mImpl->capacity;
}

std::vector<uint32_t> LightCullPass::readWords() const
{
    gl::State::memoryBarrier(gl::Barrier::BufferUpdate);
    const auto bytes = mImpl->words.read(0, mImpl->capacity * sizeof(uint32_t));
    std::vector<uint32_t> out(mImpl->capacity);
    std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

void LightCullPass::setShrinkForTesting(float fraction)
{
    mImpl->shrink = fraction;
    mImpl->haveGrid = false; // the boxes are uploaded again
}

} // namespace specula::render
