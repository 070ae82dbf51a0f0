#include "gl/Texture.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/Error.h"
#include "gl/Buffer.h"
#include "gl/Debug.h"
#include "gl/State.h"

namespace specula::gl {
namespace {

GLenum glInternalFormat(Format format)
{
    switch (format) {
    case Format::R8: return GL_R8;
    case Format::RG8: return GL_RG8;
    case Format::RGBA8: return GL_RGBA8;
    case Format::SRGB8_ALPHA8: return GL_SRGB8_ALPHA8;
    case Format::R8UI: return GL_R8UI;
    case Format::R32UI: return GL_R32UI;
    case Format::RG8UI: return GL_RG8UI;
    case Format::RGBA32UI: return GL_RGBA32UI;
    case Format::R16F: return GL_R16F;
    case Format::RG16F: return GL_RG16F;
    case Format::RGBA16F: return GL_RGBA16F;
    case Format::R32F: return GL_R32F;
    case Format::RG32F: return GL_RG32F;
    case Format::RGBA32F: return GL_RGBA32F;
    case Format::Depth24: return GL_DEPTH_COMPONENT24;
    case Format::Depth32F: return GL_DEPTH_COMPONENT32F;
    case Format::Depth24Stencil8: return GL_DEPTH24_STENCIL8;
    }
    return GL_RGBA8;
}

GLenum glTarget(TextureType type)
{
    switch (type) {
    case TextureType::Texture2D: return GL_TEXTURE_2D;
    case TextureType::Texture2DArray: return GL_TEXTURE_2D_ARRAY;
    case TextureType::Cube: return GL_TEXTURE_CUBE_MAP;
    case TextureType::Texture2DMultisample: return GL_TEXTURE_2D_MULTISAMPLE;
    case TextureType::Texture3D: return GL_TEXTURE_3D;
    case TextureType::Buffer: return GL_TEXTURE_BUFFER;
    }
    return GL_TEXTURE_2D;
}

GLenum channelFormat(int channels, bool integer = false)
{
    switch (channels) {
    case 1: return integer ? GL_RED_INTEGER : GL_RED;
    case 2: return integer ? GL_RG_INTEGER : GL_RG;
    case 3: return integer ? GL_RGB_INTEGER : GL_RGB;
    default: return integer ? GL_RGBA_INTEGER : GL_RGBA;
    }
}

GLenum glPixelType(PixelType type)
{
    switch (type) {
    case PixelType::UnsignedByte: return GL_UNSIGNED_BYTE;
    case PixelType::HalfFloat: return GL_HALF_FLOAT;
    case PixelType::Float: return GL_FLOAT;
    }
    return GL_UNSIGNED_BYTE;
}

GLenum glFilter(Filter filter, MipFilter mip)
{
    if (filter == Filter::Nearest) {
        return mip == MipFilter::None      ? GL_NEAREST
             : mip == MipFilter::Nearest   ? GL_NEAREST_MIPMAP_NEAREST
                                           : GL_NEAREST_MIPMAP_LINEAR;
    }
    return mip == MipFilter::None      ? GL_LINEAR
         : mip == MipFilter::Nearest   ? GL_LINEAR_MIPMAP_NEAREST
                                       : GL_LINEAR_MIPMAP_LINEAR;
}

GLenum glWrap(Wrap wrap)
{
    switch (wrap) {
    case Wrap::Repeat: return GL_REPEAT;
    case Wrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case Wrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    }
    return GL_REPEAT;
}

} // namespace

uint32_t internalFormat(Format format)
{
    return glInternalFormat(format);
}

void detail::deleteTexture(uint32_t id)
{
    glDeleteTextures(1, &id);
}

void detail::deleteSampler(uint32_t id)
{
    glDeleteSamplers(1, &id);
}

int Texture::fullMipChain(int width, int height)
{
    return 1 + int(std::floor(std::log2(double(std::max({width, height, 1})))));
}

Texture::Texture(const TextureDesc& desc) : mDesc(desc)
{
    if (desc.width <= 0 || desc.height <= 0) throw Error("texture '{}' has an empty size {}x{}", desc.label, desc.width, desc.height);
    if (mDesc.levels <= 0) mDesc.levels = fullMipChain(desc.width, desc.height);
    GLuint id = 0;
    glCreateTextures(glTarget(desc.type), 1, &id);
    mHandle = Handle<detail::deleteTexture>(id);
    const GLenum format = glInternalFormat(desc.format);
    switch (desc.type) {
    case TextureType::Texture2D:
    case TextureType::Cube:
        glTextureStorage2D(id, mDesc.levels, format, desc.width, desc.height);
        break;
    case TextureType::Texture2DArray:
    case TextureType::Texture3D:
        glTextureStorage3D(id, mDesc.levels, format, desc.width, desc.height, desc.layers);
        break;
    case TextureType::Texture2DMultisample:
        mDesc.levels = 1;
        glTextureStorage2DMultisample(id, desc.samples, format, desc.width, desc.height, GL_TRUE);
        break;
    case TextureType::Buffer:
        throw Error("texture '{}': a buffer texture is made from a gl::Buffer", desc.label);
    }
    if (desc.type != TextureType::Texture2DMultisample) {
        glTextureParameteri(id, GL_TEXTURE_MAX_LEVEL, mDesc.levels - 1);
        // Integer textures with a linear filter are incomplete (GL 4.5, 8.17): fetches return 0.
        const bool nearest = isInteger();
        const GLenum minFilter = mDesc.levels > 1 ? (nearest ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR)
                                                  : (nearest ? GL_NEAREST : GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, nearest ? GL_NEAREST : GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    }
    label(GL_TEXTURE, id, desc.label);
}

namespace {

int bytesPerTexel(Format format)
{
    switch (format) {
    case Format::R8: case Format::R8UI: return 1;
    case Format::RG8: case Format::RG8UI: case Format::R16F: return 2;
    case Format::RGBA8: case Format::SRGB8_ALPHA8: case Format::RG16F: case Format::R32F: case Format::R32UI: return 4;
    case Format::RGBA16F: case Format::RG32F: return 8;
    case Format::RGBA32F: case Format::RGBA32UI: return 16;
    default: return 0; // depth formats: no buffer view
    }
}

} // namespace

Texture::Texture(const Buffer& buffer, Format format, const std::string& label)
{
    const int texelBytes = bytesPerTexel(format);
    if (texelBytes == 0 || buffer.size() % size_t(texelBytes) != 0)
        throw Error("texture '{}': {} bytes are not whole texels of its format", label, buffer.size());
    const size_t texels = buffer.size() / size_t(texelBytes);
    const size_t maxTexels = maxTextureBufferTexels();
    if (texels > maxTexels)
        throw Error("texture '{}': {} texels, more than a buffer texture holds here ({}, GL_MAX_TEXTURE_BUFFER_SIZE)", label, texels,
                    maxTexels);
    mDesc = {.type = TextureType::Buffer, .format = format, .width = int(texels), .height = 1, .levels = 1, .label = label};
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &id);
    mHandle = Handle<detail::deleteTexture>(id);
    glTextureBuffer(id, glInternalFormat(format), buffer.id());
    gl::label(GL_TEXTURE, id, label);
}

int Texture::width(int level) const
{
    return std::max(1, mDesc.width >> level);
}

int Texture::height(int level) const
{
    return std::max(1, mDesc.height >> level);
}

bool Texture::isDepth() const
{
    return mDesc.format == Format::Depth24 || mDesc.format == Format::Depth32F || mDesc.format == Format::Depth24Stencil8;
}

size_t Texture::planes(int level) const
{
    switch (mDesc.type) {
    case TextureType::Cube: return 6;
    case TextureType::Texture2DArray: return size_t(mDesc.layers);
    case TextureType::Texture3D: return size_t(std::max(1, mDesc.layers >> level));
    default: return 1;
    }
}

bool Texture::isInteger() const
{
    return mDesc.format == Format::R8UI || mDesc.format == Format::RG8UI || mDesc.format == Format::R32UI ||
           mDesc.format == Format::RGBA32UI;
}

void Texture::upload(int level, int layer, int channels, PixelType type, const void* pixels)
{
    assert(level < mDesc.levels && mDesc.type != TextureType::Buffer);
    const GLuint id = mHandle.get();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const GLenum channelsFormat = channelFormat(channels, isInteger());
    if (mDesc.type == TextureType::Texture2D) {
        glTextureSubImage2D(id, level, 0, 0, width(level), height(level), channelsFormat, glPixelType(type), pixels);
    } else if (mDesc.type == TextureType::Texture3D) {
        glTextureSubImage3D(id, level, 0, 0, 0, width(level), height(level), std::max(1, mDesc.layers >> level), channelsFormat,
                            glPixelType(type), pixels);
    } else {
        // Cube faces are addressed as layers 0..5 with DSA.
        glTextureSubImage3D(id, level, 0, 0, layer, width(level), height(level), 1, channelsFormat, glPixelType(type), pixels);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

void Texture::clear(int level)
{
    const GLenum format = isDepth() ? GL_DEPTH_COMPONENT : GL_RGBA;
    glClearTexImage(mHandle.get(), level, format, GL_FLOAT, nullptr);
}

void Texture::generateMipmaps()
{
    if (mDesc.levels > 1) glGenerateTextureMipmap(mHandle.get());
}

std::vector<float> Texture::readFloat(int level, int channels) const
{
    std::vector<float> pixels(size_t(width(level)) * height(level) * channels * planes(level));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (isDepth()) {
        glGetTextureImage(mHandle.get(), level, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
    } else {
        glGetTextureImage(mHandle.get(), level, channelFormat(channels), GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                          pixels.data());
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return pixels;
}

std::vector<uint8_t> Texture::readBytes(int level, int channels) const
{
    std::vector<uint8_t> pixels(size_t(width(level)) * height(level) * channels * planes(level));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(mHandle.get(), level, channelFormat(channels, isInteger()), GL_UNSIGNED_BYTE, GLsizei(pixels.size()),
                      pixels.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return pixels;
}

Sampler::Sampler(const SamplerDesc& desc, std::string_view name) : mDesc(desc)
{
    GLuint id = 0;
    glCreateSamplers(1, &id);
    mHandle = Handle<detail::deleteSampler>(id);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, glFilter(desc.minFilter, desc.mipFilter));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, glFilter(desc.magFilter, MipFilter::None));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, glWrap(desc.wrapS));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, glWrap(desc.wrapT));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_R, glWrap(desc.wrapR));
    if (desc.maxAnisotropy > 1.0f) glSamplerParameterf(id, GL_TEXTURE_MAX_ANISOTROPY, desc.maxAnisotropy);
    if (desc.compareDepth) {
        glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(id, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    }
    label(GL_SAMPLER, id, name);
}

} // namespace specula::gl
