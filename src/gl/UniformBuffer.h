#pragma once
// A std140 uniform buffer holding one struct T (declared in shaders/shared/, so C++ and
// GLSL agree on its layout), with a CPU copy; one field or one array element can be
// uploaded alone, by offset and size.
#include <cstddef>
#include <string_view>
#include <type_traits>

#include "gl/Buffer.h"

namespace specula::gl {

void bindUniformBuffer(uint32_t binding, const Buffer& buffer);

template <typename T>
class UniformBuffer {
    static_assert(std::is_standard_layout_v<T>, "uniform blocks must be standard layout");
    static_assert(sizeof(T) % 16 == 0, "std140 blocks are padded to 16 bytes");

public:
    UniformBuffer() = default;
    explicit UniformBuffer(std::string_view label) : mBuffer(sizeof(T), &mData, label) {}

    /// The CPU copy. Edit it, then upload() what changed.
    T& data() { return mData; }
    const T& data() const { return mData; }

    /// Uploads the whole block.
    void upload() { mBuffer.update(0, sizeof(T), &mData); }

    /// Uploads one field: ubo.upload(&Block::exposure).
    template <typename Field>
    void upload(Field T::*field)
    {
        const auto* address = reinterpret_cast<const std::byte*>(&(mData.*field));
        mBuffer.update(offsetOf(address), sizeof(Field), address);
    }

    /// Uploads element `index` of an array field: ubo.upload(&Block::lights, 3).
    template <typename Element, size_t N>
    void upload(Element (T::*array)[N], size_t index)
    {
        const auto* address = reinterpret_cast<const std::byte*>(&(mData.*array)[index]);
        mBuffer.update(offsetOf(address), sizeof(Element), address);
    }

    /// Byte offset of element `index` of an array field, for tests.
    template <typename Element, size_t N>
    size_t offsetOf(Element (T::*array)[N], size_t index) const
    {
        return offsetOf(reinterpret_cast<const std::byte*>(&(mData.*array)[index]));
    }

    void bind(uint32_t binding) const { bindUniformBuffer(binding, mBuffer); }
    const Buffer& buffer() const { return mBuffer; }

private:
    size_t offsetOf(const std::byte* address) const
    {
        return size_t(address - reinterpret_cast<const std::byte*>(&mData));
    }

    T mData{};
    Buffer mBuffer;
};

} // namespace specula::gl
