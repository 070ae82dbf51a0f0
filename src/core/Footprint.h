#pragma once
// Box-filtering an image down: which source texels one output texel averages.
#include <algorithm>
#include <cstdint>
#include <utility>

namespace specula {

/// The source range [first, last) that output texel `i` of `outSize` covers along a side of
/// `inSize` texels (outSize <= inSize): at least one texel, the ranges tiling the side.
inline std::pair<int, int> footprint(int i, int outSize, int inSize)
{
    const int first = int(int64_t(i) * inSize / outSize);
    return {first, std::max(first + 1, int(int64_t(i + 1) * inSize / outSize))};
}

} // namespace specula
