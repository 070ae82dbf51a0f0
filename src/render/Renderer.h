#pragma once
// The forward renderer: a scene in, an HDR frame and a tone-mapped image out.
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "core/ImageIO.h"
#include "render/ImageBasedLighting.h"
#include "render/PostSettings.h"
#include "render/Tonemap.h"
#include "render/View.h"
#include "scene/Scene.h"

namespace specula::gl {
class State;
}

namespace specula::render {

class LightBuffer;

enum class BrdfGeometry { SmithGGX, SchlickGGX };
std::optional<BrdfGeometry> parseBrdfGeometry(std::string_view name);

/// How the environment lights and shows in a frame (its content is set with setEnvironment).
struct EnvironmentView {
    bool lighting = true;         ///< image-based lighting on (when an environment is set)
    float intensity = 1.0f;       ///< scales the environment's radiance
    float rotationDegrees = 0.0f; ///< turns the environment about +Y
    bool skybox = true;           ///< draw the environment behind the scene
    float skyboxBlur = 0.0f;      ///< perceptual roughness of the skybox (0 = sharp)
};

/// What a frame looks like. Zero values are not all defaults; use the initialisers.
struct FrameSettings {
    int width = 1280;
    int height = 720;
    int msaa = 4;                          ///< 1 = one sample at each pixel centre
    float exposureEv = 0.0f;               ///< image multiplied by 2^exposureEv
    Tonemap tonemap = Tonemap::Neutral;
    float reinhardWhite = 4.0f;            ///< white point of reinhard-ext (cd/m² after exposure)
    BrdfGeometry brdfGeometry = BrdfGeometry::SmithGGX;
    glm::vec3 background{0.0f};            ///< radiance behind the scene, cd/m²
    glm::vec3 ambient{0.0f};               ///< constant ambient radiance for the diffuse lobe
    bool gizmos = false;                   ///< draw every light as a disc in its colour (BillboardPass)
    EnvironmentView environment;
    /// Multiple-scattering compensation of the specular lobe (punctual and image-based light).
    /// Off = exactly the glTF BRDF for punctual lights.
    bool energyCompensation = true;
    /// Physical camera exposure: radiance × 1 / (1.2 × 2^ev100) (Lagarde & de Rousiers 2014),
    /// then × 2^exposureEv as compensation. Unset: no camera, only 2^exposureEv. Ignored while
    /// autoExposure is on (it measures its own EV100). See docs/units.md.
    std::optional<float> ev100;
    // Post-processing (render/PostSettings.h): each off by default and then free.
    BloomSettings bloom;
    SsaoSettings ssao;
    AutoExposureSettings autoExposure;
    FxaaSettings fxaa;
    DebugView debugView = DebugView::None;
};

/// GPU milliseconds per pass of the last frame (timer queries), when timing is on. Passes
/// in frame order: "ssao prepass", "ssao", "forward", "resolve", "bloom", "exposure",
/// "tonemap" or "resolve+tonemap", "fxaa", "debug view"; only those that ran.
struct PassTiming {
    const char* name;
    double gpuMs;
};

struct FrameStats {
    int drawCalls = 0;
    size_t triangles = 0;    ///< submitted after culling
    std::vector<PassTiming> passes;
};

class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Uploads a scene (meshes, textures, materials) and its lights.
    void setScene(const scene::Scene& scene);
    LightBuffer& lights();

    /// Sets the environment for image-based lighting and the skybox, baking it (or reading the
    /// bake from `cacheDirectory` when it holds one for this content and these settings).
    BakeReport setEnvironment(const EnvironmentMap& map, const BakeSettings& settings = {},
                              const std::filesystem::path& cacheDirectory = {});
    void clearEnvironment();
    /// The spherical-harmonics radiance of the current environment (for tests and tools).
    const Sh9* environmentSh() const;

    /// Renders one frame into the renderer's targets.
    void render(const View& view, const FrameSettings& settings);

    /// The last frame, tone-mapped and sRGB-encoded, top row first (with a debug view: that
    /// buffer).
    ImageRGBA8 readImage() const;
    /// The last frame's linear radiance × exposureScale() (before tone mapping, after bloom),
    /// top row first. With the SSAO debug view: the occlusion in r, g and b.
    ImageFloat readRadiance() const;
    /// The scale the last frame applied to radiance before tone mapping: 2^exposureEv, times
    /// the camera's or the automatic exposure (read back from the GPU when automatic).
    float exposureScale() const;

    /// Measure each pass with GPU timer queries (waits for the GPU at the end of a frame).
    void setGpuTiming(bool enabled);
    const FrameStats& stats() const;
    gl::State& state();

    /// Compiles the programs `settings` needs now rather than on first use.
    void prepare(const FrameSettings& settings);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
