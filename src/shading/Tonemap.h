#pragma once
// Tone mappers: names, parsing, and a CPU port of shaders/post/tonemap.glsl for tests.
#include <optional>
#include <string_view>

#include <glm/vec3.hpp>

namespace specula::render {

enum class Tonemap { None, Reinhard, ReinhardExtended, Aces, Neutral, Agx };

std::optional<Tonemap> parseTonemap(std::string_view name);
const char* tonemapName(Tonemap tonemap);

/// The shader's operator on exposed linear RGB (result not yet sRGB encoded).
glm::vec3 applyTonemap(Tonemap tonemap, glm::vec3 color, float whitePoint = 4.0f);
/// IEC 61966-2-1 sRGB encoding of a value in [0, 1].
float linearToSrgb(float c);
float srgbToLinear(float c);

} // namespace specula::render
