// Clustered light lists (render/passes/LightCullPass, lights/light_list.glsl, shading/LightClusters).
//
// The view is cut into clusters ("froxels"): SPECULA_CLUSTER_TILES_X × _Y screen tiles (each
// ceil(width / 16) × ceil(height / 9) pixels, so a target of any size has at most 16 × 9 tiles)
// times SPECULA_CLUSTER_SLICES depth slices spaced exponentially from the near to the far plane
// (slice k spans near · (far/near)^(k/S) to near · (far/near)^((k+1)/S)). Each cluster's bounds
// are the view-space box around its eight corners, made on the CPU when the projection or the
// target size changes. Every frame the culling pass writes one buffer of 32-bit words:
//
//   [0, 8)              header: SPECULA_CLUSTER_WORD_*
//   [8, 8 + 2C)         per cluster c: the position of its list, its length
//   [base, base + D)    the directional lights (every cluster's, unculled), base = 8 + 2C
//   [base + D, ...)     the cluster lists, one after the other, light indices ascending
//
// Shaders read it through an R32UI texel view (unit SPECULA_UNIT_CLUSTERS); the compute passes
// write it as a storage block.
//
// The test of a light against a cluster is written once, below, and compiles as GLSL and as
// C++ (the CPU twin the tests compare with): float literals carry their f so both sides work
// in single precision.
#ifdef __cplusplus
#pragma once
#include <cmath>
#endif
#include "Prelude.h"

#define SPECULA_CLUSTER_TILES_X 16
#define SPECULA_CLUSTER_TILES_Y 9
#define SPECULA_CLUSTER_SLICES 24
#define SPECULA_CLUSTER_HEADER_WORDS 8
#define SPECULA_CLUSTER_WORD_DIRECTIONAL 0 // directional lights, listed at base
#define SPECULA_CLUSTER_WORD_BASE 1        // where the light indices start: 8 + 2 × clusters
#define SPECULA_CLUSTER_WORD_VISIBLE 2     // point and spot lights that touch the view's frustum
#define SPECULA_CLUSTER_WORD_ENTRIES 3     // entries of all the cluster lists together
#define SPECULA_CLUSTER_WORD_MAX 4         // the longest cluster list
#define SPECULA_CLUSTER_WORD_CAPACITY 5    // words the buffer holds (the fill pass writes no further)
#define SPECULA_CULL_GROUP 64              // local size of lights/cluster_cull.comp
#define SPECULA_CULL_SCAN_GROUP 256        // local size of lights_in_view.comp and cluster_scan.comp

SPECULA_SHARED_BEGIN

#ifdef __cplusplus
using vec3 = glm::vec3;
using glm::clamp;
using glm::dot;
using glm::max;
using std::sqrt;
using uint = uint32_t;
#define SPECULA_FUNCTION inline
#else
#define SPECULA_FUNCTION
#endif

/// A cluster's view-space box (w unused).
struct ClusterBounds {
    vec4 lo;
    vec4 hi;
};

/// A point or spot light as the culling passes test it, in view space.
struct CullLight {
    vec4 sphere; // xyz centre, w range (< 0: infinite)
    vec4 cone;   // xyz unit axis, w cos of the outer cone angle; w < -1: no cone to test (a point light)
    uvec4 info;  // x = index in the light buffer
};

// Whether the sphere (centre, radius; radius < 0 = infinite) reaches the box: the box's nearest
// point to the centre is within the radius (Arvo 1990, "A simple method for box-sphere
// intersection testing", Graphics Gems).
SPECULA_FUNCTION bool sphereTouchesBox(vec4 sphere, vec4 lo, vec4 hi)
{
    if (sphere.w < 0.0f) return true;
    vec3 c = vec3(sphere.x, sphere.y, sphere.z);
    vec3 d = clamp(c, vec3(lo.x, lo.y, lo.z), vec3(hi.x, hi.y, hi.z)) - c;
    return dot(d, d) <= sphere.w * sphere.w;
}

