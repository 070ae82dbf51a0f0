#include "shading/EnvironmentMap.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include "core/Error.h"
#include "core/Hash.h"
#include "core/ImageIO.h"

namespace specula::render {
namespace {

constexpr float kPi = glm::pi<float>();

// Real SH basis up to l = 2 (Sloan 2008, "Stupid Spherical Harmonics Tricks", appendix).
std::array<float, 9> shBasis(const glm::vec3& d)
{
    return {0.282095f,
            0.488603f * d.y,
            0.488603f * d.z,
            0.488603f * d.x,
            1.092548f * d.x * d.y,
            1.092548f * d.y * d.z,
            0.315392f * (3.0f * d.z * d.z - 1.0f),
            1.092548f * d.x * d.z,
            0.546274f * (d.x * d.x - d.y * d.y)};
}

} // namespace

glm::vec2 directionToEquirect(const glm::vec3& d)
{
    return {0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi), std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi};
}

glm::vec3 equirectToDirection(const glm::vec2& uv)
{
    const float phi = (uv.x - 0.5f) * 2.0f * kPi;
    const float theta = uv.y * kPi;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

glm::mat3 environmentRotation(float degrees)
{
    const float a = glm::radians(degrees);
    const float c = std::cos(a), s = std::sin(a);
    // Right-handed rotation about +Y (columns).
    return glm::mat3(c, 0, -s, 0, 1, 0, s, 0, c);
}

glm::vec3 EnvironmentMap::sample(const glm::vec3& d) const
{
    const glm::vec2 uv = directionToEquirect(glm::normalize(d));
    const float x = uv.x * float(width) - 0.5f, y = std::clamp(uv.y * float(height) - 0.5f, 0.0f, float(height - 1));
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = y - float(y0);
    auto texel = [&](int xi, int yi) {
        xi = ((xi % width) + width) % width;
        yi = std::clamp(yi, 0, height - 1);
        return at(xi, yi);
    };
    return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), fx), glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), fx), fy);
}

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path)
{
    const ImageFloat image = readFloatImage(path);
    EnvironmentMap map;
    map.width = image.width;
    map.height = image.height;
    map.texels.resize(size_t(image.width) * size_t(image.height));
    for (size_t i = 0; i < map.texels.size(); ++i)
        map.texels[i] = glm::max(glm::vec3(image.pixels[4 * i], image.pixels[4 * i + 1], image.pixels[4 * i + 2]), glm::vec3(0.0f));
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    map.key = fmt::format("file-{:016x}", fnv1a64(bytes.str()));
    return map;
}

EnvironmentMap constantEnvironment(const glm::vec3& radiance)
{
    EnvironmentMap map;
    // 128x64 rather than 1x1: the SH projection samples each texel at its centre, and on a
    // coarse grid that alone leaks energy into bands 1 and 2 (3.7% at 8x4, ~0.01% here).
    map.width = 128;
    map.height = 64;
    map.texels.assign(size_t(map.width) * size_t(map.height), glm::max(radiance, glm::vec3(0.0f)));
    map.key = fmt::format("color-{:.6g}-{:.6g}-{:.6g}", radiance.x, radiance.y, radiance.z);
    return map;
}

EnvironmentMap proceduralSky(const SkyParams& p, int width)
{
    EnvironmentMap map;
    map.width = width;
    map.height = width / 2;
    map.texels.resize(size_t(map.width) * size_t(map.height));
    const glm::vec3 sun = glm::normalize(p.sunDirection);
    const float cosSun = std::cos(p.sunAngularRadius);
    // Sun disc radiance so that the disc delivers sunIlluminance lux at normal incidence:
    // E = L · solid angle, solid angle = 2π (1 − cos r).
    const float sunRadiance = p.sunIlluminance / (2.0f * kPi * (1.0f - cosSun));
    for (int y = 0; y < map.height; ++y) {
        for (int x = 0; x < map.width; ++x) {
            const glm::vec3 d = equirectToDirection({(float(x) + 0.5f) / float(map.width), (float(y) + 0.5f) / float(map.height)});
            glm::vec3 c;
            if (d.y >= 0.0f) {
                // Sky: horizon to zenith, brighter around the sun (a simple Mie-like glow).
                c = glm::mix(p.horizon, p.zenith, std::pow(d.y, 0.5f));
                const float glow = std::max(glm::dot(d, sun), 0.0f);
                c += glm::vec3(1.0f, 0.9f, 0.7f) * (0.15f * std::pow(glow, 8.0f) + 0.5f * std::pow(glow, 64.0f));
            } else {
                c = glm::mix(p.horizon * 0.5f, p.ground, std::min(-d.y * 4.0f, 1.0f));
            }
            if (glm::dot(d, sun) >= cosSun) c += glm::vec3(sunRadiance) * glm::vec3(1.0f, 0.95f, 0.88f);
            map.texels[size_t(y) * size_t(map.width) + size_t(x)] = c;
        }
    }
    map.key = fmt::format("sky-{}-{:.4g}-{:.4g}-{:.4g}-{:.4g}-{:.4g}", width, sun.x, sun.y, sun.z, p.sunIlluminance, p.sunAngularRadius);
    return map;
}

Sh9 projectSh9(const EnvironmentMap& map)
{
    Sh9 sh{};
    const float dPhi = 2.0f * kPi / float(map.width);
    for (int y = 0; y < map.height; ++y) {
        const float theta0 = kPi * float(y) / float(map.height), theta1 = kPi * float(y + 1) / float(map.height);
        const float solidAngle = (std::cos(theta0) - std::cos(theta1)) * dPhi;
        for (int x = 0; x < map.width; ++x) {
            const glm::vec3 d = equirectToDirection({(float(x) + 0.5f) / float(map.width), (float(y) + 0.5f) / float(map.height)});
            const auto basis = shBasis(d);
            const glm::vec3 radiance = map.at(x, y) * solidAngle;
            for (int i = 0; i < 9; ++i) sh[size_t(i)] += radiance * basis[size_t(i)];
        }
    }
    return sh;
}

glm::vec3 shIrradiance(const Sh9& sh, const glm::vec3& n)
{
    const auto basis = shBasis(n);
    const float band[9] = {kPi, 2.0f * kPi / 3.0f, 2.0f * kPi / 3.0f, 2.0f * kPi / 3.0f, kPi / 4.0f, kPi / 4.0f, kPi / 4.0f, kPi / 4.0f, kPi / 4.0f};
    glm::vec3 e(0.0f);
    for (int i = 0; i < 9; ++i) e += sh[size_t(i)] * (band[i] * basis[size_t(i)]);
    return glm::max(e, glm::vec3(0.0f));
}

} // namespace specula::render
