#pragma once
#include <filesystem>

#include "scene/Scene.h"

namespace specula::scene {

/// Imports a glTF 2.0 file (.gltf with external or embedded buffers, or .glb).
/// Throws specula::Error with a one-line message naming the file and the problem.
/// A missing or undecodable image is a warning (Scene::warnings); the texture is dropped.
Scene loadGltf(const std::filesystem::path& path);

} // namespace specula::scene
