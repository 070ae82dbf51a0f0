#version 450 core
// Exposure, tone mapping and sRGB encoding: the last pass, into an 8-bit target.
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"
#include "../common/color.glsl"
#include "tonemap.glsl"

layout(std140, binding = SPECULA_BINDING_FRAME) uniform FrameBlock { FrameData frame; };
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uInput;

layout(location = 0) out vec4 outColor;

void main()
{
    vec3 hdr = texelFetch(uInput, ivec2(gl_FragCoord.xy), 0).rgb * frame.exposure.x;
    vec3 mapped = tonemap(max(hdr, vec3(0.0)), frame.options.x, frame.exposure.y);
    outColor = vec4(linearToSrgb(clamp(mapped, 0.0, 1.0)), 1.0);
}
