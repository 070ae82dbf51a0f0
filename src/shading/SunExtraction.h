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

struct ExtractedSun {
    glm::vec3 direction{0.0f, 1.0f, 0.0f}; ///< towards the sun, environment space (unit)
    glm::vec3 illuminance{0.0f};           ///< lux on a surface facing it, RGB
    /// Radians: the disc with the region's second moment of angle about its centre (a uniform
    /// disc of radius ρ has a mean θ² of ρ²/2), so a dim halo around the sun hardly widens it.
    float angularDiameter = 0.0f;
    int texels = 0;                        ///< texels the region covered
};

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
/// Nullopt, and `map` untouched, when nothing in it meets `criteria`.
std::optional<ExtractedSun> extractSun(EnvironmentMap& map, const SunCriteria& criteria = {});

} // namespace specula::render
