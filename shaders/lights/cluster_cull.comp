#version 450 core
// Light culling, steps 2 and 3 (render/passes/LightCullPass): one invocation per cluster tests
// every light in view (lights_in_view.comp) against the cluster's box with
// shared/ClusterData.h's lightTouchesCluster, the test the CPU twin runs. Without CLUSTER_FILL
// it counts (the record's second word); with it, after cluster_scan.comp has placed the lists,
// it writes the indices, in light order.
#include "../shared/Bindings.h"
#include "../shared/ClusterData.h"

layout(local_size_x = SPECULA_CULL_GROUP) in;

layout(std430, binding = SPECULA_BINDING_CULL_LIGHTS) readonly buffer CullBlock { CullLight cullLights[]; };
layout(std430, binding = SPECULA_BINDING_CLUSTER_BOUNDS) readonly buffer BoundsBlock { ClusterBounds bounds[]; };
layout(std430, binding = SPECULA_BINDING_CLUSTERS) buffer ClusterBlock { uint words[]; } clusters;

uniform uint uClusters;

void main()
{
    uint c = gl_GlobalInvocationID.x;
    if (c >= uClusters) return;
    ClusterBounds box = bounds[c];
    uint visible = clusters.words[SPECULA_CLUSTER_WORD_VISIBLE];
    uint record = SPECULA_CLUSTER_HEADER_WORDS + 2u * c;
#if defined(CLUSTER_FILL)
    uint at = clusters.words[record];
    uint end = min(at + clusters.words[record + 1u], clusters.words[SPECULA_CLUSTER_WORD_CAPACITY]);
#endif
    uint count = 0u;
    for (uint i = 0u; i < visible; ++i) {
        CullLight l = cullLights[i];
        if (lightTouchesCluster(l, box)) {
#if defined(CLUSTER_FILL)
            if (at + count < end) clusters.words[at + count] = l.info.x;
#endif
            ++count;
        }
    }
#if !defined(CLUSTER_FILL)
    clusters.words[record + 1u] = count;
#endif
}
