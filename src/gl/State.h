#pragma once
// The one place that binds objects and sets fixed-function state for drawing. It remembers
// what is bound and skips redundant calls. Call reset() after third-party GL code.
#include <array>
#include <cstddef>
#include <cstdint>

namespace specula::gl {

class Buffer;
class Framebuffer;
class Program;
class Sampler;
class Texture;
class VertexArray;

enum class CompareOp : uint8_t { Less, LessEqual, Equal, Always };
enum class CullMode : uint8_t { None, Back, Front };
/// What a draw's vertices make: GL_TRIANGLES, GL_LINES (1 pixel wide), GL_POINTS (1 pixel).
enum class PrimitiveType : uint8_t { Triangles, Lines, Points };
/// WeightedOit: weighted blended order-independent transparency's two targets (McGuire &
/// Bavoil 2013): attachment 0 sums (ONE, ONE), attachment 1 multiplies by 1 − source (ZERO,
/// ONE_MINUS_SRC_COLOR).
/// ShadowTint: colour multiplied (dst × src), alpha the minimum of the two (the shadow pass's
/// tint map: render/passes/ShadowPass).
enum class BlendMode : uint8_t { None, Alpha, PremultipliedAlpha, Additive, WeightedOit, ShadowTint };

enum class ImageAccess : uint8_t { ReadOnly, WriteOnly, ReadWrite };

/// What a memory barrier makes visible to later commands (glMemoryBarrier bits): writes by
/// compute shaders (images, storage buffers) are not ordered with later reads otherwise.
enum class Barrier : uint32_t {
    TextureFetch = 1u << 0,  ///< sampling the written texture
    Image = 1u << 1,         ///< imageLoad/imageStore of it
    StorageBuffer = 1u << 2, ///< storage-buffer reads
    TextureUpdate = 1u << 3, ///< glGetTextureImage and texture uploads
    BufferUpdate = 1u << 4,  ///< buffer reads back and updates
    Framebuffer = 1u << 5,   ///< rendering to or blitting from the texture
    Uniform = 1u << 6,       ///< uniform-buffer reads of a buffer written by a shader
};
constexpr Barrier operator|(Barrier a, Barrier b) { return Barrier(uint32_t(a) | uint32_t(b)); }

/// Fixed-function state of a pass. Zero values are the defaults.
struct PipelineDesc {
    bool noDepthTest = false;
    bool noDepthWrite = false;
    CompareOp depthCompare = CompareOp::Less;
    CullMode cull = CullMode::None;
    BlendMode blend = BlendMode::None;
    bool frontFaceClockwise = false; ///< for mirrored (negative determinant) transforms
    bool framebufferSrgb = false;    ///< encode to sRGB when writing sRGB targets
    /// Depth offset of filled triangles (glPolygonOffset: slope × max depth slope + constant ×
    /// the depth format's smallest step), e.g. a shadow map's slope-scaled bias. 0, 0 = none.
    float depthBiasSlope = 0.0f;
    float depthBiasConstant = 0.0f;
    bool operator==(const PipelineDesc&) const = default;
};

class State {
public:
    State();

    void useProgram(const Program& program);
    void bindVertexArray(const VertexArray& vertexArray);
    void bindTexture(int unit, const Texture& texture);
    void bindSampler(int unit, const Sampler* sampler);
    /// nullptr binds the default framebuffer.
    void bindFramebuffer(const Framebuffer* framebuffer);
    void viewport(int x, int y, int width, int height);
    /// Limits drawing and clears to a rectangle (glScissor); noScissor() lifts it (the default).
    void scissor(int x, int y, int width, int height);
    void noScissor();
    void apply(const PipelineDesc& pipeline);

    /// Forgets the cache and restores GL defaults this class relies on (after third-party GL
    /// code, or when every object it may remember is replaced at once).
    void reset();
    /// Forgets one object about to be deleted, wherever the cache remembers it bound: GL reuses
    /// the names of deleted objects, and a new object must not pass for the old one.
    void forgetTexture(uint32_t name);
    void forgetFramebuffer(uint32_t name);

    /// Binds one level of a texture to an image unit for compute shaders, in its own format;
    /// `layered`: every face or layer of it (image2DArray / imageCube).
    void bindImage(int unit, const Texture& texture, int level, ImageAccess access, bool layered = false);
    /// Runs the bound compute program over groups × local size invocations.
    void dispatchCompute(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ = 1);
    static void memoryBarrier(Barrier barriers);

    /// Draws `count` vertices (or 32-bit indices, from index `firstIndex` of the bound index
    /// buffer) of the bound vertex array as a list of `type`.
    void draw(PrimitiveType type, uint32_t count, bool indexed, uint32_t firstIndex = 0);
    void drawTriangles(uint32_t count, bool indexed, uint32_t firstIndex = 0)
    {
        draw(PrimitiveType::Triangles, count, indexed, firstIndex);
    }
    /// Draws `instances` instances of the first `count` vertices, non-indexed (one draw call;
    /// gl_InstanceID runs from 0 in each).
    void drawTrianglesInstanced(uint32_t count, uint32_t instances);

    /// Draw calls issued through this state since the last resetCounters().
    int drawCalls() const { return mDrawCalls; }
    void resetCounters() { mDrawCalls = 0; }

private:
    static constexpr int kUnits = 37; // units up to SPECULA_UNIT_SHADOW_TINT (shaders/shared/Bindings.h)
    uint32_t mProgram = ~0u;
    uint32_t mVertexArray = ~0u;
    uint32_t mFramebuffer = ~0u;
    std::array<uint32_t, kUnits> mTextures{};
    std::array<uint32_t, kUnits> mSamplers{};
    static constexpr int kImageUnits = 8;
    struct ImageBinding {
        uint32_t texture = ~0u;
        int level = -1;
        ImageAccess access = ImageAccess::ReadOnly;
        bool layered = false;
        bool operator==(const ImageBinding&) const = default;
    };
    std::array<ImageBinding, kImageUnits> mImages{};
    std::array<int, 4> mViewport{-1, -1, -1, -1};
    std::array<int, 4> mScissor{-1, -1, -1, -1}; ///< width < 0: off
    PipelineDesc mPipeline;
    bool mPipelineKnown = false;
    int mDrawCalls = 0;
};

/// Waits until every command issued so far has finished (glFinish): for measurements only.
void finish();

void bindUniformBuffer(uint32_t binding, const Buffer& buffer);
void bindUniformBufferRange(uint32_t binding, const Buffer& buffer, size_t offset, size_t size);
/// GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT of the current context.
int uniformBufferOffsetAlignment();
void bindStorageBuffer(uint32_t binding, const Buffer& buffer);
/// GL_MAX_SHADER_STORAGE_BLOCK_SIZE of the current context: the most bytes one storage block
/// of a shader can reach (128 MiB on llvmpipe).
size_t maxStorageBlockSize();
/// GL_MAX_TEXTURE_BUFFER_SIZE of the current context: the most texels a buffer texture views.
size_t maxTextureBufferTexels();
/// GL_MAX_TEXTURE_SIZE of the current context: the widest and tallest 2D texture (16384 on llvmpipe).
int maxTextureSize();

} // namespace specula::gl
