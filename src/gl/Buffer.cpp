#include "gl/Buffer.h"

#include <epoxy/gl.h>

#include <cassert>

#include "gl/Debug.h"

namespace specula::gl {

void detail::deleteBuffer(uint32_t id)
{
    glDeleteBuffers(1, &id);
}

Buffer::Buffer(size_t size, const void* data, std::string_view name) : mSize(size)
{
    GLuint id = 0;
    glCreateBuffers(1, &id);
    mHandle = Handle<detail::deleteBuffer>(id);
    // Zero-sized storage is an error in GL; keep one byte so empty meshes stay valid objects.
    glNamedBufferStorage(id, GLsizeiptr(size ? size : 1), data, GL_DYNAMIC_STORAGE_BIT);
    label(GL_BUFFER, id, name);
}

void Buffer::update(size_t offset, size_t size, const void* data)
{
    assert(offset + size <= mSize);
    if (size == 0) return;
    glNamedBufferSubData(mHandle.get(), GLintptr(offset), GLsizeiptr(size), data);
    mLastUpdate = {offset, size};
    mBytesUpdated += size;
}

std::vector<std::byte> Buffer::read(size_t offset, size_t size) const
{
    assert(offset + size <= mSize);
    std::vector<std::byte> bytes(size);
    if (size) glGetNamedBufferSubData(mHandle.get(), GLintptr(offset), GLsizeiptr(size), bytes.data());
    return bytes;
}

} // namespace specula::gl
