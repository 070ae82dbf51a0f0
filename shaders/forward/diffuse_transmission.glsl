// KHR_materials_diffuse_transmission: a fraction of the dielectric's diffuse lobe is a
// Lambertian BTDF instead, light through a thin surface (a leaf, paper, a lampshade) from the
// other side. The extension's dielectric is
//   fresnel_mix(base = mix(diffuse_brdf(baseColor), diffuse_btdf(colour), fraction), layer = specular),
// so a light behind the surface (n.l < 0) gives (1 - F) fraction colour / pi |n.l|, and every
// diffuse light in front is scaled by 1 - fraction; the specular lobe is untouched. F is
// Schlick's at v.h of the light mirrored through the surface's plane (the Fresnel weight the
// diffuse lobe has for a light there); the metal part has no diffuse lobe to give up, so the
// colour carries (1 - metallic) as c_diff does. Image-based light reaches the BTDF as the
// irradiance from -n. Included by pbr.frag after its blocks and texture_uv.glsl.
#if defined(DIFFUSE_TRANSMISSION_TEXTURES)
layout(binding = SPECULA_UNIT_DIFFUSE_TRANSMISSION) uniform sampler2D uDiffuseTransmissionTexture;
layout(binding = SPECULA_UNIT_DIFFUSE_TRANSMISSION_COLOR) uniform sampler2D uDiffuseTransmissionColorTexture;
#endif

struct DiffuseTransmission {
    float fraction; // diffuseTransmissionFactor x diffuseTransmissionTexture's A
    vec3 color;     // diffuseTransmissionColorFactor x diffuseTransmissionColorTexture's RGB x (1 - metallic)
};

DiffuseTransmission makeDiffuseTransmission(float metallic)
{
    DiffuseTransmission t;
    t.fraction = material.diffuseTransmission.a;
    t.color = material.diffuseTransmission.rgb * (1.0 - metallic);
#if defined(DIFFUSE_TRANSMISSION_TEXTURES)
    t.fraction *= texture(uDiffuseTransmissionTexture, textureUv(TEX_DIFFUSE_TRANSMISSION)).a;
    t.color *= texture(uDiffuseTransmissionColorTexture, textureUv(TEX_DIFFUSE_TRANSMISSION_COLOR)).rgb; // sRGB: decoded by GL
#endif
    return t;
}

// Radiance towards v per unit illuminance of a light behind the surface (dot(n, l) < 0), the
// fraction not yet applied (the caller mixes the two sides).
vec3 diffuseTransmittedPunctual(SurfaceBrdf s, DiffuseTransmission t, vec3 n, vec3 v, vec3 l)
{
    float NoL = -dot(n, l);
    vec3 mirrored = l + 2.0 * NoL * n; // l reflected through the surface's plane
    float VoH = saturate(dot(v, normalize(v + mirrored)));
    return (1.0 - brdfF(s, VoH)) * t.color * (INV_PI * NoL);
}
