// Binding points shared by C++ and GLSL (explicit layout(binding = N) everywhere).
#ifdef __cplusplus
#pragma once
#endif

// Uniform buffers
#define SPECULA_BINDING_FRAME 0
#define SPECULA_BINDING_LIGHTS 1
#define SPECULA_BINDING_MATERIAL 2 // one material's range of the material buffer, per draw
// Storage buffers
#define SPECULA_BINDING_BILLBOARDS 3
// Texture units of the forward pass
#define SPECULA_UNIT_BASE_COLOR 0
#define SPECULA_UNIT_METALLIC_ROUGHNESS 1
#define SPECULA_UNIT_NORMAL 2
#define SPECULA_UNIT_OCCLUSION 3
#define SPECULA_UNIT_EMISSIVE 4
// The billboard pass's sprite
#define SPECULA_UNIT_SPRITE 0
// Post-processing input
#define SPECULA_UNIT_POST_INPUT 0

// Vertex attribute locations
#define SPECULA_ATTRIB_POSITION 0
#define SPECULA_ATTRIB_NORMAL 1
#define SPECULA_ATTRIB_TANGENT 2
#define SPECULA_ATTRIB_UV0 3
#define SPECULA_ATTRIB_UV1 4
#define SPECULA_ATTRIB_COLOR 5
