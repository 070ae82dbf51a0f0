// How much of a light reaches a shading point, per channel in [0, 1]: 0 in its shadow, 1 in full
// light, a colour behind glass. Every reflection model multiplies each light's contribution by
// it, so shadows come in here and nowhere else. The includer declares the frame block (frame:
// the camera's view for the cascades) before including this file.
//
// Without SHADOWS (no light of the frame has a map) it is exactly 1.0 and costs nothing.
// With it, a light whose GpuLight.spot.z is its slot + 1 is looked up in the shadow atlas
// (render/passes/ShadowPass, shared/ShadowData.h):
//   - the view: a directional light's cascade by view depth (dithered into the next one over
//     the last part of its range), a spot light's one view, a point light's cube face;
//   - normal-offset bias (Holbein 2011, "Normal Offset Shadows"): the lookup moves along the
//     surface normal by a few texels' world size, more at grazing light (sin θ), which with the
//     shadow pass's slope-scaled depth bias keeps acne off surfaces lit at grazing angles;
//   - the filter: "hard" one hardware-compared bilinear tap; "pcf" a tent of 3 × 3 texels
//     (SHADOW_TENT 5: 5 × 5) moved with the lookup's sub-texel position, in 4 (9)
//     hardware-compared bilinear taps (shadowTent); "pcss" (Fernando 2005, "Percentage-Closer
//     Soft Shadows"): a blocker search on raw depths, the penumbra from the light's size by
//     similar triangles, then percentage-closer filtering of that width on a Vogel disc
//     rotated per pixel (interleaved gradient noise, Jimenez 2014).
//   - SHADOW_TINT (a frame with surfaces that let light through: render::tintsShadow): the
//     filtered visibility times the tint map's colour, what those surfaces let through, where
//     the point lies beyond the nearest of them (four texels each compared, then weighted
//     bilinearly; the map at the atlas's resolution up to 4096², half of it above).
// The filter, its taps and the kinds of shadowed light are compile-time (SHADOW_* defines of
// shading/VariantKey.h): the program holds only the paths the frame uses.
#include "../shared/Bindings.h"
#include "../shared/LightData.h"
#include "../shared/ShadowData.h"

#if defined(SHADOWS)
layout(binding = SPECULA_UNIT_SHADOW_ATLAS) uniform sampler2DShadow shadowAtlas;
layout(binding = SPECULA_UNIT_SHADOW_DEPTH) uniform sampler2D shadowDepth;
layout(binding = SPECULA_UNIT_SHADOW_RECORDS) uniform samplerBuffer shadowRecords;
// 0 for a draw whose model or shape does not receive shadows (receiveShadows: false).
uniform int uReceiveShadows = 1;
#if defined(SHADOW_TINT)
layout(binding = SPECULA_UNIT_SHADOW_TINT) uniform sampler2D shadowTint;
#endif

struct ShadowViewData {
    vec4 row0, row1, row2, row3; // world → atlas, by rows (orthographic: row3 = (0, 0, 0, 1))
    vec4 rect;                   // tile in atlas uv: min.xy, max.xy
    float texelWorld;            // world size of a texel (perspective: at depth 1)
    int texel;                   // the view's first texel in the records
};

// A view's texels as the hard and PCF filters need them: an orthographic view (a cascade) has
// no fourth row to read (`orthographic` is a constant where this is called).
ShadowViewData shadowViewAt(int recordBase, int view, bool orthographic)
{
    int t = recordBase + 3 + view * SPECULA_SHADOW_VIEW_TEXELS;
    ShadowViewData v;
    v.row0 = texelFetch(shadowRecords, t);
    v.row1 = texelFetch(shadowRecords, t + 1);
    v.row2 = texelFetch(shadowRecords, t + 2);
    v.row3 = orthographic ? vec4(0.0, 0.0, 0.0, 1.0) : texelFetch(shadowRecords, t + 3);
    vec4 tile = texelFetch(shadowRecords, t + 4);
    v.rect = vec4(tile.xy, tile.xy + tile.z);
    v.texelWorld = tile.w;
    v.texel = t;
    return v;
}

// A per-pixel rotation in [0, 1): interleaved gradient noise of the window position in the
// fragment stage, a hash of the world position in the vertex stage (Gouraud).
float shadowNoise(vec3 worldPosition)
{
#if defined(SPECULA_FRAGMENT_STAGE)
    return fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
#else
    return fract(sin(dot(worldPosition, vec3(12.9898, 78.233, 37.719))) * 43758.5453);
#endif
}

