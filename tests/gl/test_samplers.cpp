// Chi-square tests of the importance samplers the bakes use (shaders/ibl/sampling.glsl), run on
// the GPU as the bakes run them: each half vector sampler must be distributed as D(h) (n·h), the
// solid-angle density of its normal distribution (shading/Brdf, the CPU port), after pbrt-v4's
// bsdfs_test.cpp: random ξ, a θ × φ histogram, expected counts from the density integrated
// over each cell, cells with fewer than 5 expected merged, Šidák-corrected significance 1%.
#include "GlTestContext.h"

#include <epoxy/gl.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gl/Program.h"
#include "gl/Texture.h"
#include "shading/Brdf.h"

using namespace specula;
using specula::test::GlTest;
namespace brdf = specula::render::brdf;

namespace {

constexpr int kSize = 512;             // kSize² samples per test
constexpr int kThetaBins = 20, kPhiBins = 40;

// Samples written by the real sampling.glsl, ξ from a PCG hash (independent, not Hammersley:
// a stratified sequence would pass a chi-square test too easily).
constexpr const char* kSampleShader = R"(#version 450 core
layout(local_size_x = 8, local_size_y = 8) in;
#include "common/math.glsl"
#include "brdf/blinn_phong.glsl"
#include "ibl/sampling.glsl"
layout(binding = 0, rgba32f) uniform writeonly image2D uOut;
uniform int uSampler;
uniform float uAlpha;
uniform uint uSeed;
uint pcg(uint v)
{
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
float uniform01(uint v) { return float(pcg(v) >> 8u) * (1.0 / 16777216.0); } // [0, 1)
void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    uint i = uint(p.y * imageSize(uOut).x + p.x);
    vec2 xi = vec2(uniform01(2u * i + uSeed), uniform01(pcg(2u * i + 1u + uSeed)));
    vec3 h = uSampler == 0 ? importanceSampleGgx(xi, uAlpha)
           : uSampler == 1 ? importanceSampleBeckmann(xi, uAlpha)
                           : importanceSampleBlinnPhong(xi, blinnPhongExponent(uAlpha));
    imageStore(uOut, p, vec4(h, 0.0));
}
)";

/// Regularised upper incomplete gamma Q(a, x) (series for x < a + 1, continued fraction above:
/// the textbook split, Numerical Recipes §6.2).
double gammaQ(double a, double x)
{
    if (x <= 0.0) return 1.0;
    const double logPrefix = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000 && std::abs(term) > std::abs(sum) * 1e-15; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(logPrefix);
    }
    // Lentz's method for the continued fraction.
    double b = x + 1.0 - a, c = 1e300, d = 1.0 / b, f = d;
    for (int n = 1; n < 10000; ++n) {
        const double an = -n * (n - a);
        b += 2.0;
        d = an * d + b;
        d = std::abs(d) < 1e-300 ? 1e-300 : d;
        c = b + an / c;
        c = std::abs(c) < 1e-300 ? 1e-300 : c;
        d = 1.0 / d;
        const double delta = d * c;
        f *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(logPrefix) * f;
}

struct ChiSquare {
    double statistic = 0.0;
    int dof = 0;
    double pValue = 1.0;
};

/// Samples (unit half vectors around +Z) against the density D(cos θ) cos θ per steradian.
template <typename Density>
ChiSquare chiSquare(const std::vector<float>& samples, Density density)
{
    std::vector<double> observed(kThetaBins * kPhiBins, 0.0), expected(kThetaBins * kPhiBins, 0.0);
    const double thetaStep = brdf::kPi / 2.0 / kThetaBins, phiStep = 2.0 * brdf::kPi / kPhiBins;
    size_t count = 0;
    for (size_t i = 0; i + 3 < samples.size(); i += 4) {
        const double x = samples[i], y = samples[i + 1], z = samples[i + 2];
        const double theta = std::acos(std::clamp(z, -1.0, 1.0));
        double phi = std::atan2(y, x);
        if (phi < 0.0) phi += 2.0 * brdf::kPi;
        const int t = std::min(int(theta / thetaStep), kThetaBins - 1), f = std::min(int(phi / phiStep), kPhiBins - 1);
        observed[size_t(t * kPhiBins + f)] += 1.0;
        ++count;
    }
    // Isotropic densities: the φ integral is phiStep; θ by composite Simpson, 512 intervals a cell.
    for (int t = 0; t < kThetaBins; ++t) {
        const int n = 512;
        const double a = t * thetaStep, h = thetaStep / n;
        double sum = 0.0;
        for (int k = 0; k <= n; ++k) {
            const double theta = a + k * h;
            const double w = k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0);
            sum += w * density(std::cos(theta)) * std::sin(theta);
        }
        const double cell = sum * h / 3.0 * phiStep * double(count);
        for (int f = 0; f < kPhiBins; ++f) expected[size_t(t * kPhiBins + f)] = cell;
    }
    // Cells expecting fewer than 5 samples are pooled (the test's approximation needs ≥ 5).
    ChiSquare result;
    double pooledObserved = 0.0, pooledExpected = 0.0;
    int cells = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5.0) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        result.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++cells;
    }
    if (pooledExpected > 0.0) {
        result.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++cells;
    }
    result.dof = cells - 1;
    result.pValue = gammaQ(result.dof / 2.0, result.statistic / 2.0);
    return result;
}

