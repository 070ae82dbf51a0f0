#include "shading/EnvironmentMap.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include "core/Error.h"
#include "core/Footprint.h"
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

EnvironmentMap downscaledToFit(const EnvironmentMap& map, int maxSize)
{
    if (map.width <= maxSize && map.height <= maxSize) return map;
    const double scale = double(maxSize) / double(std::max(map.width, map.height));
    EnvironmentMap out;
    out.width = std::clamp(int(map.width * scale), 1, maxSize);
    out.height = std::clamp(int(map.height * scale), 1, maxSize);
    out.key = fmt::format("{}-fit{}x{}", map.key, out.width, out.height);
    out.texels.resize(size_t(out.width) * size_t(out.height));
    for (int y = 0; y < out.height; ++y) {
        const auto [y0, y1] = footprint(y, out.height, map.height);
        for (int x = 0; x < out.width; ++x) {
            const auto [x0, x1] = footprint(x, out.width, map.width);
            glm::dvec3 sum(0.0);
            for (int sy = y0; sy < y1; ++sy)
                for (int sx = x0; sx < x1; ++sx) sum += glm::dvec3(map.at(sx, sy));
            out.texels[size_t(y) * size_t(out.width) + size_t(x)] = glm::vec3(sum / double(int64_t(y1 - y0) * (x1 - x0)));
        }
    }
    out.sun = map.sun;
    if (!map.skyOnly.empty()) {
        // The sky's texels downscaled the same way: those that differ from the lighting's.
        const EnvironmentMap sky = downscaledToFit(skyOf(map), maxSize);
        for (size_t i = 0; i < out.texels.size(); ++i)
            if (sky.texels[i] != out.texels[i]) out.skyOnly.push_back({i, sky.texels[i]});
    }
    return out;
}

EnvironmentMap skyOf(const EnvironmentMap& map)
{
    EnvironmentMap sky = map;
    for (const EnvironmentMap::SkyTexel& t : map.skyOnly) sky.texels[t.index] = t.radiance;
    sky.skyOnly.clear();
    sky.sun.reset();
    return sky;
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
    // equirectToDirection's sines and cosines, a column's and a row's once each (a 1600 x 800
    // map: 3x faster, the same directions).
    std::vector<float> sinPhi(size_t(map.width)), cosPhi(size_t(map.width));
    for (int x = 0; x < map.width; ++x) {
        const float phi = ((float(x) + 0.5f) / float(map.width) - 0.5f) * 2.0f * kPi;
        sinPhi[size_t(x)] = std::sin(phi);
        cosPhi[size_t(x)] = std::cos(phi);
    }
    for (int y = 0; y < map.height; ++y) {
        const float theta0 = kPi * float(y) / float(map.height), theta1 = kPi * float(y + 1) / float(map.height);
        const float solidAngle = (std::cos(theta0) - std::cos(theta1)) * dPhi;
        const float theta = (float(y) + 0.5f) / float(map.height) * kPi;
        const float sinTheta = std::sin(theta), cosTheta = std::cos(theta);
        for (int x = 0; x < map.width; ++x) {
            const glm::vec3 d{sinTheta * sinPhi[size_t(x)], cosTheta, -sinTheta * cosPhi[size_t(x)]};
            const auto basis = shBasis(d);
            const glm::vec3 radiance = map.at(x, y) * solidAngle;
            for (int i = 0; i < 9; ++i) sh[size_t(i)] += radiance * basis[size_t(i)];
        }
    }
    return sh;
}

glm::vec3 bruteForceIrradiance(const EnvironmentMap& map, const glm::vec3& n)
{
    glm::dvec3 e(0.0);
    const double dPhi = 2.0 * kPi / double(map.width);
    for (int y = 0; y < map.height; ++y) {
        const double theta0 = kPi * double(y) / double(map.height), theta1 = kPi * double(y + 1) / double(map.height);
        const double solidAngle = (std::cos(theta0) - std::cos(theta1)) * dPhi;
        for (int x = 0; x < map.width; ++x) {
            const glm::vec3 d = equirectToDirection({(float(x) + 0.5f) / float(map.width), (float(y) + 0.5f) / float(map.height)});
            const double cosine = glm::dot(n, d);
            if (cosine > 0.0) e += glm::dvec3(map.at(x, y)) * (cosine * solidAngle);
        }
    }
    return glm::vec3(e);
}

