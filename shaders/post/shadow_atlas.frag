#version 450 core
// The shadow-atlas debug view: the square depth atlas fitted into the frame, written to the
// 8-bit target without sRGB encoding. grey = 1 − (1 − window depth)^¼: white where a tile is
// empty or sees nothing (cleared to the far plane), the curve keeping a perspective tile's
// depths, all close to 1, apart. Outside the atlas's square: dark blue.
#include "../shared/Bindings.h"

layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uInput;

layout(location = 0) out vec4 outColor;

uniform vec2 uFrameSize;

void main()
{
    float side = min(uFrameSize.x, uFrameSize.y);
    vec2 origin = 0.5 * (uFrameSize - vec2(side));
    vec2 uv = (gl_FragCoord.xy - origin) / side;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
        outColor = vec4(0.0, 0.0, 0.2, 1.0);
        return;
    }
    float depth = textureLod(uInput, uv, 0.0).r;
    outColor = vec4(vec3(1.0 - pow(max(1.0 - depth, 0.0), 0.25)), 1.0);
}
