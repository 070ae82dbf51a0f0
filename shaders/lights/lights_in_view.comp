#version 450 core
// Light culling, step 1 of 3 (render/passes/LightCullPass): the point and spot lights that
// give light (shared/ClusterData.h, lightIsDark) and touch the view's frustum, as view-space
// CullLights in light order, and the directional lights' indices (every cluster's, listed once
// at the start of the index list). One work group: each invocation takes a run of lights,
// counts, a scan of the counts gives each run its place, and the runs are written in order, so
// the result does not depend on scheduling.
// shading/LightClusters.cpp's cullLights does the same on the CPU.
#define SPECULA_LIGHTS_STORAGE
#include "light_list.glsl"

layout(local_size_x = SPECULA_CULL_SCAN_GROUP) in;

layout(std430, binding = SPECULA_BINDING_CULL_LIGHTS) writeonly buffer CullBlock { CullLight cullLights[]; };
layout(std430, binding = SPECULA_BINDING_CLUSTERS) buffer ClusterBlock { uint words[]; } clusters;

uniform mat4 uView;
uniform vec4 uFrustum[6]; // view-space planes, inward unit normals (shading/LightClusters.h, viewFrustumPlanes)
uniform uint uBase;       // SPECULA_CLUSTER_HEADER_WORDS + 2 × clusters: where the directional list starts

shared uint sVisible[SPECULA_CULL_SCAN_GROUP];
shared uint sDirectional[SPECULA_CULL_SCAN_GROUP];

bool isDirectional(GpuLight light)
{
    return uint(light.directionType.w + 0.5) == SPECULA_LIGHT_DIRECTIONAL;
}

// As shading/LightClusters.cpp's cullLight.
CullLight toCullLight(GpuLight light, uint index)
{
    CullLight c;
    vec4 p = uView * vec4(light.positionRange.xyz, 1.0);
    c.sphere = vec4(p.xyz, light.positionRange.w > 0.0 ? light.positionRange.w : -1.0);
    c.cone = vec4(0.0, 0.0, 0.0, -2.0);
    bool spot = uint(light.directionType.w + 0.5) == SPECULA_LIGHT_SPOT;
    if (spot && light.spot.w >= 0.0) c.cone = vec4(normalize(mat3(uView) * light.directionType.xyz), light.spot.w);
    c.info = uvec4(index, 0u, 0u, 0u);
    return c;
}

bool inFrustum(vec4 sphere)
{
    if (sphere.w < 0.0) return true;
    bool inside = true;
    for (int i = 0; i < 6; ++i)
        inside = inside && uFrustum[i].x * sphere.x + uFrustum[i].y * sphere.y + uFrustum[i].z * sphere.z + uFrustum[i].w >= -sphere.w;
    return inside;
}

void main()
{
    uint t = gl_LocalInvocationID.x;
    uint n = frameLightCount();
    uint run = (n + SPECULA_CULL_SCAN_GROUP - 1u) / SPECULA_CULL_SCAN_GROUP;
    uint begin = min(t * run, n), end = min(begin + run, n);
    uint visible = 0u, directional = 0u;
    for (uint i = begin; i < end; ++i) {
        GpuLight light = lightAt(i);
        bool dir = isDirectional(light);
        directional += dir ? 1u : 0u;
        visible += !dir && !lightIsDark(light.colorIntensity) && inFrustum(toCullLight(light, i).sphere) ? 1u : 0u;
    }
    sVisible[t] = visible;
    sDirectional[t] = directional;
    barrier();
    if (t == 0u) {
        uint v = 0u, d = 0u;
        for (uint k = 0u; k < SPECULA_CULL_SCAN_GROUP; ++k) {
            uint a = sVisible[k], b = sDirectional[k];
            sVisible[k] = v;
            sDirectional[k] = d;
            v += a;
            d += b;
        }
        clusters.words[SPECULA_CLUSTER_WORD_DIRECTIONAL] = d;
        clusters.words[SPECULA_CLUSTER_WORD_BASE] = uBase;
        clusters.words[SPECULA_CLUSTER_WORD_VISIBLE] = v;
    }
    barrier();
    uint v = sVisible[t], d = sDirectional[t];
    for (uint i = begin; i < end; ++i) {
        GpuLight light = lightAt(i);
        if (isDirectional(light)) {
            clusters.words[uBase + d] = i;
            ++d;
        } else if (!lightIsDark(light.colorIntensity)) {
            CullLight c = toCullLight(light, i);
            if (inFrustum(c.sphere)) {
                cullLights[v] = c;
                ++v;
            }
        }
    }
}
