// The CPU port of KHR_materials_iridescence's thin-film Fresnel (shading/Iridescence.h), checked
// against what does not come from the extension's formula: (1) where its first interface
// vanishes (normal incidence, R12 = 0 exactly) a film of the outside's IOR, or of no thickness,
// leaves the plain Schlick Fresnel of the base; (2) the analytic spectral integral (Gaussian
// fits of the XYZ sensitivities in Fourier space, the Airy series cut at m = 2) against a
// brute-force one: the exact Airy reflectance of the same two interfaces (every order of
// interreflection, complex amplitudes) at each wavelength from 380 to 780 nm every 0.1 nm,
// weighted by CIE-like sensitivities of another fit (Wyman, Sloan & Shirley 2013, "Simple
// Analytic Approximations to the CIE XYZ Color Matching Functions", JCGT 2(2), the multi-lobe
// piecewise Gaussians) and taken to Rec. 709 with the extension's own matrix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include "shading/Iridescence.h"

using namespace specula::render::brdf;
using glm::dvec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

double schlick(double f0, double c)
{
    return f0 + (1.0 - f0) * std::pow(1.0 - c, 5.0);
}

// Wyman et al. 2013, eq. 2-4: each lobe a Gaussian with one width left of its peak and another right.
double lobe(double x, double mu, double left, double right)
{
    const double s = x < mu ? left : right;
    return std::exp(-0.5 * (x - mu) * (x - mu) / (s * s));
}

dvec3 cieLike(double nm)
{
    return {1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) - 0.065 * lobe(nm, 501.1, 20.4, 26.2),
            0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1),
            1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8)};
}

// The two interfaces as the extension defines them (Schlick reflectances, Snell's law, phase
// shifts 0 or pi) for a grey base: written again here so that only the spectral part differs.
struct Interfaces {
    double R12, R23, opd, phase;
};

Interfaces interfaces(double filmIor, double cosTheta1, double thickness, double baseF0)
{
    const double cosTheta2 = std::sqrt(1.0 - (1.0 - cosTheta1 * cosTheta1) / (filmIor * filmIor));
    const double f0 = std::min(baseF0 + 0.0001, 0.9999);
    const double baseIor = (1.0 + std::sqrt(f0)) / (1.0 - std::sqrt(f0));
    Interfaces i;
    i.R12 = schlick(std::pow((filmIor - 1.0) / (filmIor + 1.0), 2.0), cosTheta1);
    i.R23 = schlick(std::pow((baseIor - filmIor) / (baseIor + filmIor), 2.0), cosTheta2);
    i.opd = 2.0 * filmIor * thickness * cosTheta2;
    i.phase = (filmIor < 1.0 ? 0.0 : kPi) + (baseIor < filmIor ? kPi : 0.0); // phi21 + phi23
    return i;
}

// Airy: r = r12 + t12 t21 r23 e^{i psi} / (1 - r21 r23 e^{i psi}), with r12 = -r21 (Stokes) and
// t12 t21 = 1 - R12; |r|^2 after taking the common phase of r21 out.
double airy(const Interfaces& i, double psi)
{
    const std::complex<double> e = std::polar(1.0, psi);
    const std::complex<double> r = -std::sqrt(i.R12) + (1.0 - i.R12) * std::sqrt(i.R23) * e / (1.0 - std::sqrt(i.R12 * i.R23) * e);
    return std::norm(r);
}

// The brute-force colour of the film: XYZ_j = integral R(lambda) xbar_j / integral xbar_j, and,
// in the extension's convention (its m = 0 term C0 is added to every channel as it is, only the
// interference goes through XYZ -> Rec. 709), rgb = C0 + M (XYZ - C0), C0 the mean of R over a
// period of psi (by quadrature).
dvec3 bruteForce(double filmIor, double cosTheta1, double thickness, double baseF0)
{
    const Interfaces i = interfaces(filmIor, cosTheta1, thickness, baseF0);
    dvec3 xyz(0.0), norm(0.0);
    for (int k = 0; k <= 4000; ++k) {
        const double nm = 380.0 + 0.1 * k;
        const dvec3 w = cieLike(nm) * (k == 0 || k == 4000 ? 0.5 : 1.0); // trapezoid rule
        xyz += w * airy(i, 2.0 * kPi * i.opd / nm + i.phase);
        norm += w;
    }
    xyz /= norm;
    double c0 = 0.0;
    constexpr int kSteps = 20000;
    for (int k = 0; k < kSteps; ++k) c0 += airy(i, 2.0 * kPi * (k + 0.5) / kSteps);
    c0 /= kSteps;
    const glm::dmat3 xyzToRec709(3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108, -0.2040259, -0.4985314, 0.0415560, 1.0572252);
    return dvec3(c0) + xyzToRec709 * (xyz - dvec3(c0));
}

} // namespace

