#pragma once
// Errors that reach the user: one line, carried up to the app boundary.
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace specula {

/// An error caused by user input or the environment (a bad file, no GL context).
/// Caught once at the app boundary and printed as one line; never an assert.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}

    template <typename... Args>
    Error(fmt::format_string<Args...> format, Args&&... args)
        : std::runtime_error(fmt::format(format, std::forward<Args>(args)...))
    {
    }
};

} // namespace specula
