#pragma once
// Loading scenes: glTF 2.0 (.gltf, .glb) and Specula's JSON scene files (.json).
// The JSON schema is documented in docs/scene-format.md.
#include <filesystem>
#include <optional>
#include <string>

#include "scene/LoadOptions.h"
#include "scene/Scene.h"
#include "settings/PassSettings.h"

namespace specula::scene {

/// Render settings a scene file may give; the command line overrides each one it sets.
struct RenderSettings {
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> msaa;
    std::optional<float> exposure;       ///< EV; the image is multiplied by 2^exposure
    std::optional<std::string> tonemap;  ///< none, reinhard, reinhard-ext, aces, neutral, agx
    std::optional<std::string> brdfG;    ///< smith-ggx (default) or schlick-ggx
    std::optional<std::string> shading;  ///< every material's shading model for the frame (as --shading)
    std::optional<bool> defaultLights;   ///< false = never add the default light rig
    std::optional<std::string> transparency; ///< sorted | oit: how blended surfaces are ordered (as --transparency)
    /// Physical camera exposure as EV100 ("render": {"ev100"}), or from the camera's
    /// aperture (f-number), shutter (seconds) and ISO ("camera": {...}); at most one of them.
    std::optional<float> ev100;
    struct CameraExposure {
        float aperture = 16.0f, shutter = 0.01f, iso = 100.0f;
    };
    std::optional<CameraExposure> cameraExposure;
    /// Constant ambient radiance for the diffuse lobe. No scene-file key: a built-in scene's
    /// (the LearnOpenGL lighting demo's 0.03 × albedo).
    std::optional<glm::vec3> ambient;
};

/// The environment a scene file asks for. Until image-based lighting exists only `color`
/// (the background radiance, cd/m²) is used.
struct EnvironmentSettings {
    std::optional<glm::vec3> color;
    std::string file;       ///< path resolved against the scene file's directory
    float intensity = 1.0f;
    float rotationDegrees = 0.0f;
    /// "ibl": how the specular lobe integrates the environment, "split-sum" or "importance"
    /// (render::IblSpecular); unset: the app's default.
    std::optional<std::string> ibl;
    /// "sun": "extract" takes the map's sun out as a directional light, "keep" (default) leaves it.
    std::optional<std::string> sun;
    /// With neither `file` nor `color`: the procedural sky, or (false) no environment. No
    /// scene-file key: built-in scenes without one (a lighting tutorial, an indoor level) say so.
    bool skyByDefault = true;
};

struct SceneDocument {
    Scene scene;
    RenderSettings render;
    EnvironmentSettings environment;
    /// Post-processing the file asks for ("post"); unset values come from the command line or
    /// the defaults (settings/PassSettings.h documents them).
    PostOverrides post;
    std::filesystem::path source;
};

/// Loads a .gltf/.glb (via loadGltf) or a .json scene file, by extension.
/// Throws specula::Error with a one-line message naming the file.
/// `options`: which files it may name, what it may allocate (scene/LoadOptions.h).
SceneDocument loadScene(const std::filesystem::path& path, const LoadOptions& options = {});
/// Loads a JSON scene file.
SceneDocument loadSceneFile(const std::filesystem::path& path, const LoadOptions& options = {});
/// A JSON scene file from its text; `path` names it in messages and its directory is where its
/// paths resolve (the fuzzers read this way).
SceneDocument loadSceneText(const std::string& text, const std::filesystem::path& path, const LoadOptions& options = {});

} // namespace specula::scene
