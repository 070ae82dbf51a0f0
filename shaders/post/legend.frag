#version 450 core
// A picture drawn over the frame as it is (the light-count view's legend, render/passes/
// DebugViewPass): the input's bytes into the 8-bit target, pixel for pixel from its corner.
#include "../shared/Bindings.h"

layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uInput;

layout(location = 0) out vec4 outColor;

void main()
{
    outColor = texelFetch(uInput, ivec2(gl_FragCoord.xy), 0);
}
