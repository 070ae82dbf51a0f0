#pragma once
// The forward renderer: a scene in, an HDR frame and a tone-mapped image out.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "core/ImageIO.h"
#include "render/BakeSettings.h"
#include "render/PlacedLight.h"
#include "settings/PassSettings.h"
#include "shading/EnvironmentMap.h"
#include "shading/Tonemap.h"
#include "render/View.h"
#include "scene/Scene.h"
#include "settings/DebugView.h"
#include "settings/PassSettings.h"

namespace specula::render {

/// Masking-shadowing term of the BRDF (scene/MaterialModel.h lists every choice).
using BrdfGeometry = scene::BrdfGeometry;
/// smith-ggx, smith-ggx-correlated, schlick-ggx, neumann, kelemen, cook-torrance, implicit.
std::optional<BrdfGeometry> parseBrdfGeometry(std::string_view name);

/// A parameter of a material's record that can change at run time (Renderer::setMaterialParameter).
enum class MaterialParameter {
    BaseColor,     ///< rgba base colour factor
    Emissive,      ///< rgb emissive radiance (factor × strength)
    Metallic,      ///< x
    Roughness,     ///< x, perceptual
    PhongSpecular, ///< rgb specular colour ks of the classic models
    Shininess,     ///< x, Phong exponent (0 = from roughness)
    /// rgb: the dielectric F0 over 0.04, KHR_materials_specular colour × F0(ior) / 0.04
    /// (scene::f0FromIor); 1 = F0 0.04
    SpecularColor,
    SpecularFactor, ///< x, KHR_materials_specular factor (dielectric F0 and F90)
    SectorLight,    ///< x, the Doom model's sector light level, 0–255
    ClearcoatFactor,    ///< x, KHR_materials_clearcoat factor (0 = no layer: the CLEARCOAT variant goes)
    ClearcoatRoughness, ///< x, the layer's perceptual roughness
    /// x, KHR_materials_dispersion (20 / V_d; 0 = none: the DISPERSION variant goes); refracts
    /// per channel only through a volume (a transmissive material with a thickness)
    Dispersion,
    SheenColor,         ///< rgb, KHR_materials_sheen colour factor (black = no sheen: the SHEEN variant goes)
    SheenRoughness,     ///< x, the sheen's perceptual roughness
    AnisotropyStrength, ///< x, KHR_materials_anisotropy strength (0 = isotropic: the ANISOTROPY variant goes)
    AnisotropyRotation, ///< x, radians counter-clockwise from the tangent
    IridescenceFactor,    ///< x, KHR_materials_iridescence factor (0 = no film: the IRIDESCENCE variant goes)
    IridescenceIor,       ///< x, the film's IOR (at least 1)
    IridescenceThickness, ///< x minimum, y maximum thickness (nm, at least 0)
    /// x, KHR_materials_diffuse_transmission factor (0 = none: the DIFFUSE_TRANSMISSION variant goes)
    DiffuseTransmission,
    DiffuseTransmissionColor, ///< rgb, the transmitted light's colour (linear)
};
constexpr int kMaterialParameterCount = int(MaterialParameter::DiffuseTransmissionColor) + 1;

/// How the specular lobe integrates image-based light (docs/ibl.md).
enum class IblSpecular {
    SplitSum,   ///< prefiltered radiance × the DFG table (Karis 2013): one fetch, assumes n = v = r
    Importance, ///< per pixel, filtered importance sampling with the full BRDF (Colbert & Křivánek 2007)
};
const char* iblSpecularName(IblSpecular mode);
std::optional<IblSpecular> parseIblSpecular(std::string_view name);

/// How the environment lights and shows in a frame (its content is set with setEnvironment).
struct EnvironmentView {
    bool lighting = true;         ///< image-based lighting on (when an environment is set)
    float intensity = 1.0f;       ///< scales the environment's radiance
    float rotationDegrees = 0.0f; ///< turns the environment about +Y
    bool skybox = true;           ///< draw the environment behind the scene
    float skyboxBlur = 0.0f;      ///< perceptual roughness of the skybox (0 = sharp)
    IblSpecular specular = IblSpecular::SplitSum;
};

/// Which lights each shading point evaluates (docs/clustered-shading.md).
enum class LightCulling {
    Clustered, ///< its cluster's list, culled on the GPU every frame (the default)
    None,      ///< every light of the frame (brute force: for comparisons and measurements)
};

/// How blended surfaces are ordered (docs/transparency.md).
enum class Transparency {
    Sorted, ///< back to front by the view depth of each draw's bounds (the default)
    Oit,    ///< weighted blended order-independent transparency (McGuire & Bavoil 2013): no order
};
const char* transparencyName(Transparency transparency);
std::optional<Transparency> parseTransparency(std::string_view name);

/// What a frame looks like. Zero values are not all defaults; use the initialisers.
struct FrameSettings {
    int width = 1280;
    int height = 720;
    int msaa = 4;                          ///< 1 = one sample at each pixel centre
    float exposureEv = 0.0f;               ///< image multiplied by 2^exposureEv
    Tonemap tonemap = Tonemap::Neutral;
    float reinhardWhite = 4.0f;            ///< white point of reinhard-ext (cd/m² after exposure)
    /// G of materials that choose none. Each BRDF variant in use gets its own DFG table for
    /// image-based light and energy compensation (see docs/ibl.md).
    BrdfGeometry brdfGeometry = BrdfGeometry::SmithGGX;
    /// Overrides every material's shading model and BRDF terms for the frame (--shading,
    /// --brdf-d/g/f/diffuse); an unset field leaves each material's own choice. The Doom model
    /// makes the frame Doom's 8-bit frame (render/DoomPass): one sample a pixel, palette
    /// colours only, no exposure, tone curve, bloom, FXAA or skybox.
    scene::MaterialShading materialOverride;
    /// Overrides every blended material's blend mode for the frame (the gallery's fade and
    /// newell-newell-sancha tiles); unset: each material's own.
    std::optional<scene::BlendMode> blendModeOverride;
    Transparency transparency = Transparency::Sorted;
    glm::vec3 background{0.0f};            ///< radiance behind the scene, cd/m²
    glm::vec3 ambient{0.0f};               ///< constant ambient radiance for the diffuse lobe
    bool gizmos = false;                   ///< draw every light as a disc in its colour, with rods for directions and cones (BillboardPass)
    int selectedLight = -1;                ///< the light whose gizmo is drawn larger (a viewer's selection); -1 = none
    EnvironmentView environment;
    /// Multiple-scattering compensation of the specular lobe (punctual and image-based light).
    /// Off = exactly the glTF BRDF for punctual lights.
    bool energyCompensation = true;
    /// Physical camera exposure: radiance × 1 / (1.2 × 2^ev100) (Lagarde & de Rousiers 2014),
    /// then × 2^exposureEv as compensation. Unset: no camera, only 2^exposureEv. Ignored while
    /// autoExposure is on (it measures its own EV100). See docs/units.md.
    std::optional<float> ev100;
    /// Shadow maps (settings/PassSettings.h), on by default.
    ShadowSettings shadows;
    LightCulling lightCulling = LightCulling::Clustered;
    /// Point and spot lights without a range are given one: where their illuminance falls to
    /// lightCutoff × their illuminance at 1 m, i.e. 1 m / √lightCutoff (100 m by default); the
    /// error that makes is below lightCutoff × that illuminance everywhere. 0: infinite.
    float lightCutoff = 1e-4f;
    /// Levels of detail (scene/MeshLod.h): each draw seen by the camera uses the coarsest level
    /// of its mesh whose geometric error on screen is at most this many pixels; 0 (the
    /// default): every mesh at full detail. Shadow views draw full detail. Off by default: the
    /// image changes by more than the golden tests allow (docs/performance.md#levels-of-detail).
    float lodPixels = 0.0f;
    // Post-processing (settings/PassSettings.h): each off by default and then free.
    BloomSettings bloom;
    SsaoSettings ssao;
    AutoExposureSettings autoExposure;
    FxaaSettings fxaa;
    DebugView debugView = DebugView::None;
    /// The tone map draws straight into the default framebuffer (a window's back buffer, of
    /// width × height) when it is the frame's last pass (no FXAA, no debug view) and the back
    /// buffer is sRGB-capable: the copy present() makes is saved, the bytes are the same.
    /// readImage() has no image of such a frame (lastFrameInWindow()).
    bool toWindow = false;
};

/// GPU milliseconds per pass of the last frame (timer queries), when timing is on. Passes
/// in frame order: "ssao prepass", "ssao", "ssao blur", "forward", "resolve", "bloom", "exposure",
/// "tonemap" or "resolve+tonemap", "fxaa", "debug view"; only those that ran. A Doom frame
/// (materialOverride doom) runs "forward" (palette indices) and "colour map" instead of the
/// passes between them and "debug view".
struct PassTiming {
    const char* name; ///< valid for the renderer's lifetime
    double gpuMs;
    /// With setPassWallClock: milliseconds from before the pass was issued until the GPU
    /// finished it (glFinish on both sides), else 0. On a software renderer this is the pass's
    /// true cost: llvmpipe's timer queries miss compute dispatches that need no flush of
    /// earlier rendering (its auto-exposure pass reads 0.2 ms by query, 15 ms by wall clock).
    double wallMs = 0.0;
};

struct FrameStats {
    int drawCalls = 0;
    size_t triangles = 0;    ///< submitted after culling
    /// Bytes of the environment's uniform block uploaded for the frame: only the fields that
    /// changed (the view when the camera moves, the SH when the environment does).
    size_t environmentBytesUploaded = 0;
    /// The forward programs held the frame's lights as constants (LIGHT_CONSTANTS: a few lights,
    /// every one evaluated everywhere, no shadow maps, and no edit in the last frames), not
    /// read from the light buffer (render/passes/ForwardPass).
    bool lightConstants = false;
    std::vector<PassTiming> passes;
    /// Textures the frame graph's pool holds after the frame (its targets, and those of passes
    /// switched off until they have been idle for two frames).
    size_t transientTextures = 0;
    /// Shadow maps of the frame: lights with a map, their views (cascades, a spot's one, a
    /// point light's six faces), how many of those were rendered this frame and how many kept
    /// from an earlier frame (nothing in them changed), and the casting lights left without a
    /// map (over the budget, or no room in the atlas).
    struct Shadows {
        int lights = 0;
        int views = 0;
        int rendered = 0;
        int cached = 0;
        int dropped = 0;
        int atlasSize = 0;
    } shadows;
    /// Clustered light culling ("light culling" in `passes` is its time): the grid, the point
    /// and spot lights that touch the view, the directional lights every cluster lists, and the
    /// cluster lists' lengths. All 0 when the frame culled nothing (LightCulling::None, Doom).
    struct Clusters {
        int tilesX = 0, tilesY = 0, slices = 0;
        int lightsInView = 0;
        int directional = 0;
        int maxPerCluster = 0;
        double meanPerCluster = 0.0;
        size_t entries = 0;      ///< light indices of all the lists
        size_t bufferBytes = 0;  ///< the lists' buffer
        /// The frame shaded with every light: the culling before it had listed nearly every one
        /// of a few lights in nearly every cluster (render/passes/LightCullPass.h).
        bool everyLight = false;
    } clusters;
};

class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Uploads a scene (meshes, textures, materials) and its lights.
    void setScene(const scene::Scene& scene);
    /// Poses the scene of setScene: animation `animation` (an index into its animations; -1:
    /// the rest pose) at `seconds` (docs/gltf.md#animation). Nodes move, skinned and morphed
    /// meshes are deformed (every pass draws the deformed vertices), shadow maps are redrawn.
    /// Nothing for a scene that does not move (no animations, skins or morph targets).
    void setPose(int animation, float seconds);
    /// KHR_materials_variants: draws the scene of setScene with the materials of variant
    /// `variant` (an index into its variants; -1: none, the materials its primitives name).
    /// Shadow maps are redrawn when a draw's material changed.
    void setVariant(int variant);

