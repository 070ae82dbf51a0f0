#pragma once
#include <cstdint>

#include "gl/Handle.h"

namespace specula::gl {

namespace detail {
void deleteQuery(uint32_t id);
}

/// GPU time of the commands between begin() and end() (GL_TIME_ELAPSED).
class TimerQuery {
public:
    TimerQuery();
    void begin();
    void end();
    /// True once the result can be read without waiting.
    bool available() const;
    /// Elapsed GPU milliseconds; waits for the result if needed. 0 if never run.
    double elapsedMs() const;
    bool started() const { return mStarted; }

private:
    Handle<detail::deleteQuery> mHandle;
    bool mStarted = false;
};

} // namespace specula::gl
