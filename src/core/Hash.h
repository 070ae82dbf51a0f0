#pragma once
// Content hashes for cache keys (not for security).
#include <cstdint>
#include <string_view>

namespace specula {

/// 64-bit FNV-1a (Fowler, Noll, Vo).
constexpr uint64_t fnv1a64(std::string_view bytes)
{
    uint64_t hash = 1469598103934665603ull;
    for (const char c : bytes) {
        hash ^= uint64_t(static_cast<unsigned char>(c));
        hash *= 1099511628211ull;
    }
    return hash;
}

} // namespace specula
