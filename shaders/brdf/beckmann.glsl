// Beckmann normal distribution (Beckmann & Spizzichino 1963), in the form of Walter et al.
// 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 25:
// D = exp(-tan²θh / α²) / (π α² cos⁴θh), tan²θh = (1 - NoH²) / NoH². alpha = perceptualRoughness².
float D_Beckmann(float NoH, float alpha)
{
    float a2 = alpha * alpha;
    // 1e-8 keeps NoH = 0 (a half vector in the tangent plane, D -> 0) from dividing by zero.
    float NoH2 = max(NoH * NoH, 1e-8);
    return exp((NoH2 - 1.0) / (a2 * NoH2)) / (PI * a2 * NoH2 * NoH2);
}
