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

// render/LightBuffer: a LightHeader, then header.count.x lights. readonly: no stage writes it.
layout(std430, binding = SPECULA_BINDING_LIGHTS) readonly buffer LightsBlock {
    LightHeader header;
    GpuLight lights[];
} lightData;

// The lights that may reach a shading point: light indices lightListIndex(list, 0 .. count-1).
struct LightList {
    uint first; // where the list starts (today in the light buffer; then in a cluster's index list)
    uint count;
};

// The lights that may reach `worldPosition`, seen at window position `fragCoord`
// (gl_FragCoord: a cluster is a screen tile and a depth slice).
LightList lightList(vec3 worldPosition, vec4 fragCoord)
{
    return LightList(0u, lightData.header.count.x);
}

// For stages without gl_FragCoord (the Gouraud vertex shader): clustered shading will project
// `worldPosition` to find its cluster. Today every light, as above.
LightList lightList(vec3 worldPosition)
{
    return LightList(0u, lightData.header.count.x);
}

// The index in the light buffer of entry `k` (< list.count) of `list`.
uint lightListIndex(LightList list, uint k)
{
    return list.first + k;
}

// Light `index` of the light buffer (an index from lightListIndex, or < frameLightCount()).
GpuLight lightAt(uint index)
{
    return lightData.lights[index];
}

// Every light of the frame, whatever the shading point (the debug views show the first light).
uint frameLightCount()
{
    return lightData.header.count.x;
}
