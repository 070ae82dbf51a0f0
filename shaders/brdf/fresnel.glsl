// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering", eq. 15:
// F = f0 + (f90 - f0) Fc, with the weight Fc = (1 - VoH)^5.
float Fc_Schlick(float VoH)
{
    return pow5(1.0 - VoH);
}

vec3 F_Schlick(vec3 f0, float f90, float VoH)
{
    return f0 + (f90 - f0) * Fc_Schlick(VoH);
}

vec3 F_Schlick(vec3 f0, float VoH)
{
    return F_Schlick(f0, 1.0, VoH);
}

// Schlick's approximation with the power replaced by a spherical-Gaussian exponent:
// Karis 2013, "Real Shading in Unreal Engine 4", p. 3 (from Lagarde 2012). Cheaper than pow5.
float Fc_SchlickSG(float VoH)
{
    return exp2((-5.55473 * VoH - 6.98316) * VoH);
}

vec3 F_SchlickSG(vec3 f0, float f90, float VoH)
{
    return f0 + (f90 - f0) * Fc_SchlickSG(VoH);
}

// No Fresnel: the reflectance at normal incidence everywhere (Karis 2013, "Specular BRDF
// Reference", F_None).
vec3 F_None(vec3 f0)
{
    return f0;
}