#if !defined(SHADOW_TAPS)
#define SHADOW_TAPS 16
#endif

// Vogel (golden-angle) discs of radius 1 (PCSS): tap k of n at radius sqrt((k + 0.5) / n), angle
// k × 2.39996323 (the golden angle), so the last taps are the outermost and spread around the
// disc. Constants, rotated per pixel by a 2×2 matrix: no trigonometry per tap. The 16-tap disc
// is the blocker search's, and the filter's at the default 16 taps.
const vec2 kVogel16[16] = vec2[](
    vec2(0.176777, 0.000000), vec2(-0.225772, 0.206826), vec2(0.034558, -0.393771), vec2(0.284571, 0.371173),
    vec2(-0.522223, -0.092374), vec2(0.494695, -0.314685), vec2(-0.165466, 0.615525), vec2(-0.315561, -0.607594),
    vec2(0.684642, 0.250030), vec2(-0.712256, 0.294009), vec2(0.343355, -0.733729), vec2(0.253730, 0.808932),
    vec2(-0.764746, -0.443186), vec2(0.897134, -0.197232), vec2(-0.547507, 0.778772), vec2(-0.126487, -0.976090));
#if SHADOW_TAPS == 32
const vec2 kShadowDisc[32] = vec2[](
    vec2(0.125000, 0.000000), vec2(-0.159645, 0.146248), vec2(0.024436, -0.278438), vec2(0.201222, 0.262459),
    vec2(-0.369268, -0.065318), vec2(0.349802, -0.222516), vec2(-0.117002, 0.435242), vec2(-0.223136, -0.429634),
    vec2(0.484115, 0.176798), vec2(-0.503641, 0.207896), vec2(0.242788, -0.518824), vec2(0.179414, 0.572001),
    vec2(-0.540757, -0.313380), vec2(0.634370, -0.139464), vec2(-0.387146, 0.550675), vec2(-0.089440, -0.690200),
    vec2(0.549072, 0.462758), vec2(-0.738878, 0.030555), vec2(0.538955, -0.536332), vec2(-0.036058, 0.779792),
    vec2(-0.512818, -0.614527), vec2(0.812360, 0.109302), vec2(-0.688311, 0.478909), vec2(0.188086, -0.836061),
    vec2(0.435033, 0.759191), vec2(-0.850448, -0.271316), vec2(0.826102, -0.381680), vec2(-0.357888, 0.855156),
    vec2(-0.319407, -0.888034), vec2(0.849909, 0.446688), vec2(-0.944035, 0.248844), vec2(0.536596, -0.834530));
#else
#define kShadowDisc kVogel16
#endif

// The view depth in metres of window depth `z` of a view (linear for orthographic views), from
// the view's depth range (its texel 5: near, far, orthographic).
float shadowLinearDepth(vec4 range, float z)
{
    float n = range.x, f = range.y;
    return range.z > 0.5 ? n + z * (f - n) : n * f / (f - z * (f - n));
}

#if !defined(SHADOW_TENT)
#define SHADOW_TENT 3
#endif
#if SHADOW_TENT == 5
#define SHADOW_TENT_TAPS 3
#else
#define SHADOW_TENT_TAPS 2
#endif

// One axis of the tent: the kernel k = [1 2 1] (SHADOW_TENT 5: [1 2 3 2 1]) over the texels
// around the lookup, moved by its sub-texel position s ∈ [0, 1) with linear weights — texel j
// (from the first, (n − 1) / 2 before the one at or below the lookup) weighs
// (1 − s) k[j] + s k[j − 1], so the filter slides smoothly from texel to texel. Pairs of
// neighbouring texels are one bilinear tap each: weight w = their two weights' sum, at their
// first texel + the second's weight / w (texels from the one at or below the lookup).
void shadowTentAxis(float s, out float w[SHADOW_TENT_TAPS], out float at[SHADOW_TENT_TAPS])
{
#if SHADOW_TENT == 5
    w[0] = 3.0 - 2.0 * s; // texels −2, −1: 1 − s, 2 − s
    at[0] = -2.0 + (2.0 - s) / w[0];
    w[1] = 5.0;           // texels 0, 1: 3 − s, 2 + s
    at[1] = (2.0 + s) / 5.0;
    w[2] = 1.0 + 2.0 * s; // texels 2, 3: 1 + s, s
    at[2] = 2.0 + s / w[2];
#else
    w[0] = 3.0 - 2.0 * s; // texels −1, 0: 1 − s, 2 − s
    at[0] = -1.0 + (2.0 - s) / w[0];
    w[1] = 1.0 + 2.0 * s; // texels 1, 2: 1 + s, s
    at[1] = 1.0 + s / w[1];
#endif
}

