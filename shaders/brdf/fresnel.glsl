// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering", eq. 15.
vec3 F_Schlick(vec3 f0, float f90, float VoH)
{
    return f0 + (f90 - f0) * pow5(1.0 - VoH);
}

vec3 F_Schlick(vec3 f0, float VoH)
{
    return F_Schlick(f0, 1.0, VoH);
}
