#version 450 core
// A full-screen triangle on the far plane; the view ray goes to the fragment shader as a
// homogeneous point (linear in screen space, divided per fragment).
#include "../shared/Bindings.h"
#include "../shared/EnvironmentData.h"

layout(std140, binding = SPECULA_BINDING_ENVIRONMENT) uniform EnvironmentBlock { EnvironmentData environment; };

out vec4 vFarPoint;

void main()
{
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
    vFarPoint = environment.inverseViewProjection * vec4(p, 1.0, 1.0);
    gl_Position = vec4(p, 1.0, 1.0); // z = w: depth 1, behind everything drawn
}
