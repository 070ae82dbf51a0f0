#pragma once
#include <filesystem>

#include "scene/Scene.h"

namespace specula::scene {

/// Imports a glTF 2.0 file (.gltf with external or embedded buffers, or .glb).
/// Throws specula::Error with a one-line message naming the file and the problem.
/// A missing or undecodable image is a warning (Scene::warnings); the image is left empty
/// (width 0) and the renderer substitutes a neutral texture.
Scene loadGltf(const std::filesystem::path& path);

} // namespace specula::scene
