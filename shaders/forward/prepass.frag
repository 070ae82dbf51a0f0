#version 450 core
// Depth/normal pre-pass for SSAO (render/SsaoPass): the view-space normal of the triangle
// itself, from the derivatives of the view-space position, and the view-space z (32-bit float:
// the SSAO passes read position and normal in one fetch). The face normal is the
// plane the depth buffer holds, so a hemisphere around it never dips below a flat facet (an
// interpolated vertex normal tilts against it and would self-occlude tessellated curves);
// it also faces the camera on both sides of double-sided surfaces. Normal maps are left to
// the material's occlusion texture. Variants: ALPHA_MASK (with HAS_BASE_COLOR_TEXTURE,
// VERTEX_COLOR) discards what the forward pass discards.
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"
#include "../shared/MaterialData.h"

layout(std140, binding = SPECULA_BINDING_FRAME) uniform FrameBlock { FrameData frame; };
layout(std140, binding = SPECULA_BINDING_MATERIAL) uniform MaterialBlock { GpuMaterial material; };
layout(binding = SPECULA_UNIT_BASE_COLOR) uniform sampler2D uBaseColorTexture;

in vec3 vWorldPosition;
in vec2 vUv0;
in vec2 vUv1;
in vec4 vColor;

layout(location = 0) out vec4 outNormal;

#include "texture_uv.glsl"

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
    vec3 p = (frame.view * vec4(vWorldPosition, 1.0)).xyz;
    // Window x and y grow right and up, so this cross product points out of the screen.
    vec3 n = cross(dFdx(p), dFdy(p));
    // A triangle seen exactly edge-on has no area on screen: any normal will do.
    n = dot(n, n) > 1e-30 ? normalize(n) : vec3(0.0, 0.0, 1.0);
    outNormal = vec4(n, p.z);
}
