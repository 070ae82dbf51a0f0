#include "shading/Tonemap.h"

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
    if (name == "agx") return Tonemap::Agx;
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
    case Tonemap::Agx: return "agx";
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
    case Tonemap::Agx: {
        // Minimal AgX (Wrensch 2023, after Sobotka): see shaders/post/tonemap.glsl.
        const glm::mat3 inset(0.842479062253094f, 0.0423282422610123f, 0.0423756549057051f, 0.0784335999999992f,
                              0.878468636469772f, 0.0784336f, 0.0792237451477643f, 0.0791661274605434f, 0.879142973793104f);
        const glm::mat3 outset(1.19687900512017f, -0.0528968517574562f, -0.0529716355144438f, -0.0980208811401368f,
                               1.15190312990417f, -0.0980434501171241f, -0.0990297440797205f, -0.0989611768448433f,
                               1.15107367264116f);
        const float minEv = -12.47393f, maxEv = 4.026069f;
        glm::vec3 x = glm::clamp(glm::log2(glm::max(inset * c, glm::vec3(1e-10f))), minEv, maxEv);
        x = (x - minEv) / (maxEv - minEv);
        const glm::vec3 x2 = x * x, x4 = x2 * x2;
        x = 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 + 0.1191f * x - 0.00232f;
        return glm::pow(glm::max(outset * x, glm::vec3(0.0f)), glm::vec3(2.2f));
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
