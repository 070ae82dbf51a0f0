// Image-based lighting constants (uniform buffer, std140).
#ifdef __cplusplus
#pragma once
#endif
#include "Prelude.h"

// The brightest parts of the environment (at most this many), summed per pixel by the diffuse
// term beside the irradiance cube (shading/EnvironmentMap: splitIrradiance). They reach the
// forward programs as constants (IBL_SOURCE_COUNT, ibl/ibl.glsl), not through this block.
#define SPECULA_IBL_BRIGHT_SOURCES 32

SPECULA_SHARED_BEGIN

struct EnvironmentData {
    vec4 sh[9];                 // order-2 SH of the environment radiance (rgb), environment space
    mat4 worldToEnvironment;    // rotation about +Y taking world directions to the map's own
    mat4 inverseViewProjection; // for the skybox's view rays
    vec4 params;                // x intensity, y prefiltered mip count, z skybox lod (-1 = sharp), w skybox on
};

SPECULA_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(specula::shared::EnvironmentData) == 9 * 16 + 2 * 64 + 16);
#endif
