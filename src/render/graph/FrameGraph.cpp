#include "render/graph/FrameGraph.h"

#include <algorithm>
#include <queue>

#include "core/Error.h"

namespace specula::render {

bool isWrite(Use use)
{
    return use >= Use::ColorAttachment;
}

bool isRead(Use use)
{
    return use < Use::ColorAttachment || use == Use::ImageReadWrite || use == Use::StorageWrite;
}

namespace {

/// Writes that later commands do not see without a barrier (shader image and buffer stores).
bool incoherentWrite(Use use)
{
    return use == Use::ImageStore || use == Use::ImageReadWrite || use == Use::StorageWrite;
}

/// The barrier that makes an incoherent write visible to a later `use`.
uint32_t barrierFor(Use use)
{
    switch (use) {
    case Use::Sample: return kBarrierTextureFetch;
    case Use::ImageLoad:
    case Use::ImageStore:
    case Use::ImageReadWrite: return kBarrierImage;
    case Use::StorageRead:
    case Use::StorageWrite: return kBarrierStorage;
    case Use::UniformRead: return kBarrierUniform;
    case Use::BlitSource:
    case Use::BlitTarget:
    case Use::ColorAttachment:
    case Use::DepthAttachment: return kBarrierFramebuffer;
    }
    return 0;
}

const char* useName(Use use)
{
    switch (use) {
    case Use::Sample: return "sample";
    case Use::ImageLoad: return "image load";
    case Use::StorageRead: return "storage read";
    case Use::UniformRead: return "uniform";
    case Use::BlitSource: return "blit source";
    case Use::ColorAttachment: return "colour";
    case Use::DepthAttachment: return "depth";
    case Use::BlitTarget: return "blit target";
    case Use::ImageStore: return "image store";
    case Use::ImageReadWrite: return "image read-write";
    case Use::StorageWrite: return "storage write";
    }
    return "?";
}

} // namespace

void FrameGraph::Builder::access(ResourceKind kind, uint32_t id, Use use)
{
    if (id >= mGraph.mResources.size() || mGraph.mResources[id].kind != kind)
        throw Error("frame graph: pass '{}' uses a resource that is not in this graph", mGraph.mPasses[mPass].name);
    mGraph.mPasses[mPass].accesses.push_back({kind, id, use});
}

GraphTexture FrameGraph::Builder::create(const std::string& name, const GraphTextureDesc& desc)
{
    return mGraph.createTexture(name, desc);
}

GraphTexture FrameGraph::createTexture(const std::string& name, const GraphTextureDesc& desc)
{
    Resource r;
    r.name = name;
    r.kind = ResourceKind::Texture;
    r.desc = desc;
    mResources.push_back(std::move(r));
    return {uint32_t(mResources.size() - 1)};
}

void FrameGraph::Builder::checkedAccess(ResourceKind kind, uint32_t id, Use use, bool write)
{
    if (write && !isWrite(use))
        throw Error("frame graph: pass '{}' writes with a read use ({})", mGraph.mPasses[mPass].name, useName(use));
    if (!write && (!isRead(use) || isWrite(use)))
        throw Error("frame graph: pass '{}' reads with a write use ({})", mGraph.mPasses[mPass].name, useName(use));
    access(kind, id, use);
}

GraphTexture FrameGraph::Builder::read(GraphTexture texture, Use use)
{
    checkedAccess(ResourceKind::Texture, texture.id, use, false);
    return texture;
}

GraphTexture FrameGraph::Builder::write(GraphTexture texture, Use use)
{
    checkedAccess(ResourceKind::Texture, texture.id, use, true);
    return texture;
}

GraphBuffer FrameGraph::Builder::read(GraphBuffer buffer, Use use)
{
    checkedAccess(ResourceKind::Buffer, buffer.id, use, false);
    return buffer;
}

GraphBuffer FrameGraph::Builder::write(GraphBuffer buffer, Use use)
{
    checkedAccess(ResourceKind::Buffer, buffer.id, use, true);
    return buffer;
}

void FrameGraph::Builder::sideEffect()
{
    mGraph.mPasses[mPass].sideEffect = true;
}

void FrameGraph::addPass(const std::string& name, const std::function<void(Builder&)>& setup, std::function<void()> execute)
{
    mCompiled = false;
    mPasses.push_back({});
    mPasses.back().name = name;
    mPasses.back().execute = std::move(execute);
    Builder builder(*this, uint32_t(mPasses.size() - 1));
    setup(builder);
}

GraphTexture FrameGraph::importTexture(const std::string& name, const GraphTextureDesc& desc, int physical)
{
    Resource r;
    r.name = name;
    r.kind = ResourceKind::Texture;
    r.desc = desc;
    r.imported = true;
    r.physical = physical;
    mResources.push_back(std::move(r));
    return {uint32_t(mResources.size() - 1)};
}

GraphBuffer FrameGraph::importBuffer(const std::string& name, int physical)
{
    Resource r;
    r.name = name;
    r.kind = ResourceKind::Buffer;
    r.imported = true;
    r.physical = physical;
    mResources.push_back(std::move(r));
    return {uint32_t(mResources.size() - 1)};
}

void FrameGraph::exportTexture(GraphTexture texture)
{
    mResources.at(texture.id).exported = true;
}

void FrameGraph::compile()
{
    const size_t passCount = mPasses.size(), resourceCount = mResources.size();
    // Every read needs a writer (or an imported object) to read from.
    std::vector<std::vector<uint32_t>> writers(resourceCount), readers(resourceCount);
    for (uint32_t p = 0; p < passCount; ++p) {
        for (const Access& a : mPasses[p].accesses) {
            auto& list = isWrite(a.use) ? writers[a.id] : readers[a.id];
            if (list.empty() || list.back() != p) list.push_back(p);
            if (isWrite(a.use) && isRead(a.use) && (readers[a.id].empty() || readers[a.id].back() != p))
                readers[a.id].push_back(p);
        }
    }
    for (uint32_t p = 0; p < passCount; ++p)
        for (const Access& a : mPasses[p].accesses) {
            if (!isRead(a.use) || mResources[a.id].imported) continue;
            const auto& w = writers[a.id];
            if (w.empty() || (w.size() == 1 && w[0] == p))
                throw Error("frame graph: pass '{}' reads '{}', which no pass writes", mPasses[p].name, mResources[a.id].name);
        }

    // Culling: keep what has an effect outside the graph, then what kept passes read.
    std::vector<char> kept(passCount, 0);
    std::vector<uint32_t> work;
    for (uint32_t p = 0; p < passCount; ++p) {
        bool needed = mPasses[p].sideEffect;
        for (const Access& a : mPasses[p].accesses)
            if (isWrite(a.use) && (mResources[a.id].imported || mResources[a.id].exported)) needed = true;
        if (needed) {
            kept[p] = 1;
            work.push_back(p);
        }
    }
    while (!work.empty()) {
        const uint32_t p = work.back();
        work.pop_back();
        for (const Access& a : mPasses[p].accesses) {
            if (!isRead(a.use)) continue;
            for (uint32_t w : writers[a.id])
                if (!kept[w]) {
                    kept[w] = 1;
                    work.push_back(w);
                }
        }
    }
    for (uint32_t p = 0; p < passCount; ++p) mPasses[p].culled = !kept[p];

    // Order: writers of a resource in the order added, its readers after all its writers.
    std::vector<std::vector<uint32_t>> next(passCount);
    std::vector<int> incoming(passCount, 0);
    auto edge = [&](uint32_t from, uint32_t to) {
        if (from == to || !kept[from] || !kept[to]) return;
        if (std::find(next[from].begin(), next[from].end(), to) != next[from].end()) return;
        next[from].push_back(to);
        ++incoming[to];
    };
    for (size_t r = 0; r < resourceCount; ++r) {
        for (size_t i = 1; i < writers[r].size(); ++i) edge(writers[r][i - 1], writers[r][i]);
        for (uint32_t w : writers[r])
            for (uint32_t reader : readers[r]) edge(w, reader);
    }
    mOrder.clear();
    std::priority_queue<uint32_t, std::vector<uint32_t>, std::greater<>> ready;
    for (uint32_t p = 0; p < passCount; ++p)
        if (kept[p] && incoming[p] == 0) ready.push(p);
    while (!ready.empty()) {
        const uint32_t p = ready.top();
        ready.pop();
        mOrder.push_back(p);
        for (uint32_t n : next[p])
            if (--incoming[n] == 0) ready.push(n);
    }
    const size_t keptCount = size_t(std::count(kept.begin(), kept.end(), 1));
    if (mOrder.size() != keptCount) {
        // Name the passes of one cycle: follow edges among the unordered passes until one repeats.
        std::vector<char> left(passCount, 0);
        for (uint32_t p = 0; p < passCount; ++p) left[p] = kept[p] && incoming[p] > 0;
        uint32_t at = uint32_t(std::find(left.begin(), left.end(), 1) - left.begin());
        std::vector<uint32_t> path;
        while (std::find(path.begin(), path.end(), at) == path.end()) {
            path.push_back(at);
            for (uint32_t n : next[at])
                if (left[n]) {
                    at = n;
                    break;
                }
        }
        std::string cycle;
        for (auto it = std::find(path.begin(), path.end(), at); it != path.end(); ++it) cycle += "'" + mPasses[*it].name + "' → ";
        throw Error("frame graph: a cycle of passes: {}'{}'", cycle, mPasses[at].name);
    }

    // Lifetimes of transient textures, and barriers after incoherent writes.
    for (Pass& p : mPasses) {
        p.acquire.clear();
        p.release.clear();
        p.barriers = 0;
    }
    std::vector<int> first(resourceCount, -1), last(resourceCount, -1);
    for (size_t i = 0; i < mOrder.size(); ++i)
        for (const Access& a : mPasses[mOrder[i]].accesses) {
            if (first[a.id] < 0) first[a.id] = int(i);
            last[a.id] = int(i);
        }
    for (size_t r = 0; r < resourceCount; ++r) {
        const Resource& res = mResources[r];
        if (res.imported || res.kind != ResourceKind::Texture || first[r] < 0) continue;
        mPasses[mOrder[size_t(first[r])]].acquire.push_back(uint32_t(r));
        if (!res.exported) mPasses[mOrder[size_t(last[r])]].release.push_back(uint32_t(r));
    }
    // A barrier bit, once issued, covers every earlier write: track per resource which bits it
    // still needs since its last incoherent write.
    std::vector<char> pending(resourceCount, 0);
    std::vector<uint32_t> covered(resourceCount, 0);
    for (uint32_t p : mOrder) {
        uint32_t bits = 0;
        for (const Access& a : mPasses[p].accesses)
            if (pending[a.id]) bits |= barrierFor(a.use) & ~covered[a.id];
        mPasses[p].barriers = bits;
        for (size_t r = 0; r < resourceCount; ++r)
            if (pending[r]) covered[r] |= bits;
        for (const Access& a : mPasses[p].accesses)
            if (incoherentWrite(a.use)) {
                pending[a.id] = 1;
                covered[a.id] = 0;
            }
    }
    mFinalBarriers = 0;
    // What outlives the frame (exported and imported resources) may be read back, blitted or
    // read by the next frame.
    for (size_t r = 0; r < resourceCount; ++r)
        if ((mResources[r].exported || mResources[r].imported) && pending[r]) {
            const uint32_t readBack = mResources[r].kind == ResourceKind::Texture
                                          ? kBarrierTextureUpdate | kBarrierFramebuffer | kBarrierTextureFetch
                                          : kBarrierBufferUpdate | kBarrierStorage;
            mFinalBarriers |= readBack & ~covered[r];
        }
    mCompiled = true;
}

void FrameGraph::execute(GraphBackend& backend)
{
    if (!mCompiled) compile();
    for (uint32_t p : mOrder) {
        Pass& pass = mPasses[p];
        for (uint32_t r : pass.acquire) {
            mResources[r].physical = backend.acquireTexture(mResources[r].desc, mResources[r].name);
            mResources[r].acquired = true;
        }
        if (pass.barriers) backend.barrier(pass.barriers);
        backend.runPass(pass.name, pass.execute);
        for (uint32_t r : pass.release) {
            backend.releaseTexture(mResources[r].physical);
            mResources[r].acquired = false;
        }
    }
    if (mFinalBarriers) backend.barrier(mFinalBarriers);
}

void FrameGraph::releaseExported(GraphBackend& backend)
{
    for (Resource& r : mResources)
        if (r.acquired) {
            backend.releaseTexture(r.physical);
            r.acquired = false;
        }
}

int FrameGraph::physical(GraphTexture texture) const
{
    return mResources.at(texture.id).physical;
}

int FrameGraph::physical(GraphBuffer buffer) const
{
    return mResources.at(buffer.id).physical;
}

const GraphTextureDesc& FrameGraph::desc(GraphTexture texture) const
{
    return mResources.at(texture.id).desc;
}

std::string FrameGraph::toDot() const
{
    std::string out = "digraph frame {\n  rankdir=LR;\n  node [fontname=\"sans-serif\", fontsize=10];\n";
    for (size_t p = 0; p < mPasses.size(); ++p) {
        const bool culled = mPasses[p].culled;
        std::string barriers;
        const uint32_t bits = mPasses[p].barriers;
        const std::pair<uint32_t, const char*> names[] = {
            {kBarrierTextureFetch, "fetch"},   {kBarrierImage, "image"},         {kBarrierStorage, "storage"},
            {kBarrierTextureUpdate, "update"}, {kBarrierBufferUpdate, "buffer"}, {kBarrierFramebuffer, "framebuffer"},
            {kBarrierUniform, "uniform"}};
        for (const auto& [bit, name] : names)
            if (bits & bit) barriers += std::string(barriers.empty() ? "\\nbarrier: " : ", ") + name;
        out += "  p" + std::to_string(p) + " [shape=box, style=\"rounded,filled\", fillcolor=\"" +
               (culled ? "#dddddd" : "#ffd9a8") + "\", label=\"" + mPasses[p].name + (culled ? " (culled)" : "") + barriers +
               "\"];\n";
    }
    for (size_t r = 0; r < mResources.size(); ++r) {
        const Resource& res = mResources[r];
        out += "  r" + std::to_string(r) + " [shape=ellipse, style=filled, fillcolor=\"" +
               (res.imported ? "#c8e6c9" : res.exported ? "#bbdefb" : "#eeeeee") + "\", label=\"" + res.name;
        if (res.kind == ResourceKind::Texture && !res.imported)
            out += "\\n" + std::to_string(res.desc.width) + "×" + std::to_string(res.desc.height) +
                   (res.desc.samples > 1 ? " ×" + std::to_string(res.desc.samples) : "");
        out += "\"];\n";
    }
    for (size_t p = 0; p < mPasses.size(); ++p)
        for (const Access& a : mPasses[p].accesses) {
            const std::string pass = "p" + std::to_string(p), resource = "r" + std::to_string(a.id);
            const std::string label = std::string(" [label=\"") + useName(a.use) + "\", fontsize=8]";
            if (isRead(a.use)) out += "  " + resource + " -> " + pass + label + ";\n";
            if (isWrite(a.use)) out += "  " + pass + " -> " + resource + label + ";\n";
        }
    out += "}\n";
    return out;
}

} // namespace specula::render
