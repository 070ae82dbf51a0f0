#pragma once
// Transient objects kept across frames and handed out by descriptor: the frame graph's
// backend acquires one for a resource's lifetime and releases it after; an object released
// and asked for again with an equal descriptor (later in the frame, or next frame) is the same
// object, so nothing is created in a frame like the last. Objects idle for more than
// kMaxIdleFrames frames are destroyed: a pass switched off stops costing memory soon after.
// The pool is the only place that destroys them; `destroy` lets the owner forget the object
// (a binding cache, framebuffers made on it) before it goes. No GL here: tests use integers.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace specula::render {

template <typename Desc, typename Object>
class ResourcePool {
public:
    static constexpr uint64_t kMaxIdleFrames = 2;
    using Create = std::function<Object(const Desc&, const std::string& name)>;
    using Destroy = std::function<void(Object&)>;

    ResourcePool(Create create, Destroy destroy) : mCreate(std::move(create)), mDestroy(std::move(destroy)) {}
    ~ResourcePool() { clear(); }
    ResourcePool(const ResourcePool&) = delete;
    ResourcePool& operator=(const ResourcePool&) = delete;

    /// A free object with an equal descriptor (the most recently released), else a new one.
    int acquire(const Desc& desc, const std::string& name)
    {
        int best = -1;
        for (size_t i = 0; i < mEntries.size(); ++i) {
            const Entry& e = mEntries[i];
            if (!e.alive || e.inUse || !(e.desc == desc)) continue;
            if (best < 0 || e.releasedAt > mEntries[size_t(best)].releasedAt) best = int(i);
        }
        if (best < 0) {
            Entry e{desc, mCreate(desc, name), true, false, 0, 0};
            ++mCreated;
            for (size_t i = 0; i < mEntries.size(); ++i)
                if (!mEntries[i].alive) {
                    mEntries[i] = std::move(e);
                    best = int(i);
                    break;
                }
            if (best < 0) {
                mEntries.push_back(std::move(e));
                best = int(mEntries.size() - 1);
            }
        }
        Entry& e = mEntries[size_t(best)];
        e.inUse = true;
        e.lastUsedFrame = mFrame;
        return best;
    }

    void release(int slot)
    {
        Entry& e = mEntries.at(size_t(slot));
        e.inUse = false;
        e.lastUsedFrame = mFrame;
        e.releasedAt = ++mReleases;
    }

    Object& get(int slot) { return mEntries.at(size_t(slot)).object; }
    const Object& get(int slot) const { return mEntries.at(size_t(slot)).object; }

    /// Ends a frame: destroys the free objects no frame has used for kMaxIdleFrames frames.
    void endFrame()
    {
        ++mFrame;
        for (Entry& e : mEntries)
            if (e.alive && !e.inUse && mFrame - e.lastUsedFrame > kMaxIdleFrames) destroy(e);
    }

    /// Destroys every object (in use or not).
    void clear()
    {
        for (Entry& e : mEntries)
            if (e.alive) destroy(e);
        mEntries.clear();
    }

    size_t live() const
    {
        size_t n = 0;
        for (const Entry& e : mEntries) n += e.alive ? 1 : 0;
        return n;
    }
    size_t inUse() const
    {
        size_t n = 0;
        for (const Entry& e : mEntries) n += e.alive && e.inUse ? 1 : 0;
        return n;
    }
    /// Objects created and destroyed since the pool was made.
    size_t created() const { return mCreated; }
    size_t destroyed() const { return mDestroyed; }

private:
    struct Entry {
        Desc desc;
        Object object;
        bool alive = false;
        bool inUse = false;
        uint64_t lastUsedFrame = 0;
        uint64_t releasedAt = 0;
    };
    void destroy(Entry& e)
    {
        if (mDestroy) mDestroy(e.object);
        e.object = Object();
        e.alive = false;
        e.inUse = false;
        ++mDestroyed;
    }

    Create mCreate;
    Destroy mDestroy;
    std::vector<Entry> mEntries;
    uint64_t mFrame = 0;
    uint64_t mReleases = 0;
    size_t mCreated = 0;
    size_t mDestroyed = 0;
};

} // namespace specula::render
