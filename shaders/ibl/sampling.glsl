// Low-discrepancy sequence and importance sampling of the normal distributions for the bakes.

// Hammersley point i of n (Van der Corput radical inverse in base 2).
vec2 hammersley(uint i, uint n)
{
    return vec2(float(i) / float(n), float(bitfieldReverse(i)) * 2.3283064365386963e-10);
}

// Half vector around +Z distributed as D_GGX(h) (n.h): Walter et al. 2007, eq. 35-36;
// Karis 2013, "Real Shading in Unreal Engine 4", ImportanceSampleGGX.
vec3 importanceSampleGgx(vec2 xi, float alpha)
{
    float phi = 2.0 * PI * xi.x;
    float cosTheta = sqrt((1.0 - xi.y) / (1.0 + (alpha * alpha - 1.0) * xi.y));
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// Half vector around +Z distributed as D_Beckmann(h) (n.h): Walter et al. 2007, section 5.2,
// tan²θ = -α² ln(1 - ξ). cos θ and sin θ come from tan²θ itself, which keeps their precision
// where α is small and θ tiny.
vec3 importanceSampleBeckmann(vec2 xi, float alpha)
{
    float phi = 2.0 * PI * xi.x;
    float tan2Theta = -alpha * alpha * log(1.0 - xi.y); // xi.y < 1 (Hammersley), so finite
    float cosTheta = inversesqrt(1.0 + tan2Theta);
    float sinTheta = sqrt(tan2Theta) * cosTheta;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// Half vector around +Z distributed as the normalised Blinn-Phong D(h) (n.h) = (n + 2) / 2π
// cos^(n + 1)θ: Walter et al. 2007, section 5.2, cos θ = ξ^(1 / (n + 2)), with 1 - ξ for ξ so
// that the first Hammersley point (ξ = 0) is the pole, as for the other samplers.
vec3 importanceSampleBlinnPhong(vec2 xi, float exponent)
{
    float phi = 2.0 * PI * xi.x;
    float cosTheta = pow(1.0 - xi.y, 1.0 / (exponent + 2.0));
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// Orthonormal basis around n (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
mat3 basisAround(vec3 n)
{
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
    return mat3(t, bt, n);
}

// Half vector around +Z (tangent +X, bitangent +Y) distributed as D_GGX_Anisotropic(h) (n.h):
// GGX's slopes are those of roughness 1 stretched by (at, ab) (Heitz 2014, "Understanding the
// Masking-Shadowing Function", section 5.3), so a slope of the unit lobe (tan θ = sqrt(ξ / (1 -
// ξ)), Walter et al. 2007 eq. 35 at alpha 1) scaled per axis gives h = normalize(slope, 1) (the
// slope's sign is immaterial: the lobe is symmetric).
vec3 importanceSampleGgxAnisotropic(vec2 xi, float at, float ab)
{
    float phi = 2.0 * PI * xi.x;
    // xi.y < 1 for Hammersley points; the clamp keeps a last point finite anyway.
    float tanTheta = sqrt(xi.y / max(1.0 - xi.y, 1e-7));
    return normalize(vec3(at * tanTheta * cos(phi), ab * tanTheta * sin(phi), 1.0));
}
