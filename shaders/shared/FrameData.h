// Per-frame constants (uniform buffer, std140).
#ifdef __cplusplus
#pragma once
#endif
#include "Prelude.h"

SPECULA_SHARED_BEGIN

#define SPECULA_TONEMAP_NONE 0u
#define SPECULA_TONEMAP_REINHARD 1u
#define SPECULA_TONEMAP_REINHARD_EXT 2u
#define SPECULA_TONEMAP_ACES 3u
#define SPECULA_TONEMAP_NEUTRAL 4u
#define SPECULA_TONEMAP_AGX 5u

struct FrameData {
    mat4 view;
    mat4 projection;
    mat4 viewProjection;
    vec4 cameraPosition;   // xyz world position, w unused
    vec4 exposure;         // x = 2^EV (linear scale), y = white point for Reinhard extended
    vec4 ambient;          // rgb constant ambient radiance (cd/m^2) times albedo; w unused
    uvec4 options;         // x = tone mapper (SPECULA_TONEMAP_*), y = light count
    // The cluster grid of the light lists (shared/ClusterData.h, shading/LightClusters.h):
    uvec4 clusterGrid;     // x tiles across, y tiles up, z depth slices, w tile width | tile height << 16 (pixels)
    vec4 clusterDepth;     // slice = floor(log(view depth) * x + y); zw = the target's width and height
    uvec4 clusterLists;    // x directional lights (every cluster's), y the word their list starts at (ClusterData.h)
    vec4 clusterTiles;     // xy 1 / tile width and height (pixels): a multiply, not a vector integer division
};

SPECULA_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(specula::shared::FrameData) == 3 * 64 + 8 * 16);
#endif