TEST(Iridescence, NoFilmAtNormalIncidenceIsPlainFresnel)
{
    // At cos theta1 = 1 the extension's first interface reflects R0 = ((n2 - 1) / (n2 + 1))^2,
    // 0 for a film of the outside's IOR (and for a film of thickness 0, whose IOR goes to the
    // outside's): what is left is the base's Schlick Fresnel, within the residue of the
    // extension's clamp R12 R23 >= 1e-5 (2 sqrt(1e-5) (1 - R23) |S1| <= 0.0073 measured). Up to
    // cos theta1 = 0.9 Schlick's R12 = (1 - c)^5 stays below 1e-5 and the bound holds.
    // Beyond, the extension's Schlick first interface reflects (1 - c)^5 even without an index
    // step, a "ghost" interface whose interference the formula keeps (0.1 at cos 0.5): that is
    // the extension's approximation, not the port's, and the brute-force test below reproduces
    // it at IOR 1 from the Airy sum.
    constexpr double kTolerance = 0.008;
    double worst = 0.0;
    for (double f0 : {0.02, 0.04, 0.5, 0.95})
        for (double c : {1.0, 0.97, 0.93, 0.9}) {
            const double expected = schlick(f0 + 0.0001, c);
            const dvec3 sameIor = iridescentFresnel(1.0, 1.0, c, 400.0, dvec3(f0));
            const dvec3 noThickness = iridescentFresnel(1.0, 1.3, c, 0.0, dvec3(f0));
            for (int ch = 0; ch < 3; ++ch) {
                EXPECT_NEAR(sameIor[ch], expected, kTolerance) << "film IOR 1, F0 " << f0 << " cos " << c;
                EXPECT_NEAR(noThickness[ch], expected, kTolerance) << "thickness 0, F0 " << f0 << " cos " << c;
                worst = std::max({worst, std::abs(sameIor[ch] - expected), std::abs(noThickness[ch] - expected)});
            }
        }
    // And the film is there otherwise: 300 nm of IOR 1.3 over F0 0.04 at normal incidence takes
    // green from 0.040 to 0.005.
    const dvec3 film = iridescentFresnel(1.0, 1.3, 1.0, 300.0, dvec3(0.04));
    EXPECT_GT(std::abs(film.g - schlick(0.0401, 1.0)), 3.0 * kTolerance);
    std::printf("no film: worst |F_iridescence - F_schlick| %.5f (bound %.3f)\n", worst, kTolerance);
}

TEST(Iridescence, AnalyticSpectralIntegralMatchesBruteForceAiry)
{
    // Tolerance 0.02 absolute per channel: the largest difference measured is 0.0164 (a grey
    // metal, F0 0.9, under a film of IOR 1.8, 600 nm, at cos 0.7), dielectrics 0.0102; the
    // analytic form's Gaussian fits and its series cut at m = 2 against an exact Airy sum and
    // another fit of the CIE functions. Separation: the brute force at 10% more thickness is
    // farther than the tolerance from the analytic value in most cases.
    constexpr double kTolerance = 0.02;
    double worst = 0.0, worstDielectric = 0.0;
    int separated = 0, cases = 0;
    for (double f0 : {0.04, 0.9})
        for (double ior : {1.0, 1.3, 1.8})
            for (double thickness : {150.0, 300.0, 600.0})
                for (double c : {1.0, 0.7, 0.4}) {
                    const dvec3 analytic = iridescentFresnel(1.0, ior, c, thickness, dvec3(f0));
                    const dvec3 reference = bruteForce(ior, c, thickness, f0);
                    const dvec3 thicker = bruteForce(ior, c, 1.1 * thickness, f0);
                    double off = 0.0;
                    for (int ch = 0; ch < 3; ++ch) {
                        EXPECT_NEAR(analytic[ch], reference[ch], kTolerance)
                            << "F0 " << f0 << " film IOR " << ior << " " << thickness << " nm cos " << c << " channel " << ch;
                        worst = std::max(worst, std::abs(analytic[ch] - reference[ch]));
                        if (f0 < 0.5) worstDielectric = std::max(worstDielectric, std::abs(analytic[ch] - reference[ch]));
                        off = std::max(off, std::abs(analytic[ch] - thicker[ch]));
                    }
                    ++cases;
                    if (off > kTolerance) ++separated;
                }
    EXPECT_GE(separated, cases / 2);
    std::printf("analytic vs brute-force Airy: worst %.4f (dielectric %.4f) over %d cases; 10%% thicker off by more than the "
                "tolerance in %d\n",
                worst, worstDielectric, cases, separated);
}

TEST(Iridescence, MetalAndDielectricFilmsMixByMetallic)
{
    // filmFresnel = mix(film over the dielectric F0, film over the base colour, metallic).
    const ThinFilm film{1.0, 1.5, 350.0};
    const dvec3 f0(0.04), gold(1.0, 0.78, 0.34);
    for (double metallic : {0.0, 0.3, 1.0}) {
        const dvec3 expected = glm::mix(iridescentFresnel(1.0, 1.5, 0.8, 350.0, f0), iridescentFresnel(1.0, 1.5, 0.8, 350.0, gold), metallic);
        const dvec3 got = filmFresnel(film, f0, gold, metallic, 0.8);
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(got[ch], expected[ch], 1e-12);
    }
}
