#pragma once
// Move-only ownership of one GL object name; a moved-from handle owns nothing.
#include <cstdint>
#include <utility>

namespace specula::gl {

template <void (*Delete)(uint32_t)>
class Handle {
public:
    Handle() = default;
    explicit Handle(uint32_t id) : mId(id) {}
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
        if (mId) Delete(mId);
        mId = 0;
    }

private:
    uint32_t mId = 0;
};

} // namespace specula::gl
