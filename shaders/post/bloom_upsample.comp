#version 450 core
// Bloom, up-sampling step (Jimenez 2014): the level below, magnified 2x through a 3x3 tent
// filter (weights 1 2 1 / 2 4 2 / 1 2 1, sum 1, so energy is kept), added to this level:
//     target = uKeep * target + uScale * tent(lower)
// Going up the pyramid every level is added once, each a wider blur of the frame. The last
// step writes the HDR frame itself: uKeep = 1 and uScale = intensity / levels, so that the
// glow carries intensity x the frame's energy (uKeep = 0 leaves only the glow: debug view).
#include "../shared/Bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uLower; // bilinear, clamp to edge
layout(binding = SPECULA_IMAGE_POST_OUTPUT, rgba16f) uniform image2D uTarget;

uniform ivec2 uTargetSize;
uniform vec2 uLowerTexel;  // 1 / size of the level below
uniform float uRadius;     // tent spread in texels of the level below
uniform float uKeep;
uniform float uScale;

const float kHalfMax = 65504.0;

void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uTargetSize))) return;
    // The level below covers twice its size in this level's texels (sizes are rounded up),
    // so texel p's centre sits at (p + 0.5) / 2 of its texels: the mapping is exactly 2:1.
    vec2 uv = (vec2(p) + 0.5) * 0.5 * uLowerTexel;
    vec2 o = uRadius * uLowerTexel;
    vec3 sum = textureLod(uLower, uv, 0.0).rgb * 4.0;
    sum += (textureLod(uLower, uv + vec2(-o.x, 0.0), 0.0).rgb + textureLod(uLower, uv + vec2(o.x, 0.0), 0.0).rgb +
            textureLod(uLower, uv + vec2(0.0, -o.y), 0.0).rgb + textureLod(uLower, uv + vec2(0.0, o.y), 0.0).rgb) * 2.0;
    sum += textureLod(uLower, uv + vec2(-o.x, -o.y), 0.0).rgb + textureLod(uLower, uv + vec2(o.x, -o.y), 0.0).rgb +
           textureLod(uLower, uv + vec2(-o.x, o.y), 0.0).rgb + textureLod(uLower, uv + vec2(o.x, o.y), 0.0).rgb;
    vec4 current = imageLoad(uTarget, p);
    // The sum of two finite halves can exceed the largest half: clamp rather than store Inf.
    vec3 result = min(uKeep * current.rgb + uScale * (sum * (1.0 / 16.0)), vec3(kHalfMax));
    imageStore(uTarget, p, vec4(result, current.a));
}
