#include "IblReference.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace specula::test {
namespace {

using glm::dvec3;
using render::brdf::kPi;

double luminance(const dvec3& c)
{
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// Index of the interval of `cdf` (ascending, 0 .. 1) holding u.
size_t findInterval(const double* cdf, size_t intervals, double u)
{
    const double* it = std::upper_bound(cdf, cdf + intervals + 1, u);
    return std::min(size_t(std::max<ptrdiff_t>(it - cdf - 1, 0)), intervals - 1);
}

struct Frame {
    dvec3 t, b, n;
    explicit Frame(const dvec3& normal) : n(normal)
    {
        t = glm::normalize(glm::cross(std::abs(n.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0), n));
        b = glm::cross(n, t);
    }
    dvec3 toWorld(const dvec3& d) const { return t * d.x + b * d.y + n * d.z; }
};

// The mirror's delta lobe, exactly: F at v·h = n·v times the map in the mirror direction.
dvec3 mirrorRadiance(const render::brdf::Surface& surface, const dvec3& n, const dvec3& v, const render::EnvironmentMap& map)
{
    const double NoV = glm::dot(n, v);
    const dvec3 reflected = 2.0 * NoV * n - v;
    const dvec3 f0 = glm::mix(glm::min(surface.f0Dielectric * surface.specularColor, dvec3(1.0)) * surface.specularFactor,
                              surface.baseColor, surface.metallic);
    const double f90 = surface.specularFactor + (1.0 - surface.specularFactor) * surface.metallic;
    return render::brdf::fresnel(surface.fresnel, f0, f90, std::clamp(NoV, 0.0, 1.0)) * dvec3(map.sample(glm::vec3(reflected)));
}

} // namespace

EnvironmentSampler::EnvironmentSampler(const render::EnvironmentMap& map) : mWidth(map.width), mHeight(map.height)
{
    // Texel weight: luminance × solid angle, plus a floor (1e-3 of the mean) so that no texel
    // the bilinear lookup can reach has zero probability under both strategies.
    const size_t w = size_t(mWidth), h = size_t(mHeight);
    std::vector<double> weight(w * h);
    double total = 0.0;
    for (size_t y = 0; y < h; ++y) {
        const double solidAngle = 2.0 * kPi / double(w) * (std::cos(kPi * double(y) / double(h)) - std::cos(kPi * double(y + 1) / double(h)));
        for (size_t x = 0; x < w; ++x) {
            weight[y * w + x] = luminance(dvec3(map.at(int(x), int(y)))) * solidAngle;
            total += weight[y * w + x];
        }
    }
    const double floorWeight = 1e-3 * total / double(w * h);
    total = 0.0;
    for (double& x : weight) total += (x += floorWeight);
    mTexelProbability.resize(w * h);
    mRowWeight.assign(h, 0.0);
    mRowCdf.assign(h + 1, 0.0);
    mColumnCdf.assign(h * (w + 1), 0.0);
    for (size_t y = 0; y < h; ++y) {
        double row = 0.0;
        for (size_t x = 0; x < w; ++x) row += weight[y * w + x];
        mRowWeight[y] = row / total;
        mRowCdf[y + 1] = mRowCdf[y] + mRowWeight[y];
        double running = 0.0;
        for (size_t x = 0; x < w; ++x) {
            mTexelProbability[y * w + x] = weight[y * w + x] / total;
            running += weight[y * w + x];
            mColumnCdf[y * (w + 1) + x + 1] = running / row;
        }
    }
    mRowCdf[h] = 1.0;
}

glm::dvec3 EnvironmentSampler::sample(double u1, double u2, double u3, double& pdf) const
{
    const size_t w = size_t(mWidth), h = size_t(mHeight);
    const size_t y = findInterval(mRowCdf.data(), h, u1);
    const size_t x = findInterval(mColumnCdf.data() + y * (w + 1), w, u2);
    // Uniform in φ and cos θ within the texel: uniform in solid angle.
    const double cos0 = std::cos(kPi * double(y) / double(h)), cos1 = std::cos(kPi * double(y + 1) / double(h));
    const double cosTheta = cos0 + (cos1 - cos0) * u3;
    // φ uniform within the column: the fraction of u2 inside its interval is uniform.
    const double* cdf = mColumnCdf.data() + y * (w + 1);
    const double span = cdf[x + 1] - cdf[x];
    const double fraction = span > 0.0 ? std::clamp((u2 - cdf[x]) / span, 0.0, 1.0) : 0.5;
    const double u = (double(x) + fraction) / double(w);
    const double theta = std::acos(std::clamp(cosTheta, -1.0, 1.0));
    const glm::dvec3 d(render::equirectToDirection(glm::vec2(float(u), float(theta / kPi))));
    const double solidAngle = 2.0 * kPi / double(w) * (cos0 - cos1);
    pdf = mTexelProbability[y * w + x] / solidAngle;
    return glm::normalize(d);
}

double EnvironmentSampler::pdf(const glm::dvec3& direction) const
{
    const glm::vec2 uv = render::directionToEquirect(glm::vec3(direction));
    const size_t w = size_t(mWidth), h = size_t(mHeight);
    const size_t x = std::min(size_t(std::max(0.0, std::floor(double(uv.x) * double(w)))) % w, w - 1);
    const size_t y = std::min(size_t(std::max(0.0, std::floor(double(uv.y) * double(h)))), h - 1);
    const double solidAngle =
        2.0 * kPi / double(w) * (std::cos(kPi * double(y) / double(h)) - std::cos(kPi * double(y + 1) / double(h)));
    return mTexelProbability[y * w + x] / solidAngle;
}

ReferenceSample referenceRadiance(const render::brdf::Surface& surface, const glm::dvec3& n, const glm::dvec3& v,
                                  const render::EnvironmentMap& map, const EnvironmentSampler& sampler,
                                  const glm::dvec3& specularCompensation, int samples, uint64_t seed)
{
    namespace brdf = render::brdf;
    const bool mirror = surface.perceptualRoughness < 1e-3;
    const double r = std::clamp(surface.perceptualRoughness, brdf::kMinPerceptualRoughness, 1.0);
    const double alpha = r * r;
    const bool hasDiffuse = surface.metallic < 1.0;
    // Probability of sampling the specular lobe among the BRDF's two strategies.
    const double specularProbability = mirror ? 0.0 : hasDiffuse ? 0.5 : 1.0;
    const Frame frame(n);
    // KHR_materials_anisotropy: sample the anisotropic lobe itself (brdf::Surface::anisotropy).
    const bool anisotropic = !mirror && surface.anisotropy > 0.0 && surface.distribution == brdf::Distribution::GGX;
    const dvec3 lobeT = glm::normalize(surface.anisotropyDirection - n * glm::dot(n, surface.anisotropyDirection));
    const dvec3 lobeB = glm::cross(n, lobeT);
    const double alphaT = glm::mix(alpha, 1.0, surface.anisotropy * surface.anisotropy);

    // f(l) (n·l) without the mirror's delta.
    auto integrand = [&](const dvec3& l) -> dvec3 {
        const double NoL = glm::dot(n, l);
        if (NoL <= 0.0) return dvec3(0.0);
        dvec3 diffuse, specular;
        brdf::evaluateLobes(surface, n, v, l, diffuse, specular);
        const dvec3 f = diffuse + (mirror ? dvec3(0.0) : specular * specularCompensation);
        return f * NoL;
    };
    auto brdfPdf = [&](const dvec3& l) {
        const double NoL = glm::dot(n, l);
        if (NoL <= 0.0) return 0.0;
        double p = (1.0 - specularProbability) * NoL / kPi;
        if (specularProbability > 0.0) {
            const dvec3 h = glm::normalize(v + l);
            const double NoH = glm::dot(n, h), VoH = glm::dot(v, h);
            const double D = anisotropic ? brdf::D_GGX_Anisotropic(NoH, glm::dot(lobeT, h), glm::dot(lobeB, h), alphaT, alpha)
                                         : brdf::D_GGX(NoH, alpha);
            if (NoH > 0.0 && VoH > 0.0) p += specularProbability * D * NoH / (4.0 * VoH);
        }
        return p;
    };

    constexpr int kBatches = 8;
    const int perBatch = std::max(samples / kBatches, 1);
    Random random{seed * 0x2545f4914f6cdd1dull + 1};
    dvec3 batchMeans[kBatches];
    for (int batch = 0; batch < kBatches; ++batch) {
        dvec3 sum(0.0);
        for (int i = 0; i < perBatch; ++i) {
            // The BRDF's strategy.
            {
                const double u0 = random.next(), u1 = random.next(), u2 = random.next();
                dvec3 l;
                if (u0 < specularProbability && anisotropic) {
                    // Slopes of the unit lobe stretched by (at, ab): h distributed as D(h) n.h.
                    const double phi = 2.0 * kPi * u2, tanT = std::sqrt(u1 / std::max(1.0 - u1, 1e-300));
                    const dvec3 hl = glm::normalize(dvec3(alphaT * tanT * std::cos(phi), alpha * tanT * std::sin(phi), 1.0));
                    const dvec3 h = lobeT * hl.x + lobeB * hl.y + n * hl.z;
                    l = 2.0 * glm::dot(v, h) * h - v;
                } else if (u0 < specularProbability) {
                    const double phi = 2.0 * kPi * u2;
                    const double cosT = std::sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1));
                    const double sinT = std::sqrt(std::max(1.0 - cosT * cosT, 0.0));
                    const dvec3 h = frame.toWorld(dvec3(sinT * std::cos(phi), sinT * std::sin(phi), cosT));
                    l = 2.0 * glm::dot(v, h) * h - v;
                } else {
                    const double phi = 2.0 * kPi * u2, rr = std::sqrt(u1);
                    l = frame.toWorld(dvec3(rr * std::cos(phi), rr * std::sin(phi), std::sqrt(std::max(1.0 - u1, 0.0))));
                }
                const double pb = brdfPdf(l);
                if (pb > 0.0) sum += integrand(l) * dvec3(map.sample(glm::vec3(l))) / (pb + sampler.pdf(l));
            }
            // The map's strategy.
            {
                double pm = 0.0;
                const dvec3 l = sampler.sample(random.next(), random.next(), random.next(), pm);
                if (pm > 0.0 && glm::dot(n, l) > 0.0) sum += integrand(l) * dvec3(map.sample(glm::vec3(l))) / (brdfPdf(l) + pm);
            }
        }
        batchMeans[batch] = sum / double(perBatch);
    }
    dvec3 mean(0.0);
    for (const dvec3& m : batchMeans) mean += m;
    mean /= double(kBatches);
    double variance = 0.0;
    for (const dvec3& m : batchMeans) variance += (luminance(m) - luminance(mean)) * (luminance(m) - luminance(mean));
    variance /= double(kBatches * (kBatches - 1));

    ReferenceSample out;
    out.radiance = mean;
    if (mirror) out.radiance += mirrorRadiance(surface, n, v, map);
    const double l = luminance(out.radiance);
    out.relativeError = l > 0.0 ? std::sqrt(variance) / l : 0.0;
    return out;
}

