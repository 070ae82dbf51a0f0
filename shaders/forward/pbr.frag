#version 450 core
// Forward pass: glTF metal-rough material lit by punctual lights. This file only
// orchestrates; the BRDF lives in brdf/, light falloff in lights/.
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"
#include "../shared/MaterialData.h"
#include "../brdf/brdf.glsl"
#include "../lights/punctual.glsl"

layout(std140, binding = SPECULA_BINDING_FRAME) uniform FrameBlock { FrameData frame; };
layout(std140, binding = SPECULA_BINDING_LIGHTS) uniform LightsBlock { LightBlock lightData; };
layout(std430, binding = SPECULA_BINDING_MATERIALS) readonly buffer MaterialBuffer { GpuMaterial materials[]; };

layout(binding = SPECULA_UNIT_BASE_COLOR) uniform sampler2D uBaseColorTexture;
layout(binding = SPECULA_UNIT_METALLIC_ROUGHNESS) uniform sampler2D uMetallicRoughnessTexture;
layout(binding = SPECULA_UNIT_NORMAL) uniform sampler2D uNormalTexture;
layout(binding = SPECULA_UNIT_OCCLUSION) uniform sampler2D uOcclusionTexture;
layout(binding = SPECULA_UNIT_EMISSIVE) uniform sampler2D uEmissiveTexture;

uniform uint uMaterial;

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

vec2 textureUv(GpuMaterial m, uint texture)
{
    uint set = (m.flags.y >> (2u * texture)) & 3u;
    vec3 uv = vec3(set == 1u ? vUv1 : vUv0, 1.0);
    return vec2(dot(m.uvTransform[2u * texture].xyz, uv), dot(m.uvTransform[2u * texture + 1u].xyz, uv));
}

void main()
{
    GpuMaterial m = materials[uMaterial];
    uint flags = m.flags.x;

    vec4 baseColor = m.baseColorFactor;
    if ((flags & SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE) != 0u)
        baseColor *= texture(uBaseColorTexture, textureUv(m, TEX_BASE_COLOR)); // sRGB texture: decoded by GL
    if ((flags & SPECULA_MATERIAL_USE_VERTEX_COLOR) != 0u) baseColor *= vColor;

    if ((flags & SPECULA_MATERIAL_ALPHA_MASK) != 0u && baseColor.a < m.alpha.x) discard;
    float alpha = (flags & SPECULA_MATERIAL_ALPHA_BLEND) != 0u ? baseColor.a : 1.0;

    float metallic = m.params.x;
    float perceptualRoughness = m.params.y;
    if ((flags & SPECULA_MATERIAL_HAS_METALLIC_ROUGHNESS_TEXTURE) != 0u) {
        vec4 mr = texture(uMetallicRoughnessTexture, textureUv(m, TEX_METALLIC_ROUGHNESS));
        perceptualRoughness *= mr.g;
        metallic *= mr.b;
    }
    metallic = saturate(metallic);
    perceptualRoughness = clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0);

    // Geometric normal; back faces of double-sided materials are lit from their own side.
    vec3 n = normalize(vNormal);
    bool flip = !gl_FrontFacing && (flags & SPECULA_MATERIAL_DOUBLE_SIDED) != 0u;
    if (flip) n = -n;
    if ((flags & SPECULA_MATERIAL_HAS_NORMAL_TEXTURE) != 0u) {
        vec3 t = vTangent.xyz - n * dot(n, vTangent.xyz);
        // A zero tangent (degenerate uv) would give NaN: fall back to the geometric normal.
        if (dot(t, t) > 1e-12) {
            t = normalize(flip ? -t : t);
            vec3 b = cross(n, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
            vec3 tn = texture(uNormalTexture, textureUv(m, TEX_NORMAL)).xyz * 2.0 - 1.0;
            tn.xy *= m.params.z;
            n = normalize(mat3(t, b, n) * tn);
        }
    }

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
    if ((flags & SPECULA_MATERIAL_HAS_OCCLUSION_TEXTURE) != 0u)
        occlusion = 1.0 + m.params.w * (texture(uOcclusionTexture, textureUv(m, TEX_OCCLUSION)).r - 1.0);
    // Constant ambient (non-physical, 0 unless a scene asks): lights the diffuse part only.
    color += frame.ambient.rgb * surface.diffuseColor * occlusion;

    vec3 emissive = m.emissive.rgb;
    if ((flags & SPECULA_MATERIAL_HAS_EMISSIVE_TEXTURE) != 0u)
        emissive *= texture(uEmissiveTexture, textureUv(m, TEX_EMISSIVE)).rgb;
    color += emissive;

    outColor = vec4(min(color, vec3(kHalfMax)), alpha);
}
