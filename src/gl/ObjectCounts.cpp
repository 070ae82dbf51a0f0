#include "gl/ObjectCounts.h"

#include <fmt/format.h>

#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/TimerQuery.h"
#include "gl/VertexArray.h"

namespace specula::gl {

std::string ObjectCounts::describe() const
{
    return fmt::format("buffers {}, textures {}, samplers {}, framebuffers {}, programs {}, vertex arrays {}, queries {}",
                       buffers, textures, samplers, framebuffers, programs, vertexArrays, queries);
}

ObjectCounts liveObjects()
{
    ObjectCounts c;
    c.buffers = Handle<detail::deleteBuffer>::live();
    c.textures = Handle<detail::deleteTexture>::live();
    c.samplers = Handle<detail::deleteSampler>::live();
    c.framebuffers = Handle<detail::deleteFramebuffer>::live();
    c.programs = Handle<detail::deleteProgram>::live();
    c.vertexArrays = Handle<detail::deleteVertexArray>::live();
    c.queries = Handle<detail::deleteQuery>::live();
    return c;
}

} // namespace specula::gl
