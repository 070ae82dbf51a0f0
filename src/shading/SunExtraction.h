#pragma once
// The sun as a light (--env-sun extract): a map's sun, a compact region far brighter than the
// rest, taken out of the map and given back as a directional light of the same illuminance,
// colour, direction and angular size. Under a light it is exact for punctual shading, casts
// shadows, and no longer has to survive the half-float cube maps (a real sun peaks at
// 10⁴–10⁵ cd/m² × its 6·10⁻⁵ sr, far above 65,504).
#include <optional>

#include <glm/glm.hpp>

#include "shading/EnvironmentMap.h"

namespace specula::render {

/// What counts as a sun (docs/ibl.md#the-sun-as-a-light).
struct SunCriteria {
    /// The peak must be this many times the median luminance 8–15° around it.
    float contrast = 100.0f;
    /// The region: texels connected to the peak brighter than `threshold` × that median.
    float threshold = 8.0f;
    /// At most this angular diameter (degrees) of the region's whole solid angle: compact.
    float maxDiameterDegrees = 12.0f;
    /// At least this fraction of the map's flux onto the plane facing the sun.
    float minFraction = 0.05f;
};

/// Finds the sun of `map` and removes it (its texels set to the level around it, the excess
/// becoming the light: the map's irradiance is kept to within the rounding of that level).
/// The sky still shows it: the texels' radiance as it was goes to map.skyOnly.
/// Nullopt, and `map` untouched, when nothing in it meets `criteria`; else the sun, also kept as
/// map.sun (the light whoever shows the map must add). A map whose sun is out already: map.sun.
std::optional<ExtractedSun> extractSun(EnvironmentMap& map, const SunCriteria& criteria = {});
/// Undoes extractSun: the sun back in `map`'s texels, and map.sun, skyOnly and the key's mark
/// gone. Nothing to do for a map without an extracted sun.
void restoreSun(EnvironmentMap& map);

} // namespace specula::render
