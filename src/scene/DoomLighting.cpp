#include "scene/DoomLighting.h"

#include <algorithm>

namespace specula::scene::doom {

std::vector<std::pair<int, int>> adjacentSectors(const std::vector<Sector>& sectors)
{
    std::vector<std::pair<int, int>> pairs;
    for (size_t a = 0; a < sectors.size(); ++a) {
        for (size_t b = a + 1; b < sectors.size(); ++b) {
            const Sector& s = sectors[a];
            const Sector& t = sectors[b];
            // Overlap of the two rectangles' extents along each axis.
            const int overlapX = std::min(s.max.x, t.max.x) - std::max(s.min.x, t.min.x);
            const int overlapZ = std::min(s.max.y, t.max.y) - std::max(s.min.y, t.min.y);
            // Touching along an edge: zero extent on one axis, positive on the other.
            if ((overlapX == 0 && overlapZ > 0) || (overlapZ == 0 && overlapX > 0)) pairs.emplace_back(int(a), int(b));
        }
    }
    return pairs;
}

std::vector<int> spreadLight(const std::vector<Sector>& sectors, int attenuation)
{
    std::vector<int> level(sectors.size());
    for (size_t i = 0; i < sectors.size(); ++i) level[i] = std::clamp(sectors[i].light, 0, 255);
    const auto pairs = adjacentSectors(sectors);
    // Bellman-Ford style relaxation: levels only rise, at most 255 times, so it terminates.
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& [a, b] : pairs) {
            for (auto [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
                const int spread = level[size_t(from)] - attenuation;
                if (spread > level[size_t(to)]) {
                    level[size_t(to)] = spread;
                    changed = true;
                }
            }
        }
    }
    return level;
}

int colormapIndex(int light, double distance)
{
    constexpr int kLightLevels = 16; // LIGHTLEVELS: light >> LIGHTSEGSHIFT (4)
    const int lightNumber = std::clamp(light, 0, 255) >> 4;
    const int startmap = ((kLightLevels - 1 - lightNumber) * 2) * kColormaps / kLightLevels;
    // Distance in units of 16 map units (LIGHTZSHIFT), MAXLIGHTZ = 128 steps.
    const int z = std::clamp(int(std::max(distance, 0.0) / 16.0), 0, 127);
    const int scale = 160 / (z + 1); // (SCREENWIDTH / 2) / (z + 1)
    const int level = startmap - scale / 2; // DISTMAP = 2
    return std::clamp(level, 0, kColormaps - 1);
}

int wallColormapIndex(int light, double distance, WallContrast contrast)
{
    constexpr int kLightLevels = 16, kMaxLightScale = 48;
    const int lightNumber = std::clamp((std::clamp(light, 0, 255) >> 4) + int(contrast), 0, kLightLevels - 1);
    const int startmap = ((kLightLevels - 1 - lightNumber) * 2) * kColormaps / kLightLevels;
    // rw_scale = projection / distance, projection = 160 map units (SCREENWIDTH / 2) in 16.16
    // fixed point, >> LIGHTSCALESHIFT (12): 160 · 16 / distance.
    const int scale = std::min(int(2560.0 / std::max(distance, 1.0)), kMaxLightScale - 1);
    return std::clamp(startmap - scale / 2, 0, kColormaps - 1); // DISTMAP = 2
}

} // namespace specula::scene::doom
