// Lambertian diffuse: albedo / pi.
vec3 Fd_Lambert(vec3 diffuseColor)
{
    return diffuseColor * INV_PI;
}
