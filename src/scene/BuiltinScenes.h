#pragma once
// The built-in scenes by name, as documents: each carries its own look (tone mapper, BRDF,
// ambient, environment, light rig) as data, so that nothing above the scene layer asks which
// scene it is.
#include <optional>
#include <string_view>

#include "scene/SceneFile.h"

namespace specula::scene {

/// "demo" (also the empty name), "learnopengl", "learnopengl-ibl", "doom" or "many-lights"
/// (with `lights` point lights, 1,024 when unset); nullopt for any other name (a file, then).
std::optional<SceneDocument> builtinScene(std::string_view name, std::optional<int> lights = std::nullopt);

/// The many-lights scene's light count when none is asked for.
constexpr int kManyLightsDefault = 1024;

} // namespace specula::scene
