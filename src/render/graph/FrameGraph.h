#pragma once
// The frame as a graph of passes (after Filament's filament/src/fg/FrameGraph.h, much smaller).
//
// A frame is built anew each time: passes are added with a setup step, which declares the
// resources the pass creates, reads and writes, and an execute step. compile() then
//   - checks the graph: a read of a resource nobody writes, or a cycle, is an Error naming them;
//   - culls every pass whose results nobody reads (a pass is needed when it has a side effect,
//     writes an imported or exported resource, or writes what a needed pass reads);
//   - orders the passes: a resource's readers after all of its writers, its writers in the
//     order they were added, ties in the order passes were added (so a pipeline reads top down);
//   - finds each transient resource's lifetime, from the first pass that uses it to the last;
//   - places memory barriers: after a pass writes a resource incoherently (imageStore,
//     storage-buffer writes), the next pass that uses it gets the barrier for that use.
// execute() walks the passes through a GraphBackend, which owns the real objects: it acquires
// a transient resource before its first pass, releases it after its last (the pool reuses it,
// within the frame and across frames, by descriptor), issues the barriers, and wraps each pass
// (debug group, timer). Exported resources outlive the frame until releaseExported().
//
// This file knows no GL: the unit tests run it against a recording backend
// (tests/unit/test_frame_graph.cpp); render/graph/GlGraphBackend is the real one.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gl/Texture.h" // TextureType, Format: enums only, no GL

namespace specula::render {

/// What a transient texture is; two resources with equal descriptors may share one texture.
struct GraphTextureDesc {
    gl::TextureType type = gl::TextureType::Texture2D;
    gl::Format format = gl::Format::RGBA8;
    int width = 1;
    int height = 1;
    int layers = 1;
    int levels = 1;
    int samples = 1;
    bool operator==(const GraphTextureDesc&) const = default;
};

/// How a pass uses a resource. Reads come first; a write may also read (ImageReadWrite).
enum class Use : uint8_t {
    Sample,      ///< read: fetched or sampled by a shader
    ImageLoad,   ///< read: imageLoad
    StorageRead, ///< read: storage buffer
    UniformRead, ///< read: uniform buffer
    BlitSource,  ///< read: source of a blit or resolve
    ColorAttachment, ///< write: rendered into
    DepthAttachment, ///< write: depth-tested and written
    BlitTarget,      ///< write: target of a blit or resolve
    ImageStore,      ///< write: imageStore, not coherent with later reads
    ImageReadWrite,  ///< read and write: imageLoad and imageStore in place
    StorageWrite,    ///< write: storage buffer (may also read), not coherent with later reads
};
bool isWrite(Use use);
bool isRead(Use use);

/// The barriers a backend issues (glMemoryBarrier bits, gl::Barrier).
enum GraphBarrier : uint32_t {
    kBarrierTextureFetch = 1u << 0,
    kBarrierImage = 1u << 1,
    kBarrierStorage = 1u << 2,
    kBarrierTextureUpdate = 1u << 3,
    kBarrierBufferUpdate = 1u << 4,
    kBarrierFramebuffer = 1u << 5,
    kBarrierUniform = 1u << 6,
};

enum class ResourceKind : uint8_t { Texture, Buffer };

struct GraphTexture {
    uint32_t id = ~0u;
    explicit operator bool() const { return id != ~0u; }
};
struct GraphBuffer {
    uint32_t id = ~0u;
    explicit operator bool() const { return id != ~0u; }
};

/// The objects behind the graph's resources. Physical resources are plain integers the backend
/// hands out (a pool slot, an imported object's index): the graph never touches them.
class GraphBackend {
public:
    virtual ~GraphBackend() = default;
    virtual int acquireTexture(const GraphTextureDesc& desc, const std::string& name) = 0;
    virtual void releaseTexture(int physical) = 0;
    virtual void barrier(uint32_t graphBarriers) = 0;
    /// Runs one pass: `body` between whatever the backend wraps it in (debug group, timer).
    virtual void runPass(const std::string& name, const std::function<void()>& body) = 0;
};

class FrameGraph {
public:
    class Builder {
    public:
        /// A transient texture, allocated from the backend's pool for the passes that use it.
        GraphTexture create(const std::string& name, const GraphTextureDesc& desc);
        GraphTexture read(GraphTexture texture, Use use);
        GraphTexture write(GraphTexture texture, Use use);
        GraphBuffer read(GraphBuffer buffer, Use use);
        GraphBuffer write(GraphBuffer buffer, Use use);
        /// The pass is kept even when nobody reads what it writes.
        void sideEffect();

