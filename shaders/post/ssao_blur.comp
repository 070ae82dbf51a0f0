#version 450 core
// SSAO blur: a 4x4 box over the raw occlusion, exactly one tile of the 4x4 rotation noise, so
// on a flat surface the noise pattern averages out completely. Depth-aware (bilateral): a
// neighbour counts only while it lies near the plane of this pixel's surface, so occlusion
// never bleeds across a silhouette onto a surface at another depth. The plane rather than
// the depth difference, so that a surface seen at a grazing angle still blurs along itself.
#include "../shared/Bindings.h"
#include "../shared/PostData.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = SPECULA_BINDING_SSAO) uniform SsaoBlock { SsaoData ssao; };
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uGeometry; // view normal, view z
layout(binding = SPECULA_UNIT_POST_INPUT_2) uniform sampler2D uRawOcclusion;
layout(binding = SPECULA_IMAGE_POST_OUTPUT, r16f) uniform writeonly image2D uOcclusion;

#include "ssao.glsl"

void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(ssao.size.xy);
    if (any(greaterThanEqual(p, size))) return;
    vec4 geometry = texelFetch(uGeometry, p, 0);
    if (nothingAt(geometry)) {
        imageStore(uOcclusion, p, vec4(1.0));
        return;
    }
    vec3 position = viewPosition(p, geometry.w);
    vec3 n = geometry.xyz;
    // Neighbours within 5% of the distance (or a tenth of the radius, up close) of this
    // plane belong to the same surface.
    float tolerance = max(0.05 * abs(position.z), 0.1 * ssao.params.x);
    float sum = 0.0, weightSum = 0.0;
    for (int y = -2; y < 2; ++y) {
        for (int x = -2; x < 2; ++x) {
            ivec2 q = clamp(p + ivec2(x, y), ivec2(0), size - 1);
            vec4 g = texelFetch(uGeometry, q, 0);
            if (nothingAt(g)) continue;
            float distance = abs(dot(viewPosition(q, g.w) - position, n));
            float w = max(1.0 - distance / tolerance, 0.0);
            sum += texelFetch(uRawOcclusion, q, 0).r * w;
            weightSum += w;
        }
    }
    // The centre always has weight 1, so weightSum > 0.
    imageStore(uOcclusion, p, vec4(sum / weightSum));
}
