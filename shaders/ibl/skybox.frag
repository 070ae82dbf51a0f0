#version 450 core
// The environment behind the scene: the sky's cube (sharp) or, with SKYBOX_BLURRED, a level of
// its prefiltered chain (render/passes/SkyboxPass binds either to uSky).
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"
#include "../common/math.glsl"
#include "ibl.glsl"

layout(std140, binding = SPECULA_BINDING_FRAME) uniform FrameBlock { FrameData frame; };
layout(binding = 0) uniform samplerCube uSky;

in vec4 vFarPoint;
layout(location = 0) out vec4 outColor;

void main()
{
    vec3 direction = normalize(vFarPoint.xyz / vFarPoint.w - frame.cameraPosition.xyz);
    vec3 d = toEnvironment(direction);
#if defined(SKYBOX_BLURRED)
    vec3 radiance = textureLod(uSky, d, environment.params.z).rgb; // the prefiltered chain; params.z: the level, >= 0
#else
    vec3 radiance = textureLod(uSky, d, 0.0).rgb;
#endif
    outColor = vec4(min(radiance * environment.params.x, vec3(65504.0)), 1.0);
}
