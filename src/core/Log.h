#pragma once
// Logging goes through spdlog to stderr so stdout stays for program output.
#include <spdlog/spdlog.h>

namespace specula::log {

/// Sets up the stderr logger once; level from SPECULA_LOG (trace, debug, info, warn, error).
void init();

using spdlog::debug;
using spdlog::error;
using spdlog::info;
using spdlog::trace;
using spdlog::warn;

} // namespace specula::log
