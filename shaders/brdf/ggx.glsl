// GGX / Trowbridge-Reitz normal distribution.
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 33;
// glTF 2.0 specification, Appendix B.3.2. alpha = perceptualRoughness^2.
float D_GGX(float NoH, float alpha)
{
    float a2 = alpha * alpha;
    float f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (PI * f * f);
}

// Anisotropic GGX: Burley 2012, "Physically-Based Shading at Disney", eq. 13 (B.2); Heitz 2014,
// "Understanding the Masking-Shadowing Function", eq. 85; as KHR_materials_anisotropy writes
// it: D = 1 / (pi at ab ((t.h / at)^2 + (b.h / ab)^2 + (n.h)^2)^2). at = ab = alpha is D_GGX.
float D_GGX_Anisotropic(float NoH, float ToH, float BoH, float at, float ab)
{
    float a2 = at * ab;
    vec3 f = vec3(ab * ToH, at * BoH, a2 * NoH);
    float w2 = a2 / dot(f, f);
    return a2 * w2 * w2 / PI;
}