    // The lights, as many as there are (setScene places the scene's). Changes apply from the
    // next frame.
    int lightCount() const;
    const PlacedLight& light(int index) const; ///< index < lightCount()
    /// Replaces all lights.
    void setLights(const std::vector<PlacedLight>& lights);
    /// Changes light `index` (< lightCount()), uploading only its bytes; returns what it uploaded.
    LightWrite setLight(int index, const PlacedLight& light);

    /// Sets the environment for image-based lighting and the skybox, baking it (or reading the
    /// bake from `cacheDirectory` when it holds one for this content and these settings).
    /// BakeMode::Progressive: a small bake now, the full one over later frames
    /// (advanceEnvironmentBake).
    BakeReport setEnvironment(const EnvironmentMap& map, const BakeSettings& settings = {},
                              const std::filesystem::path& cacheDirectory = {}, BakeMode mode = BakeMode::Now);
    /// A progressive bake's next steps, for about `budgetMs` (at least one step); the frame after
    /// the last one renders with the full bake.
    BakeProgress advanceEnvironmentBake(double budgetMs);
    void clearEnvironment();
    /// Where baked tables are cached on disk (empty: nowhere). The DFG tables read there are
    /// needed with or without an environment (energy compensation), so this outlives
    /// clearEnvironment; setEnvironment's `cacheDirectory` replaces it.
    void setCacheDirectory(const std::filesystem::path& directory);
    /// The spherical-harmonics radiance of the current environment (for tests and tools).
    const Sh9* environmentSh() const;

