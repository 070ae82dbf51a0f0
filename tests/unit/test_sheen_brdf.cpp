// KHR_materials_sheen's lobe in shading/Brdf (the CPU twin of shaders/brdf/sheen.glsl): the
// Charlie distribution normalised, its albedo E within [0, 1] and agreeing with an independent
// estimate, and the albedo-scaled layering kept at or below 1 in a white furnace.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "shading/Brdf.h"

using namespace specula::render::brdf;
using glm::dvec3;


TEST(SheenBrdf, CharlieDistributionIsNormalised)
{
    // ∫ D(h) (n·h) dω_h = 1: a midpoint rule in μ = cos θ_h (D depends on θ only); 200,000 cells
    // hold the sharpest lobe here (α = 0.045², exponent 1/α ≈ 494 in sin θ) within 0.1 %.
    for (double roughness : {0.045, 0.2, 0.5, 1.0}) {
        const double alpha = roughness * roughness;
        const int n = 200000;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const double mu = (i + 0.5) / n;
            sum += D_Charlie(mu, alpha) * mu;
        }
        EXPECT_NEAR(sum * 2.0 * kPi / n, 1.0, 1e-3) << "roughness " << roughness;
    }
}

TEST(SheenBrdf, AlbedoAgreesWithSamplingAndStaysBelowOne)
{
    // E(n·v) by the quadrature of sheenDirectionalAlbedo against uniform hemisphere sampling
    // (a stratified grid of 1024² directions): within 1 % + 1e-3, and in [0, 1].
    for (double roughness : {0.1, 0.5, 1.0})
        for (double NoV : {0.1, 0.5, 0.9}) {
            const double e = sheenDirectionalAlbedo(NoV, roughness, 256);
            const dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
            const double alpha = roughness * roughness;
            constexpr int kGrid = 1024;
            double sum = 0.0;
            for (int i = 0; i < kGrid; ++i)
                for (int j = 0; j < kGrid; ++j) {
                    const double z = (i + 0.5) / kGrid, phi = 2.0 * kPi * (j + 0.5) / kGrid, s = std::sqrt(1.0 - z * z);
                    const dvec3 l(s * std::cos(phi), s * std::sin(phi), z);
                    sum += D_Charlie(glm::normalize(v + l).z, alpha) * V_Charlie(NoV, z, alpha) * z;
                }
            const double sampled = sum * 2.0 * kPi / (double(kGrid) * kGrid);
            EXPECT_NEAR(e, sampled, 0.01 * sampled + 1e-3) << "roughness " << roughness << " n.v " << NoV;
            EXPECT_GE(e, 0.0);
            EXPECT_LE(e, 1.0);
        }
}

TEST(SheenBrdf, AlbedoScalingKeepsTheFurnaceAtOrBelowOne)
{
    // A white dielectric (GGX single scattering, Lambert weighted by 1 - F) under a white sheen:
    // ∫ f (n·l) dω = E_sheen + (1 - E_sheen) ∫ f_base (n·l) dω, within 1.01 of the larger of 1
    // and the base's own albedo (docs/testing.md's furnace bound).
    for (double roughness : {0.1, 0.5, 1.0})
        for (double NoV : {0.2, 0.6, 1.0}) {
            Surface s;
            s.baseColor = dvec3(1.0);
            s.metallic = 0.0;
            s.perceptualRoughness = 0.5;
            s.sheenColor = dvec3(1.0);
            s.sheenRoughness = roughness;
            s.sheenAlbedo = sheenDirectionalAlbedo(NoV, roughness);
            const dvec3 n(0.0, 0.0, 1.0), v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
            constexpr int kGrid = 512;
            double sum = 0.0, base = 0.0;
            Surface bare = s;
            bare.sheenColor = dvec3(0.0);
            for (int i = 0; i < kGrid; ++i)
                for (int j = 0; j < kGrid; ++j) {
                    const double z = (i + 0.5) / kGrid, phi = 2.0 * kPi * (j + 0.5) / kGrid, r = std::sqrt(1.0 - z * z);
                    const dvec3 l(r * std::cos(phi), r * std::sin(phi), z);
                    sum += evaluate(s, n, v, l).x * z;
                    base += evaluate(bare, n, v, l).x * z;
                }
            sum *= 2.0 * kPi / (double(kGrid) * kGrid);
            base *= 2.0 * kPi / (double(kGrid) * kGrid);
            // The base alone need not stay below 1 (the single-scattering dielectric's Lambert
            // weighted by 1 - F(v.h) exceeds it slightly at grazing angles): the sheen adds nothing
            // above the larger of 1 and the base's own albedo.
            EXPECT_LE(sum, std::max(1.0, base) + 0.01) << "sheen roughness " << roughness << " n.v " << NoV << " base " << base;
            EXPECT_NEAR(sum, s.sheenAlbedo + (1.0 - s.sheenAlbedo) * base, 5e-3) << "sheen roughness " << roughness << " n.v " << NoV;
        }
}
