#version 450 core
// Forward pass vertex shader: world-space position, normal and tangent for lighting. With
// SHADING_GOURAUD it also lights each vertex (Gouraud 1971) with the Phong model; with SHADOW_PASS
// it projects into a light's shadow view instead of the camera's.
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"
#include "../common/frame_block.glsl"

#if defined(SHADING_GOURAUD)
// The lights are read through a buffer texture (lights/light_list.glsl), which every stage
// may sample (vertex shaders are promised no storage blocks: GL 4.5's minimum is 0).
#include "../shared/MaterialData.h"
#define SPECULA_VERTEX_STAGE // lights/light_list.glsl: a vertex outside the view gets every light
layout(std140, binding = SPECULA_BINDING_MATERIAL) uniform MaterialBlock { GpuMaterial material; };
#include "classic_lighting.glsl"
out vec3 vGouraudDiffuse;
out vec3 vGouraudSpecular;
#endif

layout(location = SPECULA_ATTRIB_POSITION) in vec3 aPosition;
layout(location = SPECULA_ATTRIB_NORMAL) in vec3 aNormal;
layout(location = SPECULA_ATTRIB_TANGENT) in vec4 aTangent;
layout(location = SPECULA_ATTRIB_UV0) in vec2 aUv0;
layout(location = SPECULA_ATTRIB_UV1) in vec2 aUv1;
layout(location = SPECULA_ATTRIB_COLOR) in vec4 aColor;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
#if defined(SHADOW_PASS)
uniform mat4 uShadowViewProjection; // the light's view (render/passes/ShadowPass)
#endif

out vec3 vWorldPosition;
out vec3 vNormal;
out vec4 vTangent;
out vec2 vUv0;
out vec2 vUv1;
out vec4 vColor;

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    vTangent = vec4(mat3(uModel) * aTangent.xyz, aTangent.w);
    vUv0 = aUv0;
    vUv1 = aUv1;
    vColor = aColor;
#if defined(SHADOW_PASS)
    gl_Position = uShadowViewProjection * world;
#else
    gl_Position = frame.viewProjection * world;
#endif
#if defined(SHADING_GOURAUD)
    // Roughness without its texture: a vertex has no texel of its own.
    float perceptualRoughness = clamp(material.params.y, 0.045, 1.0);
    vec3 n = normalize(vNormal);
    vec3 v = normalize(frame.cameraPosition.xyz - world.xyz);
    classicLighting(lightList(world.xyz), world.xyz, n, v, classicShininess(perceptualRoughness), false, vGouraudDiffuse, vGouraudSpecular);
#endif
}