glm::vec3 cubeDirection(int face, const glm::vec2& st)
{
    const glm::vec2 uv = st * 2.0f - 1.0f;
    glm::vec3 d;
    switch (face) {
    case 0: d = {1.0f, -uv.y, -uv.x}; break;
    case 1: d = {-1.0f, -uv.y, uv.x}; break;
    case 2: d = {uv.x, 1.0f, uv.y}; break;
    case 3: d = {uv.x, -1.0f, -uv.y}; break;
    case 4: d = {uv.x, -uv.y, 1.0f}; break;
    default: d = {-uv.x, -uv.y, -1.0f}; break;
    }
    return glm::normalize(d);
}

namespace {

// A source's spread (IrradianceSource::spread) from its texels' directions summed with weights
// (`centroid`) that sum to `weight`: ⟨θ²⟩ ≈ |d − ĉ|² = 2 (1 − d·ĉ) averaged, which is
// 2 (1 − |centroid| / weight).
float spreadOf(const glm::dvec3& centroid, double weight)
{
    if (weight <= 0.0) return 0.0f;
    const double moment = std::max(2.0 * (1.0 - glm::length(centroid) / weight), 0.0);
    return float(std::sqrt(1.5 * moment));
}

} // namespace

std::vector<IrradianceSource> irradianceSources(const EnvironmentMap& map, int sourceWidth)
{
    const int step = std::max(1, map.width / std::max(sourceWidth, 1));
    const int width = (map.width + step - 1) / step, height = (map.height + step - 1) / step;
    std::vector<IrradianceSource> sources;
    sources.reserve(size_t(width) * size_t(height));
    const double dPhi = 2.0 * kPi / double(map.width);
    for (int by = 0; by < height; ++by)
        for (int bx = 0; bx < width; ++bx) {
            glm::dvec3 flux(0.0), centroid(0.0), plain(0.0);
            double weight = 0.0;
            for (int y = by * step; y < (by + 1) * step && y < map.height; ++y) {
                const double theta0 = kPi * double(y) / double(map.height), theta1 = kPi * double(y + 1) / double(map.height);
                const double solidAngle = (std::cos(theta0) - std::cos(theta1)) * dPhi;
                for (int x = bx * step; x < (bx + 1) * step && x < map.width; ++x) {
                    const glm::dvec3 d(
                        equirectToDirection({(float(x) + 0.5f) / float(map.width), (float(y) + 0.5f) / float(map.height)}));
                    const glm::dvec3 l = glm::dvec3(map.at(x, y)) * solidAngle;
                    flux += l;
                    centroid += d * (l.x + l.y + l.z);
                    weight += l.x + l.y + l.z;
                    plain += d * solidAngle;
                }
            }
            const glm::dvec3 c = glm::length(centroid) > 0.0 ? centroid : plain;
            sources.push_back({glm::vec3(glm::normalize(c)), glm::vec3(flux), spreadOf(centroid, weight)});
        }
    return sources;
}

float sourceCosine(float cosine, float spread)
{
    if (spread <= 0.0f) return std::max(cosine, 0.0f);
    if (cosine >= spread) return cosine;
    const float band = std::max(cosine + spread, 0.0f);
    return band * band / (4.0f * spread);
}

glm::vec3 irradianceAt(const std::vector<IrradianceSource>& sources, const glm::vec3& n)
{
    glm::vec3 e(0.0f);
    for (const IrradianceSource& src : sources) e += src.flux * sourceCosine(glm::dot(n, src.direction), src.spread);
    return e;
}

