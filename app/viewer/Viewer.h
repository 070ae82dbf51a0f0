#pragma once
// The viewer's state and the actions the UI, the keys and scripts share. Rendering is
// render::Renderer's; this class only decides what to render and with which settings.
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "OrbitCamera.h"
#include "ShaderWatcher.h"
#include "render/PlacedLight.h"
#include "setup/SceneSetup.h"
#include "render/Renderer.h"

namespace specula::gl {
class DebugMonitor;
}
namespace specula::platform {
class Context;
}

namespace specula::viewer {

/// Start-up costs, milliseconds.
struct StartupTimes {
    double context = 0.0;
    double sceneLoad = 0.0;
    double environmentBake = 0.0;
    double sceneUpload = 0.0;   ///< the scene's meshes and textures to the GPU (Renderer::setScene)
    double firstRender = 0.0;   ///< the first frame's render and present (programs compiled on first use)
    double firstFrame = 0.0; ///< since the process started
};

/// What the last edit of a light uploaded (to check that it touched only that light's bytes).
struct LightUpload {
    int light = -1;
    size_t offset = 0;     ///< Buffer::lastUpdate of the edit
    size_t size = 0;
    size_t bytes = 0;      ///< bytes uploaded by the whole edit
    size_t lightOffset = 0; ///< where light `light` lives in the buffer
    size_t lightSize = 0;
    bool onlyThatLight() const { return offset == lightOffset && size == lightSize && bytes == lightSize; }
};

/// The Animation panel's timeline: which animation, where in it, and whether it plays.
struct Timeline {
    int animation = -1;   ///< index into the scene's animations; -1: none (the rest pose)
    float time = 0.0f;    ///< seconds
    bool playing = true;
    float speed = 1.0f;   ///< seconds of animation per second of wall clock
    bool loop = true;     ///< past the end: from the start again (else it stops there)
};

class Viewer {
public:
    Viewer(platform::Context& context, const setup::FrameOptions& options);
    ~Viewer();

    // Files. A failed load throws specula::Error and leaves the current scene or environment.
    void loadScene(const std::string& name);
    /// A new environment: with the sun as a light (setSunExtraction), its sun is taken out and
    /// replaces the last environment's sun light.
    void loadEnvironment(const std::string& file);
    /// --env-sun extract|keep for the environment on screen and those loaded after it: its sun
    /// taken out of the map and added as the light named setup::kEnvironmentSunName, or put
    /// back (the light removed). That light follows the environment's rotation and intensity.
    void setSunExtraction(bool extract);
    bool sunExtraction() const { return mExtractSun; }
    /// Whether the environment on screen has a sun taken out (and so its light).
    bool environmentSunExtracted() const { return mEnvironment && mEnvironment->sun; }
    /// A dropped file: scene or environment by extension. Errors go to lastError().
    void openFile(const std::string& path);

    /// Renders one frame at the window's size and presents it (the UI draws on top).
    void renderFrame(float deltaSeconds);
    /// The rendered frame (no panels) as PNG.
    void screenshot(const std::filesystem::path& path);
    /// What the window shows, panels included: written at the end of the next frame, from the
    /// default framebuffer before the swap (captureWindow).
    void screenshotWindow(const std::filesystem::path& path) { mPendingWindowShot = path; }
    /// Called by the frame loop once the UI is drawn, before the swap: writes a pending
    /// screenshotWindow.
    void captureWindow();
    /// Rebuilds the renderer from the shader files; on a compile error keeps the old one.
    bool reloadShaders();
    /// Hot reload: reloads when a file under the shader directory changed since the last check
    /// (ShaderWatcher). Returns whether it reloaded (successfully or not).
    bool reloadChangedShaders();

    // Lights: add/remove rewrite the whole buffer, editing one light only its bytes.
    void addLight(scene::Light::Type type);
    /// Adds `count` coloured point lights of range 4 m scattered (deterministically) over a
    /// square around what the camera looks at, twice the camera's distance across.
    void scatterLights(int count);
    void removeLight(int index);
    void editLight(int index, const render::PlacedLight& light);
    const LightUpload& lastLightUpload() const { return mLastLightUpload; }

    // Materials: the renderer's registry (the scene's materials, glTF's default material last).
    // Edits go to the renderer and to the plain copy below, and survive a shader reload.
    void setMaterialModel(int material, scene::ShadingModel model);
    void setMaterialShading(int material, const scene::MaterialShading& shading);
    /// A blended material's blend mode (fade or transparent, docs/transparency.md).
    void setMaterialBlendMode(int material, scene::BlendMode mode);
    void setMaterialParameter(int material, render::MaterialParameter parameter, const glm::vec4& value);
    /// KHR_materials_ior: the dielectric F0 from the index of refraction (and the material's
    /// KHR_materials_specular colour).
    void setMaterialIor(int material, float ior);
    /// Material `index` as plain data, kept in step with the edits above: the scene's, or the
    /// default material for the registry's last index. Throws for an index out of range.
    scene::Material& material(int index);

