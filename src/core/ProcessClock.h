#pragma once

namespace specula {

/// Milliseconds since this process was started by the kernel (Linux /proc; 10 ms resolution
/// at worst), so start-up timings include loading the executable. -1 when unknown.
double msSinceProcessStart();

} // namespace specula
