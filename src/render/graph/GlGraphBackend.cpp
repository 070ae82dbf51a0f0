#include "render/graph/GlGraphBackend.h"

#include <algorithm>

#include "core/Error.h"
#include "core/Timer.h"
#include "gl/Buffer.h"
#include "gl/Debug.h"
#include "gl/Framebuffer.h"
#include "gl/State.h"
#include "gl/TimerQuery.h"

namespace specula::render {
namespace {

/// Imported objects get negative physical ids: -2 - index (-1 is "none").
int importedId(size_t index)
{
    return -2 - int(index);
}

size_t importedIndex(int physical)
{
    return size_t(-2 - physical);
}

gl::Barrier glBarriers(uint32_t bits)
{
    uint32_t out = 0;
    if (bits & kBarrierTextureFetch) out |= uint32_t(gl::Barrier::TextureFetch);
    if (bits & kBarrierImage) out |= uint32_t(gl::Barrier::Image);
    if (bits & kBarrierStorage) out |= uint32_t(gl::Barrier::StorageBuffer);
    if (bits & kBarrierTextureUpdate) out |= uint32_t(gl::Barrier::TextureUpdate);
    if (bits & kBarrierBufferUpdate) out |= uint32_t(gl::Barrier::BufferUpdate);
    if (bits & kBarrierFramebuffer) out |= uint32_t(gl::Barrier::Framebuffer);
    if (bits & kBarrierUniform) out |= uint32_t(gl::Barrier::Uniform);
    return gl::Barrier(out);
}

} // namespace

struct GlGraphBackend::CachedFramebuffer {
    std::vector<uint32_t> key; // colour texture names, then the depth texture's (0 = none)
    gl::Framebuffer framebuffer;
};

GlGraphBackend::GlGraphBackend(gl::State& state)
    : mState(state),
      mPool(
          [](const GraphTextureDesc& d, const std::string& name) {
              gl::TextureDesc desc;
              desc.type = d.type;
              desc.format = d.format;
              desc.width = d.width;
              desc.height = d.height;
              desc.layers = d.layers;
              desc.levels = d.levels;
              desc.samples = d.samples;
              desc.label = name;
              return gl::Texture(desc);
          },
          [this](gl::Texture& texture) { forget(texture); })
{
}

GlGraphBackend::~GlGraphBackend()
{
    mPool.clear(); // while the framebuffer cache and the state it tells are still here
}

void GlGraphBackend::forget(gl::Texture& texture)
{
    const uint32_t name = texture.id();
    mState.forgetTexture(name);
    auto uses = [name](const std::unique_ptr<CachedFramebuffer>& f) {
        return std::find(f->key.begin(), f->key.end(), name) != f->key.end();
    };
    for (auto& f : mFramebuffers)
        if (uses(f)) mState.forgetFramebuffer(f->framebuffer.id());
    mFramebuffers.erase(std::remove_if(mFramebuffers.begin(), mFramebuffers.end(), uses), mFramebuffers.end());
}

void GlGraphBackend::beginFrame(const FrameGraph& graph)
{
    mGraph = &graph;
    mTimed.clear();
}

void GlGraphBackend::endFrame()
{
    // Imports are registered while a frame is built, before beginFrame: forget them after it.
    mImportedTextures.clear();
    mImportedBuffers.clear();
    mPool.endFrame();
}

int GlGraphBackend::importTexture(gl::Texture& texture)
{
    mImportedTextures.push_back(&texture);
    return importedId(mImportedTextures.size() - 1);
}

int GlGraphBackend::importBuffer(const gl::Buffer& buffer)
{
    mImportedBuffers.push_back(&buffer);
    return importedId(mImportedBuffers.size() - 1);
}

gl::Texture* GlGraphBackend::resolve(int physical) const
{
    if (physical >= 0) return const_cast<gl::Texture*>(&mPool.get(physical));
    if (physical == -1 || importedIndex(physical) >= mImportedTextures.size()) return nullptr;
    return mImportedTextures[importedIndex(physical)];
}

gl::Texture& GlGraphBackend::texture(GraphTexture handle) const
{
    gl::Texture* t = mGraph ? resolve(mGraph->physical(handle)) : nullptr;
    if (!t) throw Error("frame graph: texture used outside the passes that declared it");
    return *t;
}

const gl::Buffer& GlGraphBackend::buffer(GraphBuffer handle) const
{
    const int physical = mGraph ? mGraph->physical(handle) : -1;
    if (physical > -2 || importedIndex(physical) >= mImportedBuffers.size())
        throw Error("frame graph: buffer used outside the passes that declared it");
    return *mImportedBuffers[importedIndex(physical)];
}

gl::Framebuffer& GlGraphBackend::framebuffer(std::initializer_list<GraphTexture> colors, GraphTexture depth)
{
    std::vector<gl::Texture*> textures;
    for (GraphTexture c : colors) textures.push_back(&texture(c));
    return framebufferOf(textures, depth ? &texture(depth) : nullptr);
}

gl::Framebuffer& GlGraphBackend::framebufferOf(const std::vector<gl::Texture*>& colors, gl::Texture* depth)
{
    std::vector<uint32_t> key;
    for (const gl::Texture* c : colors) key.push_back(c->id());
    key.push_back(depth ? depth->id() : 0u);
    for (const auto& f : mFramebuffers)
        if (f->key == key) return f->framebuffer;
    auto cached = std::make_unique<CachedFramebuffer>();
    cached->key = key;
    std::string label;
    for (const gl::Texture* c : colors) label += (label.empty() ? "" : " + ") + c->desc().label;
    if (depth) label += (label.empty() ? "" : " + ") + depth->desc().label;
    cached->framebuffer = gl::Framebuffer(label);
    int index = 0;
    for (const gl::Texture* c : colors) cached->framebuffer.attachColor(index++, *c);
    if (depth) cached->framebuffer.attachDepth(*depth);
    cached->framebuffer.check();
    mFramebuffers.push_back(std::move(cached));
    return mFramebuffers.back()->framebuffer;
}

void GlGraphBackend::setTiming(bool timing, bool wallClock)
{
    mTiming = timing;
    mWallClock = wallClock;
}

int GlGraphBackend::acquireTexture(const GraphTextureDesc& desc, const std::string& name)
{
    return mPool.acquire(desc, name);
}

void GlGraphBackend::releaseTexture(int physical)
{
    mPool.release(physical);
}

void GlGraphBackend::barrier(uint32_t graphBarriers)
{
    gl::State::memoryBarrier(glBarriers(graphBarriers));
}

void GlGraphBackend::runPass(const std::string& name, const std::function<void()>& body)
{
    gl::DebugGroup group(name);
    gl::TimerQuery* timer = nullptr;
    Stopwatch wall;
    const char* timedName = nullptr;
    if (mTiming) {
        if (mWallClock) {
            gl::finish();
            wall.reset();
        }
        auto it = mTimers.try_emplace(name).first;
        if (!it->second) it->second = std::make_unique<gl::TimerQuery>();
        timer = it->second.get();
        timedName = it->first.c_str();
        timer->begin();
    }
    try {
        body();
    } catch (...) {
        // A program that fails to compile on first use: the query must not stay active into
        // the next frame (the debug group closes itself).
        if (timer) timer->end();
        throw;
    }
    if (timer) {
        timer->end();
        if (mWallClock) gl::finish();
        mTimed.push_back({timedName, timer, mWallClock ? wall.elapsedMs() : 0.0});
    }
}

} // namespace specula::render
