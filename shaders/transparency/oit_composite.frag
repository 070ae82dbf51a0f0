#version 450 core
// Weighted blended order-independent transparency, the composite (McGuire & Bavoil 2013,
// "Weighted Blended Order-Independent Transparency", JCGT 2(2), listing 2): the weighted mean
// of the blended surfaces' premultiplied colours, over the frame by the product of their
// transparencies. Drawn with premultiplied blending (ONE, ONE_MINUS_SRC_ALPHA):
//     frame = mean × (1 − revealage) + frame × revealage.
// With MULTISAMPLE it runs per sample (gl_SampleID), each sample its own layers.
#include "../shared/Bindings.h"

#if defined(MULTISAMPLE)
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2DMS uAccumulation;
layout(binding = SPECULA_UNIT_POST_INPUT_1) uniform sampler2DMS uRevealage;
#define FETCH(t, p) texelFetch(t, p, gl_SampleID)
#else
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uAccumulation;
layout(binding = SPECULA_UNIT_POST_INPUT_1) uniform sampler2D uRevealage;
#define FETCH(t, p) texelFetch(t, p, 0)
#endif

layout(location = 0) out vec4 outColor;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    float revealage = FETCH(uRevealage, p).r;
    if (revealage >= 1.0) discard; // no blended surface here: the frame stays as it is
    vec4 accumulation = FETCH(uAccumulation, p);
    // 1e-5: the sum of weights of a layer of alpha 1e-3 at the farthest weight; below it the
    // layers reveal everything anyway.
    vec3 mean = accumulation.rgb / max(accumulation.a, 1e-5);
    float coverage = 1.0 - revealage;
    outColor = vec4(mean * coverage, coverage);
}
