// The frame graph without GL (render/graph/FrameGraph.h, ResourcePool.h): culling, ordering,
// transient lifetimes and their reuse within and across frames, barrier placement, and the
// errors of a bad graph, against a backend that records what it is asked to do.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/Error.h"
#include "render/graph/FrameGraph.h"
#include "render/graph/ResourcePool.h"

using namespace specula;
using namespace specula::render;

namespace {

/// Physical textures are integers from a pool: object n is the n-th one created.
class RecordingBackend : public GraphBackend {
public:
    RecordingBackend()
        : pool([this](const GraphTextureDesc&, const std::string&) { return ++made; },
               [this](int& object) { destroyedObjects.push_back(object); })
    {
    }
    int acquireTexture(const GraphTextureDesc& desc, const std::string& name) override
    {
        const int slot = pool.acquire(desc, name);
        log.push_back("acquire " + name + " #" + std::to_string(pool.get(slot)));
        return slot;
    }
    void releaseTexture(int slot) override
    {
        log.push_back("release #" + std::to_string(pool.get(slot)));
        pool.release(slot);
    }
    void barrier(uint32_t bits) override { log.push_back("barrier " + std::to_string(bits)); }
    void runPass(const std::string& name, const std::function<void()>& body) override
    {
        log.push_back("run " + name);
        body();
    }
    int object(const FrameGraph& graph, GraphTexture t) const { return pool.get(graph.physical(t)); }

    int made = 0;
    std::vector<int> destroyedObjects;
    ResourcePool<GraphTextureDesc, int> pool;
    std::vector<std::string> log;
};

GraphTextureDesc size(int w, int h, gl::Format format = gl::Format::RGBA16F)
{
    GraphTextureDesc d;
    d.width = w;
    d.height = h;
    d.format = format;
    return d;
}

std::vector<std::string> names(const FrameGraph& g)
{
    std::vector<std::string> out;
    for (uint32_t p : g.order()) out.push_back(g.passName(p));
    return out;
}

/// A chain like the frame's: a → (x) → b → (y) → c → imported output; `d` writes z that
/// nobody reads.
struct Chain {
    FrameGraph graph;
    GraphTexture x, y, z, output;
    std::vector<std::string> ran;
    explicit Chain(bool exportZ = false)
    {
        output = graph.importTexture("output", size(8, 8, gl::Format::SRGB8_ALPHA8), 7);
        graph.addPass("a", [&](FrameGraph::Builder& b) { x = b.write(b.create("x", size(8, 8)), Use::ColorAttachment); },
                      [this] { ran.push_back("a"); });
        graph.addPass("d", [&](FrameGraph::Builder& b) { z = b.write(b.create("z", size(8, 8)), Use::ImageStore); },
                      [this] { ran.push_back("d"); });
        graph.addPass(
            "b",
            [&](FrameGraph::Builder& b) {
                b.read(x, Use::Sample);
                y = b.write(b.create("y", size(8, 8)), Use::ImageStore);
            },
            [this] { ran.push_back("b"); });
        graph.addPass(
            "c",
            [&](FrameGraph::Builder& b) {
                b.read(y, Use::Sample);
                b.write(output, Use::ColorAttachment);
            },
            [this] { ran.push_back("c"); });
        if (exportZ) graph.exportTexture(z);
    }
};

} // namespace

