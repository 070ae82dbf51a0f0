#version 450 core
// Forward pass: glTF metal-rough material lit by punctual lights. This file only
// orchestrates; the BRDF lives in brdf/, light falloff in lights/.
// Material features are compile-time variants (see Renderer's variant key): HAS_*_TEXTURE,
// VERTEX_COLOR, ALPHA_MASK, ALPHA_BLEND, DOUBLE_SIDED. A material without a feature pays
// nothing for it; without ALPHA_MASK there is no discard, so early depth testing stays on.
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"
#include "../shared/MaterialData.h"
#include "../brdf/brdf.glsl"
#include "../lights/punctual.glsl"

layout(std140, binding = SPECULA_BINDING_FRAME) uniform FrameBlock { FrameData frame; };
layout(std140, binding = SPECULA_BINDING_LIGHTS) uniform LightsBlock { LightBlock lightData; };
layout(std140, binding = SPECULA_BINDING_MATERIAL) uniform MaterialBlock { GpuMaterial material; };

layout(binding = SPECULA_UNIT_BASE_COLOR) uniform sampler2D uBaseColorTexture;
layout(binding = SPECULA_UNIT_METALLIC_ROUGHNESS) uniform sampler2D uMetallicRoughnessTexture;
layout(binding = SPECULA_UNIT_NORMAL) uniform sampler2D uNormalTexture;
layout(binding = SPECULA_UNIT_OCCLUSION) uniform sampler2D uOcclusionTexture;
layout(binding = SPECULA_UNIT_EMISSIVE) uniform sampler2D uEmissiveTexture;

in vec3 vWorldPosition;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUv0;
in vec2 vUv1;
in vec4 vColor;

layout(location = 0) out vec4 outColor;

// Filament's MIN_PERCEPTUAL_ROUGHNESS: below it D_GGX of a punctual light is a spike that
// neither half floats nor a single pixel can hold.
const float kMinPerceptualRoughness = 0.045;
// Largest finite half float: keeps a very bright highlight from becoming Inf in RGBA16F.
const float kHalfMax = 65504.0;

const uint TEX_BASE_COLOR = 0u;
const uint TEX_METALLIC_ROUGHNESS = 1u;
const uint TEX_NORMAL = 2u;
const uint TEX_OCCLUSION = 3u;
const uint TEX_EMISSIVE = 4u;

// Texture coordinates of one texture: its uv set and KHR_texture_transform.
vec2 textureUv(uint texture)
{
    uint set = (material.flags.y >> (2u * texture)) & 3u;
    vec3 uv = vec3(set == 1u ? vUv1 : vUv0, 1.0);
    return vec2(dot(material.uvTransform[2u * texture].xyz, uv),
                dot(material.uvTransform[2u * texture + 1u].xyz, uv));
}

void main()
{
    vec4 baseColor = material.baseColorFactor;
#if defined(HAS_BASE_COLOR_TEXTURE)
    baseColor *= texture(uBaseColorTexture, textureUv(TEX_BASE_COLOR)); // sRGB texture: decoded by GL
#endif
#if defined(VERTEX_COLOR)
    baseColor *= vColor;
#endif
#if defined(ALPHA_MASK)
    if (baseColor.a < material.alpha.x) discard;
#endif
#if defined(ALPHA_BLEND)
    float alpha = baseColor.a;
#else
    float alpha = 1.0;
#endif

    vec4 params = material.params;
    float metallic = params.x;
    float perceptualRoughness = params.y;
#if defined(HAS_METALLIC_ROUGHNESS_TEXTURE)
    vec4 mr = texture(uMetallicRoughnessTexture, textureUv(TEX_METALLIC_ROUGHNESS));
    perceptualRoughness *= mr.g;
    metallic *= mr.b;
#endif
    metallic = saturate(metallic);
    perceptualRoughness = clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0);

    vec3 n = normalize(vNormal);
#if defined(DOUBLE_SIDED)
    // Back faces of double-sided materials are lit from their own side.
    bool flip = !gl_FrontFacing;
    if (flip) n = -n;
#else
    const bool flip = false;
#endif
#if defined(HAS_NORMAL_TEXTURE)
    vec3 t = vTangent.xyz - n * dot(n, vTangent.xyz);
    // A zero tangent (degenerate uv) would give NaN: fall back to the geometric normal.
    if (dot(t, t) > 1e-12) {
        t = normalize(flip ? -t : t);
        vec3 b = cross(n, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
        vec3 tn = texture(uNormalTexture, textureUv(TEX_NORMAL)).xyz * 2.0 - 1.0;
        tn.xy *= params.z;
        n = normalize(mat3(t, b, n) * tn);
    }
#endif

    vec3 v = normalize(frame.cameraPosition.xyz - vWorldPosition);
    SurfaceBrdf surface = makeSurfaceBrdf(baseColor.rgb, metallic, perceptualRoughness);

    vec3 color = vec3(0.0);
    uint lightCount = min(lightData.count.x, uint(SPECULA_MAX_LIGHTS));
    for (uint i = 0u; i < lightCount; ++i) {
        vec3 l;
        vec3 illuminance = lightIlluminance(lightData.lights[i], vWorldPosition, l);
        float NoL = dot(n, l);
        if (NoL <= 0.0) continue;
        color += evaluateBrdf(surface, n, v, l) * illuminance * NoL;
    }

    float occlusion = 1.0;
#if defined(HAS_OCCLUSION_TEXTURE)
    occlusion = 1.0 + params.w * (texture(uOcclusionTexture, textureUv(TEX_OCCLUSION)).r - 1.0);
#endif
    // Constant ambient (non-physical, 0 unless a scene asks): lights the diffuse part only.
    color += frame.ambient.rgb * surface.diffuseColor * occlusion;

    vec3 emissive = material.emissive.rgb;
#if defined(HAS_EMISSIVE_TEXTURE)
    emissive *= texture(uEmissiveTexture, textureUv(TEX_EMISSIVE)).rgb;
#endif
    color += emissive;

    outColor = vec4(min(color, vec3(kHalfMax)), alpha);
}
