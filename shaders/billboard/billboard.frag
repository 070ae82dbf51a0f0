#version 450 core
// Billboards are unlit emitters: radiance = texel colour (sRGB decoded by GL) x tint, in cd/m²,
// written to the HDR target so bright sprites bloom. Cutout discards below the cutoff and
// writes alpha 1; blended sprites write their alpha for GL's alpha blending.
#include "../shared/Bindings.h"

layout(binding = SPECULA_UNIT_SPRITE) uniform sampler2D uSprite;

uniform float uAlphaCutoff; // < 0: never discard (opaque and blended sprites)
uniform bool uBlend;

in vec2 vUv;
in vec3 vTint;

layout(location = 0) out vec4 outColor;

// Largest finite half float: keeps a very bright sprite from becoming Inf in RGBA16F.
const float kHalfMax = 65504.0;

void main()
{
    // Images are stored top row first, so the sprite's top (v = 1) is at t = 0.
    vec4 texel = texture(uSprite, vec2(vUv.x, 1.0 - vUv.y));
    if (texel.a < uAlphaCutoff) discard;
    outColor = vec4(min(texel.rgb * vTint, vec3(kHalfMax)), uBlend ? texel.a : 1.0);
}
