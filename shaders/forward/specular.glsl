// KHR_materials_specular: the dielectric's specular strength and colour (makeSurfaceBrdf's
// `specular`: rgb the colour x F0(ior) / 0.04, a the factor), times the extension's textures in
// the SPECULAR_TEXTURES variant: specularColorTexture's RGB (sRGB, decoded by GL) and
// specularTexture's A (white where a material has only one of them). Included by pbr.frag after
// its blocks and texture_uv.glsl.
#if defined(SPECULAR_TEXTURES)
layout(binding = SPECULA_UNIT_SPECULAR) uniform sampler2D uSpecularTexture;
layout(binding = SPECULA_UNIT_SPECULAR_COLOR) uniform sampler2D uSpecularColorTexture;
#endif

vec4 materialSpecular()
{
    vec4 specular = material.specular;
#if defined(SPECULAR_TEXTURES)
    specular.rgb *= texture(uSpecularColorTexture, textureUv(TEX_SPECULAR_COLOR)).rgb;
    specular.a *= texture(uSpecularTexture, textureUv(TEX_SPECULAR)).a;
#endif
    return specular;
}
