#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "gl/Handle.h"

namespace specula::gl {

class Buffer;

namespace detail {
void deleteVertexArray(uint32_t id);
}

enum class AttributeType { Float, UnsignedByte, UnsignedShort };

/// A vertex array object configured with DSA (glVertexArray*).
class VertexArray {
public:
    VertexArray() = default;
    explicit VertexArray(std::string_view label);

    VertexArray& vertexBuffer(int binding, const Buffer& buffer, size_t offset, size_t stride);
    VertexArray& attribute(int location, int binding, int components, AttributeType type, size_t relativeOffset,
                           bool normalized = false);
    VertexArray& indexBuffer(const Buffer& buffer);

    uint32_t id() const { return mHandle.get(); }

private:
    Handle<detail::deleteVertexArray> mHandle;
};

} // namespace specula::gl
