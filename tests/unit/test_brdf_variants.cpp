// The BRDF variants of shading/Brdf.h (mirrors of shaders/brdf/): every D normalised, every G
// in [0, 1], reciprocity of every combination, closed forms and limits of F and the diffuse
// models, F0 from an index of refraction.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "shading/Brdf.h"

using namespace specula::render::brdf;
using glm::dvec3;
namespace scene = specula::scene;

namespace {

dvec3 sphericalDirection(double theta, double phi)
{
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

constexpr Distribution kDistributions[] = {Distribution::GGX, Distribution::Beckmann, Distribution::BlinnPhong};
constexpr Geometry kGeometries[] = {Geometry::SmithGGX, Geometry::SchlickGGX, Geometry::SmithGGXCorrelated, Geometry::Neumann,
                                    Geometry::Kelemen, Geometry::CookTorrance, Geometry::Implicit};
constexpr Fresnel kFresnels[] = {Fresnel::Schlick, Fresnel::SchlickSG, Fresnel::None};
constexpr Diffuse kDiffuses[] = {Diffuse::Lambert, Diffuse::OrenNayar, Diffuse::Burley};

} // namespace

TEST(BrdfVariants, EveryDistributionIsNormalised)
{
    // ∫ D(h) (n·h) dω_h = 1 (Walter et al. 2007, eq. 4). D depends on θ only, so the φ
    // integral is 2π and the θ integral is a midpoint rule in μ = cos θ: 200,000 cells keep
    // the sharpest lobe here (Blinn-Phong exponent 245 at roughness 0.3) within 0.1%.
    for (Distribution d : kDistributions) {
        for (double roughness : {0.3, 0.5, 0.7, 1.0}) {
            const double alpha = roughness * roughness;
            const int n = 200000;
            double sum = 0.0;
            for (int i = 0; i < n; ++i) {
                const double mu = (i + 0.5) / n;
                sum += distribution(d, mu, alpha) * mu;
            }
            const double integral = sum / n * 2.0 * kPi;
            EXPECT_NEAR(integral, 1.0, 0.001) << scene::brdfDistributionName(d) << " roughness " << roughness;
        }
    }
}

TEST(BrdfVariants, EveryGeometryTermStaysInUnitInterval)
{
    // G = V · 4 NoL NoV over a grid of view and light directions (both hemispheres' worth of
    // azimuth), roughness from nearly smooth to 1.
    const dvec3 n(0, 0, 1);
    for (Geometry g : kGeometries) {
        for (double roughness : {0.05, 0.3, 0.6, 1.0}) {
            for (double thetaV = 0.01; thetaV < 1.57; thetaV += 0.11) {
                for (double thetaL = 0.01; thetaL < 1.57; thetaL += 0.11) {
                    for (double phi = 0.0; phi < 6.28; phi += 0.4) {
                        const dvec3 v = sphericalDirection(thetaV, 0.0), l = sphericalDirection(thetaL, phi);
                        const dvec3 h = glm::normalize(v + l);
                        const double NoV = v.z, NoL = l.z, NoH = h.z, VoH = glm::dot(v, h);
                        const double G = visibility(g, NoV, NoL, NoH, VoH, roughness) * 4.0 * NoL * NoV;
                        EXPECT_GE(G, 0.0) << scene::brdfGeometryName(g);
                        ASSERT_LE(G, 1.0 + 1e-9) << scene::brdfGeometryName(g) << " r " << roughness << " θv " << thetaV
                                                 << " θl " << thetaL << " φ " << phi;
                    }
                }
            }
        }
    }
}

TEST(BrdfVariants, HeightCorrelatedSmithMatchesLambdaForm)
{
    // Heitz 2014, eq. 99: G2 = 1 / (1 + Λ(v) + Λ(l)), Λ = (-1 + sqrt(1 + α² tan²θ)) / 2 for GGX:
    // an independent form of the same function.
    for (double alpha : {0.1, 0.4, 1.0}) {
        for (double NoV : {0.1, 0.5, 0.9}) {
            for (double NoL : {0.2, 0.7, 1.0}) {
                auto lambda = [&](double c) { return (-1.0 + std::sqrt(1.0 + alpha * alpha * (1.0 - c * c) / (c * c))) / 2.0; };
                const double G2 = 1.0 / (1.0 + lambda(NoV) + lambda(NoL));
                EXPECT_NEAR(V_SmithGGXCorrelated(NoV, NoL, alpha) * 4.0 * NoL * NoV, G2, 1e-12);
            }
        }
    }
}

TEST(BrdfVariants, FresnelVariants)
{
    const dvec3 f0(0.04, 0.5, 0.95);
    // Karis 2013's spherical-Gaussian fit stays within 0.4% (absolute, of the 1 - f0 range; 0.37% at worst)
    // of Schlick's fifth power, and is exact at grazing incidence.
    for (double VoH = 0.0; VoH <= 1.0; VoH += 0.01) {
        const dvec3 a = F_Schlick(f0, 1.0, VoH), b = F_SchlickSG(f0, 1.0, VoH);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 0.004 * (1.0 - f0[c]) + 1e-12) << "VoH " << VoH;
    }
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(F_SchlickSG(f0, 1.0, 0.0)[c], 1.0);
    // No Fresnel: F0 at every angle.
    for (double VoH : {0.0, 0.5, 1.0}) EXPECT_EQ(fresnel(Fresnel::None, f0, 1.0, VoH), f0);
}

