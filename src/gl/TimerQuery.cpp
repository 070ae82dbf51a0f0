#include "gl/TimerQuery.h"

#include <epoxy/gl.h>

namespace specula::gl {

void detail::deleteQuery(uint32_t id)
{
    glDeleteQueries(1, &id);
}

TimerQuery::TimerQuery()
{
    GLuint id = 0;
    glCreateQueries(GL_TIME_ELAPSED, 1, &id);
    mHandle = Handle<detail::deleteQuery>(id);
}

void TimerQuery::begin()
{
    glBeginQuery(GL_TIME_ELAPSED, mHandle.get());
}

void TimerQuery::end()
{
    glEndQuery(GL_TIME_ELAPSED);
    mStarted = true;
}

bool TimerQuery::available() const
{
    if (!mStarted) return false;
    GLuint ready = GL_FALSE;
    glGetQueryObjectuiv(mHandle.get(), GL_QUERY_RESULT_AVAILABLE, &ready);
    return ready == GL_TRUE;
}

double TimerQuery::elapsedMs() const
{
    if (!mStarted) return 0.0;
    GLuint64 ns = 0;
    glGetQueryObjectui64v(mHandle.get(), GL_QUERY_RESULT, &ns);
    return double(ns) * 1e-6;
}

} // namespace specula::gl