// Whether a spot light's cone (apex, unit axis, range, cos and sin of the outer angle, which
// is at most 90°) reaches the sphere (centre, radius) bounding a cluster: Wronski 2017, "Cull
// that cone! Improved cone/spotlight visibility tests for tiled and clustered lighting". The
// distance from the sphere's centre to the cone's surface, the sphere wholly in front of the
// range or behind the apex.
SPECULA_FUNCTION bool coneTouchesSphere(vec3 apex, vec3 axis, float range, float cosAngle, float sinAngle, vec3 centre, float radius)
{
    vec3 v = centre - apex;
    float lengthSquared = dot(v, v);
    float along = dot(v, axis);
    float across = sqrt(max(lengthSquared - along * along, 0.0f));
    float distanceToCone = cosAngle * across - along * sinAngle;
    bool outsideAngle = distanceToCone > radius;
    bool beyondRange = range >= 0.0f && along > radius + range;
    bool behindApex = along < -radius;
    return !(outsideAngle || beyondRange || behindApex);
}

// Whether a light gives no light (its colour × intensity, shared/LightData.h's colorIntensity,
// is zero: a zero intensity, a black colour, or a hidden node's light, which render/LightBuffer
// packs with intensity 0). Such a point or spot light is in no cluster's list and not counted
// in view; directional lights are listed whatever their intensity (the frame's uniforms count them).
SPECULA_FUNCTION bool lightIsDark(vec4 colorIntensity)
{
    return colorIntensity.w == 0.0f || (colorIntensity.x == 0.0f && colorIntensity.y == 0.0f && colorIntensity.z == 0.0f);
}

// Whether light `l` can reach any point of cluster `b`: its range sphere touches the box and,
// for a spot light, its cone touches the box's bounding sphere.
SPECULA_FUNCTION bool lightTouchesCluster(CullLight l, ClusterBounds b)
{
    if (!sphereTouchesBox(l.sphere, b.lo, b.hi)) return false;
    if (l.cone.w < -1.0f) return true;
    vec3 lo = vec3(b.lo.x, b.lo.y, b.lo.z), hi = vec3(b.hi.x, b.hi.y, b.hi.z);
    vec3 centre = (lo + hi) * 0.5f;
    vec3 extent = (hi - lo) * 0.5f;
    float radius = sqrt(dot(extent, extent));
    float sinAngle = sqrt(max(1.0f - l.cone.w * l.cone.w, 0.0f));
    return coneTouchesSphere(vec3(l.sphere.x, l.sphere.y, l.sphere.z), vec3(l.cone.x, l.cone.y, l.cone.z), l.sphere.w, l.cone.w,
                             sinAngle, centre, radius);
}

// The light-count view's bins: 0, 1, 2–3, 4–7, ..., 128–255, 256 and more (bin 1 + log2 n).
#define SPECULA_LIGHT_COUNT_BINS 10
SPECULA_FUNCTION uint lightCountBin(uint n)
{
    uint bin = 0u;
    for (uint m = n; m > 0u && bin < uint(SPECULA_LIGHT_COUNT_BINS - 1); m >>= 1u) ++bin;
    return bin;
}

// Each bin's colour (sRGB): black, then a heat ramp from blue to white.
SPECULA_FUNCTION vec4 lightCountColor(uint bin)
{
    if (bin == 0u) return vec4(0.0f, 0.0f, 0.0f, 1.0f);
    if (bin == 1u) return vec4(0.10f, 0.10f, 0.45f, 1.0f);
    if (bin == 2u) return vec4(0.15f, 0.30f, 0.90f, 1.0f);
    if (bin == 3u) return vec4(0.10f, 0.65f, 0.95f, 1.0f);
    if (bin == 4u) return vec4(0.10f, 0.80f, 0.45f, 1.0f);
    if (bin == 5u) return vec4(0.60f, 0.90f, 0.10f, 1.0f);
    if (bin == 6u) return vec4(1.00f, 0.85f, 0.10f, 1.0f);
    if (bin == 7u) return vec4(1.00f, 0.50f, 0.05f, 1.0f);
    if (bin == 8u) return vec4(0.90f, 0.10f, 0.05f, 1.0f);
    return vec4(1.0f, 1.0f, 1.0f, 1.0f);
}

SPECULA_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(specula::shared::ClusterBounds) == 32);
static_assert(sizeof(specula::shared::CullLight) == 48);
#endif
