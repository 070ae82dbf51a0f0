#version 450 core
// Shadow-map pass (render/passes/ShadowPass). Variants: ALPHA_MASK (with
// HAS_BASE_COLOR_TEXTURE, VERTEX_COLOR) cuts out what the forward pass cuts out, with the
// material's cutoff and texture, so masked leaves cast leaf-shaped shadows; TRANSMISSION_CUTOUT
// cuts out the texels that let half the light or more through (the factor times the
// transmission texture's R: render::transmissionCutout), so a window's glass casts none and its
// frame does. Depth only, except SHADOW_TINT.
//
// SHADOW_TINT draws a surface that lets light through (render::tintsShadow) into the tint map,
// blended by gl::BlendMode::ShadowTint: rgb multiplies what the surfaces over a texel let
// through, alpha keeps the nearest one's depth (lights/shadow.glsl tints only what lies beyond
// it). What one face lets through:
//   - transmission t (factor × texture R) × (1 − metallic factor) of the light, tinted by the base
//     colour — by its square root on each face of a volume (thickness above 0: a closed mesh,
//     crossed twice, tinted once as the forward pass tints it) — and attenuated over half the
//     volume's thickness (scaled as the object is) by KHR_materials_volume's colour;
//   - blended (ALPHA_BLEND): 1 − alpha of the light untouched, plus alpha × the above.
// The surfaces' Fresnel reflection is left out: clear glass of base colour white casts none.
#include "../shared/Bindings.h"
#include "../shared/MaterialData.h"

layout(std140, binding = SPECULA_BINDING_MATERIAL) uniform MaterialBlock { GpuMaterial material; };
layout(binding = SPECULA_UNIT_BASE_COLOR) uniform sampler2D uBaseColorTexture;
layout(binding = SPECULA_UNIT_TRANSMISSION_FACTOR) uniform sampler2D uTransmissionTexture;
#if defined(SHADOW_TINT)
layout(binding = SPECULA_UNIT_THICKNESS) uniform sampler2D uThicknessTexture;
uniform mat4 uModel; // the vertex stage's: the volume's thickness is in object space
layout(location = 0) out vec4 outTint;
#endif

in vec2 vUv0;
in vec2 vUv1;
in vec4 vColor;

#include "../forward/texture_uv.glsl"

void main()
{
    vec4 base = material.baseColorFactor;
#if defined(HAS_BASE_COLOR_TEXTURE) && (defined(ALPHA_MASK) || defined(SHADOW_TINT))
    base *= texture(uBaseColorTexture, textureUv(TEX_BASE_COLOR));
#endif
#if defined(VERTEX_COLOR)
    base *= vColor;
#endif
#if defined(ALPHA_MASK)
    if (base.a < material.alpha.x) discard;
#endif
#if defined(TRANSMISSION_CUTOUT)
    float transmission = material.transmission.x * texture(uTransmissionTexture, textureUv(TEX_TRANSMISSION)).r;
    if (transmission >= SPECULA_TRANSMISSION_SHADOW_LIMIT) discard;
#endif
#if defined(SHADOW_TINT)
    vec3 through = vec3(0.0);
#if defined(TRANSMISSION)
    float t = material.transmission.x * (1.0 - material.params.x);
    float thickness = material.transmission.z;
#if defined(TRANSMISSION_TEXTURES)
    t *= texture(uTransmissionTexture, textureUv(TEX_TRANSMISSION)).r;
    thickness *= texture(uThicknessTexture, textureUv(TEX_THICKNESS)).g;
#endif
    through = t * (material.transmission.z > 0.0 ? sqrt(base.rgb) : base.rgb);
    if (thickness > 0.0 && material.transmission.w > 0.0) {
        float scale = (length(uModel[0].xyz) + length(uModel[1].xyz) + length(uModel[2].xyz)) / 3.0;
        through *= pow(material.attenuation.rgb, vec3(0.5 * thickness * scale / material.transmission.w));
    }
#endif
#if defined(ALPHA_BLEND)
    vec3 tint = vec3(1.0 - base.a) + base.a * through;
#else
    vec3 tint = through;
#endif
    // The depth a little beyond the surface (its slope over a texel), so that the surface itself
    // and one lying on it (a decal) are not behind it.
    float z = gl_FragCoord.z;
    outTint = vec4(tint, z + 2.0 * max(abs(dFdx(z)), abs(dFdy(z))) + 1e-5);
#endif
}