// Percentage-closer filtering with the tent (the "pcf" filter): SHADOW_TENT_TAPS² hardware-
// compared bilinear taps, each clamped into the view's tile; no noise. A 3 × 3 tent blurs
// about as much as 16 taps on a disc of 1.5 texels (σ 0.82 against 0.85 texel), in 4 taps.
float shadowTent(vec4 rect, vec2 uv, float depth)
{
    vec2 size = vec2(textureSize(shadowAtlas, 0));
    vec2 texel = 1.0 / size;
    vec2 lo = rect.xy + 0.5 * texel, hi = rect.zw - 0.5 * texel;
    vec2 x = uv * size - 0.5; // texel centres at whole numbers
    vec2 base = floor(x);
    vec2 s = x - base;
    float wx[SHADOW_TENT_TAPS], ax[SHADOW_TENT_TAPS], wy[SHADOW_TENT_TAPS], ay[SHADOW_TENT_TAPS];
    shadowTentAxis(s.x, wx, ax);
    shadowTentAxis(s.y, wy, ay);
    float lit = 0.0;
    for (int j = 0; j < SHADOW_TENT_TAPS; ++j)
        for (int i = 0; i < SHADOW_TENT_TAPS; ++i)
            lit += wx[i] * wy[j] * texture(shadowAtlas, vec3(clamp((base + vec2(ax[i], ay[j]) + 0.5) * texel, lo, hi), depth));
    const float total = SHADOW_TENT == 5 ? 9.0 : 4.0; // the kernel's sum along one axis
    return lit * (1.0 / (total * total));
}

// The hard filter: one hardware-compared bilinear tap, clamped into the view's tile.
float shadowHard(vec4 rect, vec2 uv, float depth)
{
    vec2 texel = 1.0 / vec2(textureSize(shadowAtlas, 0));
    return texture(shadowAtlas, vec3(clamp(uv, rect.xy + 0.5 * texel, rect.zw - 0.5 * texel), depth));
}

// PCSS's filter: percentage-closer filtering over a disc of `radius` texels, SHADOW_TAPS
// hardware-compared bilinear taps, the disc turned by `rotation` (cos, sin). The four outermost
// taps go first: where they agree (all lit or all in shadow) the pixel is done — the disc inside
// them almost always agrees too — and only pixels in a penumbra pay for the rest.
float shadowDisc(vec4 rect, vec2 uv, float depth, float radius, vec2 rotation)
{
    vec2 texel = 1.0 / vec2(textureSize(shadowAtlas, 0));
    vec2 lo = rect.xy + 0.5 * texel, hi = rect.zw - 0.5 * texel;
    mat2 turn = mat2(rotation.x, rotation.y, -rotation.y, rotation.x) * radius;
    float lit = 0.0;
    for (int k = SHADOW_TAPS - 4; k < SHADOW_TAPS; ++k)
        lit += texture(shadowAtlas, vec3(clamp(uv + (turn * kShadowDisc[k]) * texel, lo, hi), depth));
    // The rest in a loop under the if: a CPU rasteriser runs both sides of an if, but leaves a
    // loop as soon as none of its pixels is still in it.
    bool penumbra = lit > 0.0 && lit < 4.0;
    if (penumbra)
    for (int k = 0; k < SHADOW_TAPS - 4; ++k)
        lit += texture(shadowAtlas, vec3(clamp(uv + (turn * kShadowDisc[k]) * texel, lo, hi), depth));
    return penumbra ? lit * (1.0 / float(SHADOW_TAPS)) : lit * 0.25;
}

#if defined(SHADOW_TINT)
// One texel of the tint map: what the surfaces over it let through where `depth` lies beyond the
// nearest of them (the map's alpha), white elsewhere.
vec3 shadowTintTexel(ivec2 texel, ivec2 lo, ivec2 hi, float depth)
{
    vec4 tint = texelFetch(shadowTint, clamp(texel, lo, hi), 0);
    return depth > tint.a ? tint.rgb : vec3(1.0);
}

