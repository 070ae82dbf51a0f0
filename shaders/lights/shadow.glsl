// How much of a light reaches a shading point, in [0, 1]: 0 in its shadow, 1 in full light.
// Every reflection model multiplies each light's contribution by it, so shadows come in here
// and nowhere else. The includer declares the frame block (frame: the camera's view for the
// cascades) before including this file.
//
// Without SHADOWS (no light of the frame has a map) it is exactly 1.0 and costs nothing.
// With it, a light whose GpuLight.spot.z is its slot + 1 is looked up in the shadow atlas
// (render/passes/ShadowPass, shared/ShadowData.h):
//   - the view: a directional light's cascade by view depth (blended into the next one over
//     the last part of its range), a spot light's one view, a point light's cube face;
//   - normal-offset bias (Holbein 2011, "Normal Offset Shadows"): the lookup moves along the
//     surface normal by a few texels' world size, more at grazing light (sin θ), which with the
//     shadow pass's slope-scaled depth bias keeps acne off surfaces lit at grazing angles;
//   - the filter: "hard" one hardware-compared bilinear tap; "pcf" taps on a Vogel disc
//     rotated per pixel (interleaved gradient noise, Jimenez 2014), each a hardware-compared
//     bilinear tap; "pcss" (Fernando 2005, "Percentage-Closer Soft Shadows"): a blocker search
//     on raw depths, the penumbra from the light's size by similar triangles, then PCF of
//     that width.
#include "../shared/Bindings.h"
#include "../shared/LightData.h"
#include "../shared/ShadowData.h"

#if defined(SHADOWS)
layout(binding = SPECULA_UNIT_SHADOW_ATLAS) uniform sampler2DShadow shadowAtlas;
layout(binding = SPECULA_UNIT_SHADOW_DEPTH) uniform sampler2D shadowDepth;
layout(binding = SPECULA_UNIT_SHADOW_RECORDS) uniform samplerBuffer shadowRecords;
// 0 for a draw whose model or shape does not receive shadows (receiveShadows: false).
uniform int uReceiveShadows = 1;

struct ShadowViewData {
    mat4 worldToAtlas;
    vec4 rect;   // tile in atlas uv: min.xy, max.xy
    vec4 params; // near, far, texel world size, orthographic
};

