// Shadow maps as shading reads them (render/passes/ShadowPass, lights/shadow.glsl): one depth
// atlas for every map, and a buffer texture of RGBA32F texels holding one fixed-size record
// per shadowed light. A light's record is found from its GpuLight: spot.z = slot + 1 (0 = the
// light casts no shadow this frame).
//
// Record of slot s, from texel s * SPECULA_SHADOW_RECORD_TEXELS:
//   texel 0: x kind (SPECULA_SHADOW_*), y view count, z light size (directional: tan of half
//            the angular diameter; spot and point: radius in metres), w filter (SPECULA_SHADOW_FILTER_*)
//   texel 1: x normal-offset bias (texels), y unused, z cascade blend (fraction of a cascade's
//            depth range), w unused (the filter's size is compiled in: SHADOW_TENT, SHADOW_TAPS)
//   texel 2: cascades' far view depths (metres), x..w
//   then SPECULA_SHADOW_VIEW_TEXELS texels per view (cascade 0.., a spot's one, a point
//   light's six faces +X −X +Y −Y +Z −Z):
//     0-3: columns of world → atlas (uv, window depth, w)
//     4:   the view's tile in atlas uv: min.xy, max.xy
//     5:   x near, y far (metres), z world size of a texel (orthographic; perspective: at
//          depth 1), w 1 = orthographic
#ifdef __cplusplus
#pragma once
#endif

#define SPECULA_SHADOW_DIRECTIONAL 0
#define SPECULA_SHADOW_SPOT 1
#define SPECULA_SHADOW_POINT 2

#define SPECULA_SHADOW_FILTER_HARD 0
#define SPECULA_SHADOW_FILTER_PCF 1
#define SPECULA_SHADOW_FILTER_PCSS 2

#define SPECULA_SHADOW_MAX_CASCADES 4
#define SPECULA_SHADOW_VIEW_TEXELS 6
#define SPECULA_SHADOW_RECORD_TEXELS (3 + 6 * SPECULA_SHADOW_VIEW_TEXELS)
