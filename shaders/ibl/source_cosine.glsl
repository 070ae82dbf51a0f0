// What a surface receives from one of the environment's irradiance sources, per unit of its
// flux, as a function of c = n·direction and the source's spread s (radians; the half-width of
// a band of uniform light with the same second moment of angle): c where the whole band is
// above the horizon, nothing where it is all below, and (c + s)² / 4s in between — the cosine
// integrated over the band, which rounds the kink a point source has at the terminator. The CPU
// twin is shading/EnvironmentMap's sourceCosine.
float sourceCosine(float c, float s)
{
    float band = max(c + s, 0.0);
    return c >= s ? c : band * band / max(4.0 * s, 1e-30);
}
