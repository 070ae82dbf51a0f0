#pragma once
// Immutable-storage buffer object (glNamedBufferStorage) updated by sub-range.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "gl/Handle.h"

namespace specula::gl {

namespace detail {
void deleteBuffer(uint32_t id);
}

class Buffer {
public:
    struct Range {
        size_t offset = 0;
        size_t size = 0;
    };

    Buffer() = default;
    /// Allocates `size` bytes, optionally filled from `data`, updatable with update().
    Buffer(size_t size, const void* data = nullptr, std::string_view label = {});

    template <typename T>
    static Buffer fromSpan(std::span<const T> items, std::string_view label = {})
    {
        return Buffer(items.size_bytes(), items.data(), label);
    }

    /// Rewrites bytes [offset, offset + size) only (glNamedBufferSubData).
    void update(size_t offset, size_t size, const void* data);
    /// Reads bytes back (tests, screenshots); stalls the pipeline.
    std::vector<std::byte> read(size_t offset, size_t size) const;

    uint32_t id() const { return mHandle.get(); }
    size_t size() const { return mSize; }
    explicit operator bool() const { return bool(mHandle); }
    /// The range written by the last update() call (for tests and statistics).
    Range lastUpdate() const { return mLastUpdate; }
    /// Total bytes uploaded through update() since creation.
    size_t bytesUpdated() const { return mBytesUpdated; }

private:
    Handle<detail::deleteBuffer> mHandle;
    size_t mSize = 0;
    Range mLastUpdate;
    size_t mBytesUpdated = 0;
};

} // namespace specula::gl
