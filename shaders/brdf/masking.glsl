// Masking-shadowing terms that are not Smith's, as visibility V = G / (4 NoL NoV). Names and
// forms as in Karis 2013, "Specular BRDF Reference" (graphicrants.blogspot.com).

// Implicit: G = NoL NoV (what a BRDF without a G term implies), so V = 1/4.
float V_Implicit()
{
    return 0.25;
}

// Neumann et al. 1999, "Compact Metallic Reflectance Models": G = NoL NoV / max(NoL, NoV).
float V_Neumann(float NoV, float NoL)
{
    // 1e-7: both grazing (carries no energy) would divide by zero.
    return 0.25 / max(max(NoL, NoV), 1e-7);
}

// Kelemen & Szirmay-Kalos 2001, "A Microfacet Based Coupled Specular-Matte BRDF Model with
// Importance Sampling": G = NoL NoV / VoH², an approximation of Cook-Torrance's.
float V_Kelemen(float VoH)
{
    // 1e-7: VoH = 0 only for v = -l, which no lit pixel sees.
    return 0.25 / max(VoH * VoH, 1e-7);
}

// Cook & Torrance 1982, "A Reflectance Model for Computer Graphics", eq. 5 (V-groove cavities,
// Torrance & Sparrow 1967): G = min(1, 2 NoH NoV / VoH, 2 NoH NoL / VoH).
float V_CookTorrance(float NoV, float NoL, float NoH, float VoH)
{
    float vh = max(VoH, 1e-7); // as in V_Kelemen
    float G = min(1.0, 2.0 * NoH * min(NoV, NoL) / vh);
    return G / max(4.0 * NoL * NoV, 1e-7); // 1e-7: grazing NoL = NoV = 0 carries no energy
}