    /// Renders one frame into the renderer's targets.
    void render(const View& view, const FrameSettings& settings);

    /// The last frame, tone-mapped and sRGB-encoded, top row first (with a debug view: that
    /// buffer). Throws specula::Error after a frame that went to the window (toWindow).
    ImageRGBA8 readImage() const;
    /// Copies the last frame (what readImage() returns) into the default framebuffer's
    /// rectangle (0, 0, width, height), scaled, for windows; after a frame that went there
    /// itself (toWindow), only binds the default framebuffer for what the window draws on top.
    void present(int width, int height);
    /// Whether the last frame was drawn straight into the default framebuffer (toWindow).
    bool lastFrameInWindow() const;
    /// The last frame's linear radiance × exposureScale() (before tone mapping, after bloom),
    /// top row first. With the SSAO debug view: the occlusion in r, g and b.
    ImageFloat readRadiance() const;
    /// The scale the last frame applied to radiance before tone mapping: 2^exposureEv, times
    /// the camera's or the automatic exposure (read back from the GPU when automatic).
    float exposureScale() const;

    /// Measure each pass with GPU timer queries (waits for the GPU at the end of a frame).
    void setGpuTiming(bool enabled);
    /// With GPU timing on, also time each pass by wall clock, waiting for the GPU before and
    /// after it (PassTiming::wallMs). Serialises the frame: for measurements only.
    void setPassWallClock(bool enabled);
    const FrameStats& stats() const;
    /// Tells the renderer that GL state changed behind its back (third-party GL code such as a
    /// UI's backend, or a read of the default framebuffer): it forgets what it thought bound.
    void invalidateGlState();

