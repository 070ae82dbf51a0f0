#version 450 core
// Shadow-map pass (render/passes/ShadowPass): depth only. Variants: ALPHA_MASK (with
// HAS_BASE_COLOR_TEXTURE, VERTEX_COLOR) cuts out what the forward pass cuts out, with the
// material's cutoff and texture, so masked leaves cast leaf-shaped shadows; TRANSMISSION_CUTOUT
// cuts out the texels that let half the light or more through (the factor times the
// transmission texture's R: render::transmissionCutout), so a window's glass casts none and its
// frame does.
#include "../shared/Bindings.h"
#include "../shared/MaterialData.h"

layout(std140, binding = SPECULA_BINDING_MATERIAL) uniform MaterialBlock { GpuMaterial material; };
layout(binding = SPECULA_UNIT_BASE_COLOR) uniform sampler2D uBaseColorTexture;
layout(binding = SPECULA_UNIT_TRANSMISSION_FACTOR) uniform sampler2D uTransmissionTexture;

in vec2 vUv0;
in vec2 vUv1;
in vec4 vColor;

#include "../forward/texture_uv.glsl"

void main()
{
#if defined(ALPHA_MASK)
    float alpha = material.baseColorFactor.a;
#if defined(HAS_BASE_COLOR_TEXTURE)
    alpha *= texture(uBaseColorTexture, textureUv(TEX_BASE_COLOR)).a;
#endif
#if defined(VERTEX_COLOR)
    alpha *= vColor.a;
#endif
    if (alpha < material.alpha.x) discard;
#endif
#if defined(TRANSMISSION_CUTOUT)
    float transmission = material.transmission.x * texture(uTransmissionTexture, textureUv(TEX_TRANSMISSION)).r;
    if (transmission >= SPECULA_TRANSMISSION_SHADOW_LIMIT) discard;
#endif
}