EnvironmentQuadrature::EnvironmentQuadrature(const render::EnvironmentMap& map, int block) : mMap(&map), mBlock(block)
{
    const int w = map.width, h = map.height;
    mTexels.resize(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y) {
        const double solidAngle = 2.0 * kPi / double(w) * (std::cos(kPi * double(y) / double(h)) - std::cos(kPi * double(y + 1) / double(h)));
        for (int x = 0; x < w; ++x) {
            const glm::vec3 d = render::equirectToDirection({(float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h)});
            mTexels[size_t(y) * size_t(w) + size_t(x)] = {glm::normalize(d), map.at(x, y) * float(solidAngle)};
        }
    }
    for (int by = 0; by < h; by += block)
        for (int bx = 0; bx < w; bx += block) {
            Block b;
            b.x0 = bx, b.y0 = by;
            dvec3 centroid(0.0), plain(0.0);
            for (int y = by; y < std::min(by + block, h); ++y)
                for (int x = bx; x < std::min(bx + block, w); ++x) {
                    const Texel& t = mTexels[size_t(y) * size_t(w) + size_t(x)];
                    b.flux += dvec3(t.flux);
                    centroid += dvec3(t.direction) * luminance(dvec3(t.flux));
                    plain += dvec3(t.direction);
                }
            b.centre = glm::normalize(plain);
            b.direction = glm::length(centroid) > 0.0 ? glm::normalize(centroid) : b.centre;
            for (int y = by; y < std::min(by + block, h); ++y)
                for (int x = bx; x < std::min(bx + block, w); ++x) {
                    const dvec3 d(mTexels[size_t(y) * size_t(w) + size_t(x)].direction);
                    b.radius = std::max(b.radius, std::acos(std::clamp(glm::dot(d, b.centre), -1.0, 1.0)));
                }
            mBlocks.push_back(b);
        }
}

