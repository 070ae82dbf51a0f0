#include "gl/VertexArray.h"

#include <epoxy/gl.h>

#include "gl/Buffer.h"
#include "gl/Debug.h"

namespace specula::gl {

void detail::deleteVertexArray(uint32_t id)
{
    glDeleteVertexArrays(1, &id);
}

VertexArray::VertexArray(std::string_view name)
{
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    mHandle = Handle<detail::deleteVertexArray>(id);
    label(GL_VERTEX_ARRAY, id, name);
}

VertexArray& VertexArray::vertexBuffer(int binding, const Buffer& buffer, size_t offset, size_t stride)
{
    glVertexArrayVertexBuffer(id(), GLuint(binding), buffer.id(), GLintptr(offset), GLsizei(stride));
    return *this;
}

VertexArray& VertexArray::attribute(int location, int binding, int components, AttributeType type,
                                    size_t relativeOffset, bool normalized)
{
    const GLenum glType = type == AttributeType::Float         ? GL_FLOAT
                        : type == AttributeType::UnsignedByte  ? GL_UNSIGNED_BYTE
                                                               : GL_UNSIGNED_SHORT;
    glEnableVertexArrayAttrib(id(), GLuint(location));
    glVertexArrayAttribFormat(id(), GLuint(location), components, glType, normalized ? GL_TRUE : GL_FALSE,
                              GLuint(relativeOffset));
    glVertexArrayAttribBinding(id(), GLuint(location), GLuint(binding));
    return *this;
}

VertexArray& VertexArray::indexBuffer(const Buffer& buffer)
{
    glVertexArrayElementBuffer(id(), buffer.id());
    return *this;
}

} // namespace specula::gl
