// Normalised Blinn-Phong distribution: Blinn 1977, "Models of Light Reflection for Computer
// Synthesized Pictures", with the (n + 2) / 2π normalisation that makes ∫ D (n·h) dω = 1 and
// the exponent n = 2 / α² - 2 that matches Beckmann's α (Walter et al. 2007, eq. 30).
float blinnPhongExponent(float alpha)
{
    return 2.0 / (alpha * alpha) - 2.0;
}

float D_BlinnPhong(float NoH, float alpha)
{
    float n = blinnPhongExponent(alpha);
    return (n + 2.0) * (0.5 * INV_PI) * pow(NoH, n);
}
