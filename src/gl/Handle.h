#pragma once
// Move-only ownership of one GL object name; a moved-from handle owns nothing.
#include <atomic>
#include <cstdint>
#include <utility>

namespace specula::gl {

template <void (*Delete)(uint32_t)>
class Handle {
public:
    Handle() = default;
    explicit Handle(uint32_t id) : mId(id)
    {
        if (mId) sLive.fetch_add(1, std::memory_order_relaxed);
    }
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : mId(std::exchange(other.mId, 0)) {}
    Handle& operator=(Handle&& other) noexcept
    {
        if (this != &other) {
            reset();
            mId = std::exchange(other.mId, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    uint32_t get() const { return mId; }
    explicit operator bool() const { return mId != 0; }
    void reset()
    {
        if (mId) {
            Delete(mId);
            sLive.fetch_sub(1, std::memory_order_relaxed);
        }
        mId = 0;
    }

    /// Objects of this kind alive now, in every context (gl/ObjectCounts.h). One relaxed
    /// atomic add per creation and deletion: cheap enough to count in every build, so that the
    /// soak test runs in the build users get.
    static int64_t live() { return sLive.load(std::memory_order_relaxed); }

private:
    uint32_t mId = 0;
    static inline std::atomic<int64_t> sLive{0};
};

} // namespace specula::gl
