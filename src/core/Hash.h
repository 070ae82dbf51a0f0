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

/// A fixed integer hash of `x` (Wellons' lowbias32) mapped to [0, 1): deterministic scatter
/// (the many-lights scene, the viewer's scattered lights).
constexpr float unitHash(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return float(x >> 8) / float(1u << 24);
}

} // namespace specula
