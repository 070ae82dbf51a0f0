#pragma once
// The built-in scenes by name, as documents: each carries its own look (tone mapper, BRDF,
// ambient, environment, light rig) as data, so that nothing above the scene layer asks which
// scene it is.
#include <optional>
#include <string_view>

#include "scene/SceneFile.h"

namespace specula::scene {

/// "demo" (also the empty name), "learnopengl", "learnopengl-ibl" or "doom"; nullopt for any
/// other name (a file, then).
std::optional<SceneDocument> builtinScene(std::string_view name);

} // namespace specula::scene
