#pragma once

namespace specula {

/// This process's resident set size in MiB (Linux /proc/self/statm); -1 when unknown.
double residentMebibytes();

} // namespace specula
