#pragma once
// Environments on the CPU: equirectangular radiance (cd/m²), the direction convention, the
// procedural sky, and order-2 spherical harmonics for irradiance. No GL here.
//
// Convention: +Y is up; a world direction d maps to u = 0.5 + atan2(d.x, -d.z) / 2π,
// v = acos(d.y) / π, (0, 0) the top-left pixel. An environment rotated by `rotation`
// degrees about +Y shows at world direction d what the file holds at Ry(-rotation) d.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace specula::render {

/// Equirectangular linear radiance, RGB 32-bit float, top row first.
struct EnvironmentMap {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> texels;
    /// Identifies the content for the bake cache (a hash of the file bytes or of the parameters).
    std::string key;

    glm::vec3 at(int x, int y) const { return texels[size_t(y) * size_t(width) + size_t(x)]; }
    /// Bilinear lookup in direction d (environment space), wrapping in u.
    glm::vec3 sample(const glm::vec3& d) const;
};

struct SkyParams {
    glm::vec3 sunDirection = glm::normalize(glm::vec3(0.4f, 0.55f, -0.7f)); ///< towards the sun
    float sunIlluminance = 6.0f;                      ///< lux on a surface facing the sun
    float sunAngularRadius = glm::radians(1.5f);      ///< larger than the real 0.27° to be visible at 1k
    glm::vec3 zenith{0.06f, 0.12f, 0.3f};             ///< cd/m²
    glm::vec3 horizon{0.3f, 0.33f, 0.36f};
    glm::vec3 ground{0.08f, 0.075f, 0.07f};
};

glm::vec2 directionToEquirect(const glm::vec3& d);
glm::vec3 equirectToDirection(const glm::vec2& uv);
/// Rotation about +Y by `degrees` (applied to environment-space directions to get world ones).
glm::mat3 environmentRotation(float degrees);

/// Reads .hdr or .exr (negatives clamped to 0, 32-bit float kept); key = hash of the file bytes.
EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path);
EnvironmentMap constantEnvironment(const glm::vec3& radiance);
EnvironmentMap proceduralSky(const SkyParams& params = {}, int width = 512);

/// Order-2 (9-coefficient) real spherical harmonics of the radiance, projected with the exact
/// solid angle of each equirectangular texel, (cos θ0 − cos θ1) Δφ.
using Sh9 = std::array<glm::vec3, 9>;
Sh9 projectSh9(const EnvironmentMap& map);
/// Irradiance E(n) (lux) from the SH radiance, convolved with the clamped cosine
/// (Ramamoorthi & Hanrahan 2001, eq. 8: Â0 = π, Â1 = 2π/3, Â2 = π/4).
glm::vec3 shIrradiance(const Sh9& sh, const glm::vec3& n);

} // namespace specula::render