    /// Selects the material of the surface under window pixel (x, y) (top left = 0, 0) in the
    /// last frame; returns it, or -1 when the ray meets nothing (selection unchanged).
    int pickMaterial(float x, float y);

    /// Selects the orbit camera (-1) or a scene camera.
    void useCamera(int index);
    void resetCamera();

    platform::Context& context() { return mContext; }
    render::Renderer& renderer() { return *mRenderer; }
    render::FrameSettings& settings() { return mSettings; }
    scene::SceneDocument& document() { return mDocument; }
    OrbitCamera& camera() { return mCamera; }
    int sceneCamera() const { return mSceneCamera; }
    const std::string& sceneName() const { return mSceneName; }
    const std::string& environmentName() const { return mEnvironmentName; }
    const StartupTimes& startup() const { return mStartup; }
    /// After a frame is shown: the environment's progressive bake (a preview renders until it
    /// is done) runs its next steps for as long as the frame took to render, 8 to 100 ms.
    void advanceEnvironmentBake();
    /// The rest of the progressive bake at once (before a screenshot); whether one was pending.
    bool finishEnvironmentBake();
    const render::BakeProgress& bakeProgress() const { return mBake; }
    void setContextTime(double ms) { mStartup.context = ms; }
    /// The monitor whose errors a failed shader compile discards: a compile error in an edited
    /// shader is the user's to fix (shown in the UI), not a bug of the viewer.
    void setDebugMonitor(gl::DebugMonitor* monitor) { mDebug = monitor; }

    int selectedLight = -1;
    int selectedMaterial = 0;
    bool showUi = true;
    bool flyMode = false;
    /// Panels to open (true) or close on the next frame, by header name ("Materials"): a pick
    /// opens the Materials panel, scripts arrange the panels for screenshots.
    std::map<std::string, bool> panelRequests;
    bool gpuTiming = true;
    std::string lastError;   ///< shown in the UI until dismissed
    std::string lastMessage; ///< e.g. where a screenshot went
    float brdfViewDegrees = 30.0f;            ///< BRDF explorer: angle of the view to the normal
    std::array<char, 512> environmentInput{}; ///< Environment panel: the path being typed
    Timeline timeline;
    /// KHR_materials_variants: the variant the scene is drawn with (-1: none, the file's materials).
    int variant() const { return mVariant; }
    void setVariant(int variant);
    /// The animation's length in seconds (0: none, or no keyframes).
    float animationDuration() const;
    /// Frame times (ms), oldest first, for the graph.
    std::array<float, 120> frameTimes{};

private:
    void uploadScene();
    /// `map` on `renderer` with --bake-preset and the bake cache; without a cache entry, a
    /// progressive bake (advanceEnvironmentBake).
    void setEnvironment(render::Renderer& renderer, const render::EnvironmentMap& map);
    /// Moves the timeline on by `deltaSeconds` when playing, and poses the scene when its
    /// animation or time changed since the last pose.
    void advanceTimeline(float deltaSeconds);
    /// The renderer's lights with the environment's sun light (if any) replaced by the one for
    /// mEnvironment's sun under the settings' rotation and intensity (none when it has no sun).
    void placeEnvironmentSun();
    /// Turns and scales the environment's sun light when the environment's rotation or
    /// intensity changed since it was placed (an edit of the light's other fields stays).
    void followEnvironmentSun();
    bool mExtractSun = false;     ///< --env-sun extract, for environments loaded later too
    float mSunRotation = 0.0f;    ///< the rotation and intensity the sun light was placed with
    float mSunIntensity = 1.0f;
    std::optional<std::pair<int, float>> mPosed; ///< the pose the renderer holds
    int mVariant = -1;
    platform::Context& mContext;
    setup::FrameOptions mOptions;
    std::unique_ptr<render::Renderer> mRenderer;
    scene::SceneDocument mDocument;
    std::optional<render::EnvironmentMap> mEnvironment;
    render::FrameSettings mSettings;
    OrbitCamera mCamera;
    int mSceneCamera = -1;
    std::string mSceneName;
    std::string mEnvironmentName;
    StartupTimes mStartup;
    LightUpload mLastLightUpload;
    bool mFirstFrame = true;
    double mLastRenderMs = 0.0; ///< the last frame's render and present
    render::BakeProgress mBake;
    render::View mLastView;
    render::FrameSettings mLastFrameSettings; // the last frame's, for a screenshot to render it again
    glm::vec2 mLastSize{1.0f};
    gl::DebugMonitor* mDebug = nullptr;
    std::filesystem::path mPendingWindowShot;
    scene::Material mDefaultMaterial{.name = "default"}; ///< glTF's default material, as edited
    ShaderWatcher mShaderWatcher;
};

} // namespace specula::viewer
