#pragma once

namespace specula {

/// This process's resident set size in MiB (Linux /proc/self/statm); -1 when unknown.
double residentMebibytes();

/// Bytes the C library's allocator has handed out and not had back, in MiB (glibc's mallinfo2:
/// the main arena, the thread arenas and blocks mapped on their own); -1 where unknown. Resident
/// memory that grows while this stays flat is the allocator's free lists or a driver's own
/// mappings, not a leak of the program's allocations.
double heapInUseMebibytes();

} // namespace specula
