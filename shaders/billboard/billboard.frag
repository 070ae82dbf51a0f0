#version 450 core
// Billboards are unlit emitters: radiance = texel colour (sRGB decoded by GL) x tint, in cd/m²,
// written to the HDR target so bright sprites bloom. Cutout discards below the cutoff and
// writes alpha 1; blended sprites write their alpha for GL's alpha blending.
// DOOM_INDEXED (a Doom frame, render/DoomPass): texel x tint becomes a palette index, written
// with the sprite's colour-map level; blended sprites are cut out at half coverage, as an
// index cannot be blended.
#include "../shared/Bindings.h"
#if defined(DOOM_INDEXED)
#include "../doom/palette.glsl"
#endif

layout(binding = SPECULA_UNIT_SPRITE) uniform sampler2D uSprite;

uniform float uAlphaCutoff; // < 0: never discard (opaque and blended sprites)
uniform bool uBlend;

in vec2 vUv;
in vec3 vTint;
#if defined(DOOM_INDEXED)
flat in uint vDoomLevel;
layout(location = 0) out uvec4 outIndexed;
#else
layout(location = 0) out vec4 outColor;
#endif

// Largest finite half float: keeps a very bright sprite from becoming Inf in RGBA16F.
const float kHalfMax = 65504.0;

void main()
{
    // Images are stored top row first, so the sprite's top (v = 1) is at t = 0.
    vec4 texel = texture(uSprite, vec2(vUv.x, 1.0 - vUv.y));
    if (texel.a < uAlphaCutoff) discard;
#if defined(DOOM_INDEXED)
    if (uBlend && texel.a < 0.5) discard;
    outIndexed = uvec4(doomPaletteIndex(texel.rgb * vTint), vDoomLevel, 0u, 0u);
#else
    outColor = vec4(min(texel.rgb * vTint, vec3(kHalfMax)), uBlend ? texel.a : 1.0);
#endif
}
