// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering", eq. 15.
vec3 F_Schlick(vec3 f0, float VoH)
{
    return f0 + (1.0 - f0) * pow5(1.0 - VoH);
}
