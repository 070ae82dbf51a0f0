// KHR_materials_iridescence: a thin dielectric film over the base whose interference colours
// its specular reflection. The extension replaces the specular lobe's Fresnel by
// F = mix(F_schlick, F_iridescence, iridescence) (brdf/thin_film.glsl), the dielectric base's
// and the metal's films mixed by metallic, and weights the diffuse lobe by 1 - max(F_iridescence)
// where the film is ("rgb_mix": 1 - F per channel would tint it with the inverse colour).
// Punctual light: the film at each light's v.h. Image-based light: the split sum takes the film
// at n.v in place of the DFG table's Fresnel, E = F_iridescence(n.v) (A + B), as the Khronos
// sample renderer does; --ibl importance: the film per sample (ibl/importance.glsl).
// Included by pbr.frag after its blocks and texture_uv.glsl.
#include "../brdf/thin_film.glsl"

layout(binding = SPECULA_UNIT_IRIDESCENCE) uniform sampler2D uIridescenceTexture;
layout(binding = SPECULA_UNIT_IRIDESCENCE_THICKNESS) uniform sampler2D uIridescenceThicknessTexture;

// The film of this fragment: factor x texture R; thickness mix(minimum, maximum, texture G)
// (a white texture without one: the maximum, as the extension says). `specular`:
// materialSpecular() (forward/specular.glsl).
ThinFilm makeIridescence(vec3 baseColor, float metallic, vec4 specular)
{
    ThinFilm f;
    f.factor = saturate(material.iridescence.x * texture(uIridescenceTexture, textureUv(TEX_IRIDESCENCE)).r);
    f.ior = material.iridescence.y;
    f.thickness = mix(material.iridescence.z, material.iridescence.w,
                      texture(uIridescenceThicknessTexture, textureUv(TEX_IRIDESCENCE_THICKNESS)).g);
    // makeSurfaceBrdf's dielectric F0 (KHR_materials_specular and _ior included).
    f.f0Dielectric = min(vec3(0.04) * specular.rgb, vec3(1.0)) * specular.a;
    f.f0Metal = baseColor;
    f.metallic = metallic;
    return f;
}

float iridescenceMax3(vec3 c)
{
    return max(c.r, max(c.g, c.b));
}

// The diffuse lobe's weight where the specular lobe's Fresnel is mix(F, film, factor).
vec3 iridescentDiffuseWeight(vec3 F, vec3 film, float factor)
{
    return mix(1.0 - F, vec3(max(1.0 - iridescenceMax3(film), 0.0)), factor);
}

// The lobes with the film's Fresnel mixed in at v.h, for the specular lobe's D V.
void iridescentLobes(SurfaceBrdf s, ThinFilm film, float DV, float NoV, float NoL, float VoH, float VoL, out vec3 diffuse,
                     out vec3 specular)
{
    vec3 F = brdfF(s, VoH);
    vec3 filmF = thinFilmFresnel(film, VoH);
    specular = mix(F, filmF, film.factor) * DV;
    diffuse = iridescentDiffuseWeight(F, filmF, film.factor) * brdfDiffuse(s, NoV, NoL, VoH, VoL);
}

// evaluateBrdfLobes (brdf/brdf.glsl) with the film's Fresnel.
void evaluateIridescentLobes(SurfaceBrdf s, ThinFilm film, vec3 n, vec3 v, vec3 l, out vec3 diffuse, out vec3 specular)
{
    vec3 h = normalize(v + l);
    float NoV = abs(dot(n, v));
    float NoL = saturate(dot(n, l));
    float NoH = saturate(dot(n, h));
    float VoH = saturate(dot(v, h));
    float DV = brdfD(NoH, s.alpha) * brdfV(s, NoV, NoL, NoH, VoH);
    iridescentLobes(s, film, DV, NoV, NoL, VoH, dot(v, l), diffuse, specular);
}

#if defined(ANISOTROPY)
// Both: evaluateAnisotropicLobes (forward/anisotropy.glsl) with the film's Fresnel.
void evaluateIridescentAnisotropicLobes(SurfaceBrdf s, ThinFilm film, AnisotropicLobe a, vec3 n, vec3 v, vec3 l, out vec3 diffuse,
                                        out vec3 specular)
{
    vec3 h = normalize(v + l);
    float NoV = abs(dot(n, v));
    float NoL = saturate(dot(n, l));
    float NoH = saturate(dot(n, h));
    float VoH = saturate(dot(v, h));
    iridescentLobes(s, film, anisotropicDV(s, a, v, l, h, NoV, NoL, NoH), NoV, NoL, VoH, dot(v, l), diffuse, specular);
}
#endif

// The Fresnel the specular lobe has at n.v (the debug view, the split sum, transmission).
vec3 iridescentFresnelAt(SurfaceBrdf s, ThinFilm film, float NoV)
{
    return mix(brdfF(s, NoV), thinFilmFresnel(film, NoV), film.factor);
}
