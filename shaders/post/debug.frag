#version 450 core
// Debug view of a single-channel buffer (the SSAO result): its value as grey, written to the
// 8-bit target without sRGB encoding, so a byte reads value × 255.
#include "../shared/Bindings.h"

layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uInput;

layout(location = 0) out vec4 outColor;

void main()
{
    float value = texelFetch(uInput, ivec2(gl_FragCoord.xy), 0).r;
    outColor = vec4(vec3(clamp(value, 0.0, 1.0)), 1.0);
}
