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
// Today the list is every light of the frame. Clustered shading will return the lights of the
// shading point's cluster instead (a range of a light-index list found from the fragment's
// screen tile and view depth), as Bevy's clustered_forward.wgsl does with
// fragment_cluster_index, unpack_offset_and_counts and get_clusterable_object_id; callers do
// not change.
#include "../shared/Bindings.h"
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

// Every light of the frame, whatever the shading point (the debug views show the first light).
uint frameLightCount()
{
#ifdef SPECULA_LIGHTS_STORAGE
    return lightData.header.count.x;
#else
    return texelFetch(lightTexels, 0).x;
#endif
}

// The lights that may reach a shading point: light indices lightListIndex(list, 0 .. count-1).
struct LightList {
    uint first; // where the list starts (today in the light buffer; then in a cluster's index list)
    uint count;
};

// The lights that may reach `worldPosition`, seen at window position `fragCoord`
// (gl_FragCoord: a cluster is a screen tile and a depth slice).
LightList lightList(vec3 worldPosition, vec4 fragCoord)
{
    return LightList(0u, frameLightCount());
}

// For stages without gl_FragCoord (the Gouraud vertex shader): clustered shading will project
// `worldPosition` to find its cluster. Today every light, as above.
LightList lightList(vec3 worldPosition)
{
    return LightList(0u, frameLightCount());
}

// The index in the light buffer of entry `k` (< list.count) of `list`.
uint lightListIndex(LightList list, uint k)
{
    return list.first + k;
}

// Light `index` of the light buffer (an index from lightListIndex, or < frameLightCount()).
GpuLight lightAt(uint index)
{
#ifdef SPECULA_LIGHTS_STORAGE
    return lightData.lights[index];
#else
    int texel = 1 + 4 * int(index);
    return GpuLight(uintBitsToFloat(texelFetch(lightTexels, texel)), uintBitsToFloat(texelFetch(lightTexels, texel + 1)),
                    uintBitsToFloat(texelFetch(lightTexels, texel + 2)), uintBitsToFloat(texelFetch(lightTexels, texel + 3)));
#endif
}
