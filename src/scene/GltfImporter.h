#pragma once
#include <filesystem>
#include <vector>

#include "scene/LoadOptions.h"
#include "scene/Scene.h"

namespace specula::scene {

/// Imports a glTF 2.0 file (.gltf with external or embedded buffers, or .glb).
/// Throws specula::Error with a one-line message naming the file and the problem.
/// A missing or undecodable image is a warning (Scene::warnings); the image is left empty
/// (width 0) and the renderer substitutes a neutral texture.
/// `options` says which other files its URIs may name and what it may allocate
/// (scene/LoadOptions.h); a refusal is an Error naming the URI or the limit and its flag.
Scene loadGltf(const std::filesystem::path& path, const LoadOptions& options = {});
/// The same from the file's bytes; `path` names it in messages and its directory is where its
/// URIs resolve (the fuzzers read this way).
Scene loadGltfFromMemory(const std::vector<unsigned char>& bytes, const std::filesystem::path& path,
                         const LoadOptions& options = {});

} // namespace specula::scene