glm::dvec3 EnvironmentQuadrature::radiance(const render::brdf::Surface& surface, const glm::dvec3& n, const glm::dvec3& v,
                                           const glm::dvec3& specularCompensation, bool everyTexel, const dvec3* diffuseWeight) const
{
    namespace brdf = render::brdf;
    const bool mirror = surface.perceptualRoughness < 1e-3;
    const double r = std::clamp(surface.perceptualRoughness, brdf::kMinPerceptualRoughness, 1.0);
    const double alpha = r * r;
    auto integrand = [&](const dvec3& l) -> dvec3 {
        if (glm::dot(n, l) <= 0.0) return dvec3(0.0);
        dvec3 diffuse, specular;
        brdf::evaluateLobes(surface, n, v, l, diffuse, specular);
        if (diffuseWeight) {
            // The diffuse lobe itself, uncoupled from this direction's Fresnel, then weighted.
            const dvec3 h = glm::normalize(v + l);
            diffuse = surface.baseColor * (1.0 - surface.metallic) * *diffuseWeight *
                      brdf::diffuseLobe(surface.diffuse, r, std::abs(glm::dot(n, v)), glm::dot(n, l),
                                        std::clamp(glm::dot(l, h), 0.0, 1.0), glm::dot(v, l));
        }
        return (diffuse + (mirror ? dvec3(0.0) : specular * specularCompensation)) * glm::dot(n, l);
    };
    // Where D is above 1 % of its peak: θ_h < atan(3α), θ_l < 2 θ_h about the mirror direction
    // for n = v, doubled for the lobe's stretch away from it, plus a block's size.
    const bool sharp = !mirror && alpha < 0.1;
    const double refine = everyTexel ? 4.0 : sharp ? 4.0 * std::atan(3.0 * alpha) + glm::radians(3.0) : -1.0;
    const dvec3 reflected = 2.0 * glm::dot(n, v) * n - v;
    const int w = mMap->width, h = mMap->height;
    dvec3 sum(0.0);
    for (const Block& b : mBlocks) {
        // A block wholly below the horizon adds nothing (n·l < 0 at every texel).
        if (glm::dot(n, b.centre) < -std::sin(b.radius)) continue;
        const double angle = std::acos(std::clamp(glm::dot(b.centre, reflected), -1.0, 1.0)) - b.radius;
        // Blocks across the horizon are summed texel by texel too: max(0, n·l) kinks there.
        if (angle < refine || std::abs(glm::dot(n, b.centre)) < std::sin(b.radius)) {
            for (int y = b.y0; y < std::min(b.y0 + mBlock, h); ++y)
                for (int x = b.x0; x < std::min(b.x0 + mBlock, w); ++x) {
                    const Texel& t = mTexels[size_t(y) * size_t(w) + size_t(x)];
                    sum += integrand(dvec3(t.direction)) * dvec3(t.flux);
                }
        } else {
            sum += integrand(b.direction) * b.flux;
        }
    }
    if (mirror) sum += mirrorRadiance(surface, n, v, *mMap);
    return sum;
}

void parallelFor(size_t count, const std::function<void(size_t)>& f)
{
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            for (size_t k = t; k < count; k += threads) f(k);
        });
    for (std::thread& w : workers) w.join();
}

} // namespace specula::test
