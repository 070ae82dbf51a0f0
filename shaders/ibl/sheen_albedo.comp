#version 450 core
// The sheen lobe's directional albedo E(n.v, roughness) = integral of D_Charlie V_Charlie (n.l)
// over the hemisphere (sheen colour 1), for n.v = x and sheen perceptual roughness = y: the
// albedo scaling of KHR_materials_sheen (the base keeps 1 - max(sheen colour) E(n.v)) and the
// image-based sheen's scale (forward/sheen.glsl). Baked like the DFG table (ibl/dfg.comp), into
// R; half vectors importance-sampled by D_Charlie, which cancels from the estimator.
#include "../brdf/sheen.glsl"
#include "sampling.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rg16f) uniform writeonly image2D uLut;
uniform uint uSamples;

void main()
{
    ivec2 id = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uLut);
    if (id.x >= size.x || id.y >= size.y) return;
    float NoV = (float(id.x) + 0.5) / float(size.x);
    // The forward pass clamps the sheen roughness the same way (forward/sheen.glsl).
    float perceptualRoughness = max((float(id.y) + 0.5) / float(size.y), 0.045);
    float alpha = perceptualRoughness * perceptualRoughness;
    vec3 v = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
    float sum = 0.0;
    for (uint i = 0u; i < uSamples; ++i) {
        vec3 h = importanceSampleCharlie(hammersley(i, uSamples), alpha);
        float VoH = dot(v, h);
        vec3 l = 2.0 * VoH * h - v;
        // l above the horizon needs n.h > n.v / (2 v.h): the division below stays finite.
        if (l.z <= 0.0 || VoH <= 0.0) continue;
        // f (n.l) / pdf with pdf(l) = D (n.h) / (4 v.h): D cancels.
        sum += V_Charlie(NoV, l.z, alpha) * 4.0 * VoH * l.z / h.z;
    }
    imageStore(uLut, id, vec4(sum / float(uSamples), 0.0, 0.0, 0.0));
}
