#version 450 core
// FXAA 3.11, quality variant (Timothy Lottes, NVIDIA 2011), after the walk-through in Simon
// Rodriguez's "Implementing FXAA" (2017): find pixels on a luma edge, decide whether the edge
// runs horizontally or vertically, walk along it both ways (steps of FXAA's quality preset 39)
// until the edge ends, and re-sample the image shifted across the edge by how far this pixel
// is from the nearer end; plus a sub-pixel blend for features smaller than a pixel.
//
// The input is the tone-mapped image already sRGB-encoded, in a UNORM texture: luma is taken
// from perceptual values and the re-sampling blends them, as FXAA was designed (its input is
// gamma-encoded LDR). The output is written as is to the sRGB target (no second encoding).
#include "../shared/Bindings.h"
#include "../common/color.glsl"

layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uInput; // sRGB-encoded; bilinear, clamp to edge

uniform vec2 uTexel; // 1 / size

layout(location = 0) out vec4 outColor;

// Lottes's defaults for the quality variant: ignore contrasts below 1/12 of the local maximum
// ("high quality") or below 1/24 absolute (dark areas), blend sub-pixel aliasing at 3/4.
const float kEdgeThreshold = 0.125;
const float kEdgeThresholdMin = 0.0312;
const float kSubpixelQuality = 0.75;
const int kSteps = 12;
const float kStepSizes[kSteps] = float[](1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0);

float luma(vec3 c)
{
    return luminance(c); // Rec. 709 weights on encoded values: FXAA's luma
}

float lumaAt(vec2 uv)
{
    return luma(textureLod(uInput, uv, 0.0).rgb);
}

// The 3x3 neighbourhood lies on pixel centres: unfiltered fetches, which cost far less than
// bilinear ones of the same texels (on llvmpipe every fetch of a shader runs, branch or not),
// clamped at the border as the sampler would be.
float lumaFetch(ivec2 p)
{
    return luma(texelFetch(uInput, clamp(p, ivec2(0), textureSize(uInput, 0) - 1), 0).rgb);
}

