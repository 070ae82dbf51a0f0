// Material parameters: one record per material in one buffer, each bound as a uniform block
// range for its draws. (A storage buffer indexed per draw would be simpler, but llvmpipe
// returns zeros for storage-buffer loads in helper invocations, which breaks the texture
// derivatives of KHR_texture_transform'd uvs along triangle edges.)
#ifdef __cplusplus
#pragma once
#endif
#include "Prelude.h"

SPECULA_SHARED_BEGIN

#define SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE 1u
#define SPECULA_MATERIAL_HAS_METALLIC_ROUGHNESS_TEXTURE 2u
#define SPECULA_MATERIAL_HAS_NORMAL_TEXTURE 4u
#define SPECULA_MATERIAL_HAS_OCCLUSION_TEXTURE 8u
#define SPECULA_MATERIAL_HAS_EMISSIVE_TEXTURE 16u
#define SPECULA_MATERIAL_DOUBLE_SIDED 32u
#define SPECULA_MATERIAL_ALPHA_MASK 64u
#define SPECULA_MATERIAL_ALPHA_BLEND 128u
#define SPECULA_MATERIAL_USE_VERTEX_COLOR 256u
#define SPECULA_MATERIAL_BLEND_TRANSPARENT 512u // blended: specular and emission not scaled by alpha
#define SPECULA_MATERIAL_TRANSMISSION 1024u     // KHR_materials_transmission factor above 0
#define SPECULA_MATERIAL_CLEARCOAT 2048u        // KHR_materials_clearcoat factor above 0
#define SPECULA_MATERIAL_HAS_CLEARCOAT_NORMAL_TEXTURE 4096u // read at run time by the CLEARCOAT variant
// Bits 16-30 of a material's feature word hold its shading choice (shading/ShadingVariant.h).
#define SPECULA_MATERIAL_DISPERSION 0x80000000u // KHR_materials_dispersion above 0 on a volume
#define SPECULA_MATERIAL_SHEEN 8192u            // KHR_materials_sheen colour factor above 0
#define SPECULA_MATERIAL_ANISOTROPY 16384u      // KHR_materials_anisotropy strength above 0 (GGX only)
#define SPECULA_MATERIAL_IRIDESCENCE 32768u     // KHR_materials_iridescence factor above 0
// The shadow rule for light that passes through (render::castsShadow): a surface casts where
// its transmission (factor × texture) is below this.
#define SPECULA_TRANSMISSION_SHADOW_LIMIT 0.5

struct GpuMaterial {
    vec4 baseColorFactor;
    vec4 emissive;        // rgb emissive factor x KHR_materials_emissive_strength, w Doom sector light / 255
    vec4 params;          // x metallic, y perceptual roughness, z normal scale, w occlusion strength
    vec4 alpha;           // x alpha cutoff
    uvec4 flags;          // x SPECULA_MATERIAL_* bits; y, z texCoord sets, 2 bits per texture, y
                          // for textures 0-15, z for 16 on (render::TextureSlot: base colour,
                          // metallic-roughness, normal, occlusion, emissive, clearcoat, clearcoat
                          // roughness, clearcoat normal, sheen colour, sheen roughness, anisotropy,
                          // iridescence, iridescence thickness, specular, specular colour,
                          // transmission, thickness, diffuse transmission, diffuse transmission
                          // colour: 19)
    vec4 uvTransform[38]; // per texture two rows (a b c)(d e f) of KHR_texture_transform
    vec4 specular;        // KHR_materials_specular: rgb specularColorFactor, a specularFactor; rgb also
                          // carries KHR_materials_ior: x (F0(ior) / 0.04), so 0.04 x rgb is the dielectric F0
    vec4 phong;           // Phong, Blinn-Phong, Gouraud, flat: rgb dielectric specular colour ks,
                          // a shininess (0 = from roughness)
    vec4 transmission;    // x KHR_materials_transmission factor, y ior (refraction; 1.5 by default),
                          // z KHR_materials_volume thickness (object-space metres, 0 = thin-walled),
                          // w attenuation distance (metres, 0 = infinite)
    vec4 attenuation;     // rgb KHR_materials_volume attenuation colour, w KHR_materials_dispersion (20 / V_d)
    vec4 clearcoat;       // KHR_materials_clearcoat: x clearcoatFactor, y clearcoatRoughnessFactor
                          // (perceptual), z clearcoat normal texture scale
    vec4 sheen;           // KHR_materials_sheen: rgb sheenColorFactor (linear), a sheenRoughnessFactor (perceptual)
    vec4 anisotropy;      // KHR_materials_anisotropy: x anisotropyStrength, y cos, z sin of anisotropyRotation,
                          // w 1 with an anisotropyTexture (read at run time by the ANISOTROPY variant)
    vec4 iridescence;     // KHR_materials_iridescence: x iridescenceFactor, y iridescenceIor,
                          // z iridescenceThicknessMinimum, w iridescenceThicknessMaximum (nm)
    vec4 diffuseTransmission; // KHR_materials_diffuse_transmission: rgb diffuseTransmissionColorFactor
                              // (linear), a diffuseTransmissionFactor (read by the DIFFUSE_TRANSMISSION variant)
};

SPECULA_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(specula::shared::GpuMaterial) == 52 * 16);
// Feature bits above the record's 32, in render::MaterialBinding::features only: which of an
// extension's textures a variant samples (the record needs no flag for them).
#define SPECULA_MATERIAL_SPECULAR_TEXTURES (uint64_t(1) << 32)     // KHR_materials_specular's
#define SPECULA_MATERIAL_TRANSMISSION_TEXTURES (uint64_t(1) << 33) // KHR_materials_transmission's and _volume's
// KHR_materials_diffuse_transmission: its factor above 0 (the record's 32 bits are all taken:
// the variant alone reads the factor), and its textures.
#define SPECULA_MATERIAL_DIFFUSE_TRANSMISSION (uint64_t(1) << 34)
#define SPECULA_MATERIAL_DIFFUSE_TRANSMISSION_TEXTURES (uint64_t(1) << 35)
#endif
