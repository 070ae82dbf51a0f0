// The one way a shader reaches the lights: the list of lights that can touch a shading point,
// then each light of it by index. Every light loop is written
//
//     LightList list = lightList(worldPosition, gl_FragCoord);
//     for (uint k = 0u; k < list.count; ++k) {
//         uint index = lightListIndex(list, k);
//         GpuLight light = lightAt(index);
//         ...
//     }
//
// The list is the shading point's cluster's (clustered forward shading, docs/clustered-shading.md;
// as Bevy's clustered_forward.wgsl finds it with fragment_cluster_index and
// unpack_offset_and_counts): the frame's directional lights, then the point and spot lights the
// culling pass (render/passes/LightCullPass) found reaching the cluster, the screen tile and
// view-depth slice the point lies in. The loop's trip count is that list's length: a CPU
// rasteriser (llvmpipe) leaves a loop once every lane of it is done, but runs both sides of an
// if. With LIGHTS_ALL (the brute-force frame, --light-culling none) and in compute passes the
// list is every light of the frame.
#include "../shared/Bindings.h"
#include "../shared/ClusterData.h"
#include "../shared/LightData.h"

// render/LightBuffer: a LightHeader, then header.count.x lights, read two ways. The shading
// passes read a texel view of the bytes (16 bytes a texel: the header, then four a light): on
// llvmpipe a texelFetch costs far less than a storage-block read per fragment. A compute pass
// that defines SPECULA_LIGHTS_STORAGE reads the same bytes as the std430 block. Nothing writes.
#ifdef SPECULA_LIGHTS_STORAGE
layout(std430, binding = SPECULA_BINDING_LIGHTS) readonly buffer LightsBlock {
    LightHeader header;
    GpuLight lights[];
} lightData;
#else
layout(binding = SPECULA_UNIT_LIGHTS) uniform usamplerBuffer lightTexels;
#endif

#if !defined(SPECULA_LIGHTS_STORAGE) && !defined(LIGHTS_ALL)
#define SPECULA_CLUSTERED_LIGHTS
#include "../common/frame_block.glsl"
// The culling pass's words (shared/ClusterData.h), an R32UI view.
layout(binding = SPECULA_UNIT_CLUSTERS) uniform usamplerBuffer clusterWords;
#endif

// Every light of the frame, whatever the shading point (the debug views show the first light).
// With LIGHT_COUNT (LIGHTS_ALL and a few lights: shading/VariantKey's LightVariant) the count
// is a constant of the program, so a light loop has a constant trip count and is unrolled
// (on llvmpipe: learnopengl's forward pass 35 → 28 ms, docs/performance.md).
uint frameLightCount()
{
#if defined(LIGHT_COUNT) && !defined(SPECULA_LIGHTS_STORAGE)
    return LIGHT_COUNT;
#elif defined(SPECULA_LIGHTS_STORAGE)
    return lightData.header.count.x;
#else
    return texelFetch(lightTexels, 0).x;
#endif
}

// The lights that may reach a shading point: light indices lightListIndex(list, 0 .. count-1).
// Entries [0, directional) are the directional lights, listed from word `base`; the others
// are the cluster's, from word `first` + k. `direct`: every light, entry k is light k (only the
// vertex stage, SPECULA_VERTEX_STAGE, has such lists besides LIGHTS_ALL: a vertex outside the view).
struct LightList {
    uint first;
    uint count;
    uint directional;
    uint base;
    bool direct;
};

LightList allLights()
{
    return LightList(0u, frameLightCount(), 0u, 0u, true);
}

#ifdef SPECULA_CLUSTERED_LIGHTS
// The list of cluster `cluster`.
LightList clusterList(uint cluster)
{
    // The header's directional count and base, as the frame's uniforms: two fetches a pixel fewer.
    uint directional = frame.clusterLists.x;
    uint base = frame.clusterLists.y;
    int record = SPECULA_CLUSTER_HEADER_WORDS + 2 * int(cluster);
    uint first = texelFetch(clusterWords, record).x;
    uint count = texelFetch(clusterWords, record + 1).x;
    return LightList(first - directional, directional + count, directional, base, false);
}

