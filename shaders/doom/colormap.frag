#version 450 core
// The colour-map pass of a Doom frame (render/DoomPass): the forward and billboard passes wrote
// a palette index and a colour-map level per pixel, as Doom's 8-bit frame buffer held them;
// here each becomes its palette colour, as Doom's COLORMAP and PLAYPAL did. Output 0 is the
// HDR target (linear radiance, for readRadiance), output 1 the 8-bit target: the sRGB bytes
// themselves, written without sRGB encoding, so the image holds exactly the palette's bytes.
#include "../shared/Bindings.h"
#include "palette.glsl"

layout(binding = SPECULA_UNIT_POST_INPUT) uniform usampler2D uIndexed;

layout(location = 0) out vec4 outRadiance;
layout(location = 1) out vec4 outColor;

void main()
{
    uvec2 indexLevel = texelFetch(uIndexed, ivec2(gl_FragCoord.xy), 0).rg;
    vec3 color = doomColor(indexLevel.x, indexLevel.y);
    outRadiance = vec4(srgbToLinear(color), 1.0);
    outColor = vec4(color, 1.0);
}
