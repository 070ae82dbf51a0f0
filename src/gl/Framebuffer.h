#pragma once
// Framebuffer objects with several colour attachments and a depth attachment.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gl/Handle.h"

namespace specula::gl {

class Texture;

namespace detail {
void deleteFramebuffer(uint32_t id);
}

class Framebuffer {
public:
    Framebuffer() = default;
    explicit Framebuffer(std::string_view label);

    /// Attaches `level` of a texture (or one layer / cube face when layer >= 0) as colour `index`.
    Framebuffer& attachColor(int index, const Texture& texture, int level = 0, int layer = -1);
    Framebuffer& attachDepth(const Texture& texture, int level = 0);
    /// Sets the draw buffers to the attached colours and throws specula::Error naming the
    /// framebuffer and the reason when it is incomplete.
    void check();

    void clearColor(int index, float r, float g, float b, float a);
    /// Clears an unsigned-integer colour attachment (clearColor's floats are undefined there).
    void clearColorUint(int index, uint32_t r, uint32_t g, uint32_t b, uint32_t a);
    void clearDepth(float depth = 1.0f);
    /// Copies colour attachment 0 into `target`'s (resolving multisampling), nearest filter.
    void blitColorTo(const Framebuffer& target, int width, int height) const;
    /// Copies colour attachment 0 (width × height) into the default framebuffer's rectangle
    /// (0, 0, targetWidth, targetHeight), scaled with linear filtering (a window's present).
    void blitColorToDefault(int width, int height, int targetWidth, int targetHeight) const;

    uint32_t id() const { return mHandle.get(); }

private:
    Handle<detail::deleteFramebuffer> mHandle;
    std::string mLabel;
    uint32_t mColorMask = 0;
};

/// The default framebuffer's back buffer (what a window shows after the next swap), RGBA8,
/// bottom row first: `width` × `height` pixels from the bottom left. Binds framebuffer 0 for
/// reading; callers with a binding cache must reset it.
std::vector<uint8_t> readDefaultFramebuffer(int width, int height);
/// Whether the default framebuffer's back buffer is sRGB-encoded (GL_FRAMEBUFFER_SRGB then
/// encodes what is drawn into it). Only with a window: a surfaceless context has none.
bool defaultFramebufferIsSrgb();

} // namespace specula::gl