// The tint at atlas point `uv`: the four nearest texels each compared with `depth`, then
// weighted bilinearly (as percentage-closer filtering does), so that the tint's edges are
// smooth where a filtered depth would cut them along the texels; texels from the view's tile.
vec3 shadowTintAt(vec4 rect, vec2 uv, float depth)
{
    vec2 size = vec2(textureSize(shadowTint, 0));
    ivec2 lo = ivec2(rect.xy * size + 0.5), hi = ivec2(rect.zw * size - 0.5);
    vec2 x = uv * size - 0.5;
    vec2 f = fract(x);
    ivec2 t = ivec2(floor(x));
    return mix(mix(shadowTintTexel(t, lo, hi, depth), shadowTintTexel(t + ivec2(1, 0), lo, hi, depth), f.x),
               mix(shadowTintTexel(t + ivec2(0, 1), lo, hi, depth), shadowTintTexel(t + ivec2(1, 1), lo, hi, depth), f.x), f.y);
}
#endif

// The filtered depth test at atlas point s (xy in the view's tile, z its depth).
float shadowFiltered(ShadowViewData v, vec3 s, int recordBase, vec2 rotation)
{
#if defined(SHADOW_FILTER_PCSS)
    vec2 texel = 1.0 / vec2(textureSize(shadowAtlas, 0));
    vec2 lo = v.rect.xy + 0.5 * texel, hi = v.rect.zw - 0.5 * texel;
    vec4 range = texelFetch(shadowRecords, v.texel + 5);
    bool ortho = range.z > 0.5;
    float receiver = shadowLinearDepth(range, s.z);
    float size = texelFetch(shadowRecords, recordBase + 2).x;
    // The texel's world size at the receiver; the region of the map whose blockers can
    // hide part of the light from the receiver (at most 32 texels).
    float texelAtReceiver = ortho ? v.texelWorld : v.texelWorld * receiver;
    float search = ortho ? size * (receiver - range.x) / v.texelWorld
                         : size * (receiver - range.x) / (receiver * v.texelWorld * range.x);
    search = clamp(search, 1.0, 32.0);
    float blockers = 0.0, blockerDepth = 0.0;
    mat2 turn = mat2(rotation.x, rotation.y, -rotation.y, rotation.x) * search;
    for (int k = 0; k < 16; ++k) {
        vec2 q = clamp(s.xy + (turn * kVogel16[k]) * texel, lo, hi);
        float z = textureLod(shadowDepth, q, 0.0).r;
        if (z < s.z) {
            blockers += 1.0;
            blockerDepth += shadowLinearDepth(range, z);
        }
    }
    if (blockers == 0.0) return 1.0;
    blockerDepth /= blockers;
    // Similar triangles: the penumbra's full width on the receiver.
    float penumbra = ortho ? 2.0 * size * (receiver - blockerDepth) : 2.0 * size * (receiver - blockerDepth) / blockerDepth;
    float radius = clamp(0.5 * penumbra / texelAtReceiver, 0.5, 32.0);
    return shadowDisc(v.rect, s.xy, s.z, radius, rotation);
#elif defined(SHADOW_FILTER_HARD)
    return shadowHard(v.rect, s.xy, s.z);
#else
    return shadowTent(v.rect, s.xy, s.z);
#endif
}

// The light seen through one view: `p` already offset along the normal.
vec3 shadowInView(ShadowViewData v, vec3 p, int recordBase, vec2 rotation)
{
    vec4 q = vec4(p, 1.0);
    vec3 s = vec3(dot(v.row0, q), dot(v.row1, q), dot(v.row2, q)) / dot(v.row3, q);
    // Outside the view's depth range (beyond a cascade's far side) or its window (a Gouraud
    // vertex outside the camera's view, hence outside its cascade): nothing there casts.
    if (s.z >= 1.0 || any(lessThan(s.xy, v.rect.xy)) || any(greaterThan(s.xy, v.rect.zw))) return vec3(1.0);
    float lit = shadowFiltered(v, s, recordBase, rotation);
#if defined(SHADOW_TINT)
    return lit * shadowTintAt(v.rect, s.xy, s.z);
#else
    return vec3(lit);
#endif
}