TEST(BrdfVariants, DiffuseModelsReduceToLambert)
{
    // Oren-Nayar with σ = 0 is Lambert (A = 1, B = 0); Burley at roughness 0.25 with
    // LoH = 1 has F_D90 = 1 and is Lambert too.
    for (double NoV : {0.1, 0.6, 1.0}) {
        for (double NoL : {0.2, 0.9}) {
            EXPECT_NEAR(Fd_OrenNayar(0.0, NoV, NoL, 0.3), 1.0 / kPi, 1e-15);
            EXPECT_NEAR(Fd_Burley(0.25, NoV, NoL, 1.0), 1.0 / kPi, 1e-15);
        }
    }
    // Rough Oren-Nayar brightens back-scattering (light and view together) over Lambert.
    EXPECT_GT(Fd_OrenNayar(1.0, 0.5, 0.5, 1.0), 1.0 / kPi);
}

TEST(BrdfVariants, EveryCombinationIsReciprocal)
{
    const dvec3 n(0, 0, 1);
    for (Distribution d : kDistributions)
        for (Geometry g : kGeometries)
            for (Fresnel f : kFresnels)
                for (Diffuse fd : kDiffuses) {
                    Surface s{{0.8, 0.5, 0.2}, 0.3, 0.5, g};
                    s.distribution = d;
                    s.fresnel = f;
                    s.diffuse = fd;
                    for (int i = 0; i < 12; ++i) {
                        const dvec3 v = sphericalDirection(0.12 * i, 0.7 * i);
                        const dvec3 l = sphericalDirection(1.5 - 0.11 * i, 2.0 + 0.4 * i);
                        const dvec3 a = evaluate(s, n, v, l), b = evaluate(s, n, l, v);
                        for (int c = 0; c < 3; ++c) ASSERT_NEAR(a[c], b[c], 1e-9 * std::max(1.0, a[c]));
                    }
                }
}

