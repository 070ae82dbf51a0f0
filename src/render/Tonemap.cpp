#include "render/Tonemap.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace specula::render {

std::optional<Tonemap> parseTonemap(std::string_view name)
{
    if (name == "none") return Tonemap::None;
    if (name == "reinhard") return Tonemap::Reinhard;
    if (name == "reinhard-ext") return Tonemap::ReinhardExtended;
    if (name == "aces") return Tonemap::Aces;
    if (name == "neutral") return Tonemap::Neutral;
    return std::nullopt;
}

const char* tonemapName(Tonemap tonemap)
{
    switch (tonemap) {
    case Tonemap::None: return "none";
    case Tonemap::Reinhard: return "reinhard";
    case Tonemap::ReinhardExtended: return "reinhard-ext";
    case Tonemap::Aces: return "aces";
    case Tonemap::Neutral: return "neutral";
    }
    return "none";
}

glm::vec3 applyTonemap(Tonemap tonemap, glm::vec3 c, float whitePoint)
{
    c = glm::max(c, glm::vec3(0.0f));
    switch (tonemap) {
    case Tonemap::None: return c;
    case Tonemap::Reinhard: return c / (1.0f + c);
    case Tonemap::ReinhardExtended: {
        const float l = glm::dot(c, glm::vec3(0.2126f, 0.7152f, 0.0722f));
        if (l <= 0.0f) return glm::vec3(0.0f);
        const float mapped = l * (1.0f + l / (whitePoint * whitePoint)) / (1.0f + l);
        return c * (mapped / l);
    }
    case Tonemap::Aces: {
        const glm::mat3 in(0.59719f, 0.07600f, 0.02840f, 0.35458f, 0.90834f, 0.13383f, 0.04823f, 0.01566f, 0.83777f);
        const glm::mat3 out(1.60475f, -0.10208f, -0.00327f, -0.53108f, 1.10813f, -0.07276f, -0.07367f, -0.00605f,
                            1.07602f);
        glm::vec3 v = in * c;
        const glm::vec3 a = v * (v + 0.0245786f) - 0.000090537f;
        const glm::vec3 b = v * (0.983729f * v + 0.4329510f) + 0.238081f;
        return glm::clamp(out * (a / b), 0.0f, 1.0f);
    }
    case Tonemap::Neutral: {
        const float startCompression = 0.8f - 0.04f;
        const float desaturation = 0.15f;
        const float x = std::min({c.x, c.y, c.z});
        const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
        c -= offset;
        const float peak = std::max({c.x, c.y, c.z});
        if (peak < startCompression) return c;
        const float d = 1.0f - startCompression;
        const float newPeak = 1.0f - d * d / (peak + d - startCompression);
        c *= newPeak / peak;
        const float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
        return glm::mix(c, glm::vec3(newPeak), g);
    }
    }
    return c;
}

float linearToSrgb(float c)
{
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float c)
{
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

} // namespace specula::render