// The cascade of a directional light's map at `worldPosition` (0..count-1); -1 beyond the
// shadow distance; -2 when the light has no cascades (the cascades debug view).
int shadowCascade(GpuLight light, vec3 worldPosition)
{
    int slot = int(light.spot.z + 0.5) - 1;
    if (slot < 0) return -2;
    int base = slot * SPECULA_SHADOW_RECORD_TEXELS;
    vec4 record0 = texelFetch(shadowRecords, base);
    if (int(record0.x + 0.5) != SPECULA_SHADOW_DIRECTIONAL) return -2;
    vec4 splits = texelFetch(shadowRecords, base + 1);
    float depth = -(frame.view * vec4(worldPosition, 1.0)).z;
    int count = int(record0.y + 0.5);
    for (int c = 0; c < count; ++c)
        if (depth <= splits[c]) return c;
    return -1;
}

// Only the kinds of shadowed light the frame has are compiled in (SHADOW_DIRECTIONAL,
// SHADOW_SPOT, SHADOW_POINT: shading/VariantKey.h).
vec3 shadowVisibility(GpuLight light, vec3 worldPosition, vec3 normal, vec3 l)
{
    int slot = int(light.spot.z + 0.5) - 1;
    if (slot < 0 || uReceiveShadows == 0) return vec3(1.0);
    int base = slot * SPECULA_SHADOW_RECORD_TEXELS;
    vec4 record0 = texelFetch(shadowRecords, base);
    int kind = int(record0.x + 0.5);
    float noise = shadowNoise(worldPosition);
    float angle = 6.28318531 * noise;
    vec2 rotation = vec2(cos(angle), sin(angle));
    float NoL = clamp(dot(normal, l), 0.0, 1.0);
    float offsetTexels = record0.z * sqrt(1.0 - NoL * NoL);
#if defined(SHADOW_DIRECTIONAL)
#if defined(SHADOW_SPOT) || defined(SHADOW_POINT)
    if (kind == SPECULA_SHADOW_DIRECTIONAL)
#endif
    {
        vec4 splits = texelFetch(shadowRecords, base + 1);
        int count = int(record0.y + 0.5);
        float depth = -(frame.view * vec4(worldPosition, 1.0)).z;
        int cascade = 0;
        while (cascade < count && depth > splits[cascade]) ++cascade;
        if (cascade >= count) return vec3(1.0); // beyond the shadow distance
        // Over the last part of a cascade's range, blend into the next one (no seam) by
        // dithering: a pixel reads the next cascade with the blend's weight as probability,
        // so that one lookup per light is made, not two.
        float begin = cascade == 0 ? 0.0 : splits[cascade - 1];
        float blendStart = splits[cascade] - record0.w * (splits[cascade] - begin);
        float weight = (depth - blendStart) / max(splits[cascade] - blendStart, 1e-6);
        if (cascade + 1 < count && fract(noise * 7.0 + 0.5) < weight) ++cascade;
        ShadowViewData v = shadowViewAt(base, cascade, true);
        return shadowInView(v, worldPosition + normal * (offsetTexels * v.texelWorld), base, rotation);
    }
#endif
#if defined(SHADOW_SPOT) || defined(SHADOW_POINT)
    vec3 toPoint = worldPosition - light.positionRange.xyz;
    int view = 0;
    float viewDepth;
#if defined(SHADOW_POINT) && defined(SHADOW_SPOT)
    if (kind == SPECULA_SHADOW_POINT)
#endif
#if defined(SHADOW_POINT)
    {
        vec3 a = abs(toPoint);
        if (a.x >= a.y && a.x >= a.z) view = toPoint.x >= 0.0 ? 0 : 1;
        else if (a.y >= a.z) view = toPoint.y >= 0.0 ? 2 : 3;
        else view = toPoint.z >= 0.0 ? 4 : 5;
        viewDepth = max(a.x, max(a.y, a.z));
    }
#endif
#if defined(SHADOW_POINT) && defined(SHADOW_SPOT)
    else
#endif
#if defined(SHADOW_SPOT)
    {
        viewDepth = dot(toPoint, light.directionType.xyz);
    }
#endif
    ShadowViewData v = shadowViewAt(base, view, false);
    float texelAtPoint = v.texelWorld * max(viewDepth, record0.w); // record0.w: the views' near plane
    return shadowInView(v, worldPosition + normal * (offsetTexels * texelAtPoint), base, rotation);
#else
    return vec3(1.0);
#endif
}
#else
vec3 shadowVisibility(GpuLight light, vec3 worldPosition, vec3 normal, vec3 l)
{
    return vec3(1.0);
}

int shadowCascade(GpuLight light, vec3 worldPosition)
{
    return -2;
}
#endif
