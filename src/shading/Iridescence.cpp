#include "shading/Iridescence.h"

#include <algorithm>
#include <cmath>

namespace specula::render::brdf {
namespace {

using glm::dvec3;
constexpr double kPi = 3.14159265358979323846;

double sq(double x) { return x * x; }

double iorToFresnel0(double transmittedIor, double incidentIor)
{
    return sq((transmittedIor - incidentIor) / (transmittedIor + incidentIor));
}

double schlick(double f0, double c)
{
    return f0 + (1.0 - f0) * std::pow(1.0 - std::clamp(c, 0.0, 1.0), 5.0);
}

} // namespace

dvec3 iridescenceSensitivity(double opdNm, const dvec3& shift)
{
    const double phase = 2.0 * kPi * opdNm * 1.0e-9;
    const dvec3 val(5.4856e-13, 4.4201e-13, 5.2481e-13);
    const dvec3 pos(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const dvec3 var(4.3278e+09, 9.3046e+09, 6.6121e+09);
    dvec3 xyz;
    for (int k = 0; k < 3; ++k)
        xyz[k] = val[k] * std::sqrt(2.0 * kPi * var[k]) * std::cos(pos[k] * phase + shift[k]) * std::exp(-sq(phase) * var[k]);
    xyz.x += 9.7470e-14 * std::sqrt(2.0 * kPi * 4.5282e+09) * std::cos(2.2399e+06 * phase + shift[0]) * std::exp(-4.5282e+09 * sq(phase));
    xyz /= 1.0685e-7;
    // XYZ to linear Rec. 709 (the extension's XYZ_TO_REC709, written row by row).
    return {3.2404542 * xyz.x - 1.5371385 * xyz.y - 0.4985314 * xyz.z,
            -0.9692660 * xyz.x + 1.8760108 * xyz.y + 0.0415560 * xyz.z,
            0.0556434 * xyz.x - 0.2040259 * xyz.y + 1.0572252 * xyz.z};
}

dvec3 iridescentFresnel(double outsideIor, double filmIor, double cosTheta1, double thicknessNm, const dvec3& baseF0)
{
    // No film at zero thickness (the sample renderer's rule; the formula alone would not vanish).
    const double t = std::clamp(thicknessNm / 0.03, 0.0, 1.0);
    const double eta2 = outsideIor + (filmIor - outsideIor) * t * t * (3.0 - 2.0 * t);
    // Snell's law into the film; past the critical angle all is reflected.
    const double sinTheta2Sq = sq(outsideIor / eta2) * (1.0 - sq(cosTheta1));
    const double cosTheta2Sq = 1.0 - sinTheta2Sq;
    if (cosTheta2Sq < 0.0) return dvec3(1.0);
    const double cosTheta2 = std::sqrt(cosTheta2Sq);

    // First interface, outside to film (Schlick; R21 = R12, T121 = 1 - R12).
    const double R12 = schlick(iorToFresnel0(eta2, outsideIor), cosTheta1);
    const double T121 = 1.0 - R12;
    const double phi12 = eta2 < outsideIor ? kPi : 0.0;
    const double phi21 = kPi - phi12;
    // Second interface, film to base: the base's IOR from its F0 (the extension's guard of
    // +0.0001 against F0 = 0, and below 1 so that a white metal keeps a finite IOR).
    dvec3 R23(0.0), phi23(0.0);
    for (int k = 0; k < 3; ++k) {
        const double f0 = std::min(baseF0[k] + 0.0001, 0.9999);
        const double baseIor = (1.0 + std::sqrt(f0)) / (1.0 - std::sqrt(f0));
        R23[k] = schlick(iorToFresnel0(baseIor, eta2), cosTheta2);
        phi23[k] = baseIor < eta2 ? kPi : 0.0;
    }
    // First-order optical path difference and the phase shift.
    const double opd = 2.0 * eta2 * thicknessNm * cosTheta2;
    const dvec3 phi = dvec3(phi21) + phi23;

    // Compound terms and the Fourier series to m = 2.
    const dvec3 R123 = glm::clamp(R12 * R23, 1e-5, 0.9999);
    const dvec3 r123 = glm::sqrt(R123);
    const dvec3 Rs = sq(T121) * R23 / (dvec3(1.0) - R123);
    dvec3 I = R12 + Rs;
    dvec3 Cm = Rs - T121;
    for (int m = 1; m <= 2; ++m) {
        Cm *= r123;
        I += Cm * 2.0 * iridescenceSensitivity(double(m) * opd, double(m) * phi);
    }
    return glm::max(I, dvec3(0.0));
}

dvec3 filmFresnel(const ThinFilm& film, const dvec3& f0Dielectric, const dvec3& baseColor, double metallic, double cosTheta)
{
    dvec3 dielectric(0.0), metal(0.0);
    if (metallic < 1.0) dielectric = iridescentFresnel(1.0, film.ior, cosTheta, film.thickness, f0Dielectric);
    if (metallic > 0.0) metal = iridescentFresnel(1.0, film.ior, cosTheta, film.thickness, baseColor);
    return glm::mix(dielectric, metal, metallic);
}

} // namespace specula::render::brdf
