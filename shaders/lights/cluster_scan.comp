#version 450 core
// Light culling, between counting and filling (render/passes/LightCullPass): places every
// cluster's list after the directional lights (an exclusive prefix sum of the counts, one work
// group: each invocation sums a run of clusters, one scans the runs), and writes the totals the
// renderer reads back to size the buffer (shared/ClusterData.h's header).
#include "../shared/Bindings.h"
#include "../shared/ClusterData.h"

layout(local_size_x = SPECULA_CULL_SCAN_GROUP) in;

layout(std430, binding = SPECULA_BINDING_CLUSTERS) buffer ClusterBlock { uint words[]; } clusters;

uniform uint uClusters;

shared uint sSum[SPECULA_CULL_SCAN_GROUP];
shared uint sMax[SPECULA_CULL_SCAN_GROUP];

void main()
{
    uint t = gl_LocalInvocationID.x;
    uint run = (uClusters + SPECULA_CULL_SCAN_GROUP - 1u) / SPECULA_CULL_SCAN_GROUP;
    uint begin = min(t * run, uClusters), end = min(begin + run, uClusters);
    uint sum = 0u, longest = 0u;
    for (uint c = begin; c < end; ++c) {
        uint n = clusters.words[SPECULA_CLUSTER_HEADER_WORDS + 2u * c + 1u];
        sum += n;
        longest = max(longest, n);
    }
    sSum[t] = sum;
    sMax[t] = longest;
    barrier();
    if (t == 0u) {
        uint total = 0u, m = 0u;
        for (uint k = 0u; k < SPECULA_CULL_SCAN_GROUP; ++k) {
            uint a = sSum[k];
            sSum[k] = total;
            total += a;
            m = max(m, sMax[k]);
        }
        clusters.words[SPECULA_CLUSTER_WORD_ENTRIES] = total;
        clusters.words[SPECULA_CLUSTER_WORD_MAX] = m;
    }
    barrier();
    uint at = clusters.words[SPECULA_CLUSTER_WORD_BASE] + clusters.words[SPECULA_CLUSTER_WORD_DIRECTIONAL] + sSum[t];
    for (uint c = begin; c < end; ++c) {
        uint record = SPECULA_CLUSTER_HEADER_WORDS + 2u * c;
        clusters.words[record] = at;
        at += clusters.words[record + 1u];
    }
}
