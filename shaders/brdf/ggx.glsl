// GGX / Trowbridge-Reitz normal distribution.
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 33;
// glTF 2.0 specification, Appendix B.3.2. alpha = perceptualRoughness^2.
float D_GGX(float NoH, float alpha)
{
    float a2 = alpha * alpha;
    float f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (PI * f * f);
}
