#version 450 core
// Bloom, up-sampling step (Jimenez 2014): the level below, magnified 2x through a 3x3 tent
// filter (weights 1 2 1 / 2 4 2 / 1 2 1, sum 1, so energy is kept), added to this level:
//     target = uKeep * target + uScale * tent(lower)
// Going up the pyramid every level is added once, each a wider blur of the frame. The last
// step writes the HDR frame itself: uKeep = 1 and uScale = intensity / levels, so that the
// glow carries intensity x the frame's energy (uKeep = 0 leaves only the glow: debug view).
// Borders: see bloom.glsl.
#include "../shared/Bindings.h"
#include "bloom.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uLower; // bilinear, clamped (taps are reflected first)
layout(binding = SPECULA_IMAGE_POST_OUTPUT, rgba16f) uniform image2D uTarget;

uniform ivec2 uTargetSize;
uniform vec2 uLowerTexel;  // 1 / size of the level below
uniform vec2 uLowerExtent; // where the frame ends in the level below, in its texels
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
    vec2 position = (vec2(p) + 0.5) * 0.5;
    vec3 taps[9];
    int t = 0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            taps[t++] = textureLod(uLower, reflectIntoFrame(position + vec2(x, y) * uRadius, uLowerExtent) * uLowerTexel, 0.0).rgb;
    vec3 sum = (taps[0] + taps[2] + taps[6] + taps[8]) + (taps[1] + taps[3] + taps[5] + taps[7]) * 2.0 + taps[4] * 4.0;
    vec4 current = imageLoad(uTarget, p);
    // The sum of two finite halves can exceed the largest half: clamp rather than store Inf.
    vec3 result = min(uKeep * current.rgb + uScale * (sum * (1.0 / 16.0)), vec3(kHalfMax));
    imageStore(uTarget, p, vec4(result, current.a));
}
