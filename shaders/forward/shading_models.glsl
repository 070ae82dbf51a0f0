// Shading models of the forward pass as variants of pbr.frag (scene::ShadingModel):
// SHADING_UNLIT, SHADING_FLAT, SHADING_GOURAUD, SHADING_PHONG, SHADING_BLINN_PHONG, SHADING_DOOM; none of
// them is the physically based model (brdf/brdf.glsl). Included by pbr.frag after its blocks,
// samplers and inputs.
#include "classic_lighting.glsl"
#include "doom.glsl"

#if defined(SHADING_UNLIT) || defined(SHADING_FLAT) || defined(SHADING_GOURAUD) || defined(SHADING_PHONG) || defined(SHADING_BLINN_PHONG) || \
    defined(SHADING_DOOM)
#define SHADING_CLASSIC
#endif

#if defined(SHADING_GOURAUD)
in vec3 vGouraudDiffuse;  // per-vertex lighting (pbr.vert), interpolated (Gouraud 1971)
in vec3 vGouraudSpecular;
#endif

// kd = the base colour's diffuse part; ks = material.phong.rgb for dielectrics, the base
// colour for metals (as F0 is in the metal-rough model).
vec3 shadeClassic(vec3 baseColor, float metallic, float perceptualRoughness, vec3 n, vec3 v, float occlusion, vec3 emissive)
{
#if defined(SHADING_UNLIT)
    return baseColor + emissive;
#elif defined(SHADING_DOOM)
    // No lights, no emission: the sector's light level and the distance (doom.glsl).
    return shadeDoom(baseColor);
#else
    vec3 kd = baseColor * (1.0 - metallic);
    vec3 ks = mix(material.phong.rgb, baseColor, metallic);
    vec3 diffuse, specular;
#if defined(SHADING_GOURAUD)
    diffuse = vGouraudDiffuse;
    specular = vGouraudSpecular;
#else
#if defined(SHADING_FLAT)
    // One shade per face (Warnock 1969; Gouraud 1971 calls it "faceted"): the plane of the
    // triangle, from the screen derivatives of its position, facing the viewer.
    vec3 face = cross(dFdx(vWorldPosition), dFdy(vWorldPosition));
    n = dot(face, face) > 1e-30 ? normalize(face) : n; // edge-on: no area, keep the vertex normal
#endif
#if defined(SHADING_BLINN_PHONG)
    const bool blinn = true;
#else
    const bool blinn = false;
#endif
    classicLighting(lightList(vWorldPosition, gl_FragCoord), vWorldPosition, n, v, classicShininess(perceptualRoughness), blinn, diffuse, specular);
#endif
    // Ambient (Phong's ka Ia): the frame's constant ambient, plus the environment's
    // irradiance when image-based lighting is on; no specular image-based light. ka is the
    // base colour (the classic ka = kd, which for a metal is its colour), so that metals do
    // not go black away from their highlights.
    vec3 ambient = frame.ambient.rgb;
#if defined(IBL)
    ambient += irradianceSh(toEnvironment(n)) * INV_PI * environment.params.x;
#endif
    return kd * diffuse + baseColor * ambient * occlusion + ks * specular + emissive;
#endif
}