TEST(FrameGraph, CullsPassesWhoseResultsNobodyReads)
{
    Chain chain;
    chain.graph.compile();
    EXPECT_EQ(names(chain.graph), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_TRUE(chain.graph.culled(1)); // d
    RecordingBackend backend;
    chain.graph.execute(backend);
    EXPECT_EQ(chain.ran, (std::vector<std::string>{"a", "b", "c"}));
    // z is never allocated: a culled pass costs nothing.
    for (const std::string& line : backend.log) EXPECT_EQ(line.find("acquire z"), std::string::npos) << line;
}

TEST(FrameGraph, KeepsPassesWithSideEffectsAndExportedResults)
{
    Chain exported(/*exportZ*/ true);
    exported.graph.compile();
    EXPECT_FALSE(exported.graph.culled(1));
    EXPECT_EQ(names(exported.graph), (std::vector<std::string>{"a", "d", "b", "c"}));

    FrameGraph g;
    bool ran = false;
    g.addPass("query", [](FrameGraph::Builder& b) { b.sideEffect(); }, [&] { ran = true; });
    RecordingBackend backend;
    g.execute(backend);
    EXPECT_TRUE(ran);
}

TEST(FrameGraph, TransientLifetimesSpanFirstToLastUse)
{
    Chain chain;
    RecordingBackend backend;
    chain.graph.execute(backend);
    // x lives from a to b, y from b to c; the output is imported and never acquired. c samples
    // what b stored: a texture-fetch barrier between them.
    EXPECT_EQ(backend.log, (std::vector<std::string>{"acquire x #1", "run a", "acquire y #2", "run b", "release #1",
                                                     "barrier 1", "run c", "release #2"}));
}

TEST(FrameGraph, ReusesTexturesWithinAFrameAndAcrossFrames)
{
    RecordingBackend backend;
    // Within a frame: t1 dies after p2, t2 (same descriptor) is born in p3: the same texture.
    auto build = [](FrameGraph& g, GraphTexture& t1, GraphTexture& t2) {
        const GraphTexture out = g.importTexture("out", size(4, 4), 0);
        g.addPass("p1", [&](FrameGraph::Builder& b) { t1 = b.write(b.create("t1", size(4, 4)), Use::ColorAttachment); }, [] {});
        g.addPass("p2", [&](FrameGraph::Builder& b) {
            b.read(t1, Use::Sample);
            b.write(out, Use::ColorAttachment);
        }, [] {});
        g.addPass("p3", [&](FrameGraph::Builder& b) { t2 = b.write(b.create("t2", size(4, 4)), Use::ColorAttachment); }, [] {});
        g.addPass("p4", [&](FrameGraph::Builder& b) {
            b.read(t2, Use::Sample);
            b.write(out, Use::ColorAttachment);
        }, [] {});
    };
    for (int frame = 0; frame < 3; ++frame) {
        FrameGraph g;
        GraphTexture t1, t2;
        build(g, t1, t2);
        g.execute(backend);
        backend.pool.endFrame();
    }
    EXPECT_EQ(backend.made, 1) << "one texture serves both resources in every frame";
    EXPECT_EQ(backend.pool.live(), 1u);

    // A different size is a different descriptor: a new texture, and the old one goes once it
    // has been idle for more than kMaxIdleFrames frames.
    for (int frame = 0; frame < 4; ++frame) {
        FrameGraph g;
        const GraphTexture out = g.importTexture("out", size(4, 4), 0);
        g.addPass("big", [&](FrameGraph::Builder& b) {
            b.write(b.create("big", size(16, 16)), Use::ColorAttachment);
            b.write(out, Use::ColorAttachment);
        }, [] {});
        g.execute(backend);
        backend.pool.endFrame();
    }
    EXPECT_EQ(backend.made, 2);
    EXPECT_EQ(backend.destroyedObjects, (std::vector<int>{1}));
    EXPECT_EQ(backend.pool.live(), 1u);
}

TEST(FrameGraph, ExportedTexturesOutliveTheFrameUntilReleased)
{
    RecordingBackend backend;
    FrameGraph g;
    GraphTexture kept;
    g.addPass("p", [&](FrameGraph::Builder& b) { kept = b.write(b.create("kept", size(2, 2)), Use::ImageStore); }, [] {});
    g.exportTexture(kept);
    g.execute(backend);
    EXPECT_EQ(backend.pool.inUse(), 1u) << "readable after the frame";
    EXPECT_EQ(backend.object(g, kept), 1);
    // An image store read back after the frame needs the read-back barriers.
    EXPECT_EQ(g.finalBarriers(), kBarrierTextureUpdate | kBarrierFramebuffer | kBarrierTextureFetch);
    g.releaseExported(backend);
    EXPECT_EQ(backend.pool.inUse(), 0u);
}

TEST(FrameGraph, PlacesBarriersOnlyAfterIncoherentWrites)
{
    FrameGraph g;
    const GraphTexture out = g.importTexture("out", size(4, 4), 0);
    const GraphBuffer state = g.importBuffer("state", 0);
    GraphTexture rendered, stored;
    g.addPass("render", [&](FrameGraph::Builder& b) { rendered = b.write(b.create("rendered", size(4, 4)), Use::ColorAttachment); }, [] {});
    g.addPass("compute", [&](FrameGraph::Builder& b) {
        b.read(rendered, Use::Sample); // rendering is coherent with later sampling: no barrier
        stored = b.write(b.create("stored", size(4, 4)), Use::ImageStore);
        b.write(state, Use::StorageWrite);
    }, [] {});
    g.addPass("in place", [&](FrameGraph::Builder& b) { b.write(stored, Use::ImageReadWrite); }, [] {});
    g.addPass("draw", [&](FrameGraph::Builder& b) {
        b.read(stored, Use::Sample);
        b.read(state, Use::StorageRead);
        b.write(out, Use::ColorAttachment);
    }, [] {});
    g.compile();
    EXPECT_EQ(g.barriersBefore(0), 0u);
    EXPECT_EQ(g.barriersBefore(1), 0u);
    EXPECT_EQ(g.barriersBefore(2), uint32_t(kBarrierImage)) << "image store, then image load/store";
    EXPECT_EQ(g.barriersBefore(3), uint32_t(kBarrierTextureFetch | kBarrierStorage));
    // The imported buffer outlives the frame: it may be read back (the stored texture may not).
    EXPECT_EQ(g.finalBarriers(), uint32_t(kBarrierBufferUpdate));
}

TEST(FrameGraph, ReadersRunAfterAllWriters)
{
    // Declared out of order: the reader first. A read-modify-write pass (bloom on the frame)
    // runs after the first writer and before the reader.
    FrameGraph g;
    const GraphTexture out = g.importTexture("out", size(4, 4), 0);
    GraphTexture frame;
    g.addPass("forward", [&](FrameGraph::Builder& b) { frame = b.write(b.create("frame", size(4, 4)), Use::ColorAttachment); }, [] {});
    g.addPass("tonemap", [&](FrameGraph::Builder& b) {
        b.read(frame, Use::Sample);
        b.write(out, Use::ColorAttachment);
    }, [] {});
    g.addPass("bloom", [&](FrameGraph::Builder& b) { b.write(frame, Use::ImageReadWrite); }, [] {});
    g.compile();
    EXPECT_EQ(names(g), (std::vector<std::string>{"forward", "bloom", "tonemap"}));
}

TEST(FrameGraph, AReadOfANeverWrittenResourceIsAnError)
{
    FrameGraph g;
    const GraphTexture out = g.importTexture("out", size(4, 4), 0);
    g.addPass("lonely", [&](FrameGraph::Builder& b) {
        b.read(b.create("ghost", size(4, 4)), Use::Sample);
        b.write(out, Use::ColorAttachment);
    }, [] {});
    try {
        g.compile();
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "frame graph: pass 'lonely' reads 'ghost', which no pass writes");
    }
}

