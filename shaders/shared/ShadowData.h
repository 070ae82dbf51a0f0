// Shadow maps as shading reads them (render/passes/ShadowPass, lights/shadow.glsl): one depth
// atlas for every map, and a buffer texture of RGBA32F texels holding one fixed-size record
// per shadowed light. A light's record is found from its GpuLight: spot.z = slot + 1 (0 = the
// light casts no shadow this frame).
//
// Record of slot s, from texel s * SPECULA_SHADOW_RECORD_TEXELS. The filters read as few
// texels as they need (every texel fetch is paid per pixel and light): "hard" and "pcf" read
// texels 0 and 1 and a view's first three (orthographic) or four (perspective) texels and its
// tile; PCSS also reads texel 2 and the view's depth range.
//   texel 0: x kind (SPECULA_SHADOW_*), y view count, z normal-offset bias (texels),
//            w directional: cascade blend (fraction of a cascade's depth range);
//              spot and point: the views' near plane (metres)
//   texel 1: cascades' far view depths (metres), x..w
//   texel 2: x light size (directional: tan of half the angular diameter; spot and point:
//            radius in metres); y..w unused (the filter is compiled in: SHADOW_FILTER_*)
//   then SPECULA_SHADOW_VIEW_TEXELS texels per view (cascade 0.., a spot's one, a point
//   light's six faces +X −X +Y −Y +Z −Z):
//     0-3: rows of world → atlas (uv, window depth, w); an orthographic view's last row is
//          (0, 0, 0, 1) and is not read
//     4:   the view's square tile in atlas uv: min.xy, z its side; w world size of a texel
//          (orthographic; perspective: at depth 1)
//     5:   x near, y far (metres), z 1 = orthographic (PCSS)
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
