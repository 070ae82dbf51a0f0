#pragma once
// Private to the platform layer: see KeepDriverLoaded.cpp.

namespace specula::platform {

/// Sanitizer builds: pins Mesa's driver libraries in memory until exit (once per process).
/// Other builds: nothing.
void keepDriverLoaded();

} // namespace specula::platform
