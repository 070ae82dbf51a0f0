// Billboard instances (storage buffer, std430): one record per billboard. What a group shares
// (kind, size, anchor, sprite, alpha mode) is set per draw by BillboardPass.
#ifdef __cplusplus
#pragma once
#endif
#include "Prelude.h"

SPECULA_SHARED_BEGIN

// Values of scene::BillboardKind.
#define SPECULA_BILLBOARD_POINT_SPRITE 0u
#define SPECULA_BILLBOARD_AXIS_ALIGNED 1u
#define SPECULA_BILLBOARD_ARBITRARY_AXIS 2u

struct GpuBillboard {
    vec4 positionScale; // xyz world position (metres), w multiplies the group's size
    vec4 tint;          // rgb radiance of a white texel, cd/m² (group tint x billboard tint), w the group's Doom sector light / 255
    vec4 axis;          // xyz the axis an arbitrary-axis billboard turns about, w unused
};

SPECULA_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(specula::shared::GpuBillboard) == 48);
#endif
