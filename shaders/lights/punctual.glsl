// KHR_lights_punctual attenuation.
#include "../shared/LightData.h"

// Inverse square law with the glTF range window (KHR_lights_punctual, "Range Property"):
// max(min(1 - (d / range)^4, 1), 0) / d^2; range 0 means infinite.
float rangeAttenuation(float range, float distance)
{
    float inverseSquare = 1.0 / max(distance * distance, 1e-8); // 1e-8: a light inside the surface stays finite
    if (range <= 0.0) return inverseSquare;
    float ratio = distance / range;
    return clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0) * inverseSquare;
}

// Smooth spot falloff of KHR_lights_punctual: saturate(cd * scale + offset)^2.
float spotAttenuation(vec3 lightDirection, vec3 toLight, vec2 scaleOffset)
{
    float cd = dot(lightDirection, -toLight);
    float a = clamp(cd * scaleOffset.x + scaleOffset.y, 0.0, 1.0);
    return a * a;
}

// Incident radiance scale (illuminance on a surface facing the light, lux) and the unit
// direction l from the surface point towards the light.
//
// A kind of light the frame has none of is compiled out (NO_DIRECTIONAL_LIGHTS,
// NO_POINT_LIGHTS, NO_SPOT_LIGHTS: shading/VariantKey's LightVariant): a CPU rasteriser runs
// both sides of a branch on the light's type, so a frame of point lights only pays for them
// alone. A frame with one kind has no branch on the type at all.
#if defined(NO_POINT_LIGHTS) && defined(NO_SPOT_LIGHTS)
#define SPECULA_ONLY_DIRECTIONAL_LIGHTS
#endif
vec3 lightIlluminance(GpuLight light, vec3 worldPosition, out vec3 l)
{
    vec3 intensity = light.colorIntensity.rgb * light.colorIntensity.a;
#if defined(SPECULA_ONLY_DIRECTIONAL_LIGHTS) && defined(NO_DIRECTIONAL_LIGHTS)
    // No light of any kind: nothing calls this (LIGHT_COUNT 0), but it must compile.
    l = vec3(0.0, 0.0, 1.0);
    return vec3(0.0);
#elif defined(SPECULA_ONLY_DIRECTIONAL_LIGHTS)
    l = -light.directionType.xyz;
    return intensity;
#else
#if !defined(NO_DIRECTIONAL_LIGHTS) || (!defined(NO_POINT_LIGHTS) && !defined(NO_SPOT_LIGHTS))
    uint type = uint(light.directionType.w + 0.5);
#endif
#if !defined(NO_DIRECTIONAL_LIGHTS)
    if (type == SPECULA_LIGHT_DIRECTIONAL) {
        l = -light.directionType.xyz;
        return intensity;
    }
#endif
    vec3 toLight = light.positionRange.xyz - worldPosition;
    float distance = length(toLight);
    l = toLight / max(distance, 1e-8);
    float attenuation = rangeAttenuation(light.positionRange.w, distance);
#if !defined(NO_SPOT_LIGHTS) && defined(NO_POINT_LIGHTS)
    attenuation *= spotAttenuation(light.directionType.xyz, l, light.spot.xy);
#elif !defined(NO_SPOT_LIGHTS)
    if (type == SPECULA_LIGHT_SPOT) attenuation *= spotAttenuation(light.directionType.xyz, l, light.spot.xy);
#endif
    return intensity * attenuation;
#endif
}
