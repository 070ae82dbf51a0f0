#pragma once
// The frame graph's GL side: transient textures from a pool (the only place that deletes them,
// telling gl::State and the framebuffer cache to forget their names first), framebuffers made
// from a pass's attachments and cached, memory barriers, and each pass in a debug group and,
// when timing, a GPU timer query (and a wall clock with glFinish on both sides).
//
// Pass bodies reach their resources through it: texture(handle), buffer(handle),
// framebuffer({colours}, depth).
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/Texture.h"
#include "render/graph/FrameGraph.h"
#include "render/graph/ResourcePool.h"

namespace specula::gl {
class Buffer;
class Framebuffer;
class State;
class TimerQuery;
} // namespace specula::gl

namespace specula::render {

/// One timed pass of the last frame (FrameStats::passes).
struct GraphPassTiming {
    const char* name; ///< the pass's name, valid for the backend's lifetime
    gl::TimerQuery* timer = nullptr;
    double wallMs = 0.0;
};

class GlGraphBackend : public GraphBackend {
public:
    explicit GlGraphBackend(gl::State& state);
    ~GlGraphBackend() override;
    GlGraphBackend(const GlGraphBackend&) = delete;
    GlGraphBackend& operator=(const GlGraphBackend&) = delete;

    /// Starts running `graph` (built, with its imports registered): forgets last frame's timings.
    void beginFrame(const FrameGraph& graph);
    /// Ends it: forgets the imports; the pool destroys what has been idle too long.
    void endFrame();

    /// Physical ids of objects owned elsewhere, for FrameGraph::importTexture/importBuffer;
    /// valid until endFrame.
    int importTexture(gl::Texture& texture);
    int importBuffer(const gl::Buffer& buffer);

    gl::Texture& texture(GraphTexture handle) const;
    const gl::Buffer& buffer(GraphBuffer handle) const;
    /// A framebuffer with these attachments (level 0), made on first use and kept while they
    /// live. Attachments must be the graph's textures (pool or imported).
    gl::Framebuffer& framebuffer(std::initializer_list<GraphTexture> colors, GraphTexture depth = {});
    /// The same for textures outside a frame (the pool's, read after a frame).
    gl::Framebuffer& framebufferOf(const std::vector<gl::Texture*>& colors, gl::Texture* depth = nullptr);
    gl::State& state() const { return mState; }

    /// A texture from the pool outside any graph (a read-back's resolve target); give it back
    /// with releasePooled.
    int acquirePooled(const GraphTextureDesc& desc, const std::string& name) { return acquireTexture(desc, name); }
    gl::Texture& pooled(int physical) const { return *resolve(physical); }
    void releasePooled(int physical) { releaseTexture(physical); }

    /// Timing: a GL_TIME_ELAPSED query around each pass, and with `wallClock` a glFinish on
    /// both sides and the wall time between them.
    void setTiming(bool timing, bool wallClock);
    const std::vector<GraphPassTiming>& timings() const { return mTimed; }

    size_t liveTextures() const { return mPool.live(); }

    int acquireTexture(const GraphTextureDesc& desc, const std::string& name) override;
    void releaseTexture(int physical) override;
    void barrier(uint32_t graphBarriers) override;
    void runPass(const std::string& name, const std::function<void()>& body) override;

private:
    gl::Texture* resolve(int physical) const;
    void forget(gl::Texture& texture);

    gl::State& mState;
    const FrameGraph* mGraph = nullptr;
    ResourcePool<GraphTextureDesc, gl::Texture> mPool;
    std::vector<gl::Texture*> mImportedTextures;
    std::vector<const gl::Buffer*> mImportedBuffers;
    struct CachedFramebuffer;
    std::vector<std::unique_ptr<CachedFramebuffer>> mFramebuffers;
    bool mTiming = false, mWallClock = false;
    std::map<std::string, std::unique_ptr<gl::TimerQuery>> mTimers;
    std::vector<GraphPassTiming> mTimed;
};

} // namespace specula::render