ShadowViewData shadowViewAt(int recordBase, int view)
{
    int t = recordBase + 3 + view * SPECULA_SHADOW_VIEW_TEXELS;
    ShadowViewData v;
    v.worldToAtlas = mat4(texelFetch(shadowRecords, t), texelFetch(shadowRecords, t + 1), texelFetch(shadowRecords, t + 2),
                          texelFetch(shadowRecords, t + 3));
    v.rect = texelFetch(shadowRecords, t + 4);
    v.params = texelFetch(shadowRecords, t + 5);
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

// Tap k of n on a Vogel (golden-angle) disc of radius 1, rotated by `angle`.
vec2 vogelTap(int k, int n, float angle)
{
    float r = sqrt((float(k) + 0.5) / float(n));
    float theta = float(k) * 2.39996323 + angle;
    return r * vec2(cos(theta), sin(theta));
}

// The view depth in metres of window depth `z` of a view (linear for orthographic views).
float shadowLinearDepth(ShadowViewData v, float z)
{
    float n = v.params.x, f = v.params.y;
    return v.params.w > 0.5 ? n + z * (f - n) : n * f / (f - z * (f - n));
}

// Percentage-closer filtering: the lit fraction over a disc of `radius` texels around uv.
float shadowPcf(ShadowViewData v, vec2 uv, float depth, float radius, int taps, float angle)
{
    vec2 texel = 1.0 / vec2(textureSize(shadowAtlas, 0));
    vec2 lo = v.rect.xy + 0.5 * texel, hi = v.rect.zw - 0.5 * texel;
    if (taps <= 1 || radius <= 0.0) return texture(shadowAtlas, vec3(clamp(uv, lo, hi), depth));
    float lit = 0.0;
    for (int k = 0; k < taps; ++k) {
        vec2 p = clamp(uv + vogelTap(k, taps, angle) * radius * texel, lo, hi);
        lit += texture(shadowAtlas, vec3(p, depth));
    }
    return lit / float(taps);
}

// The light seen through one view: `p` already offset along the normal.
float shadowInView(ShadowViewData v, vec3 p, vec4 record0, vec4 record1, float angle)
{
    vec4 c = v.worldToAtlas * vec4(p, 1.0);
    vec3 s = c.xyz / c.w;
    // Outside the view's depth range (beyond a cascade's far side) or its window (a Gouraud
    // vertex outside the camera's view, hence outside its cascade): nothing there casts.
    if (s.z >= 1.0 || any(lessThan(s.xy, v.rect.xy)) || any(greaterThan(s.xy, v.rect.zw))) return 1.0;
    int filterKind = int(record0.w + 0.5);
    int taps = int(record1.w + 0.5);
    float radius = record1.y;
    if (filterKind == SPECULA_SHADOW_FILTER_HARD) return shadowPcf(v, s.xy, s.z, 0.0, 1, angle);
    if (filterKind == SPECULA_SHADOW_FILTER_PCSS) {
        vec2 texel = 1.0 / vec2(textureSize(shadowAtlas, 0));
        vec2 lo = v.rect.xy + 0.5 * texel, hi = v.rect.zw - 0.5 * texel;
        bool ortho = v.params.w > 0.5;
        float receiver = shadowLinearDepth(v, s.z);
        float size = record0.z;
        // The texel's world size at the receiver; the region of the map whose blockers can
        // hide part of the light from the receiver (at most 32 texels).
        float texelAtReceiver = ortho ? v.params.z : v.params.z * receiver;
        float search = ortho ? size * (receiver - v.params.x) / v.params.z
                             : size * (receiver - v.params.x) / (receiver * v.params.z * v.params.x);
        search = clamp(search, 1.0, 32.0);
        float blockers = 0.0, blockerDepth = 0.0;
        for (int k = 0; k < 16; ++k) {
            vec2 q = clamp(s.xy + vogelTap(k, 16, angle) * search * texel, lo, hi);
            float z = textureLod(shadowDepth, q, 0.0).r;
            if (z < s.z) {
                blockers += 1.0;
                blockerDepth += shadowLinearDepth(v, z);
            }
        }
        if (blockers == 0.0) return 1.0;
        blockerDepth /= blockers;
        // Similar triangles: the penumbra's full width on the receiver.
        float penumbra = ortho ? 2.0 * size * (receiver - blockerDepth) : 2.0 * size * (receiver - blockerDepth) / blockerDepth;
        radius = clamp(0.5 * penumbra / texelAtReceiver, 0.5, 32.0);
        taps = max(taps, 16);
    }
    return shadowPcf(v, s.xy, s.z, radius, taps, angle);
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
    vec4 splits = texelFetch(shadowRecords, base + 2);
    float depth = -(frame.view * vec4(worldPosition, 1.0)).z;
    int count = int(record0.y + 0.5);
    for (int c = 0; c < count; ++c)
        if (depth <= splits[c]) return c;
    return -1;
}

float shadowVisibility(GpuLight light, vec3 worldPosition, vec3 normal, vec3 l)
{
    int slot = int(light.spot.z + 0.5) - 1;
    if (slot < 0 || uReceiveShadows == 0) return 1.0;
    int base = slot * SPECULA_SHADOW_RECORD_TEXELS;
    vec4 record0 = texelFetch(shadowRecords, base);
    vec4 record1 = texelFetch(shadowRecords, base + 1);
    int kind = int(record0.x + 0.5);
    float angle = 6.28318531 * shadowNoise(worldPosition);
    float NoL = clamp(dot(normal, l), 0.0, 1.0);
    float offsetTexels = record1.x * sqrt(1.0 - NoL * NoL);
    if (kind == SPECULA_SHADOW_DIRECTIONAL) {
        vec4 splits = texelFetch(shadowRecords, base + 2);
        int count = int(record0.y + 0.5);
        float depth = -(frame.view * vec4(worldPosition, 1.0)).z;
        int cascade = 0;
        while (cascade < count && depth > splits[cascade]) ++cascade;
        if (cascade >= count) return 1.0; // beyond the shadow distance
        ShadowViewData v = shadowViewAt(base, cascade);
        float lit = shadowInView(v, worldPosition + normal * (offsetTexels * v.params.z), record0, record1, angle);
        // Over the last part of a cascade's range, blend into the next one: no seam.
        float begin = cascade == 0 ? 0.0 : splits[cascade - 1];
        float blendStart = splits[cascade] - record1.z * (splits[cascade] - begin);
        if (cascade + 1 < count && depth > blendStart) {
            ShadowViewData w = shadowViewAt(base, cascade + 1);
            float next = shadowInView(w, worldPosition + normal * (offsetTexels * w.params.z), record0, record1, angle);
            lit = mix(lit, next, (depth - blendStart) / max(splits[cascade] - blendStart, 1e-6));
        }
        return lit;
    }
    vec3 toPoint = worldPosition - light.positionRange.xyz;
    int view = 0;
    float viewDepth;
    if (kind == SPECULA_SHADOW_POINT) {
        vec3 a = abs(toPoint);
        if (a.x >= a.y && a.x >= a.z) view = toPoint.x >= 0.0 ? 0 : 1;
        else if (a.y >= a.z) view = toPoint.y >= 0.0 ? 2 : 3;
        else view = toPoint.z >= 0.0 ? 4 : 5;
        viewDepth = max(a.x, max(a.y, a.z));
    } else {
        viewDepth = dot(toPoint, light.directionType.xyz);
    }
    ShadowViewData v = shadowViewAt(base, view);
    float texelAtPoint = v.params.z * max(viewDepth, v.params.x);
    return shadowInView(v, worldPosition + normal * (offsetTexels * texelAtPoint), record0, record1, angle);
}
#else
float shadowVisibility(GpuLight light, vec3 worldPosition, vec3 normal, vec3 l)
{
    return 1.0;
}

int shadowCascade(GpuLight light, vec3 worldPosition)
{
    return -2;
}
#endif
