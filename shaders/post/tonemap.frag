#version 450 core
// Exposure and tone mapping: the last pass, into an 8-bit sRGB target (GL encodes with
// GL_FRAMEBUFFER_SRGB, the exact IEC 61966-2-1 curve). With MSAA_SAMPLES defined it also
// resolves: the box average of the linear HDR samples, the same as a blit resolve. With
// AUTO_EXPOSURE the exposure measured on the GPU multiplies frame.exposure.x. With ENCODE_SRGB
// it encodes itself, for a UNORM target (FXAA's input).
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"
#include "../common/color.glsl"
#include "tonemap.glsl"

layout(std140, binding = SPECULA_BINDING_FRAME) uniform FrameBlock { FrameData frame; };
#if defined(AUTO_EXPOSURE)
#include "../shared/PostData.h"
// Left by the auto-exposure pass (render/ExposurePass) on the GPU: no read-back, no stall.
layout(std430, binding = SPECULA_BINDING_EXPOSURE) readonly buffer ExposureBlock { ExposureState exposureState; };
#endif
#if defined(MSAA_SAMPLES)
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2DMS uInput;

vec3 fetchRadiance(ivec2 p)
{
    vec3 sum = vec3(0.0);
    for (int i = 0; i < MSAA_SAMPLES; ++i) sum += texelFetch(uInput, p, i).rgb;
    return sum * (1.0 / float(MSAA_SAMPLES));
}
#else
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uInput;

vec3 fetchRadiance(ivec2 p)
{
    return texelFetch(uInput, p, 0).rgb;
}
#endif

// render/passes/TonemapPass makes a program per operator (TONEMAP_OPERATOR, a SPECULA_TONEMAP_*
// constant): gallivm runs every operator of a branch on a uniform. This file alone reads the frame's.
#ifndef TONEMAP_OPERATOR
#define TONEMAP_OPERATOR frame.options.x
#endif

layout(location = 0) out vec4 outColor;

void main()
{
    float exposure = frame.exposure.x;
#if defined(AUTO_EXPOSURE)
    exposure *= exposureState.value.y; // frame.exposure.x is then the compensation, 2^EV
#endif
    vec3 hdr = fetchRadiance(ivec2(gl_FragCoord.xy)) * exposure;
    vec3 mapped = tonemap(max(hdr, vec3(0.0)), TONEMAP_OPERATOR, frame.exposure.y);
#if defined(ENCODE_SRGB)
    // Into FXAA's 8-bit UNORM input, encoded here with the same curve: FXAA works on
    // perceptual values, and reading UNORM is cheaper than decoding sRGB at every fetch.
    outColor = vec4(linearToSrgb(clamp(mapped, 0.0, 1.0)), 1.0);
#else
    outColor = vec4(clamp(mapped, 0.0, 1.0), 1.0);
#endif
}
