// Lambertian diffuse: albedo / pi.
vec3 Fd_Lambert(vec3 diffuseColor)
{
    return diffuseColor * INV_PI;
}

// Burley 2012, "Physically-Based Shading at Disney", section 5.3: Lambert with a retro-
// reflective rim, F_D90 = 0.5 + 2 roughness cos²θd (roughness = perceptual roughness).
vec3 Fd_Burley(vec3 diffuseColor, float perceptualRoughness, float NoV, float NoL, float LoH)
{
    float f90 = 0.5 + 2.0 * perceptualRoughness * LoH * LoH;
    float lightScatter = 1.0 + (f90 - 1.0) * pow5(1.0 - NoL);
    float viewScatter = 1.0 + (f90 - 1.0) * pow5(1.0 - NoV);
    return diffuseColor * (INV_PI * lightScatter * viewScatter);
}

// Oren & Nayar 1994, "Generalization of Lambert's Reflectance Model", eq. 30 (the qualitative
// model), with σ = perceptual roughness in radians. sin α tan β cos(φv - φl) is written with
// vectors: s / max(NoL, NoV), s = VoL - NoV NoL (Fujii's form; no trigonometry).
vec3 Fd_OrenNayar(vec3 diffuseColor, float perceptualRoughness, float NoV, float NoL, float VoL)
{
    float s2 = perceptualRoughness * perceptualRoughness;
    float A = 1.0 - 0.5 * s2 / (s2 + 0.33);
    float B = 0.45 * s2 / (s2 + 0.09);
    float s = VoL - NoV * NoL;
    // 1e-7: both grazing (carries no energy) would divide by zero.
    return diffuseColor * (INV_PI * (A + B * max(s, 0.0) / max(max(NoL, NoV), 1e-7)));
}
