// KHR_materials_clearcoat: a dielectric GGX layer (ior 1.5, F0 = 0.04, F90 = 1) over the
// whole material, with its own roughness and normal. The extension's layering: the base
// (its diffuse and specular lobes, transmission and emission alike) is dimmed by what the
// layer reflects, 1 - clearcoat Fc(n_c.v), and the layer's own lobe, clearcoat F D V, is added
// (KHR_materials_clearcoat, "Implementation"; the Khronos sample viewer does the same). The
// layer has the draw's D, V and F terms (brdf/brdf.glsl) and thus reads the draw's DFG table.
// Included by pbr.frag after its blocks and texture_uv.glsl.

layout(binding = SPECULA_UNIT_CLEARCOAT) uniform sampler2D uClearcoatTexture;
layout(binding = SPECULA_UNIT_CLEARCOAT_ROUGHNESS) uniform sampler2D uClearcoatRoughnessTexture;
layout(binding = SPECULA_UNIT_CLEARCOAT_NORMAL) uniform sampler2D uClearcoatNormalTexture;

struct ClearcoatLayer {
    float factor;          // clearcoatFactor x clearcoatTexture.r
    SurfaceBrdf brdf;      // F0 0.04, F90 1, the layer's (clamped) perceptual roughness
    float iblRoughness;    // the layer's roughness unclamped, for image-based light
    vec3 n;                // the layer's normal: the geometric one, or its own normal map's
    float NoV;
    vec3 attenuation;      // 1 - factor Fc(n_c.v): what passes the layer to the base and back
};

// ng: the geometric normal (already flipped to the viewer's side for a back face); the
// layer's normal map uses the mesh's tangent frame, as normalTexture does.
ClearcoatLayer makeClearcoat(vec3 ng, bool flip, vec3 v)
{
    ClearcoatLayer c;
    c.factor = saturate(material.clearcoat.x * texture(uClearcoatTexture, textureUv(TEX_CLEARCOAT)).r);
    float roughness = saturate(material.clearcoat.y * texture(uClearcoatRoughnessTexture, textureUv(TEX_CLEARCOAT_ROUGHNESS)).g);
    c.iblRoughness = roughness;
    // The base's floor, for the same reason (a punctual light's spike).
    c.brdf = makeSurfaceBrdf(vec3(0.0), 0.0, clamp(roughness, kMinPerceptualRoughness, 1.0), vec4(1.0));
    c.n = ng;
    vec3 t = vTangent.xyz - ng * dot(ng, vTangent.xyz);
    // Only a real normal map: the flat fallback's 128 / 255 would tilt the layer by 0.3
    // degrees, which a smooth layer's highlight shows. A uniform branch, no variant. A zero
    // tangent (degenerate uv) would give NaN: keep the geometric normal.
    if ((material.flags.x & SPECULA_MATERIAL_HAS_CLEARCOAT_NORMAL_TEXTURE) != 0u && dot(t, t) > 1e-12) {
        t = normalize(flip ? -t : t);
        vec3 b = cross(ng, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
        vec3 tn = texture(uClearcoatNormalTexture, textureUv(TEX_CLEARCOAT_NORMAL)).xyz * 2.0 - 1.0;
        tn.xy *= material.clearcoat.z;
        c.n = normalize(mat3(t, b, ng) * tn);
    }
    c.NoV = max(dot(c.n, v), 1e-4); // as the base's: a mapped normal can face away
    c.attenuation = 1.0 - c.factor * brdfF(c.brdf, c.NoV);
    return c;
}

// The layer's lobe for one light, f_c NoL_c x clearcoat (1/sr), zero below its horizon.
vec3 clearcoatPunctual(ClearcoatLayer c, vec3 v, vec3 l)
{
    float NoL = dot(c.n, l);
    if (NoL <= 0.0) return vec3(0.0);
    vec3 diffuse, specular;
    evaluateBrdfLobes(c.brdf, c.n, v, l, diffuse, specular); // diffuse colour 0: no diffuse lobe
    return specular * (NoL * c.factor);
}
