#version 450 core
// Bloom, down-sampling step: one level of the pyramid from the level above, with the 13-tap
// filter of Jimenez 2014 ("Next Generation Post Processing in Call of Duty: Advanced Warfare",
// SIGGRAPH course, "bloom" slides). Each of its 13 bilinear taps lands on a texel corner, so
// it reads a 2x2 box; together they are five overlapping 4x4 boxes (the centre one weighted
// 1/2, the four diagonal ones 1/8 each). Decimated by 2 every source texel gives exactly 1/4
// of itself to the level below, so the pyramid conserves energy (texel value x area).
//
// FIRST_LEVEL: reads the HDR frame; applies the optional soft-knee threshold and, with
// KARIS_AVERAGE, weights the five boxes by 1 / (1 + luma) (Karis 2013, "Tone mapping", and
// Jimenez 2014's "partial Karis average"), so one very bright pixel cannot dominate its box.
#include "../shared/Bindings.h"
#include "../common/color.glsl"
#include "bloom.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// Bilinear, clamped to the edge (taps are reflected into the image before they sample).
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uSource;
layout(binding = SPECULA_IMAGE_POST_OUTPUT, rgba16f) uniform writeonly image2D uTarget;

uniform ivec2 uTargetSize;
uniform vec2 uSourceTexel;   // 1 / source size
uniform vec2 uSourceExtent;  // where the frame ends in the source, in its texels (see bloom.glsl)
uniform vec4 uThreshold;     // x threshold (0 = off), y knee half-width, z exposure scale

// Largest finite half float: the target is RGBA16F.
const float kHalfMax = 65504.0;

vec3 tap(vec2 centre, vec2 offset)
{
    return textureLod(uSource, reflectIntoFrame(centre + offset, uSourceExtent) * uSourceTexel, 0.0).rgb;
}

#if defined(FIRST_LEVEL)
// Quadratic soft knee: no change far above the threshold, a smooth quadratic ramp within
// `knee` of it, nothing far below (Unity's post-processing stack, Keijiro Takahashi's Kino
// Bloom). Measured on the brightest channel after exposure, so the threshold reads as a
// pixel value.
vec3 softThreshold(vec3 c)
{
    float threshold = uThreshold.x, knee = uThreshold.y;
    float brightness = max(c.r, max(c.g, c.b)) * uThreshold.z;
    float soft = clamp(brightness - threshold + knee, 0.0, 2.0 * knee);
    soft = soft * soft / (4.0 * knee + 1e-5); // 1e-5: knee 0 is a hard threshold, not 0/0
    float contribution = max(soft, brightness - threshold) / max(brightness, 1e-5);
    return c * contribution;
}
#endif

#if defined(KARIS_AVERAGE)
float karisWeight(vec3 box)
{
    // Luma after exposure: the weighting should treat alike what looks alike on screen.
    return 1.0 / (1.0 + luminance(box) * uThreshold.z);
}
#endif

void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uTargetSize))) return;
    // Target texel p covers source texels 2p and 2p + 1: its centre is their shared corner.
    // Target sizes are rounded up, so an odd last row or column of the source still has a
    // texel below it (whose missing half reads the reflection of the frame's edge).
    vec2 c = vec2(2 * p + 1);

    vec3 a = tap(c, vec2(-2.0, -2.0));
    vec3 b = tap(c, vec2(0.0, -2.0));
    vec3 d = tap(c, vec2(2.0, -2.0));
    vec3 e = tap(c, vec2(-1.0, -1.0));
    vec3 f = tap(c, vec2(1.0, -1.0));
    vec3 g = tap(c, vec2(-2.0, 0.0));
    vec3 h = tap(c, vec2(0.0, 0.0));
    vec3 i = tap(c, vec2(2.0, 0.0));
    vec3 j = tap(c, vec2(-1.0, 1.0));
    vec3 k = tap(c, vec2(1.0, 1.0));
    vec3 l = tap(c, vec2(-2.0, 2.0));
    vec3 m = tap(c, vec2(0.0, 2.0));
    vec3 n = tap(c, vec2(2.0, 2.0));

    vec3 centre = (e + f + j + k) * 0.25;
    vec3 topLeft = (a + b + g + h) * 0.25;
    vec3 topRight = (b + d + h + i) * 0.25;
    vec3 bottomLeft = (g + h + l + m) * 0.25;
    vec3 bottomRight = (h + i + m + n) * 0.25;
    vec4 weights = vec4(0.125);
    float centreWeight = 0.5;
#if defined(KARIS_AVERAGE)
    centreWeight *= karisWeight(centre);
    weights *= vec4(karisWeight(topLeft), karisWeight(topRight), karisWeight(bottomLeft), karisWeight(bottomRight));
#endif
    vec3 result = centre * centreWeight + topLeft * weights.x + topRight * weights.y + bottomLeft * weights.z +
                  bottomRight * weights.w;
    result /= centreWeight + weights.x + weights.y + weights.z + weights.w;
#if defined(FIRST_LEVEL)
    if (uThreshold.x > 0.0) result = softThreshold(result);
#endif
    imageStore(uTarget, p, vec4(min(result, vec3(kHalfMax)), 1.0));
}
