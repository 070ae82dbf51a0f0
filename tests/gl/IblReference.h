#pragma once
// A converged Monte Carlo reference of the rendering equation at a surface point lit by an
// environment map only: L_o(v) = ∫ f(l, v) L(l) (n·l) dω over the hemisphere, with
//   - the glTF BRDF of shading/Brdf (its lobes: (1 - F) diffuse + F D V), the specular lobe
//     scaled by the renderer's multiple-scattering compensation (given, computed by the caller
//     from an independent CPU estimate of E);
//   - L the full-resolution map, looked up bilinearly (EnvironmentMap::sample);
//   - multiple importance sampling (Veach 1997, balance heuristic) of the BRDF (GGX half
//     vectors and cosine-weighted directions) and of the map (texels by luminance × solid
//     angle, then uniform in φ and cos θ within the texel).
// Nothing of the GPU's bake enters it: it is what the image-based lighting approximates.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "shading/Brdf.h"
#include "shading/EnvironmentMap.h"

namespace specula::test {

/// SplitMix64 (Steele et al. 2014): uniform doubles in [0, 1); independent streams from
/// consecutive seeds, so each pixel's estimate is reproducible whatever thread computes it.
struct Random {
    uint64_t state;
    double next()
    {
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
        return double(z >> 11) * (1.0 / 9007199254740992.0);
    }
};

/// f(0) .. f(count - 1) on every core (interleaved: item k on thread k mod threads).
void parallelFor(size_t count, const std::function<void(size_t)>& f);

/// Directions distributed as the map's luminance, with their solid-angle pdf.
class EnvironmentSampler {
public:
    explicit EnvironmentSampler(const render::EnvironmentMap& map);
    /// A direction for the point (u1, u2, u3) of the unit cube, and its pdf (1/sr).
    glm::dvec3 sample(double u1, double u2, double u3, double& pdf) const;
    double pdf(const glm::dvec3& direction) const;

private:
    int mWidth = 0, mHeight = 0;
    std::vector<double> mRowCdf;    // mHeight + 1 entries, 0 .. 1
    std::vector<double> mColumnCdf; // per row, mWidth + 1 entries, 0 .. 1
    std::vector<double> mRowWeight; // each row's probability
    std::vector<double> mTexelProbability;
};

struct ReferenceSample {
    glm::dvec3 radiance{0.0};
    /// Standard error of the estimate over its mean, in luminance (from independent batches).
    double relativeError = 0.0;
};

/// L_o(v) at normal n for `surface` under `map`, with `samples` samples of each strategy.
/// A perceptual roughness below 1e-3 makes the specular lobe the mirror (its delta integrated
/// exactly: F(n·v) L(r)); the diffuse lobe is then sampled by the cosine and the map.
ReferenceSample referenceRadiance(const render::brdf::Surface& surface, const glm::dvec3& n, const glm::dvec3& v,
                                  const render::EnvironmentMap& map, const EnvironmentSampler& sampler,
                                  const glm::dvec3& specularCompensation, int samples, uint64_t seed);

/// The same integral with no noise: a quadrature over the map's texels, each texel's radiance ×
/// its exact solid angle, (cos θ0 − cos θ1) Δφ, seen from its centre — the rendering equation
/// for the map as a piecewise-constant function of direction (EnvironmentMap::at), which is
/// what the map is. Blocks of `block`² texels stand for their texels (their flux seen from its
/// luminance-weighted centroid) wherever the integrand is smooth across a block; near a sharp
/// specular lobe's peak (GGX α < 0.1: within 4 atan(3α) + 3° of the mirror direction, where D
/// is above 1 % of its peak) every texel is summed. Tests: IblReference.Quadrature* (against
/// every texel summed one by one, and against referenceRadiance).
class EnvironmentQuadrature {
public:
    explicit EnvironmentQuadrature(const render::EnvironmentMap& map, int block = 4);
    /// L_o(v), as referenceRadiance's (the mirror's delta likewise exact, the map read
    /// bilinearly in the mirror direction). `everyTexel` sums every texel one by one.
    /// `diffuseWeight` null: the glTF BRDF's coupling, the diffuse lobe × (1 − F(v·h)) for each
    /// light direction. Else the energy-conserving layering of Cycles' Principled BSDF and
    /// OpenPBR (albedo scaling, Kulla & Conty 2017): the diffuse lobe × *diffuseWeight, one
    /// weight for all directions, 1 − the specular lobe's directional albedo E(n·v).
    glm::dvec3 radiance(const render::brdf::Surface& surface, const glm::dvec3& n, const glm::dvec3& v,
                        const glm::dvec3& specularCompensation, bool everyTexel = false,
                        const glm::dvec3* diffuseWeight = nullptr) const;

private:
    struct Texel {
        glm::vec3 direction;
        glm::vec3 flux; // radiance × solid angle
    };
    struct Block {
        glm::dvec3 direction{0.0}; // luminance-weighted centroid of its texels
        glm::dvec3 flux{0.0};
        glm::dvec3 centre{0.0}; // its texels' mean direction, for the refinement test
        double radius = 0.0;  // the largest angle (radians) from the centre to a texel's
        int x0 = 0, y0 = 0;
    };
    const render::EnvironmentMap* mMap;
    int mBlock;
    std::vector<Texel> mTexels; // row after row
    std::vector<Block> mBlocks;
};

} // namespace specula::test