class SamplerTest : public GlTest {
protected:
    void SetUp() override
    {
        GlTest::SetUp();
        root = std::filesystem::temp_directory_path() / ("specula-samplers-" + std::to_string(::getpid()));
        std::filesystem::remove_all(root);
        std::filesystem::copy(gl::shaderRoot(), root, std::filesystem::copy_options::recursive);
        std::ofstream(root / "sample_test.comp") << kSampleShader;
        program = gl::Program({.compute = "sample_test.comp", .label = "sampler test", .root = root});
    }
    void TearDown() override
    {
        program = {};
        std::filesystem::remove_all(root);
        GlTest::TearDown();
    }
    /// kSize² half vectors from sampler 0 (GGX), 1 (Beckmann) or 2 (Blinn-Phong).
    std::vector<float> sample(int sampler, float alpha, uint32_t seed)
    {
        gl::TextureDesc desc;
        desc.format = gl::Format::RGBA32F;
        desc.width = kSize;
        desc.height = kSize;
        desc.label = "samples";
        gl::Texture image(desc);
        glUseProgram(program.id());
        program.set(program.uniformLocation("uSampler"), sampler);
        program.set(program.uniformLocation("uAlpha"), alpha);
        program.set(program.uniformLocation("uSeed"), seed);
        glBindImageTexture(0, image.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glDispatchCompute(kSize / 8, kSize / 8, 1);
        glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
        glUseProgram(0);
        return image.readFloat(0, 4);
    }
    std::filesystem::path root;
    gl::Program program;
};

} // namespace

TEST_F(SamplerTest, EachSamplerFollowsItsDistribution)
{
    const brdf::Distribution distributions[] = {brdf::Distribution::GGX, brdf::Distribution::Beckmann,
                                                brdf::Distribution::BlinnPhong};
    const char* names[] = {"ggx", "beckmann", "blinn-phong"};
    const float alphas[] = {0.2f, 0.5f, 0.9f};
    const int tests = 3 * 3;
    const double significance = 1.0 - std::pow(1.0 - 0.01, 1.0 / tests); // Šidák
    uint32_t seed = 1;
    for (int s = 0; s < 3; ++s) {
        for (float alpha : alphas) {
            const std::vector<float> samples = sample(s, alpha, seed += 2u * kSize * kSize); // disjoint hash inputs
            const ChiSquare r = chiSquare(samples, [&](double cosTheta) {
                return brdf::distribution(distributions[s], cosTheta, alpha) * cosTheta;
            });
            std::printf("  %-12s alpha %.1f: chi2 %.1f, %d dof, p = %.3f\n", names[s], alpha, r.statistic, r.dof, r.pValue);
            EXPECT_GT(r.dof, 20) << names[s] << " alpha " << alpha; // enough cells to mean something
            EXPECT_GT(r.pValue, significance) << names[s] << " alpha " << alpha << ": chi2 " << r.statistic << ", "
                                              << r.dof << " dof";
        }
    }
}

// The test can tell: GGX's samples against Beckmann's density at the same α, and against
// GGX at a 10% different α, are rejected outright.
TEST_F(SamplerTest, RejectsTheWrongDistribution)
{
    const std::vector<float> samples = sample(0, 0.5f, 12345u);
    const ChiSquare beckmann = chiSquare(samples, [](double c) { return brdf::D_Beckmann(c, 0.5) * c; });
    const ChiSquare otherAlpha = chiSquare(samples, [](double c) { return brdf::D_GGX(c, 0.55) * c; });
    std::printf("  ggx samples vs beckmann: p = %.3g; vs ggx alpha 0.55: p = %.3g\n", beckmann.pValue, otherAlpha.pValue);
    EXPECT_LT(beckmann.pValue, 1e-6);
    EXPECT_LT(otherAlpha.pValue, 1e-6);
}