    private:
        friend class FrameGraph;
        Builder(FrameGraph& graph, uint32_t pass) : mGraph(graph), mPass(pass) {}
        void access(ResourceKind kind, uint32_t id, Use use);
        void checkedAccess(ResourceKind kind, uint32_t id, Use use, bool write);
        FrameGraph& mGraph;
        uint32_t mPass;
    };

    /// Adds a pass; `setup` runs now, `execute` (if the pass survives culling) in execute().
    void addPass(const std::string& name, const std::function<void(Builder&)>& setup, std::function<void()> execute);

    /// A transient texture (as Builder::create), declared outside any pass: for a resource that
    /// several passes write, whichever of them a pipeline adds.
    GraphTexture createTexture(const std::string& name, const GraphTextureDesc& desc);

    /// An object that lives outside the graph (persistent targets, buffers): never allocated or
    /// released by the graph; writing one keeps the pass.
    GraphTexture importTexture(const std::string& name, const GraphTextureDesc& desc, int physical);
    GraphBuffer importBuffer(const std::string& name, int physical);
    /// The resource is read after the frame (read back, presented): its writers are kept, it is
    /// not released at the end of the frame, and it gets the barriers a read-back needs.
    void exportTexture(GraphTexture texture);

    /// Culls, orders, finds lifetimes and barriers. Throws specula::Error on a read of a resource
    /// nobody writes and on a cycle. Called by execute() if not called before.
    void compile();
    void execute(GraphBackend& backend);
    /// Gives the exported textures back to the backend's pool (before the next frame's execute).
    void releaseExported(GraphBackend& backend);

    /// The physical texture of `texture` while its passes run (and after, if exported).
    int physical(GraphTexture texture) const;
    const GraphTextureDesc& desc(GraphTexture texture) const;
    int physical(GraphBuffer buffer) const;

    // After compile(): what the graph decided, for tests, stats and --print-graph.
    /// Surviving passes in execution order (indices in the order added).
    const std::vector<uint32_t>& order() const { return mOrder; }
    bool culled(uint32_t pass) const { return mPasses[pass].culled; }
    const std::string& passName(uint32_t pass) const { return mPasses[pass].name; }
    /// Barrier bits issued before pass `pass` runs, and after the last pass (read-backs).
    uint32_t barriersBefore(uint32_t pass) const { return mPasses[pass].barriers; }
    uint32_t finalBarriers() const { return mFinalBarriers; }
    /// The graph in Graphviz dot: passes as boxes (culled ones grey), resources as ellipses.
    std::string toDot() const;

private:
    struct Access {
        ResourceKind kind;
        uint32_t id;
        Use use;
    };
    struct Pass {
        std::string name;
        std::vector<Access> accesses;
        bool sideEffect = false;
        std::function<void()> execute;
        bool culled = false;
        uint32_t barriers = 0;
        std::vector<uint32_t> acquire, release; // textures
    };
    struct Resource {
        std::string name;
        ResourceKind kind = ResourceKind::Texture;
        GraphTextureDesc desc;
        bool imported = false;
        bool exported = false;
        int physical = -1;
        bool acquired = false;
    };
    std::vector<Pass> mPasses;
    std::vector<Resource> mResources; // textures and buffers, GraphTexture/GraphBuffer ids index it
    std::vector<uint32_t> mOrder;
    uint32_t mFinalBarriers = 0;
    bool mCompiled = false;
};

} // namespace specula::render
