// Punctual lights (uniform buffer, std140). Units as in KHR_lights_punctual: point and spot
// intensity in candela, directional in lux; colour is a linear RGB tint.
#ifdef __cplusplus
#pragma once
#endif
#include "Prelude.h"

SPECULA_SHARED_BEGIN

#define SPECULA_LIGHT_DIRECTIONAL 0u
#define SPECULA_LIGHT_POINT 1u
#define SPECULA_LIGHT_SPOT 2u
// 16 + 255 * 64 = 16336 bytes: fits the 16 KiB GL_MAX_UNIFORM_BLOCK_SIZE every GL 4.5 driver offers.
#define SPECULA_MAX_LIGHTS 255

struct GpuLight {
    vec4 positionRange;  // xyz world position, w range in metres (0 = infinite)
    vec4 directionType;  // xyz unit direction the light points to, w type (SPECULA_LIGHT_*)
    vec4 colorIntensity; // rgb colour, a intensity (cd or lux)
    vec4 spot;           // x = 1 / (cos inner - cos outer), y = -cos outer * x (KHR_lights_punctual)
};

struct LightBlock {
    uvec4 count;         // x = number of lights in use
    GpuLight lights[SPECULA_MAX_LIGHTS];
};

SPECULA_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(specula::shared::GpuLight) == 64);
static_assert(sizeof(specula::shared::LightBlock) == 16 + SPECULA_MAX_LIGHTS * 64);
#endif