TEST(BrdfVariants, F0FromIndexOfRefraction)
{
    EXPECT_NEAR(scene::f0FromIor(1.5f), 0.04f, 1e-7f);
    EXPECT_NEAR(scene::f0FromIor(1.0f), 0.0f, 1e-9f);     // no interface, no reflection
    EXPECT_NEAR(scene::f0FromIor(2.0f), 1.0f / 9.0f, 1e-7f);
    // A smooth dielectric seen and lit head-on reflects F0 D V (+ diffuse): F0 scales with it.
    Surface a{dvec3(0.0), 0.0, 0.5}, b = a;
    b.f0Dielectric = double(scene::f0FromIor(2.0f));
    const dvec3 n(0, 0, 1);
    EXPECT_NEAR(evaluate(b, n, n, n).x / evaluate(a, n, n, n).x, (1.0 / 9.0) / 0.04, 1e-6);
}

TEST(BrdfVariants, ClassicModels)
{
    const dvec3 n(0, 0, 1), kd(0.5, 0.4, 0.3), ks(0.5);
    // Mirror direction: (R·V) = 1 for Phong, (N·H) = 1 for Blinn-Phong: the full highlight.
    const dvec3 l = glm::normalize(dvec3(1, 0, 1)), v = glm::normalize(dvec3(-1, 0, 1));
    for (bool blinn : {false, true}) {
        const dvec3 f = evaluateClassic(kd, ks, 50.0, blinn, n, v, l);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], (kd[c] * l.z + ks[c]) / kPi, 1e-12);
        EXPECT_EQ(evaluateClassic(kd, ks, 50.0, blinn, n, v, -l), dvec3(0.0)); // unlit side
    }
    // Off the mirror direction Blinn's (N·H)^n falls slower than Phong's (R·V)^n (the half
    // angle is half the reflection angle).
    const dvec3 v2 = glm::normalize(dvec3(-1, 0.3, 1));
    EXPECT_GT(evaluateClassic(dvec3(0), ks, 50.0, true, n, v2, l).x, evaluateClassic(dvec3(0), ks, 50.0, false, n, v2, l).x);
    EXPECT_DOUBLE_EQ(classicShininess(1.0), 1.0);
}

TEST(BrdfVariants, SchlickGgxImageBasedKeepsMoreThanItsPunctualForm)
{
    // The DFG table of schlick-ggx integrates k = α/2 (UE4's image-based form), the punctual
    // lights use k = (r + 1)²/8 >= α/2 (equal at r = 1): the image-based G1 is the larger, so a
    // white metal's image-based albedo is too. The energy compensation, taken from that table,
    // therefore restores a punctual-lit schlick-ggx white metal to E_punctual / E_image-based,
    // not to 1: printed here (docs/materials.md), midpoint rule in (cos θ_l, φ_l).
    const dvec3 n(0, 0, 1);
    for (double roughness : {0.3, 0.5, 0.8, 1.0}) {
        for (double NoV : {0.2, 0.5, 1.0}) {
            const dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
            double albedo[2] = {0.0, 0.0};
            for (int imageBased = 0; imageBased < 2; ++imageBased) {
                Surface s{dvec3(1.0), 1.0, roughness, Geometry::SchlickGGX};
                s.imageBased = imageBased == 1;
                const int nMu = 1200, nPhi = 240;
                double sum = 0.0;
                for (int i = 0; i < nMu; ++i) {
                    const double mu = (i + 0.5) / nMu;
                    for (int j = 0; j < nPhi; ++j) {
                        const dvec3 l = sphericalDirection(std::acos(mu), (j + 0.5) / nPhi * kPi);
                        sum += evaluate(s, n, v, l).x * mu;
                    }
                }
                albedo[imageBased] = 2.0 * sum / nMu * kPi / nPhi;
            }
            if (roughness < 1.0) {
                EXPECT_GT(albedo[1], albedo[0]) << "roughness " << roughness << " n.v " << NoV;
            } else {
                EXPECT_NEAR(albedo[1], albedo[0], 1e-12) << "n.v " << NoV;
            }
            std::printf("schlick-ggx white metal, roughness %.1f, n.v %.1f: albedo %.3f punctual, %.3f image-based, ratio %.2f\n",
                        roughness, NoV, albedo[0], albedo[1], albedo[0] / albedo[1]);
        }
    }
}
