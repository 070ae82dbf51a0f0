// Masking-shadowing terms, written as visibility V = G / (4 NoL NoV).

// Separable Smith G for GGX, as the glTF 2.0 specification (Appendix B.3.2) gives it:
// G1(X) = 2 NoX / (NoX + sqrt(alpha^2 + (1 - alpha^2) NoX^2)), so the 4 NoL NoV cancels.
float V_SmithGGX(float NoV, float NoL, float alpha)
{
    float a2 = alpha * alpha;
    float gl = NoL + sqrt(a2 + (1.0 - a2) * NoL * NoL);
    float gv = NoV + sqrt(a2 + (1.0 - a2) * NoV * NoV);
    return 1.0 / (gl * gv);
}

// Schlick-GGX with k = (r + 1)^2 / 8 for punctual lights: Karis 2013, "Real Shading in
// Unreal Engine 4", eq. 4 (r is the perceptual roughness; the remap reduces hotness).
float V_SchlickGGX(float NoV, float NoL, float perceptualRoughness)
{
    float k = (perceptualRoughness + 1.0) * (perceptualRoughness + 1.0) / 8.0;
    float gl = NoL / (NoL * (1.0 - k) + k);
    float gv = NoV / (NoV * (1.0 - k) + k);
    // The 1e-7 keeps grazing NoL = NoV = 0 finite; those samples carry no energy.
    return gl * gv / max(4.0 * NoL * NoV, 1e-7);
}

// Schlick-GGX with k = alpha / 2 = r^2 / 2 for image-based light: Karis 2013, "Real Shading in
// Unreal Engine 4", p. 3 (the (r + 1) / 2 remap of V_SchlickGGX is for punctual lights only; the
// LearnOpenGL IBL tutorial does the same).
float V_SchlickGGXImageBased(float NoV, float NoL, float alpha)
{
    float k = alpha * 0.5;
    float gl = NoL / (NoL * (1.0 - k) + k);
    float gv = NoV / (NoV * (1.0 - k) + k);
    return gl * gv / max(4.0 * NoL * NoV, 1e-7); // as V_SchlickGGX
}

// Height-correlated Smith G for GGX: Heitz 2014, "Understanding the Masking-Shadowing Function
// in Microfacet-Based BRDFs", eq. 99, written as V (Lagarde & de Rousiers 2014, eq. 3; Filament).
float V_SmithGGXCorrelated(float NoV, float NoL, float alpha)
{
    float a2 = alpha * alpha;
    float lambdaV = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float lambdaL = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    // 1e-7: grazing NoL = NoV = 0 carries no energy but would divide by zero.
    return 0.5 / max(lambdaV + lambdaL, 1e-7);
}

// Anisotropic height-correlated Smith G for GGX: Heitz 2014, eq. 99 with the anisotropic
// Lambda (eq. 86: alpha along each direction's azimuth), as V (KHR_materials_anisotropy's
// V_GGX_anisotropic; Filament's V_SmithGGXCorrelated_Anisotropic). at = ab = alpha is
// V_SmithGGXCorrelated.
float V_SmithGGXCorrelatedAnisotropic(float NoV, float NoL, float ToV, float BoV, float ToL, float BoL, float at, float ab)
{
    float lambdaV = NoL * length(vec3(at * ToV, ab * BoV, NoV));
    float lambdaL = NoV * length(vec3(at * ToL, ab * BoL, NoL));
    // The extension clamps V to [0, 1] ("Implementation"), which V_SmithGGXCorrelated does not:
    // kept, as the extension is the reference (it darkens only grazing n.v n.l, where V > 1).
    return min(0.5 / max(lambdaV + lambdaL, 1e-7), 1.0);
}