    /// The frame `settings` would run, as a graph of passes and resources in Graphviz dot
    /// (`specula render --print-graph`). Compiles its programs; renders nothing.
    std::string frameGraphDot(const View& view, const FrameSettings& settings);

    /// Builds and compiles the frame `settings` ask for without running it: its programs are
    /// compiled and its tables baked now rather than on first use.
    void prepare(const FrameSettings& settings);

    // The material registry: the scene's materials by index, the glTF default material last.
    // Changes apply from the next frame without reloading the scene; programs are compiled on
    // first use and cached for the run.
    int materialCount() const;
    scene::MaterialShading materialShading(int material) const;
    /// Changes one material's shading model and BRDF terms (its shader variant only).
    void setMaterialShading(int material, const scene::MaterialShading& shading);
    /// A blended material's blend mode (its shader variant); Fade for the others.
    scene::BlendMode materialBlendMode(int material) const;
    /// Changes a blended material's blend mode; nothing for a material that does not blend.
    void setMaterialBlendMode(int material, scene::BlendMode mode);
    /// Rewrites one parameter in one material's record of the material buffer: that field's
    /// bytes and no others (unused components of `value` are ignored).
    void setMaterialParameter(int material, MaterialParameter parameter, const glm::vec4& value);
    /// The parameter's current value (as the buffer holds it; unused components 0).
    glm::vec4 materialParameter(int material, MaterialParameter parameter) const;
    /// GL texture names of every texture a material samples, in scene::kMaterialTextures' order
    /// (base colour, metallic-roughness, normal, occlusion, emissive, then the extensions'; 0
    /// where it has none), for UI thumbnails (ImGui::Image).
    std::vector<uint32_t> materialTextureNames(int material) const;
    /// A picture of the last frame's shadow atlas, drawn now as the shadow-atlas debug view
    /// draws it, `size`² RGBA8 (UI, ImGui::Image): its GL texture name, 0 when no light had a map.
    uint32_t shadowAtlasImage(int size);

    /// Tests only: shrinks every light cluster's box about its centre by `fraction` of its
    /// size (0: the true boxes), so that a test can show the clustered frame then differs.
    void setClusterShrinkForTesting(float fraction);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
