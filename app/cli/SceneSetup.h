#pragma once
// Glue shared by the commands: which scene, which settings, which view.
#include <optional>
#include <string>

#include "render/Renderer.h"
#include "scene/SceneFile.h"

namespace specula::cli {

/// Options every rendering command shares; unset ones come from the scene file, then defaults.
struct FrameOptions {
    std::optional<int> width, height, msaa;
    std::optional<float> exposure;
    std::optional<std::string> tonemap;
    std::optional<std::string> brdfG;
    int camera = -1;
    bool noDefaultLights = false;
};

/// `name` is a .gltf/.glb/.json path, or a built-in scene ("demo", "learnopengl"); empty = demo.
scene::SceneDocument loadSceneOrBuiltin(const std::string& name);

/// Settings from the scene document overridden by the command line. Throws Error on bad values.
render::FrameSettings resolveSettings(const scene::SceneDocument& document, const FrameOptions& options);

/// The view for the frame; adds the default light rig to `document` when it has no lights
/// and the user did not forbid it. Returns the number of default lights added via `added`.
render::View prepareView(scene::SceneDocument& document, const FrameOptions& options,
                         const render::FrameSettings& settings, int* added = nullptr);

} // namespace specula::cli
