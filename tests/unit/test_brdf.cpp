// BRDF math on the CPU (shading/Brdf.h mirrors shaders/brdf/): normalisation, bounds,
// Fresnel limits, reciprocity and energy (white furnace).
#include <gtest/gtest.h>

#include <cmath>

#include "shading/Brdf.h"

using namespace specula::render::brdf;
using glm::dvec3;

namespace {

dvec3 sphericalDirection(double theta, double phi)
{
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Midpoint rule over the hemisphere in (cos theta, phi): dω = d(cosθ) dφ, exact for smooth integrands
// as the grid is refined. 2000 x 400 cells are enough for 0.5% at alpha = 0.1.
template <typename F>
double integrateHemisphere(F&& f, int nMu = 2000, int nPhi = 400)
{
    double sum = 0.0;
    const double dMu = 1.0 / nMu, dPhi = 2.0 * kPi / nPhi;
    for (int i = 0; i < nMu; ++i) {
        const double mu = (i + 0.5) * dMu;
        const double theta = std::acos(mu);
        for (int j = 0; j < nPhi; ++j) sum += f(sphericalDirection(theta, (j + 0.5) * dPhi));
    }
    return sum * dMu * dPhi;
}

} // namespace

TEST(Brdf, GgxDistributionIsNormalised)
{
    // ∫ D(h) (n·h) dω_h = 1 over the hemisphere (Walter et al. 2007, eq. 4).
    for (double roughness : {0.3, 0.5, 0.7, 1.0}) {
        const double alpha = roughness * roughness;
        const double integral = integrateHemisphere([&](const dvec3& h) { return D_GGX(h.z, alpha) * h.z; },
                                                    roughness < 0.4 ? 20000 : 4000, 64);
        EXPECT_NEAR(integral, 1.0, 0.005) << "roughness " << roughness;
    }
}

TEST(Brdf, GeometryTermsStayInUnitInterval)
{
    for (double roughness : {0.05, 0.25, 0.5, 0.75, 1.0}) {
        const double alpha = roughness * roughness;
        for (double NoV = 0.01; NoV <= 1.0; NoV += 0.07) {
            for (double NoL = 0.01; NoL <= 1.0; NoL += 0.07) {
                const double smith = V_SmithGGX(NoV, NoL, alpha) * 4.0 * NoL * NoV;
                const double schlick = V_SchlickGGX(NoV, NoL, roughness) * 4.0 * NoL * NoV;
                const double schlickImageBased = V_SchlickGGXImageBased(NoV, NoL, alpha) * 4.0 * NoL * NoV;
                EXPECT_GE(smith, 0.0);
                EXPECT_LE(smith, 1.0 + 1e-12);
                EXPECT_GE(schlick, 0.0);
                EXPECT_LE(schlick, 1.0 + 1e-12);
                EXPECT_GE(schlickImageBased, 0.0);
                EXPECT_LE(schlickImageBased, 1.0 + 1e-12);
            }
        }
        // Looking straight down at a lit surface, nothing is masked as roughness -> 0.
        EXPECT_NEAR(V_SmithGGX(1.0, 1.0, 1e-4) * 4.0, 1.0, 1e-6);
    }
}

TEST(Brdf, FresnelLimits)
{
    const dvec3 f0(0.04, 0.5, 0.95);
    const dvec3 normal = F_Schlick(f0, 1.0);  // VoH = 1: 0 degrees
    const dvec3 grazing = F_Schlick(f0, 0.0); // VoH = 0: 90 degrees
    for (int c = 0; c < 3; ++c) {
        EXPECT_DOUBLE_EQ(normal[c], f0[c]);
        EXPECT_DOUBLE_EQ(grazing[c], 1.0);
    }
}

TEST(Brdf, IsReciprocal)
{
    const dvec3 n(0, 0, 1);
    for (Geometry g : {Geometry::SmithGGX, Geometry::SchlickGGX}) {
        for (double roughness : {0.1, 0.5, 1.0}) {
            for (double metallic : {0.0, 1.0}) {
                Surface s{{0.8, 0.5, 0.2}, metallic, roughness, g};
                for (int i = 0; i < 50; ++i) {
                    const dvec3 v = sphericalDirection(0.03 * i, 0.7 * i);
                    const dvec3 l = sphericalDirection(1.5 - 0.029 * i, 2.0 + 0.4 * i);
                    const dvec3 a = evaluate(s, n, v, l), b = evaluate(s, n, l, v);
                    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-9 * std::max(1.0, a[c]));
                }
            }
        }
    }
}

