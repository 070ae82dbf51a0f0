#include "gl/Debug.h"

#include <epoxy/gl.h>

#include "core/Log.h"

namespace specula::gl {
namespace {

void GLAPIENTRY debugCallback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                              const GLchar* message, const void* user)
{
    auto* monitor = static_cast<DebugMonitor*>(const_cast<void*>(user));
    monitor->onMessage(source, type, id, severity,
                       length >= 0 ? std::string_view(message, size_t(length)) : std::string_view(message));
}

const char* typeName(GLenum type)
{
    switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    default: return "other";
    }
}

} // namespace

DebugMonitor::DebugMonitor()
{
    glEnable(GL_DEBUG_OUTPUT);
    // Synchronous, so the message arrives inside the call that caused it (useful in a debugger).
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(debugCallback, this);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    // Push/pop group notifications are our own markers, not news.
    glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PUSH_GROUP, GL_DONT_CARE, 0, nullptr, GL_FALSE);
    glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_POP_GROUP, GL_DONT_CARE, 0, nullptr, GL_FALSE);
}

DebugMonitor::~DebugMonitor()
{
    glDebugMessageCallback(nullptr, nullptr);
}

void DebugMonitor::onMessage(uint32_t source, uint32_t type, uint32_t id, uint32_t severity, std::string_view text)
{
    (void)source;
    const bool isError = type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
    if (isError) {
        log::error("GL {} ({}): {}", typeName(type), id, text);
        std::lock_guard lock(mMutex);
        mErrors.emplace_back(text);
    } else if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) {
        log::trace("GL {}: {}", typeName(type), text);
    } else {
        log::debug("GL {} ({}): {}", typeName(type), id, text);
    }
}

int DebugMonitor::errorCount() const
{
    std::lock_guard lock(mMutex);
    return int(mErrors.size());
}

std::vector<std::string> DebugMonitor::errors() const
{
    std::lock_guard lock(mMutex);
    return mErrors;
}

void DebugMonitor::clear()
{
    std::lock_guard lock(mMutex);
    mErrors.clear();
}

void DebugMonitor::discardAfter(int count)
{
    std::lock_guard lock(mMutex);
    if (count >= 0 && size_t(count) < mErrors.size()) mErrors.resize(size_t(count));
}

void label(uint32_t identifier, uint32_t name, std::string_view text)
{
    if (name && !text.empty()) glObjectLabel(identifier, name, GLsizei(text.size()), text.data());
}

DebugGroup::DebugGroup(std::string_view name)
{
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, GLsizei(name.size()), name.data());
}

DebugGroup::~DebugGroup()
{
    glPopDebugGroup();
}

} // namespace specula::gl
