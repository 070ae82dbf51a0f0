#version 450 core
// The opaque frame for transmission (render/passes/ForwardPass): the HDR colour resolved
// (averaged over its samples) into level 0 of a mip chain. With ENVIRONMENT_BEHIND the copy
// holds radiance × coverage and the coverage, the fraction of samples with a surface (depth
// below the clear value 1): forward/transmission.glsl sees the environment through the rest.
// Without it (no image-based light) what the frame shows behind is all there is: alpha 1.
#include "../shared/Bindings.h"

#if defined(MULTISAMPLE)
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2DMS uColor;
layout(binding = SPECULA_UNIT_POST_INPUT_1) uniform sampler2DMS uDepth;
uniform int uSamples;
#else
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uColor;
layout(binding = SPECULA_UNIT_POST_INPUT_1) uniform sampler2D uDepth;
const int uSamples = 1;
#endif

layout(location = 0) out vec4 outColor;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 sum = vec3(0.0);
    float covered = 0.0;
    for (int s = 0; s < uSamples; ++s) {
#if defined(MULTISAMPLE)
        vec3 c = texelFetch(uColor, p, s).rgb;
        float depth = texelFetch(uDepth, p, s).r;
#else
        vec3 c = texelFetch(uColor, p, 0).rgb;
        float depth = texelFetch(uDepth, p, 0).r;
#endif
#if defined(ENVIRONMENT_BEHIND)
        float surface = depth < 1.0 ? 1.0 : 0.0;
#else
        float surface = 1.0;
#endif
        sum += c * surface;
        covered += surface;
    }
    outColor = vec4(sum, covered) / float(uSamples);
}
