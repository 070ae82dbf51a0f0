#include "gl/State.h"

#include <epoxy/gl.h>

#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"

namespace specula::gl {

State::State()
{
    reset();
}

void State::reset()
{
    mProgram = mVertexArray = mFramebuffer = ~0u;
    mTextures.fill(~0u);
    mSamplers.fill(~0u);
    mImages.fill({});
    mViewport = {-1, -1, -1, -1};
    mScissor = {-1, -1, -1, -1};
    mPipelineKnown = false;
    // Reversed or odd state from other code would silently change our results.
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

void State::forgetTexture(uint32_t name)
{
    for (uint32_t& t : mTextures)
        if (t == name) t = ~0u;
    for (ImageBinding& i : mImages)
        if (i.texture == name) i = {};
}

void State::forgetFramebuffer(uint32_t name)
{
    if (mFramebuffer == name) mFramebuffer = ~0u;
}

void State::draw(PrimitiveType type, uint32_t count, bool indexed, uint32_t firstIndex)
{
    const GLenum mode = type == PrimitiveType::Lines ? GL_LINES : type == PrimitiveType::Points ? GL_POINTS : GL_TRIANGLES;
    if (indexed) {
        glDrawElements(mode, GLsizei(count), GL_UNSIGNED_INT, reinterpret_cast<const void*>(uintptr_t(firstIndex) * sizeof(uint32_t)));
    } else {
        glDrawArrays(mode, 0, GLsizei(count));
    }
    ++mDrawCalls;
}

void State::drawTrianglesInstanced(uint32_t count, uint32_t instances)
{
    glDrawArraysInstanced(GL_TRIANGLES, 0, GLsizei(count), GLsizei(instances));
    ++mDrawCalls;
}

void State::bindImage(int unit, const Texture& texture, int level, ImageAccess access, bool layered)
{
    const ImageBinding binding{texture.id(), level, access, layered};
    if (mImages[size_t(unit)] == binding) return;
    mImages[size_t(unit)] = binding;
    const GLenum glAccess = access == ImageAccess::ReadOnly    ? GL_READ_ONLY
                          : access == ImageAccess::WriteOnly ? GL_WRITE_ONLY
                                                             : GL_READ_WRITE;
    glBindImageTexture(GLuint(unit), texture.id(), level, layered ? GL_TRUE : GL_FALSE, 0, glAccess, internalFormat(texture.desc().format));
}

void State::dispatchCompute(uint32_t groupsX, uint32_t groupsY, uint32_t groupsZ)
{
    glDispatchCompute(groupsX, groupsY, groupsZ);
}

void State::memoryBarrier(Barrier barriers)
{
    const uint32_t b = uint32_t(barriers);
    GLbitfield bits = 0;
    if (b & uint32_t(Barrier::TextureFetch)) bits |= GL_TEXTURE_FETCH_BARRIER_BIT;
    if (b & uint32_t(Barrier::Image)) bits |= GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
    if (b & uint32_t(Barrier::StorageBuffer)) bits |= GL_SHADER_STORAGE_BARRIER_BIT;
    if (b & uint32_t(Barrier::TextureUpdate)) bits |= GL_TEXTURE_UPDATE_BARRIER_BIT;
    if (b & uint32_t(Barrier::BufferUpdate)) bits |= GL_BUFFER_UPDATE_BARRIER_BIT;
    if (b & uint32_t(Barrier::Framebuffer)) bits |= GL_FRAMEBUFFER_BARRIER_BIT;
    if (b & uint32_t(Barrier::Uniform)) bits |= GL_UNIFORM_BARRIER_BIT;
    glMemoryBarrier(bits);
}

void State::useProgram(const Program& program)
{
    if (mProgram != program.id()) {
        mProgram = program.id();
        glUseProgram(mProgram);
    }
}

void State::bindVertexArray(const VertexArray& vertexArray)
{
    if (mVertexArray != vertexArray.id()) {
        mVertexArray = vertexArray.id();
        glBindVertexArray(mVertexArray);
    }
}

void State::bindTexture(int unit, const Texture& texture)
{
    if (mTextures[size_t(unit)] != texture.id()) {
        mTextures[size_t(unit)] = texture.id();
        glBindTextureUnit(GLuint(unit), texture.id());
    }
}

void State::bindSampler(int unit, const Sampler* sampler)
{
    const uint32_t id = sampler ? sampler->id() : 0;
    if (mSamplers[size_t(unit)] != id) {
        mSamplers[size_t(unit)] = id;
        glBindSampler(GLuint(unit), id);
    }
}

void State::bindFramebuffer(const Framebuffer* framebuffer)
{
    const uint32_t id = framebuffer ? framebuffer->id() : 0;
    if (mFramebuffer != id) {
        mFramebuffer = id;
        glBindFramebuffer(GL_FRAMEBUFFER, id);
    }
}

void State::viewport(int x, int y, int width, int height)
{
    const std::array<int, 4> v{x, y, width, height};
    if (v != mViewport) {
        mViewport = v;
        glViewport(x, y, width, height);
    }
}

void State::scissor(int x, int y, int width, int height)
{
    const std::array<int, 4> r{x, y, width, height};
    if (r == mScissor) return;
    if (mScissor[2] < 0) glEnable(GL_SCISSOR_TEST);
    mScissor = r;
    glScissor(x, y, width, height);
}

void State::noScissor()
{
    if (mScissor[2] < 0) return;
    mScissor = {-1, -1, -1, -1};
    glDisable(GL_SCISSOR_TEST);
}

void State::apply(const PipelineDesc& p)
{
    if (mPipelineKnown && p == mPipeline) return;
    const bool first = !mPipelineKnown;
    if (first || p.noDepthTest != mPipeline.noDepthTest) p.noDepthTest ? glDisable(GL_DEPTH_TEST) : glEnable(GL_DEPTH_TEST);
    if (first || p.noDepthWrite != mPipeline.noDepthWrite) glDepthMask(p.noDepthWrite ? GL_FALSE : GL_TRUE);
    if (first || p.depthCompare != mPipeline.depthCompare) {
        const GLenum func = p.depthCompare == CompareOp::Less        ? GL_LESS
                          : p.depthCompare == CompareOp::LessEqual   ? GL_LEQUAL
                          : p.depthCompare == CompareOp::Equal       ? GL_EQUAL
                                                                     : GL_ALWAYS;
        glDepthFunc(func);
    }
    if (first || p.cull != mPipeline.cull) {
        if (p.cull == CullMode::None) {
            glDisable(GL_CULL_FACE);
        } else {
            glEnable(GL_CULL_FACE);
            glCullFace(p.cull == CullMode::Back ? GL_BACK : GL_FRONT);
        }
    }
    if (first || p.blend != mPipeline.blend) {
        // Only the tint map's mode takes the minimum of the alphas.
        if (first || mPipeline.blend == BlendMode::ShadowTint) glBlendEquation(GL_FUNC_ADD);
        switch (p.blend) {
        case BlendMode::None: glDisable(GL_BLEND); break;
        case BlendMode::Alpha:
            glEnable(GL_BLEND);
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            break;
        case BlendMode::PremultipliedAlpha:
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            break;
        case BlendMode::Additive:
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE);
            break;
        case BlendMode::WeightedOit:
            // Per attachment; the other modes' glBlendFunc sets every attachment back.
            glEnable(GL_BLEND);
            glBlendFunci(0, GL_ONE, GL_ONE);
            glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
            break;
        case BlendMode::ShadowTint:
            glEnable(GL_BLEND);
            glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ONE, GL_ONE);
            glBlendEquationSeparate(GL_FUNC_ADD, GL_MIN);
            break;
        }
    }
    if (first || p.framebufferSrgb != mPipeline.framebufferSrgb)
        p.framebufferSrgb ? glEnable(GL_FRAMEBUFFER_SRGB) : glDisable(GL_FRAMEBUFFER_SRGB);
    if (first || p.frontFaceClockwise != mPipeline.frontFaceClockwise) glFrontFace(p.frontFaceClockwise ? GL_CW : GL_CCW);
    if (first || p.depthBiasSlope != mPipeline.depthBiasSlope || p.depthBiasConstant != mPipeline.depthBiasConstant) {
        if (p.depthBiasSlope != 0.0f || p.depthBiasConstant != 0.0f) {
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(p.depthBiasSlope, p.depthBiasConstant);
        } else {
            glDisable(GL_POLYGON_OFFSET_FILL);
        }
    }
    mPipeline = p;
    mPipelineKnown = true;
}

void finish()
{
    glFinish();
}

void bindUniformBuffer(uint32_t binding, const Buffer& buffer)
{
    glBindBufferBase(GL_UNIFORM_BUFFER, binding, buffer.id());
}

void bindUniformBufferRange(uint32_t binding, const Buffer& buffer, size_t offset, size_t size)
{
    glBindBufferRange(GL_UNIFORM_BUFFER, binding, buffer.id(), GLintptr(offset), GLsizeiptr(size));
}

int uniformBufferOffsetAlignment()
{
    GLint alignment = 256;
    glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
    return alignment;
}

void bindStorageBuffer(uint32_t binding, const Buffer& buffer)
{
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer.id());
}

size_t maxStorageBlockSize()
{
    GLint64 size = 1 << 24; // the GL 4.3 minimum, should the query fail
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &size);
    return size_t(size);
}

size_t maxTextureBufferTexels()
{
    GLint texels = 65536; // the GL 4.5 minimum
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
    return size_t(texels);
}

int maxTextureSize()
{
    GLint size = 16384; // the GL 4.5 minimum
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
    return int(size);
}

} // namespace specula::gl