TEST(Brdf, DirectionalAlbedoAtMostOne)
{
    // White furnace: ∫ f(l, v) (n·l) dω_l <= 1 for a white surface. Holds for metals at every
    // view angle. For dielectrics the glTF mix (1 - F(VoH)) · diffuse + F · specular gains
    // energy at grazing view (measured with an 8000x3000 grid: 1.017 at 57°, 1.09 at 69°,
    // 1.32 at 80° for roughness 0.2), a property of the specification's BRDF, so the
    // dielectric bound is checked up to 45°. The 1% margin is the grid's integration error.
    const dvec3 n(0, 0, 1);
    for (Geometry g : {Geometry::SmithGGX, Geometry::SchlickGGX}) {
        for (double roughness : {0.3, 0.6, 1.0}) {
            for (double metallic : {0.0, 1.0}) {
                const Surface s{dvec3(1.0), metallic, roughness, g};
                for (double thetaV : {0.0, 0.4, 0.78, 1.0, 1.4}) {
                    if (metallic == 0.0 && thetaV > 0.79) continue;
                    const dvec3 v = sphericalDirection(thetaV, 0.0);
                    const double albedo =
                        integrateHemisphere([&](const dvec3& l) { return evaluate(s, n, v, l).x * l.z; }, 2000, 400);
                    EXPECT_LE(albedo, 1.01) << "roughness " << roughness << " metallic " << metallic << " thetaV " << thetaV;
                    // Single-scattering GGX loses energy but not all of it: 1 - ln 2 = 0.307 at
                    // alpha = 1, normal incidence, is the smallest value here.
                    EXPECT_GT(albedo, 0.25);
                }
            }
        }
    }
}

TEST(Brdf, RoughWhiteMetalAlbedoMatchesClosedForm)
{
    // At alpha = 1, D = 1/pi and with NoV = 1 the separable Smith V = 1 / (2 (NoL + 1)), so the
    // albedo is ∫0^1 mu / (mu + 1) dmu = 1 - ln 2: an independent check of the integrator and V.
    const Surface s{dvec3(1.0), 1.0, 1.0, Geometry::SmithGGX};
    const dvec3 n(0, 0, 1), v(0, 0, 1);
    const double albedo = integrateHemisphere([&](const dvec3& l) { return evaluate(s, n, v, l).x * l.z; }, 2000, 16);
    EXPECT_NEAR(albedo, 1.0 - std::log(2.0), 1e-4);
}

TEST(Brdf, PunctualFalloff)
{
    EXPECT_DOUBLE_EQ(rangeAttenuation(0.0, 2.0), 0.25);
    EXPECT_DOUBLE_EQ(rangeAttenuation(4.0, 4.0), 0.0);
    EXPECT_NEAR(rangeAttenuation(4.0, 2.0), (1.0 - 1.0 / 16.0) / 4.0, 1e-12);
    // Inside the inner cone: full; outside the outer: none; in between: smooth.
    const dvec3 down(0, -1, 0);
    EXPECT_DOUBLE_EQ(spotAttenuation(down, dvec3(0, 1, 0), 0.2, 0.4), 1.0);
    EXPECT_DOUBLE_EQ(spotAttenuation(down, dvec3(1, 0, 0), 0.2, 0.4), 0.0);
    const double mid = spotAttenuation(down, glm::normalize(dvec3(std::sin(0.3), std::cos(0.3), 0.0)), 0.2, 0.4);
    EXPECT_GT(mid, 0.0);
    EXPECT_LT(mid, 1.0);
}

TEST(Brdf, SpecularFactorZeroIsLambert)
{
    // KHR_materials_specular with specularFactor 0: no specular lobe, f = albedo / pi.
    Surface s{dvec3(0.7, 0.5, 0.2), 0.0, 0.4, Geometry::SmithGGX, 0.0};
    const dvec3 n(0, 0, 1);
    for (int i = 0; i < 20; ++i) {
        const dvec3 v = sphericalDirection(0.07 * i, 0.3 * i), l = sphericalDirection(1.4 - 0.07 * i, 2.0 + 0.5 * i);
        const dvec3 f = evaluate(s, n, v, l);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], s.baseColor[c] / kPi, 1e-12);
    }
}
