// The sun as a light (shading/SunExtraction): found where it is, with the illuminance it
// delivers, and the map less the sun plus the light lighting like the map did.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <glm/gtc/constants.hpp>

#include "shading/EnvironmentMap.h"
#include "shading/SunExtraction.h"

using namespace specula::render;

namespace {

float luminance(const glm::vec3& c)
{
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

double angleDegrees(const glm::vec3& a, const glm::vec3& b)
{
    return glm::degrees(std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0)));
}

// The brute-force irradiance of the map less its sun plus the sun as a directional light,
// against the original map's, at the 6 axes, the sun's direction and 45° off it: the largest
// relative difference (luminance).
double worstIrradianceChange(const EnvironmentMap& original, const EnvironmentMap& extracted, const ExtractedSun& sun)
{
    std::vector<glm::vec3> normals = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, sun.direction};
    const glm::vec3 side = glm::normalize(glm::cross(sun.direction, std::abs(sun.direction.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    normals.push_back(glm::normalize(sun.direction + side));
    double worst = 0.0;
    for (const glm::vec3& n : normals) {
        const float before = luminance(bruteForceIrradiance(original, n));
        const float after = luminance(bruteForceIrradiance(extracted, n) + sun.illuminance * std::max(glm::dot(n, sun.direction), 0.0f));
        worst = std::max(worst, std::abs(double(after - before)) / std::max(double(before), 1e-9));
    }
    return worst;
}

} // namespace

TEST(SunExtraction, FindsTheProceduralSkysSunWithItsIlluminanceAndSize)
{
    // The procedural sky's sun: a disc of angular radius 1.5° whose radiance delivers 6 lux ×
    // (1, 0.95, 0.88) at normal incidence, above a sky that glows around it. Bounds: direction
    // within 0.5°, luminance within 3 % (the disc drawn on 512 × 256 texels), diameter within 15 %.
    const SkyParams params;
    EnvironmentMap map = proceduralSky(params, 512);
    const EnvironmentMap original = map;
    const auto sun = extractSun(map);
    ASSERT_TRUE(sun.has_value());
    EXPECT_LT(angleDegrees(sun->direction, params.sunDirection), 0.5);
    const float expected = params.sunIlluminance * luminance(glm::vec3(1.0f, 0.95f, 0.88f));
    EXPECT_NEAR(luminance(sun->illuminance), expected, 0.03f * expected);
    EXPECT_NEAR(sun->angularDiameter, 2.0f * params.sunAngularRadius, 0.15f * 2.0f * params.sunAngularRadius);
    EXPECT_LT(worstIrradianceChange(original, map, *sun), 0.01);
    EXPECT_NE(map.key, original.key); // the bake cache tells them apart
}

TEST(SunExtraction, RealSunsKeepTheMapsIrradianceAndDirection)
{
    // park_1k and sky_1k hold real suns, park_1k's beyond half-float range (peak ~2·10⁵):
    // the light's direction within 0.5° of the brightest texel's, the map less the sun plus
    // the light within 1 % of the map's brute-force irradiance at 8 normals, and what is left
    // in the map fits half floats.
    for (const char* name : {"park_1k.hdr", "sky_1k.hdr"}) {
        SCOPED_TRACE(name);
        const std::string file = std::string(SPECULA_ASSETS_DIR) + "/env/" + name;
        ASSERT_TRUE(std::filesystem::exists(file)) << "shared assets missing";
        EnvironmentMap map = loadEnvironmentMap(file);
        const EnvironmentMap original = map;
        size_t peak = 0;
        for (size_t i = 0; i < map.texels.size(); ++i)
            if (luminance(map.texels[i]) > luminance(map.texels[peak])) peak = i;
        const glm::vec3 peakDirection =
            equirectToDirection({(float(peak % size_t(map.width)) + 0.5f) / float(map.width), (float(peak / size_t(map.width)) + 0.5f) / float(map.height)});
        const auto sun = extractSun(map);
        ASSERT_TRUE(sun.has_value());
        std::printf("%s: sun %d texels, %.1f lux, diameter %.2f deg, %.2f deg from the peak texel, peak left %.0f\n", name,
                    sun->texels, luminance(sun->illuminance), glm::degrees(sun->angularDiameter),
                    angleDegrees(sun->direction, peakDirection), [&] {
                        float m = 0.0f;
                        for (const glm::vec3& t : map.texels) m = std::max(m, std::max(t.x, std::max(t.y, t.z)));
                        return m;
                    }());
        EXPECT_LT(angleDegrees(sun->direction, peakDirection), 0.5);
        EXPECT_LT(worstIrradianceChange(original, map, *sun), 0.01);
        for (const glm::vec3& t : map.texels) ASSERT_LT(std::max(t.x, std::max(t.y, t.z)), 65504.0f);
    }
}

TEST(SunExtraction, TheSkyStillShowsTheSun)
{
    // What extraction takes out of the texels lighting reads, the sky keeps (skyOnly): skyOf
    // gives back the map as loaded, texel for texel, and so does a downscaled copy (the
    // downscale of the map as loaded). Fails if extraction forgets what it took or the
    // downscale drops it.
    const SkyParams params;
    const EnvironmentMap original = proceduralSky(params, 512);
    EnvironmentMap map = original;
    ASSERT_TRUE(extractSun(map).has_value());
    ASSERT_FALSE(map.skyOnly.empty());
    EXPECT_TRUE(original.skyOnly.empty());
    EXPECT_FALSE(map.texels == original.texels);
    const EnvironmentMap sky = skyOf(map);
    EXPECT_TRUE(sky.texels == original.texels);
    EXPECT_TRUE(sky.skyOnly.empty());
    const EnvironmentMap small = downscaledToFit(map, 128), smallOriginal = downscaledToFit(original, 128);
    ASSERT_EQ(small.width, 128);
    EXPECT_FALSE(small.skyOnly.empty());
    EXPECT_FALSE(small.texels == smallOriginal.texels);
    EXPECT_TRUE(skyOf(small).texels == smallOriginal.texels);
    // restoreSun undoes the extraction: the texels, the key (the bake cache's entry) and no sun.
    restoreSun(map);
    EXPECT_TRUE(map.texels == original.texels);
    EXPECT_EQ(map.key, original.key);
    EXPECT_FALSE(map.sun.has_value());
    EXPECT_TRUE(map.skyOnly.empty());
}

TEST(SunExtraction, MapsWithoutASunAreLeftAlone)
{
    // A constant environment has no peak; a studio's softboxes are bright but large.
    EnvironmentMap constant = constantEnvironment(glm::vec3(1.0f));
    EXPECT_FALSE(extractSun(constant).has_value());
    const std::string file = std::string(SPECULA_ASSETS_DIR) + "/env/studio_1k.hdr";
    ASSERT_TRUE(std::filesystem::exists(file)) << "shared assets missing";
    EnvironmentMap studio = loadEnvironmentMap(file);
    const std::string key = studio.key;
    EXPECT_FALSE(extractSun(studio).has_value());
    EXPECT_EQ(studio.key, key);
}
