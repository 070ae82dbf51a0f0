#pragma once
// The setup every app shares before its first frame: which scene, which settings, which
// environment, which view. A layer above render (it composes render's types) and below the
// apps, which only parse arguments into FrameOptions and draw their UI.
#include <filesystem>
#include <optional>
#include <string>

#include "render/Renderer.h"
#include "scene/SceneFile.h"
#include "settings/PassSettings.h"

namespace specula::setup {

/// What the user asks of every frame, over the scene document; unset options come from the
/// scene file, then from the defaults. The apps fill it from the command line, so errors name
/// each option by its flag (--msaa).
struct FrameOptions {
    std::optional<int> width, height, msaa;
    std::optional<float> exposure;
    std::optional<std::string> tonemap;
    std::optional<std::string> brdfG;
    // Material system: --brdf-d, --brdf-f, --brdf-diffuse, --shading override every material;
    // --debug-view shows one buffer instead of the frame.
    std::optional<std::string> brdfD, brdfF, brdfDiffuse, shading, debugView;
    int camera = -1;
    bool allCameras = false; ///< --camera all (render only: one image per camera)
    bool noDefaultLights = false;
    // Environment: --env FILE|sky|none, --env-color R,G,B, --env-intensity, --env-rotation,
    // --skybox on|off|blur=R, --bake-preset default|reference, --no-cache.
    std::optional<std::string> env;
    std::optional<std::string> envColor;
    std::optional<float> envIntensity;
    std::optional<float> envRotation;
    std::optional<std::string> skybox;
    std::optional<std::string> envSun; ///< extract | keep (--env-sun), over the scene file's
    std::optional<std::string> ibl; ///< split-sum | importance (--ibl), over the scene file's
    std::string bakePreset = "default";
    bool noCache = false;
    std::optional<std::string> energyCompensation; ///< on (default) | off
    bool gizmos = false;
    /// The post-processing passes' flags (--bloom, --bloom-intensity, ...: the passes' tables);
    /// resolveSettings checks each value against its table's range.
    PostOverrides post;
    std::optional<float> ev100; ///< physical camera exposure (--ev100)
    std::optional<std::string> shadowQuality; ///< low | medium | high (--shadow-quality)
    std::optional<std::string> shadowFilter;  ///< hard | pcf | pcss (--shadow-filter)
    /// Which files a scene may name and what it may allocate (--allow-external-files,
    /// --max-buffer-bytes, --max-accessor-count, --max-image-size, --max-texture-memory).
    scene::LoadOptions load;
    std::optional<std::string> lightCulling;  ///< clustered | none (--light-culling)
    std::optional<float> lightCutoff;         ///< --light-cutoff
    std::optional<float> lodPixels;           ///< --lod-error
    std::optional<std::string> transparency;  ///< sorted | oit (--transparency)
    std::optional<int> lights;                ///< the many-lights scene's count (--lights)
    std::optional<float> time;                ///< seconds into the animation (--time)
    std::optional<std::string> animation;     ///< its name or index, or none (--animation)
    std::optional<std::string> variant;       ///< KHR_materials_variants: its name or index, or none (--variant)
};

/// The pose a frame shows: animation `index` of the scene (-1: none, the rest pose) at `seconds`.
struct AnimationChoice {
    int index = -1;
    float seconds = 0.0f;
};
/// --animation NAME|INDEX|none and --time SECONDS over the scene: by default the scene's first
/// animation, at 0 s. Throws Error naming the flag: a negative time, an animation the scene
/// does not have (listing those it has). --time on a scene without animations is a warning.
AnimationChoice resolveAnimation(const scene::Scene& scene, const FrameOptions& options);
/// --variant NAME|INDEX|none over the scene's KHR_materials_variants: the variant's index, or
/// -1 (none: the materials the primitives name, the default). Throws Error naming the flag for
/// a variant the scene does not have (listing those it has).
int resolveVariant(const scene::Scene& scene, const FrameOptions& options);

/// `name` is a .gltf/.glb/.json path, or a built-in scene (scene/BuiltinScenes.h); empty = demo.
/// `lights`: the many-lights scene's count.
scene::SceneDocument loadSceneOrBuiltin(const std::string& name, const scene::LoadOptions& options = {},
                                        std::optional<int> lights = std::nullopt);

/// Settings from the scene document overridden by the options. Throws Error on bad values.
render::FrameSettings resolveSettings(const scene::SceneDocument& document, const FrameOptions& options);

/// The environment the frame asks for: none, or a map (file, constant colour, procedural sky).
/// Options over scene file; with neither, the procedural sky unless the document says it wants
/// none (EnvironmentSettings::skyByDefault). With --env-sun extract (or the scene file's
/// "sun": "extract"), a sun found in the map is taken out of it and added to `document` as a
/// directional light (shading/SunExtraction.h) of the environment's intensity and rotation.
/// Throws Error for bad files or values.
std::optional<render::EnvironmentMap> loadEnvironment(scene::SceneDocument& document, const FrameOptions& options);
/// --env-sun (or the scene file's "sun"): whether the map's sun becomes a light. Throws Error
/// for a word other than extract or keep.
bool extractsSun(const scene::SceneDocument& document, const FrameOptions& options);
bool extractsSun(const std::string& mode);
/// The name of the light that stands for an environment's sun.
inline constexpr const char* kEnvironmentSunName = "environment sun";
/// The directional light that stands for `sun` (an extracted sun, EnvironmentMap::sun) under
/// the environment turned by `rotationDegrees` and scaled by `intensity`: it follows both.
render::PlacedLight environmentSunLight(const render::ExtractedSun& sun, float rotationDegrees, float intensity);
/// Takes `map`'s sun out (render::extractSun) and logs what it found; returns its light under
/// that rotation and intensity (environmentSunLight), or nothing, `map` untouched, when it has none.
std::optional<render::PlacedLight> extractEnvironmentSun(render::EnvironmentMap& map, float rotationDegrees, float intensity);
/// Bake settings and cache directory for the frame (--bake-preset, --no-cache).
render::BakeSettings resolveBakeSettings(const FrameOptions& options);
std::filesystem::path cacheDirectory(const FrameOptions& options);

/// The image size for the scene camera the frame is seen through (`options.camera`, or the
/// first camera where none is chosen and the scene has one): a perspective camera's
/// aspectRatio (glTF's, or a scene file's) gives the width for the height when neither the
/// command line nor the scene file gives a size (the height then 720), the height for a width
/// given alone, and the width for a height given alone; a size given whole, or a camera without
/// an aspect ratio, leaves `settings` as they are. The result is held to the size limits.
void fitSizeToCamera(render::FrameSettings& settings, const scene::SceneDocument& document, const FrameOptions& options);

/// The view for the frame; adds the default light rig to `document` when it has no lights,
/// no environment, and the user did not forbid it. Returns the number of default lights added via `added`.
/// A scene camera is where `animation` puts it (its node, and KHR_animation_pointer's properties).
render::View prepareView(scene::SceneDocument& document, const FrameOptions& options,
                         const render::FrameSettings& settings, int* added = nullptr, bool hasEnvironment = false,
                         const AnimationChoice& animation = {});

} // namespace specula::setup
