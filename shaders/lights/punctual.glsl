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
vec3 lightIlluminance(GpuLight light, vec3 worldPosition, out vec3 l)
{
    uint type = uint(light.directionType.w + 0.5);
    vec3 intensity = light.colorIntensity.rgb * light.colorIntensity.a;
    if (type == SPECULA_LIGHT_DIRECTIONAL) {
        l = -light.directionType.xyz;
        return intensity;
    }
    vec3 toLight = light.positionRange.xyz - worldPosition;
    float distance = length(toLight);
    l = toLight / max(distance, 1e-8);
    float attenuation = rangeAttenuation(light.positionRange.w, distance);
    if (type == SPECULA_LIGHT_SPOT) attenuation *= spotAttenuation(light.directionType.xyz, l, light.spot.xy);
    return intensity * attenuation;
}
