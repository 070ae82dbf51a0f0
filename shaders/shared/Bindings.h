// Binding points shared by C++ and GLSL (explicit layout(binding = N) everywhere).
#ifdef __cplusplus
#pragma once
#endif

// Uniform buffers
#define SPECULA_BINDING_FRAME 0
#define SPECULA_BINDING_MATERIAL 2 // one material's range of the material buffer, per draw
#define SPECULA_BINDING_ENVIRONMENT 4
// Storage buffers
#define SPECULA_BINDING_BILLBOARDS 3
#define SPECULA_BINDING_LIGHTS 9 // LightHeader + GpuLight[] (shared/LightData.h), compute passes' view of it
#define SPECULA_BINDING_CLUSTERS 10      // the cluster lists' words (shared/ClusterData.h), as the culling passes write them
#define SPECULA_BINDING_CULL_LIGHTS 11   // CullLight[]: the point and spot lights in view
#define SPECULA_BINDING_CLUSTER_BOUNDS 12 // ClusterBounds[]: each cluster's view-space box
// Texture units of the forward pass
#define SPECULA_UNIT_BASE_COLOR 0
#define SPECULA_UNIT_METALLIC_ROUGHNESS 1
#define SPECULA_UNIT_NORMAL 2
#define SPECULA_UNIT_OCCLUSION 3
#define SPECULA_UNIT_EMISSIVE 4
// The billboard pass's sprite
#define SPECULA_UNIT_SPRITE 0
// Image-based lighting (forward pass and skybox)
#define SPECULA_UNIT_PREFILTERED 8
#define SPECULA_UNIT_DFG 9
// Post-processing input
#define SPECULA_UNIT_POST_INPUT 0
// Post-processing (render/BloomPass, SsaoPass, ExposurePass, FxaaPass)
#define SPECULA_UNIT_POST_INPUT_1 1      // a compute pass's second and third inputs
#define SPECULA_UNIT_POST_INPUT_2 2
#define SPECULA_IMAGE_POST_OUTPUT 0      // image unit a compute pass writes
#define SPECULA_UNIT_SHADOW_ATLAS 5      // depth atlas with a comparison sampler (lights/shadow.glsl)
#define SPECULA_UNIT_SHADOW_DEPTH 6      // the same atlas, raw depths (PCSS blocker search)
#define SPECULA_UNIT_SHADOW_RECORDS 7    // shadow records, RGBA32F buffer texture (shared/ShadowData.h)
#define SPECULA_UNIT_LIGHTS 10           // the light buffer's texel view (lights/light_list.glsl)
#define SPECULA_UNIT_CLUSTERS 11         // the cluster lists' texel view, R32UI (lights/light_list.glsl)
#define SPECULA_UNIT_IRRADIANCE 16       // the irradiance cube (ibl/ibl.glsl); GL 4.5 promises 16 units, every
                                         // desktop driver has 32 (Renderer checks: gl::maxTextureUnits)
#define SPECULA_UNIT_TRANSMISSION 17     // forward pass: the opaque frame and its mips (forward/transmission.glsl)
#define SPECULA_UNIT_ENVIRONMENT_CUBE 18 // the environment cube, box-filtered mips (ibl/importance.glsl)
#define SPECULA_UNIT_CLEARCOAT 19           // KHR_materials_clearcoat's three textures (forward pass)
#define SPECULA_UNIT_CLEARCOAT_ROUGHNESS 20
#define SPECULA_UNIT_CLEARCOAT_NORMAL 21
#define SPECULA_UNIT_SHEEN_COLOR 22         // KHR_materials_sheen's two textures (forward pass)
#define SPECULA_UNIT_SHEEN_ROUGHNESS 23
#define SPECULA_UNIT_SHEEN_ALBEDO 27        // the sheen lobe's directional albedo E(n.v, roughness) (ibl/sheen_albedo.comp)
#define SPECULA_UNIT_RESIDUAL_CUBE 28       // the environment cube less its bright sources, box-filtered mips (ibl/bright_sources.glsl)
#define SPECULA_UNIT_RESIDUAL_PREFILTERED 29 // its prefiltered levels from ImageBasedLighting::kResidualFirstLevel on
#define SPECULA_UNIT_ANISOTROPY 24          // KHR_materials_anisotropy's texture (forward pass, ANISOTROPY variant)
#define SPECULA_UNIT_IRIDESCENCE 25           // KHR_materials_iridescence's two textures (forward pass)
#define SPECULA_UNIT_IRIDESCENCE_THICKNESS 26
#define SPECULA_UNIT_SPECULAR 30            // KHR_materials_specular's two textures (forward pass)
#define SPECULA_UNIT_SPECULAR_COLOR 31
// Above 31: a fragment shader may use any unit below GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS (every
// GL 4.5 has far more than 36) as long as one program samples no more than
// GL_MAX_TEXTURE_IMAGE_UNITS textures: the widest forward program samples 25 on
// llvmpipe (GlTest.TheWidestForwardProgramLinksWithinTheTextureUnits checks it against the count).
#define SPECULA_UNIT_TRANSMISSION_FACTOR 32 // KHR_materials_transmission's texture (forward pass)
#define SPECULA_UNIT_THICKNESS 33           // KHR_materials_volume's
#define SPECULA_UNIT_DIFFUSE_TRANSMISSION 34       // KHR_materials_diffuse_transmission's two textures
#define SPECULA_UNIT_DIFFUSE_TRANSMISSION_COLOR 35 // (forward pass, DIFFUSE_TRANSMISSION_TEXTURES variant)
#define SPECULA_UNIT_SHADOW_TINT 36         // what surfaces over a shadow texel let through, and the nearest one's depth (lights/shadow.glsl, SHADOW_TINT)
#define SPECULA_UNIT_SSAO 12             // forward pass: the blurred ambient occlusion
#define SPECULA_BINDING_SSAO 5           // uniform buffer: SsaoData
#define SPECULA_BINDING_EXPOSURE_PARAMS 6 // uniform buffer: ExposureParams
#define SPECULA_BINDING_EXPOSURE 7       // storage buffer: ExposureState
#define SPECULA_BINDING_HISTOGRAM 8      // storage buffer: luminance histogram
// The Doom model's colour tables (render/DoomPass, shaders/doom/palette.glsl): forward,
// billboard and colour-map passes
#define SPECULA_UNIT_DOOM_NEAREST 13     // nearest-index table, 3D R8UI
#define SPECULA_UNIT_DOOM_COLORMAP 14    // colour map, 256 x 32 R8UI
#define SPECULA_UNIT_DOOM_PALETTE 15     // palette, 256 x 1 RGBA8 (sRGB bytes)

// Vertex attribute locations
#define SPECULA_ATTRIB_POSITION 0
#define SPECULA_ATTRIB_NORMAL 1
#define SPECULA_ATTRIB_TANGENT 2
#define SPECULA_ATTRIB_UV0 3
#define SPECULA_ATTRIB_UV1 4
#define SPECULA_ATTRIB_COLOR 5
