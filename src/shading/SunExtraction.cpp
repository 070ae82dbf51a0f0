#include "shading/SunExtraction.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include <glm/gtc/constants.hpp>

namespace specula::render {
namespace {

/// What extraction appends to the map's key (the bake cache keeps the two apart).
constexpr std::string_view kExtractedMark = ":sun-extracted";

float luminance(const glm::vec3& c)
{
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// Direction and exact solid angle of texel (x, y) of a w × h equirectangular map.
struct Texel {
    glm::dvec3 direction;
    double solidAngle;
};
Texel texel(int x, int y, int w, int h)
{
    const double pi = glm::pi<double>();
    const glm::vec2 uv((float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h));
    return {glm::dvec3(equirectToDirection(uv)), 2.0 * pi / w * (std::cos(pi * y / h) - std::cos(pi * (y + 1) / h))};
}

} // namespace

std::optional<ExtractedSun> extractSun(EnvironmentMap& map, const SunCriteria& criteria)
{
    if (map.sun) return map.sun; // taken out already
    const int w = map.width, h = map.height;
    if (w < 4 || h < 2) return std::nullopt;
    size_t peak = 0;
    for (size_t i = 1; i < map.texels.size(); ++i)
        if (luminance(map.texels[i]) > luminance(map.texels[peak])) peak = i;
    const float peakLuminance = luminance(map.texels[peak]);
    const int px = int(peak % size_t(w)), py = int(peak / size_t(w));
    const glm::dvec3 peakDirection = texel(px, py, w, h).direction;

    // The level around the peak: the median of an annulus 8–15° from it, and the mean colour
    // of its texels at or below that median (what the sun's texels are set to).
    std::vector<float> ring;
    glm::dvec3 fillSum(0.0);
    const double cosInner = std::cos(glm::radians(8.0)), cosOuter = std::cos(glm::radians(15.0));
    for (int pass = 0; pass < 2; ++pass) {
        const float median = pass == 1 ? ring[ring.size() / 2] : 0.0f;
        double count = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double c = glm::dot(texel(x, y, w, h).direction, peakDirection);
                if (c > cosInner || c < cosOuter) continue;
                const glm::vec3 value = map.at(x, y);
                if (pass == 0) {
                    ring.push_back(luminance(value));
                } else if (luminance(value) <= median) {
                    fillSum += glm::dvec3(value);
                    count += 1.0;
                }
            }
        if (pass == 0) {
            if (ring.empty()) return std::nullopt;
            std::nth_element(ring.begin(), ring.begin() + ptrdiff_t(ring.size() / 2), ring.end());
        } else if (count > 0.0) {
            fillSum /= count;
        }
    }
    const float background = std::max(ring[ring.size() / 2], 1e-6f);
    if (peakLuminance < criteria.contrast * background) return std::nullopt;
    const glm::vec3 fill(fillSum);

    // The region: 8-connected to the peak (wrapping in x), brighter than threshold × background.
    const float threshold = criteria.threshold * background;
    std::vector<uint8_t> inRegion(map.texels.size(), 0);
    std::vector<size_t> region{peak}, stack{peak};
    inRegion[peak] = 1;
    while (!stack.empty()) {
        const size_t i = stack.back();
        stack.pop_back();
        const int x = int(i % size_t(w)), y = int(i / size_t(w));
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int ny = y + dy;
                if (ny < 0 || ny >= h) continue;
                const int nx = ((x + dx) % w + w) % w;
                const size_t j = size_t(ny) * size_t(w) + size_t(nx);
                if (inRegion[j] || luminance(map.texels[j]) <= threshold) continue;
                inRegion[j] = 1;
                region.push_back(j);
                stack.push_back(j);
            }
    }

    // The excess over the fill level is the light: its flux, centroid and spread.
    glm::dvec3 illuminance(0.0), weightedDirection(0.0);
    double solidAngle = 0.0, weight = 0.0;
    for (size_t i : region) {
        const Texel t = texel(int(i % size_t(w)), int(i / size_t(w)), w, h);
        const glm::dvec3 excess = glm::max(glm::dvec3(map.texels[i]) - glm::dvec3(fill), glm::dvec3(0.0));
        illuminance += excess * t.solidAngle;
        const double l = double(luminance(glm::vec3(excess))) * t.solidAngle;
        weightedDirection += l * t.direction;
        weight += l;
        solidAngle += t.solidAngle;
    }
    if (weight <= 0.0) return std::nullopt;
    const glm::dvec3 direction = glm::normalize(weightedDirection);
    double secondMoment = 0.0;
    for (size_t i : region) {
        const Texel t = texel(int(i % size_t(w)), int(i / size_t(w)), w, h);
        const glm::dvec3 excess = glm::max(glm::dvec3(map.texels[i]) - glm::dvec3(fill), glm::dvec3(0.0));
        const double angle = std::acos(std::clamp(glm::dot(t.direction, direction), -1.0, 1.0));
        secondMoment += double(luminance(glm::vec3(excess))) * t.solidAngle * angle * angle;
    }
    secondMoment /= weight;

    // Compact: the region's whole solid angle within a disc of maxDiameterDegrees.
    const double maxRadius = glm::radians(double(criteria.maxDiameterDegrees)) / 2.0;
    if (solidAngle > 2.0 * glm::pi<double>() * (1.0 - std::cos(maxRadius))) return std::nullopt;
    // Significant: a fair share of the flux onto the plane facing the sun.
    double facing = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Texel t = texel(x, y, w, h);
            const double c = glm::dot(t.direction, direction);
            if (c > 0.0) facing += double(luminance(map.at(x, y))) * t.solidAngle * c;
        }
    if (double(luminance(glm::vec3(illuminance))) < criteria.minFraction * facing) return std::nullopt;

    for (size_t i : region) {
        const glm::vec3 lit = glm::min(map.texels[i], fill);
        if (lit != map.texels[i]) map.skyOnly.push_back({i, map.texels[i]}); // the sky still shows the sun
        map.texels[i] = lit;
    }
    ExtractedSun sun;
    sun.direction = glm::vec3(direction);
    sun.illuminance = glm::vec3(illuminance);
    sun.angularDiameter = float(2.0 * std::sqrt(2.0 * secondMoment));
    sun.texels = int(region.size());
    map.key += kExtractedMark;
    map.sun = sun;
    return sun;
}

void restoreSun(EnvironmentMap& map)
{
    if (!map.sun) return;
    for (const EnvironmentMap::SkyTexel& t : map.skyOnly) map.texels[t.index] = t.radiance;
    map.skyOnly.clear();
    map.sun.reset();
    if (map.key.size() >= kExtractedMark.size() && map.key.compare(map.key.size() - kExtractedMark.size(), kExtractedMark.size(), kExtractedMark) == 0)
        map.key.resize(map.key.size() - kExtractedMark.size());
}

} // namespace specula::render
