// The thin-film Fresnel term of KHR_materials_iridescence: Belcour & Barla 2017, "A Practical
// Extension to Microfacet Theory for the Modeling of Varying Iridescence" (ACM TOG 36(4)), in
// the approximate form the extension's "Iridescence Fresnel" section writes: Schlick
// reflectances at the outside/film and film/base interfaces, phase shifts of 0 or pi, the
// Airy series to m = 2 integrated over the spectrum in Fourier space against Gaussian fits of
// the XYZ sensitivities (sec. 4), then XYZ to Rec. 709. The CPU port is src/shading/Iridescence.cpp.
// Pure maths: the material's inputs are forward/iridescence.glsl's.
#include "../common/math.glsl"

struct ThinFilm {
    float factor;      // iridescenceFactor x texture R: the weight of the film's Fresnel (0 = none)
    float ior;         // the film's IOR
    float thickness;   // nanometres
    vec3 f0Dielectric; // the dielectric base's F0 (KHR_materials_specular's weight included)
    vec3 f0Metal;      // the metal base's F0, its base colour
    float metallic;
};

ThinFilm noThinFilm()
{
    return ThinFilm(0.0, 1.0, 0.0, vec3(0.0), vec3(0.0), 0.0);
}

// The extension's evalSensitivity: the Fourier transform of the XYZ Gaussians at optical path
// difference `opd` (nm), shifted by `shift`, in Rec. 709.
vec3 thinFilmSensitivity(float opd, vec3 shift)
{
    float phase = 2.0 * PI * opd * 1.0e-9;
    const vec3 val = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13);
    const vec3 pos = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const vec3 var = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
    vec3 xyz = val * sqrt(2.0 * PI * var) * cos(pos * phase + shift) * exp(-phase * phase * var);
    xyz.x += 9.7470e-14 * sqrt(2.0 * PI * 4.5282e+09) * cos(2.2399e+06 * phase + shift.x) * exp(-4.5282e+09 * phase * phase);
    xyz /= 1.0685e-7;
    const mat3 XYZ_TO_REC709 = mat3(3.2404542, -0.9692660, 0.0556434,
                                    -1.5371385, 1.8760108, -0.2040259,
                                    -0.4985314, 0.0415560, 1.0572252);
    return XYZ_TO_REC709 * xyz;
}

float thinFilmSchlick(float f0, float c)
{
    return f0 + (1.0 - f0) * pow5(1.0 - saturate(c));
}

float thinFilmIorToF0(float transmittedIor, float incidentIor)
{
    float r = (transmittedIor - incidentIor) / (transmittedIor + incidentIor);
    return r * r;
}

// F_iridescence at cos(theta1) = cosTheta1 over a base of normal-incidence reflectance baseF0.
vec3 F_ThinFilm(float outsideIor, float filmIor, float cosTheta1, float thickness, vec3 baseF0)
{
    // No film at zero thickness: its IOR goes to the outside's over 0-0.03 nm (the Khronos
    // sample renderer's rule; the series alone would leave a trace of a film of no thickness).
    float eta2 = mix(outsideIor, filmIor, smoothstep(0.0, 0.03, thickness));
    // Snell's law into the film; past the critical angle all is reflected.
    float sinTheta2Sq = (outsideIor / eta2) * (outsideIor / eta2) * (1.0 - cosTheta1 * cosTheta1);
    float cosTheta2Sq = 1.0 - sinTheta2Sq;
    if (cosTheta2Sq < 0.0) return vec3(1.0);
    float cosTheta2 = sqrt(cosTheta2Sq);

    // First interface (R21 = R12, T121 = 1 - R12) and its phase shifts.
    float R12 = thinFilmSchlick(thinFilmIorToF0(eta2, outsideIor), cosTheta1);
    float T121 = 1.0 - R12;
    float phi12 = eta2 < outsideIor ? PI : 0.0;
    float phi21 = PI - phi12;
    // Second interface: the base's IOR from its F0 (the extension's +0.0001 guard against
    // F0 = 0, and below 1 so that a white metal keeps a finite IOR).
    vec3 sqrtF0 = sqrt(min(baseF0 + 0.0001, vec3(0.9999)));
    vec3 baseIor = (1.0 + sqrtF0) / (1.0 - sqrtF0);
    vec3 r1 = (baseIor - eta2) / (baseIor + eta2);
    vec3 R1 = r1 * r1;
    vec3 R23 = R1 + (1.0 - R1) * pow5(1.0 - cosTheta2);
    vec3 phi23 = mix(vec3(0.0), vec3(PI), lessThan(baseIor, vec3(eta2)));

    float opd = 2.0 * eta2 * thickness * cosTheta2; // first-order optical path difference
    vec3 phi = vec3(phi21) + phi23;

    vec3 R123 = clamp(R12 * R23, 1e-5, 0.9999);
    vec3 r123 = sqrt(R123);
    vec3 Rs = T121 * T121 * R23 / (1.0 - R123);
    vec3 I = R12 + Rs; // m = 0
    vec3 Cm = Rs - T121;
    for (int m = 1; m <= 2; ++m) {
        Cm *= r123;
        I += Cm * 2.0 * thinFilmSensitivity(float(m) * opd, float(m) * phi);
    }
    return max(I, vec3(0.0));
}

// The film over a metal-rough base (the extension's iridescent_dielectric_layer and
// iridescent_conductor_layer, outside IOR 1: a clearcoat's interface is ignored, as it says),
// mixed by metallic; each base evaluated only where it has weight.
vec3 thinFilmFresnel(ThinFilm f, float cosTheta)
{
    vec3 dielectric = vec3(0.0), metal = vec3(0.0);
    if (f.metallic < 1.0) dielectric = F_ThinFilm(1.0, f.ior, cosTheta, f.thickness, f.f0Dielectric);
    if (f.metallic > 0.0) metal = F_ThinFilm(1.0, f.ior, cosTheta, f.thickness, f.f0Metal);
    return mix(dielectric, metal, f.metallic);
}
