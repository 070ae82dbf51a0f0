// KHR_materials_anisotropy: the specular GGX lobe grows rougher along one direction of the
// tangent plane, alpha_t = mix(alpha, 1, strength^2), and keeps alpha_b = alpha across it, with
// the extension's anisotropic D and height-correlated V (brdf/ggx.glsl, brdf/smith.glsl); F
// and the diffuse lobe are the material's. The direction is the mesh's tangent turned by
// anisotropyRotation, or the texture's RG (x 2 - 1) turned by it, in the tangent frame
// normalTexture uses; the texture's B scales the strength (KHR_materials_anisotropy,
// "Anisotropy" and "Implementation"). Included by pbr.frag after its blocks and texture_uv.glsl.

layout(binding = SPECULA_UNIT_ANISOTROPY) uniform sampler2D uAnisotropyTexture;

struct AnisotropicLobe {
    float strength;
    vec2 direction; // in the tangent frame, rotated (the debug view's)
    vec3 t;         // world space, the rougher direction, orthogonal to the shading normal
    vec3 b;         // cross(n, t)
};

vec3 anyPerpendicular(vec3 n)
{
    return normalize(cross(abs(n.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0), n));
}

// The direction in the tangent frame (xy, unit) and the strength (z) at this fragment.
vec3 anisotropyDirectionStrength()
{
    vec2 rotation = material.anisotropy.yz; // cos, sin of anisotropyRotation
    float strength = material.anisotropy.x;
    vec2 direction = rotation;
    // A uniform branch: only a material with a texture reads it (its default, (1, 0.5, 1), is
    // what no texture gives, and the white fallback is not that).
    if (material.anisotropy.w > 0.0) {
        vec3 texel = texture(uAnisotropyTexture, textureUv(TEX_ANISOTROPY)).rgb;
        vec2 d = texel.rg * 2.0 - 1.0;
        // A texel of (0.5, 0.5) has no direction; the tangent's is as good as any.
        d = dot(d, d) > 1e-8 ? normalize(d) : vec2(1.0, 0.0);
        direction = mat2(rotation.x, rotation.y, -rotation.y, rotation.x) * d;
        strength *= texel.b;
    }
    return vec3(direction, saturate(strength));
}

// n: the shading normal; ng: the geometric one (flipped to the viewer for a back face).
AnisotropicLobe makeAnisotropicLobe(vec3 n, vec3 ng, bool flip)
{
    AnisotropicLobe a;
    vec3 ds = anisotropyDirectionStrength();
    a.direction = ds.xy;
    a.strength = ds.z;
    // The tangent frame of normalTexture (pbr.frag): t orthogonal to the geometric normal.
    vec3 t = vTangent.xyz - ng * dot(ng, vTangent.xyz);
    if (dot(t, t) <= 1e-12) {
        // No tangent (degenerate uv): no direction to be anisotropic along.
        t = anyPerpendicular(ng);
        a.strength = 0.0;
    }
    t = normalize(flip ? -t : t);
    vec3 b = cross(ng, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
    vec3 at = t * a.direction.x + b * a.direction.y;
    // Orthogonal to the shading normal, so that (t, b, n) is orthonormal and D stays
    // normalised where a normal map tilts n (the same frame without one).
    at -= n * dot(n, at);
    a.t = dot(at, at) > 1e-12 ? normalize(at) : anyPerpendicular(n);
    a.b = cross(n, a.t);
    return a;
}

// alpha_t and alpha_b of the lobe for the material's alpha.
vec2 anisotropicAlphas(AnisotropicLobe a, float alpha)
{
    return vec2(mix(alpha, 1.0, a.strength * a.strength), alpha);
}

// The split-sum table's roughness for the anisotropic lobe: the perceptual roughness of the
// root mean square of alpha_t and alpha_b. Measured against the lobe's own albedo (white
// metal, averaged over the azimuth of v): within 6 % at strength 1, 1.3 % at 0.5, where the
// mean or the geometric mean of the two are off by 25 % and 80 % (docs/materials.md).
float anisotropicTableRoughness(AnisotropicLobe a, float perceptualRoughness)
{
    vec2 alphas = anisotropicAlphas(a, perceptualRoughness * perceptualRoughness);
    return sqrt(sqrt(0.5 * dot(alphas, alphas)));
}

// The anisotropic lobe's D V for half vector h (NoV, NoL, NoH clamped as evaluateBrdfLobes does).
float anisotropicDV(SurfaceBrdf s, AnisotropicLobe a, vec3 v, vec3 l, vec3 h, float NoV, float NoL, float NoH)
{
    vec2 alphas = anisotropicAlphas(a, s.alpha);
    float D = D_GGX_Anisotropic(NoH, dot(a.t, h), dot(a.b, h), alphas.x, alphas.y);
    float V = V_SmithGGXCorrelatedAnisotropic(NoV, NoL, dot(a.t, v), dot(a.b, v), dot(a.t, l), dot(a.b, l), alphas.x, alphas.y);
    return D * V;
}

// evaluateBrdfLobes (brdf/brdf.glsl) with the anisotropic D and V.
void evaluateAnisotropicLobes(SurfaceBrdf s, AnisotropicLobe a, vec3 n, vec3 v, vec3 l, out vec3 diffuse, out vec3 specular)
{
    vec3 h = normalize(v + l);
    float NoV = abs(dot(n, v));
    float NoL = saturate(dot(n, l));
    float NoH = saturate(dot(n, h));
    float VoH = saturate(dot(v, h));
    vec3 F = brdfF(s, VoH);
    specular = F * anisotropicDV(s, a, v, l, h, NoV, NoL, NoH);
    diffuse = (1.0 - F) * brdfDiffuse(s, NoV, NoL, VoH, dot(v, l));
}

#if defined(IBL)
// The split sum's lookup direction for the anisotropic lobe: the normal bent towards v in the
// plane across b, so that the reflection stretches along t, by (1 - strength (1 - roughness))^4
// (McAuley 2015, "Rendering the World of Far Cry 4"; Filament's and the Khronos sample viewer's
// anisotropic IBL). Strength 0 leaves n.
vec3 anisotropicBentNormal(AnisotropicLobe a, vec3 n, vec3 v, float perceptualRoughness)
{
    vec3 across = cross(cross(a.b, v), a.b); // v's part orthogonal to b
    float bend = 1.0 - a.strength * (1.0 - perceptualRoughness);
    bend *= bend;
    bend *= bend;
    return dot(across, across) > 1e-12 ? normalize(mix(normalize(across), n, bend)) : n;
}
#endif