IrradianceSplit splitIrradiance(const EnvironmentMap& map, int brightCount, int brightWidth, int cubeWidth)
{
    const std::vector<IrradianceSource> fine = irradianceSources(map, brightWidth);
    const int step = std::max(1, map.width / std::max(brightWidth, 1));
    const int width = (map.width + step - 1) / step, height = (map.height + step - 1) / step;
    // The brightest fine sources, by index.
    std::vector<size_t> order(fine.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    const auto luminance = [&](size_t i) { return glm::dot(fine[i].flux, glm::vec3(0.2126f, 0.7152f, 0.0722f)); };
    const size_t n = std::min(order.size(), size_t(std::max(brightCount, 0)));
    std::partial_sort(order.begin(), order.begin() + ptrdiff_t(n), order.end(),
                      [&](size_t a, size_t b) { return luminance(a) > luminance(b) || (luminance(a) == luminance(b) && a < b); });
    IrradianceSplit split;
    std::vector<bool> taken(fine.size(), false);
    split.blockSize = step;
    for (size_t k = 0; k < n; ++k) {
        split.bright.push_back(fine[order[k]]);
        split.brightBlocks.emplace_back(int(order[k] % size_t(width)) * step, int(order[k] / size_t(width)) * step);
        taken[order[k]] = true;
    }
    // The rest merged into coarser blocks: flux summed, directions by flux-weighted centroid.
    const int merge = std::max(1, width / std::max(cubeWidth, 1));
    for (int by = 0; by < height; by += merge)
        for (int bx = 0; bx < width; bx += merge) {
            glm::dvec3 flux(0.0), centroid(0.0), plain(0.0);
            for (int y = by; y < by + merge && y < height; ++y)
                for (int x = bx; x < bx + merge && x < width; ++x) {
                    const size_t i = size_t(y) * size_t(width) + size_t(x);
                    plain += glm::dvec3(fine[i].direction);
                    if (taken[i]) continue;
                    const glm::dvec3 f(fine[i].flux);
                    flux += f;
                    centroid += glm::dvec3(fine[i].direction) * (f.x + f.y + f.z);
                }
            const glm::dvec3 c = glm::length(centroid) > 0.0 ? centroid : plain;
            // Points (spread 0): the cube's bilinear filter already spreads them over a texel, and
            // with their own spread as well the cube was further from brute force (bridge_1k
            // 1.0 % against 0.5 %: Environment.IrradianceMatchesBruteForceOnEveryHdr).
            split.cube.push_back({glm::vec3(glm::normalize(c)), glm::vec3(flux)});
        }
    return split;
}

size_t foldSmoothSources(IrradianceSplit& split, size_t keepAtLeast, int cubeSize, float tolerance)
{
    const size_t count = split.bright.size();
    keepAtLeast = std::min(keepAtLeast, count);
    if (keepAtLeast == count || cubeSize < 2) return count;
    // Test places: the middle between four texel centres, where a bilinear filter strays most
    // from a function with a kink, in every other cell of each face. Each keeps its corners'
    // and its middle's irradiance from the sources folded so far, and its scale per channel:
    // max(E(middle), 5 % of the mean irradiance) of the whole map.
    struct Place {
        std::array<glm::vec3, 4> cornerDirection;
        glm::vec3 middleDirection;
        std::array<glm::vec3, 4> corner{};
        glm::vec3 middle{0.0f};
        glm::vec3 scale{0.0f};
    };
    std::vector<IrradianceSource> all = split.cube;
    all.insert(all.end(), split.bright.begin(), split.bright.end());
    glm::dvec3 flux(0.0);
    for (const IrradianceSource& s : all) flux += glm::dvec3(s.flux);
    const glm::vec3 floor = glm::vec3(0.05 * flux / 4.0); // the mean over the sphere of E(n) is flux / 4
    const float size = float(cubeSize);
    std::vector<Place> places;
    for (int face = 0; face < 6; ++face)
        for (int t = 0; t + 1 < cubeSize; t += 2)
            for (int s = 0; s + 1 < cubeSize; s += 2) {
                Place place;
                for (int c = 0; c < 4; ++c)
                    place.cornerDirection[size_t(c)] =
                        cubeDirection(face, {(float(s + (c & 1)) + 0.5f) / size, (float(t + (c >> 1)) + 0.5f) / size});
                place.middleDirection = cubeDirection(face, {(float(s) + 1.0f) / size, (float(t) + 1.0f) / size});
                place.scale = glm::max(irradianceAt(all, place.middleDirection), floor);
                places.push_back(place);
            }
    // Fold from the faintest up while every place stays within the tolerance.
    size_t keep = count;
    while (keep > keepAtLeast) {
        const IrradianceSource& source = split.bright[keep - 1];
        float worst = 0.0f;
        for (Place& place : places) {
            glm::vec3 filtered(0.0f);
            for (size_t c = 0; c < 4; ++c) {
                place.corner[c] += source.flux * sourceCosine(glm::dot(place.cornerDirection[c], source.direction), source.spread);
                filtered += 0.25f * place.corner[c];
            }
            place.middle += source.flux * sourceCosine(glm::dot(place.middleDirection, source.direction), source.spread);
            const glm::vec3 error = glm::abs(filtered - place.middle) / place.scale;
            worst = std::max({worst, error.x, error.y, error.z});
        }
        if (worst > tolerance) break;
        --keep;
    }
    for (size_t k = keep; k < count; ++k) split.cube.push_back(split.bright[k]);
    split.bright.resize(keep);
    split.brightBlocks.resize(std::min(split.brightBlocks.size(), keep));
    return keep;
}

EnvironmentMap withoutBrightSources(const EnvironmentMap& map, const IrradianceSplit& split, int count)
{
    EnvironmentMap rest = map;
    const size_t n = count < 0 ? split.brightBlocks.size() : std::min(split.brightBlocks.size(), size_t(count));
    for (size_t k = 0; k < n; ++k) {
        const glm::ivec2 block = split.brightBlocks[k];
        for (int y = block.y; y < std::min(block.y + split.blockSize, map.height); ++y)
            for (int x = block.x; x < std::min(block.x + split.blockSize, map.width); ++x)
                rest.texels[size_t(y) * size_t(map.width) + size_t(x)] = glm::vec3(0.0f);
    }
    rest.key = map.key + "-without-bright-" + std::to_string(n);
    return rest;
}

float brightFluxShare(const IrradianceSplit& split, int count)
{
    const glm::dvec3 weights(0.2126, 0.7152, 0.0722);
    const size_t n = count < 0 ? split.bright.size() : std::min(split.bright.size(), size_t(count));
    double part = 0.0, total = 0.0;
    for (size_t k = 0; k < split.bright.size(); ++k) {
        const double flux = glm::dot(glm::dvec3(split.bright[k].flux), weights);
        total += flux;
        if (k < n) part += flux;
    }
    for (const IrradianceSource& s : split.cube) total += glm::dot(glm::dvec3(s.flux), weights);
    return total > 0.0 ? float(part / total) : 0.0f;
}

int leadingSourceCount(const std::vector<IrradianceSource>& bright, float fraction)
{
    const glm::vec3 weights(0.2126f, 0.7152f, 0.0722f);
    double total = 0.0;
    for (const IrradianceSource& s : bright) total += glm::dot(s.flux, weights);
    double running = 0.0;
    for (size_t k = 0; k < bright.size(); ++k) {
        running += glm::dot(bright[k].flux, weights);
        if (running >= double(fraction) * total) return int(k + 1);
    }
    return int(bright.size());
}

std::vector<glm::vec3> irradianceCube(const std::vector<IrradianceSource>& sources, int size)
{
    std::vector<glm::vec3> out(size_t(6) * size_t(size) * size_t(size));
    for (int face = 0; face < 6; ++face)
        for (int t = 0; t < size; ++t)
            for (int s = 0; s < size; ++s) {
                const glm::vec3 n = cubeDirection(face, {(float(s) + 0.5f) / float(size), (float(t) + 0.5f) / float(size)});
                out[(size_t(face) * size_t(size) + size_t(t)) * size_t(size) + size_t(s)] = irradianceAt(sources, n);
            }
    return out;
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
