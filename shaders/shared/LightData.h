// Punctual lights (one buffer, std430 layout, render/LightBuffer). Units as in KHR_lights_punctual:
// point and spot intensity in candela, directional in lux; colour is a linear RGB tint.
//
// The buffer is a LightHeader followed by as many GpuLight records as the header counts: no
// fixed count (a runtime-sized array to compute passes, texels to the others: lights/light_list.glsl). Light i lives at
// byte sizeof(LightHeader) + i * sizeof(GpuLight); both structs hold only vec4s and uvec4s, so
// std430, std140 and C++ agree on that layout.
#ifdef __cplusplus
#pragma once
#endif
#include "Prelude.h"

SPECULA_SHARED_BEGIN

#define SPECULA_LIGHT_DIRECTIONAL 0u
#define SPECULA_LIGHT_POINT 1u
#define SPECULA_LIGHT_SPOT 2u

struct LightHeader {
    uvec4 count;         // x = number of lights in the buffer
};

struct GpuLight {
    vec4 positionRange;  // xyz world position, w range in metres: the light's own, else from the cutoff (0 = infinite)
    vec4 directionType;  // xyz unit direction the light points to, w type (SPECULA_LIGHT_*)
    vec4 colorIntensity; // rgb colour, a intensity (cd or lux)
    vec4 spot;           // x = 1 / (cos inner - cos outer), y = -cos outer * x (KHR_lights_punctual), z = shadow slot + 1
                         // (0: no map), w = cos outer (the culling's cone)
};

SPECULA_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(specula::shared::LightHeader) == 16);
static_assert(sizeof(specula::shared::GpuLight) == 64);
#endif