// The cluster of window position `window` (pixels) at view depth `depth`: as
// shading/LightClusters.h's ClusterGrid::clusterAt.
uint clusterIndex(vec2 window, float depth)
{
    uvec4 grid = frame.clusterGrid;
    uvec2 tile = min(uvec2(max(window, vec2(0.0)) * frame.clusterTiles.xy), grid.xy - 1u);
    float s = floor(log(max(depth, 1e-6)) * frame.clusterDepth.x + frame.clusterDepth.y);
    uint slice = uint(clamp(s, 0.0, float(grid.z - 1u)));
    return tile.x + grid.x * (tile.y + grid.y * slice);
}
#endif

// The lights that may reach `worldPosition`, seen at window position `fragCoord`
// (gl_FragCoord: a cluster is a screen tile and a depth slice).
LightList lightList(vec3 worldPosition, vec4 fragCoord)
{
#ifdef SPECULA_CLUSTERED_LIGHTS
    float depth = -dot(vec4(frame.view[0].z, frame.view[1].z, frame.view[2].z, frame.view[3].z), vec4(worldPosition, 1.0));
    return clusterList(clusterIndex(fragCoord.xy, depth));
#else
    return allLights();
#endif
}

// For stages without gl_FragCoord (the Gouraud vertex shader): the cluster of `worldPosition`
// projected into the view; a point outside the view lies in no cluster and gets every light.
LightList lightList(vec3 worldPosition)
{
#ifdef SPECULA_CLUSTERED_LIGHTS
    vec4 clip = frame.viewProjection * vec4(worldPosition, 1.0);
    if (!all(lessThanEqual(abs(clip.xyz), vec3(clip.w))) || clip.w <= 0.0) return allLights();
    vec2 window = (clip.xy / clip.w * 0.5 + 0.5) * frame.clusterDepth.zw;
    float depth = -dot(vec4(frame.view[0].z, frame.view[1].z, frame.view[2].z, frame.view[3].z), vec4(worldPosition, 1.0));
    return clusterList(clusterIndex(window, depth));
#else
    return allLights();
#endif
}

// The index in the light buffer of entry `k` (< list.count) of `list`.
uint lightListIndex(LightList list, uint k)
{
#ifdef SPECULA_CLUSTERED_LIGHTS
#ifdef SPECULA_VERTEX_STAGE
    if (list.direct) return k;
#endif
    return texelFetch(clusterWords, int(k < list.directional ? list.base + k : list.first + k)).x;
#else
    return k;
#endif
}

// Light `index` of the light buffer (an index from lightListIndex, or < frameLightCount()).
GpuLight lightAt(uint index)
{
#ifdef SPECULA_LIGHTS_STORAGE
    return lightData.lights[index];
#elif defined(LIGHT_CONSTANTS)
    // The lights as constants of the program (LIGHT_VALUES: the light buffer's records, written by
    // render/passes/ForwardPass while the lights stay still): with LIGHT_COUNT's unrolled loop
    // every field folds into the code, where four texel fetches a light a pixel were (on llvmpipe
    // learnopengl's forward pass 28-29 -> 25-26 ms, docs/performance.md).
    const GpuLight values[LIGHT_COUNT] = GpuLight[](LIGHT_VALUES);
    return values[index];
#else
    int texel = 1 + 4 * int(index);
    return GpuLight(uintBitsToFloat(texelFetch(lightTexels, texel)), uintBitsToFloat(texelFetch(lightTexels, texel + 1)),
                    uintBitsToFloat(texelFetch(lightTexels, texel + 2)), uintBitsToFloat(texelFetch(lightTexels, texel + 3)));
#endif
}
