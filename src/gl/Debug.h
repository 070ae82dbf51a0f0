#pragma once
// KHR_debug: messages to the logger, errors counted so tests can fail on them.
#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace specula::gl {

/// Registers a synchronous debug callback for the current context. Messages of type
/// error or of high severity are counted and kept; others go to the logger only.
class DebugMonitor {
public:
    DebugMonitor();
    ~DebugMonitor();
    DebugMonitor(const DebugMonitor&) = delete;
    DebugMonitor& operator=(const DebugMonitor&) = delete;

    /// Errors and high-severity messages since construction or the last clear().
    int errorCount() const;
    std::vector<std::string> errors() const;
    void clear();
    /// Forgets the errors after the first `count`: those of a failure the caller expected and
    /// handled (a shader that does not compile reports a GL error too).
    void discardAfter(int count);

    void onMessage(uint32_t source, uint32_t type, uint32_t id, uint32_t severity, std::string_view text);

private:
    mutable std::mutex mMutex;
    std::vector<std::string> mErrors;
};

/// Names a GL object for debuggers and debug messages (glObjectLabel).
void label(uint32_t identifier, uint32_t name, std::string_view text);

/// glPushDebugGroup / glPopDebugGroup for the lifetime of the object.
class DebugGroup {
public:
    explicit DebugGroup(std::string_view name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

} // namespace specula::gl
