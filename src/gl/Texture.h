#pragma once
// Texture objects with immutable storage (glTextureStorage*), internal format chosen by the caller.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gl/Handle.h"

namespace specula::gl {

class Buffer;

namespace detail {
void deleteTexture(uint32_t id);
}

/// Buffer: a view of a gl::Buffer's bytes as texels (GL_TEXTURE_BUFFER, read with texelFetch);
/// made by Texture(const Buffer&, ...), never uploaded to or read as an image.
enum class TextureType { Texture2D, Texture2DArray, Cube, Texture2DMultisample, Texture3D, Buffer };

enum class Format {
    R8, RG8, RGBA8, SRGB8_ALPHA8,
    R8UI, RG8UI, R32UI, RGBA32UI, ///< unsigned integers: read with usampler and texelFetch, never filtered
    R16F, RG16F, RGBA16F,
    R32F, RG32F, RGBA32F,
    Depth24, Depth32F, Depth24Stencil8,
};

/// The GL internal format (GLenum) of `format`, for calls that name it (image binding).
uint32_t internalFormat(Format format);

/// Type of the client-side pixels passed to upload() or wanted from read().
enum class PixelType { UnsignedByte, HalfFloat, Float };

struct TextureDesc {
    TextureType type = TextureType::Texture2D;
    Format format = Format::RGBA8;
    int width = 1;
    int height = 1;
    int layers = 1;  ///< array layers (Texture2DArray), depth (Texture3D)
    int levels = 1;  ///< mip levels; 0 = full chain down to 1x1
    int samples = 1; ///< Texture2DMultisample only
    std::string label;
};

class Texture {
public:
    Texture() = default;
    explicit Texture(const TextureDesc& desc);
    /// A texel view of all of `buffer` (GL_TEXTURE_BUFFER) in `format`: width() texels of
    /// its bytes, in order. The buffer must outlive the view; it is not uploaded to.
    Texture(const Buffer& buffer, Format format, const std::string& label);

    /// Uploads a whole level of one layer (or cube face, 0..5 = +X,-X,+Y,-Y,+Z,-Z; a 3D
    /// texture's whole volume, `layer` ignored). `channels` is 1..4; rows are tightly packed,
    /// first row at the bottom (GL convention); integer formats take UnsignedByte.
    void upload(int level, int layer, int channels, PixelType type, const void* pixels);
    void generateMipmaps();
    /// Sets every texel of `level` to zero (glClearTexImage).
    void clear(int level = 0);
    /// Reads a whole level back (stalls): every face, layer or slice, one after the other;
    /// size = levelWidth × levelHeight × channels × those.
    std::vector<float> readFloat(int level = 0, int channels = 4) const;
    std::vector<uint8_t> readBytes(int level = 0, int channels = 4) const;

    uint32_t id() const { return mHandle.get(); }
    explicit operator bool() const { return bool(mHandle); }
    const TextureDesc& desc() const { return mDesc; }
    int width(int level = 0) const;
    int height(int level = 0) const;
    int levels() const { return mDesc.levels; }
    bool isDepth() const;
    bool isInteger() const;

    static int fullMipChain(int width, int height);

private:
    size_t planes(int level) const; ///< faces, layers or slices of a level

    Handle<detail::deleteTexture> mHandle;
    TextureDesc mDesc;
};

enum class Filter { Nearest, Linear };
enum class MipFilter { None, Nearest, Linear };
enum class Wrap { Repeat, MirroredRepeat, ClampToEdge };

struct SamplerDesc {
    Filter minFilter = Filter::Linear;
    Filter magFilter = Filter::Linear;
    MipFilter mipFilter = MipFilter::Linear;
    Wrap wrapS = Wrap::Repeat;
    Wrap wrapT = Wrap::Repeat;
    Wrap wrapR = Wrap::Repeat;
    float maxAnisotropy = 1.0f;
    /// Depth textures: sampled through sampler2DShadow, each tap compared with the reference
    /// (lit when reference ≤ stored depth) and, with Linear, the four results filtered.
    bool compareDepth = false;
    bool operator==(const SamplerDesc&) const = default;
};

namespace detail {
void deleteSampler(uint32_t id);
}

class Sampler {
public:
    Sampler() = default;
    explicit Sampler(const SamplerDesc& desc, std::string_view label = {});
    uint32_t id() const { return mHandle.get(); }
    const SamplerDesc& desc() const { return mDesc; }

private:
    Handle<detail::deleteSampler> mHandle;
    SamplerDesc mDesc;
};

} // namespace specula::gl