TEST(FrameGraph, ACycleIsAnErrorNamingItsPasses)
{
    FrameGraph g;
    const GraphTexture out = g.importTexture("out", size(4, 4), 0);
    GraphTexture x, y;
    // a writes x and reads y; b writes y and reads x: neither can go first.
    g.addPass("a", [&](FrameGraph::Builder& b) {
        x = b.create("x", size(4, 4));
        y = b.create("y", size(4, 4));
        b.write(x, Use::ColorAttachment);
        b.read(y, Use::Sample);
        b.write(out, Use::ColorAttachment);
    }, [] {});
    g.addPass("b", [&](FrameGraph::Builder& b) {
        b.read(x, Use::Sample);
        b.write(y, Use::ImageStore);
    }, [] {});
    try {
        g.compile();
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "frame graph: a cycle of passes: 'a' → 'b' → 'a'");
    }
}

TEST(FrameGraph, DotShowsPassesResourcesAndCulling)
{
    Chain chain;
    chain.graph.compile();
    const std::string dot = chain.graph.toDot();
    EXPECT_NE(dot.find("digraph frame"), std::string::npos);
    EXPECT_NE(dot.find("label=\"d (culled)\""), std::string::npos);
    EXPECT_NE(dot.find("label=\"x\\n8×8\""), std::string::npos);
}
