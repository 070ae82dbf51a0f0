#include "gl/Framebuffer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <vector>

#include "core/Error.h"
#include "gl/Debug.h"
#include "gl/Texture.h"

namespace specula::gl {
namespace {

const char* statusName(GLenum status)
{
    switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED: return "undefined";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "an attachment is incomplete";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "no attachment";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "a draw buffer has no attachment";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "the read buffer has no attachment";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "this combination of formats is unsupported";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "attachments have different sample counts";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "attachments are not all layered";
    default: return "unknown status";
    }
}

} // namespace

void detail::deleteFramebuffer(uint32_t id)
{
    glDeleteFramebuffers(1, &id);
}

Framebuffer::Framebuffer(std::string_view name) : mLabel(name)
{
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    mHandle = Handle<detail::deleteFramebuffer>(id);
    label(GL_FRAMEBUFFER, id, name);
}

Framebuffer& Framebuffer::attachColor(int index, const Texture& texture, int level, int layer)
{
    if (layer >= 0) {
        glNamedFramebufferTextureLayer(id(), GL_COLOR_ATTACHMENT0 + index, texture.id(), level, layer);
    } else {
        glNamedFramebufferTexture(id(), GL_COLOR_ATTACHMENT0 + index, texture.id(), level);
    }
    mColorMask |= 1u << index;
    return *this;
}

Framebuffer& Framebuffer::attachDepth(const Texture& texture, int level)
{
    const GLenum attachment =
        texture.desc().format == Format::Depth24Stencil8 ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    glNamedFramebufferTexture(id(), attachment, texture.id(), level);
    return *this;
}

void Framebuffer::check()
{
    std::vector<GLenum> buffers;
    for (int i = 0; i < 8; ++i) {
        if (mColorMask & (1u << i)) {
            buffers.resize(size_t(i) + 1, GL_NONE);
            buffers[size_t(i)] = GL_COLOR_ATTACHMENT0 + i;
        }
    }
    if (buffers.empty()) {
        glNamedFramebufferDrawBuffer(id(), GL_NONE);
        glNamedFramebufferReadBuffer(id(), GL_NONE);
    } else {
        glNamedFramebufferDrawBuffers(id(), GLsizei(buffers.size()), buffers.data());
        glNamedFramebufferReadBuffer(id(), GL_COLOR_ATTACHMENT0);
    }
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw Error("framebuffer '{}' is incomplete: {} (0x{:x})", mLabel, statusName(status), status);
    }
}

void Framebuffer::clearColor(int index, float r, float g, float b, float a)
{
    const float value[4] = {r, g, b, a};
    glClearNamedFramebufferfv(id(), GL_COLOR, index, value);
}

void Framebuffer::clearColorUint(int index, uint32_t r, uint32_t g, uint32_t b, uint32_t a)
{
    const GLuint value[4] = {r, g, b, a};
    glClearNamedFramebufferuiv(id(), GL_COLOR, index, value);
}

void Framebuffer::clearDepth(float depth)
{
    glClearNamedFramebufferfv(id(), GL_DEPTH, 0, &depth);
}

void Framebuffer::blitColorTo(const Framebuffer& target, int width, int height) const
{
    glBlitNamedFramebuffer(id(), target.id(), 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void Framebuffer::blitColorToDefault(int width, int height, int targetWidth, int targetHeight) const
{
    glBlitNamedFramebuffer(id(), 0, 0, 0, width, height, 0, 0, targetWidth, targetHeight, GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

std::vector<uint8_t> readDefaultFramebuffer(int width, int height)
{
    std::vector<uint8_t> pixels(size_t(std::max(width, 0)) * size_t(std::max(height, 0)) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glNamedFramebufferReadBuffer(0, GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadnPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return pixels;
}

bool defaultFramebufferIsSrgb()
{
    GLint encoding = GL_LINEAR;
    glGetNamedFramebufferAttachmentParameteriv(0, GL_BACK_LEFT, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &encoding);
    return encoding == GL_SRGB;
}

} // namespace specula::gl
