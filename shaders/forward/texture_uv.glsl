// Texture coordinates of a material's textures, shared by the forward pass and the depth/normal
// pre-pass. The includer declares the `material` block (GpuMaterial) and the inputs vUv0, vUv1.

const uint TEX_BASE_COLOR = 0u;
const uint TEX_METALLIC_ROUGHNESS = 1u;
const uint TEX_NORMAL = 2u;
const uint TEX_OCCLUSION = 3u;
const uint TEX_EMISSIVE = 4u;
const uint TEX_CLEARCOAT = 5u;
const uint TEX_CLEARCOAT_ROUGHNESS = 6u;
const uint TEX_CLEARCOAT_NORMAL = 7u;
const uint TEX_SHEEN_COLOR = 8u;
const uint TEX_SHEEN_ROUGHNESS = 9u;
const uint TEX_ANISOTROPY = 10u; // 8, 9: KHR_materials_sheen's; 11, 12: KHR_materials_iridescence's
const uint TEX_IRIDESCENCE = 11u; // 8-10: sheen and anisotropy (issue 18)
const uint TEX_IRIDESCENCE_THICKNESS = 12u;
const uint TEX_SPECULAR = 13u; // KHR_materials_specular's two
const uint TEX_SPECULAR_COLOR = 14u;
const uint TEX_TRANSMISSION = 15u; // KHR_materials_transmission's, then KHR_materials_volume's
const uint TEX_THICKNESS = 16u;
const uint TEX_DIFFUSE_TRANSMISSION = 17u; // KHR_materials_diffuse_transmission's two
const uint TEX_DIFFUSE_TRANSMISSION_COLOR = 18u;

// Texture coordinates of one texture: its uv set and KHR_texture_transform.
vec2 textureUv(uint texture)
{
    uint sets = texture < 16u ? material.flags.y : material.flags.z; // 2 bits a texture
    uint set = (sets >> (2u * (texture & 15u))) & 3u;
    vec3 uv = vec3(set == 1u ? vUv1 : vUv0, 1.0);
    return vec2(dot(material.uvTransform[2u * texture].xyz, uv),
                dot(material.uvTransform[2u * texture + 1u].xyz, uv));
}
