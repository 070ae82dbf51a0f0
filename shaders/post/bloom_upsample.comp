#version 450 core
// Bloom, up-sampling step (Jimenez 2014): the level below, magnified 2x through a 3x3 tent
// filter (weights 1 2 1 / 2 4 2 / 1 2 1, sum 1, so energy is kept), added to this level:
//     target = uKeep * target + uScale * tent(lower)
// Going up the pyramid every level is added once, each a wider blur of the frame. The last
// step writes the HDR frame itself: uKeep = 1 and uScale = intensity / levels, so that the
// glow carries intensity x the frame's energy (uKeep = 0 leaves only the glow: debug view).
//
// Borders: the pyramid treats the image as continued by its mirror image, which keeps every
// filter's energy inside. The down-sampling sampler mirrors about each level's edge. Here,
// when this level's size is odd, the level below holds half a texel of that mirror beyond the
// true edge; the true edge is the centre of its last texel, so near that border the taps
// reflect about that centre instead (done by hand: no wrap mode does it).
#include "../shared/Bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uLower; // bilinear, mirrored at the border
layout(binding = SPECULA_IMAGE_POST_OUTPUT, rgba16f) uniform image2D uTarget;

uniform ivec2 uTargetSize;
uniform vec2 uLowerTexel;  // 1 / size of the level below
uniform float uRadius;     // tent spread in texels of the level below
uniform float uKeep;
uniform float uScale;

const float kHalfMax = 65504.0;

// Index i of the level below (size n) reflected into it; `aboutCentre`: about the centre of
// the last texel (odd target size), else about the edge.
int reflectIndex(int i, int n, bool aboutCentre)
{
    if (i < 0) i = -1 - i;
    if (i >= n) i = aboutCentre ? 2 * (n - 1) - i : 2 * n - 1 - i;
    return clamp(i, 0, n - 1); // a radius wider than the whole level folds once, then clamps
}

vec3 bilinearReflected(vec2 position) // in texels of the level below
{
    ivec2 n = textureSize(uLower, 0);
    bvec2 aboutCentre = bvec2((uTargetSize.x & 1) == 1, (uTargetSize.y & 1) == 1);
    vec2 p = position - 0.5;
    ivec2 i0 = ivec2(floor(p));
    vec2 f = p - vec2(i0);
    int x0 = reflectIndex(i0.x, n.x, aboutCentre.x), x1 = reflectIndex(i0.x + 1, n.x, aboutCentre.x);
    int y0 = reflectIndex(i0.y, n.y, aboutCentre.y), y1 = reflectIndex(i0.y + 1, n.y, aboutCentre.y);
    vec3 bottom = mix(texelFetch(uLower, ivec2(x0, y0), 0).rgb, texelFetch(uLower, ivec2(x1, y0), 0).rgb, f.x);
    vec3 top = mix(texelFetch(uLower, ivec2(x0, y1), 0).rgb, texelFetch(uLower, ivec2(x1, y1), 0).rgb, f.x);
    return mix(bottom, top, f.y);
}

void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uTargetSize))) return;
    // The level below covers twice its size in this level's texels (sizes are rounded up),
    // so texel p's centre sits at (p + 0.5) / 2 of its texels: the mapping is exactly 2:1.
    vec2 position = (vec2(p) + 0.5) * 0.5;
    vec2 n = vec2(textureSize(uLower, 0));
    vec3 taps[9];
    // Inside, where no tap's footprint reaches past a border, the sampler's bilinear filter
    // does the work.
    bool inside = all(greaterThanEqual(position, vec2(uRadius + 1.0))) && all(lessThanEqual(position, n - uRadius - 1.0));
    int t = 0;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            vec2 q = position + vec2(x, y) * uRadius;
            taps[t++] = inside ? textureLod(uLower, q * uLowerTexel, 0.0).rgb : bilinearReflected(q);
        }
    }
    vec3 sum = (taps[0] + taps[2] + taps[6] + taps[8]) + (taps[1] + taps[3] + taps[5] + taps[7]) * 2.0 + taps[4] * 4.0;
    vec4 current = imageLoad(uTarget, p);
    // The sum of two finite halves can exceed the largest half: clamp rather than store Inf.
    vec3 result = min(uKeep * current.rgb + uScale * (sum * (1.0 / 16.0)), vec3(kHalfMax));
    imageStore(uTarget, p, vec4(result, current.a));
}