void main()
{
    vec2 uv = gl_FragCoord.xy * uTexel;
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 centreColor = texelFetch(uInput, p, 0).rgb;
    float lumaCentre = luma(centreColor);
    float lumaDown = lumaFetch(p + ivec2(0, -1));
    float lumaUp = lumaFetch(p + ivec2(0, 1));
    float lumaLeft = lumaFetch(p + ivec2(-1, 0));
    float lumaRight = lumaFetch(p + ivec2(1, 0));
    float lumaMin = min(lumaCentre, min(min(lumaDown, lumaUp), min(lumaLeft, lumaRight)));
    float lumaMax = max(lumaCentre, max(max(lumaDown, lumaUp), max(lumaLeft, lumaRight)));
    float range = lumaMax - lumaMin;
    // No edge here: most pixels leave at this point, untouched.
    if (range < max(kEdgeThresholdMin, lumaMax * kEdgeThreshold)) {
        outColor = vec4(centreColor, 1.0);
        return;
    }

    float lumaDownLeft = lumaFetch(p + ivec2(-1, -1));
    float lumaUpRight = lumaFetch(p + ivec2(1, 1));
    float lumaUpLeft = lumaFetch(p + ivec2(-1, 1));
    float lumaDownRight = lumaFetch(p + ivec2(1, -1));
    float lumaDownUp = lumaDown + lumaUp;
    float lumaLeftRight = lumaLeft + lumaRight;
    float lumaLeftCorners = lumaDownLeft + lumaUpLeft;
    float lumaDownCorners = lumaDownLeft + lumaDownRight;
    float lumaRightCorners = lumaDownRight + lumaUpRight;
    float lumaUpCorners = lumaUpRight + lumaUpLeft;

    // Second differences across rows vs across columns: which way does the edge run?
    float edgeHorizontal = abs(-2.0 * lumaLeft + lumaLeftCorners) + abs(-2.0 * lumaCentre + lumaDownUp) * 2.0 +
                           abs(-2.0 * lumaRight + lumaRightCorners);
    float edgeVertical = abs(-2.0 * lumaUp + lumaUpCorners) + abs(-2.0 * lumaCentre + lumaLeftRight) * 2.0 +
                         abs(-2.0 * lumaDown + lumaDownCorners);
    bool horizontal = edgeHorizontal >= edgeVertical;

    // Which side of this pixel the edge lies on: the neighbour with the steeper gradient.
    float luma1 = horizontal ? lumaDown : lumaLeft;
    float luma2 = horizontal ? lumaUp : lumaRight;
    float gradient1 = luma1 - lumaCentre;
    float gradient2 = luma2 - lumaCentre;
    bool steepest1 = abs(gradient1) >= abs(gradient2);
    float gradientScaled = 0.25 * max(abs(gradient1), abs(gradient2));
    float stepLength = horizontal ? uTexel.y : uTexel.x;
    float lumaLocalAverage;
    if (steepest1) {
        stepLength = -stepLength;
        lumaLocalAverage = 0.5 * (luma1 + lumaCentre);
    } else {
        lumaLocalAverage = 0.5 * (luma2 + lumaCentre);
    }

    // Walk along the edge, half a pixel towards it, both ways, until the luma leaves the
    // edge's average by more than a quarter of its gradient.
    vec2 edgeUv = uv;
    if (horizontal) edgeUv.y += stepLength * 0.5;
    else edgeUv.x += stepLength * 0.5;
    vec2 along = horizontal ? vec2(uTexel.x, 0.0) : vec2(0.0, uTexel.y);
    vec2 uv1 = edgeUv - along * kStepSizes[0];
    vec2 uv2 = edgeUv + along * kStepSizes[0];
    float lumaEnd1 = lumaAt(uv1) - lumaLocalAverage;
    float lumaEnd2 = lumaAt(uv2) - lumaLocalAverage;
    bool reached1 = abs(lumaEnd1) >= gradientScaled;
    bool reached2 = abs(lumaEnd2) >= gradientScaled;
    if (!reached1) uv1 -= along * kStepSizes[1];
    if (!reached2) uv2 += along * kStepSizes[1];
    for (int i = 2; i < kSteps && !(reached1 && reached2); ++i) {
        if (!reached1) {
            lumaEnd1 = lumaAt(uv1) - lumaLocalAverage;
            reached1 = abs(lumaEnd1) >= gradientScaled;
        }
        if (!reached2) {
            lumaEnd2 = lumaAt(uv2) - lumaLocalAverage;
            reached2 = abs(lumaEnd2) >= gradientScaled;
        }
        if (!reached1) uv1 -= along * kStepSizes[i];
        if (!reached2) uv2 += along * kStepSizes[i];
    }

    float distance1 = horizontal ? uv.x - uv1.x : uv.y - uv1.y;
    float distance2 = horizontal ? uv2.x - uv.x : uv2.y - uv.y;
    bool direction1 = distance1 < distance2;
    float distanceFinal = min(distance1, distance2);
    float edgeLength = distance1 + distance2;
    float pixelOffset = -distanceFinal / edgeLength + 0.5;
    // Only when the luma at the nearer end varies the same way as at the centre is this pixel
    // on the side of the edge that should be blended.
    bool centreSmaller = lumaCentre < lumaLocalAverage;
    bool correctVariation = ((direction1 ? lumaEnd1 : lumaEnd2) < 0.0) != centreSmaller;
    float finalOffset = correctVariation ? pixelOffset : 0.0;

    // Sub-pixel aliasing: how much the centre differs from its 3x3 neighbourhood's average.
    float lumaAverage = (1.0 / 12.0) * (2.0 * (lumaDownUp + lumaLeftRight) + lumaLeftCorners + lumaRightCorners);
    float subpixel1 = clamp(abs(lumaAverage - lumaCentre) / range, 0.0, 1.0);
    float subpixel2 = (-2.0 * subpixel1 + 3.0) * subpixel1 * subpixel1;
    finalOffset = max(finalOffset, subpixel2 * subpixel2 * kSubpixelQuality);

    vec2 finalUv = uv;
    if (horizontal) finalUv.y += finalOffset * stepLength;
    else finalUv.x += finalOffset * stepLength;
    outColor = vec4(textureLod(uInput, finalUv, 0.0).rgb, 1.0);
}
