#include "setup/SceneSetup.h"

#include "shading/SunExtraction.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>
#include <variant>

#include "core/Error.h"
#include "core/Log.h"
#include "shading/CameraExposure.h"
#include "shading/SunExtraction.h"
#include "scene/BuiltinScenes.h"
#include "scene/DemoScenes.h"
#include "scene/Pose.h"

namespace specula::setup {

scene::SceneDocument loadSceneOrBuiltin(const std::string& name, const scene::LoadOptions& options, std::optional<int> lights)
{
    if (lights && (*lights < 0 || *lights > (1 << 22))) throw Error("--lights must be between 0 and 4194304 (got {})", *lights);
    if (std::optional<scene::SceneDocument> builtin = scene::builtinScene(name, lights)) return std::move(*builtin);
    return scene::loadScene(name, options);
}

namespace {

template <typename T, typename Parse>
std::optional<T> parseOption(const std::optional<std::string>& value, const char* flag, Parse parse, const char* names)
{
    if (!value) return std::nullopt;
    const std::optional<T> parsed = parse(*value);
    if (!parsed) throw Error("unknown {} '{}' ({})", flag, *value, names);
    return parsed;
}

/// --shading and --brdf-*: every material's choice for this frame; --debug-view.
void applyMaterialOverrides(const scene::SceneDocument& document, const FrameOptions& options, render::FrameSettings& s)
{
    scene::MaterialShading& o = s.materialOverride;
    // The command line's --shading, else the scene's render.shading.
    o.model = parseOption<scene::ShadingModel>(options.shading ? options.shading : document.render.shading, "--shading",
                                               scene::parseShadingModel, scene::shadingModelNames());
    o.distribution = parseOption<scene::BrdfDistribution>(options.brdfD, "--brdf-d", scene::parseBrdfDistribution,
                                                          scene::brdfDistributionNames());
    o.geometry = parseOption<scene::BrdfGeometry>(options.brdfG, "--brdf-g", scene::parseBrdfGeometryName, scene::brdfGeometryNames());
    o.fresnel = parseOption<scene::BrdfFresnel>(options.brdfF, "--brdf-f", scene::parseBrdfFresnel, scene::brdfFresnelNames());
    o.diffuse = parseOption<scene::BrdfDiffuse>(options.brdfDiffuse, "--brdf-diffuse", scene::parseBrdfDiffuse, scene::brdfDiffuseNames());
    if (options.debugView) {
        const auto view = parseDebugView(*options.debugView);
        if (!view)
            throw Error("unknown --debug-view '{}' (base-color, normal, roughness, metallic, occlusion, emissive, brdf-d, brdf-g, "
                        "brdf-f, ssao, bloom, cascades, shadow-atlas, light-count, sheen, anisotropy, iridescence, clearcoat, clearcoat-normal)", *options.debugView);
        s.debugView = *view;
    }
}

/// Checks each value the options set of a pass against its table: "--bloom-levels must be
/// between 1 and 8 (got 9)". (The scene file's values were checked as it was read.)
template <typename T>
void checkFlags(const SettingsOverride<T>& flags)
{
    const SettingsTable<T>& table = settingsTable<T>();
    for (const SettingField<T>& field : table.fields) {
        const bool set = std::visit([&](auto m) { return flags.has(m); }, field.member);
        if (!set) continue;
        const double value = field.value(flags.values());
        if (!field.range.contains(value)) throw Error("--{} {} (got {})", flagName(table, field), field.range.requirement(), value);
    }
}

/// The passes and the camera exposure: options over scene file over defaults.
void resolvePostSettings(const scene::SceneDocument& document, const FrameOptions& options, render::FrameSettings& s)
{
    forEachPass(
        [](auto& pass, const auto& file, const auto& flags) {
            file.applyTo(pass);
            checkFlags(flags);
            flags.applyTo(pass);
        },
        s, document.post, options.post);

    // The camera: --ev100, else the file's render.ev100 or camera aperture/shutter/ISO.
    if (options.ev100) {
        s.ev100 = *options.ev100;
    } else if (document.render.ev100) {
        s.ev100 = *document.render.ev100;
    } else if (const auto& camera = document.render.cameraExposure) {
        s.ev100 = render::ev100FromCamera(camera->aperture, camera->shutter, camera->iso);
    }
    if (s.ev100 && !std::isfinite(*s.ev100)) throw Error("--ev100 must be a finite number (got {})", double(*s.ev100));

    if (options.shadowQuality) {
        const std::string& q = *options.shadowQuality;
        if (q == "low") s.shadows.quality = ShadowQuality::Low;
        else if (q == "medium") s.shadows.quality = ShadowQuality::Medium;
        else if (q == "high") s.shadows.quality = ShadowQuality::High;
        else throw Error("--shadow-quality must be low, medium or high (got '{}')", q);
    }
    if (options.shadowFilter) {
        const std::string& f = *options.shadowFilter;
        if (f == "hard") s.shadows.filter = ShadowFilter::Hard;
        else if (f == "pcf") s.shadows.filter = ShadowFilter::Pcf;
        else if (f == "pcss") s.shadows.filter = ShadowFilter::Pcss;
        else throw Error("--shadow-filter must be hard, pcf or pcss (got '{}')", f);
    }
    if (options.lightCulling) {
        const std::string& c = *options.lightCulling;
        if (c == "clustered") s.lightCulling = render::LightCulling::Clustered;
        else if (c == "none") s.lightCulling = render::LightCulling::None;
        else throw Error("--light-culling must be clustered or none (got '{}')", c);
    }
    // --transparency, else the scene's render.transparency (checked as the file was read).
    if (const auto& t = options.transparency ? options.transparency : document.render.transparency) {
        const auto transparency = render::parseTransparency(*t);
        if (!transparency) throw Error("--transparency must be sorted or oit (got '{}')", *t);
        s.transparency = *transparency;
    }
    if (options.lightCutoff) {
        const float c = *options.lightCutoff;
        if (!(c >= 0.0f && c < 1.0f)) throw Error("--light-cutoff must be at least 0 and below 1 (got {})", double(c));
        s.lightCutoff = c;
    }
    if (options.lodPixels) {
        const float e = *options.lodPixels;
        if (!(e >= 0.0f && e <= 16.0f)) throw Error("--lod-error must be between 0 and 16 pixels (got {})", double(e));
        s.lodPixels = e;
    }
}

/// `name`'s index among `names` (a name, else a decimal index), -1 for "none"; Error naming
/// `flag` and listing what there is otherwise.
int chooseByNameOrIndex(const std::vector<std::string>& names, const std::string& name, std::string_view flag,
                        std::string_view kind)
{
    if (name == "none") return -1;
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return int(i);
    const bool digits = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (digits && name.size() < 9 && size_t(std::stoi(name)) < names.size()) return std::stoi(name);
    std::string available = "the scene has none";
    for (size_t i = 0; i < names.size(); ++i)
        available = fmt::format("{}{} '{}'", i ? available + ", " : std::string("the scene has: "), i, names[i]);
    throw Error("{}: no {} '{}' ({})", flag, kind, name, available);
}

} // namespace

AnimationChoice resolveAnimation(const scene::Scene& scene, const FrameOptions& options)
{
    AnimationChoice choice;
    if (options.time) {
        if (!(*options.time >= 0.0f)) throw Error("--time must be 0 or more seconds (got {})", *options.time);
        choice.seconds = *options.time;
    }
    if (options.animation) {
        std::vector<std::string> names;
        for (const scene::Animation& animation : scene.animations) names.push_back(animation.name);
        choice.index = chooseByNameOrIndex(names, *options.animation, "--animation", "animation");
        return choice;
    }
    if (scene.animations.empty()) {
        if (options.time) log::warn("--time {} is ignored: the scene has no animations", *options.time);
        return choice;
    }
    choice.index = 0;
    return choice;
}

int resolveVariant(const scene::Scene& scene, const FrameOptions& options)
{
    if (!options.variant) return -1;
    return chooseByNameOrIndex(scene.variants, *options.variant, "--variant", "material variant");
}

render::FrameSettings resolveSettings(const scene::SceneDocument& document, const FrameOptions& options)
{
    render::FrameSettings s;
    const scene::RenderSettings& file = document.render;
    s.width = options.width.value_or(file.width.value_or(s.width));
    s.height = options.height.value_or(file.height.value_or(s.height));
    s.msaa = options.msaa.value_or(file.msaa.value_or(s.msaa));
    s.exposureEv = options.exposure.value_or(file.exposure.value_or(s.exposureEv));
    if (s.width < 1 || s.height < 1 || s.width > 16384 || s.height > 16384)
        throw Error("image size {}x{} is out of range (1 to 16384)", s.width, s.height);
    if (s.msaa != 1 && s.msaa != 2 && s.msaa != 4 && s.msaa != 8)
        throw Error("--msaa must be 1, 2, 4 or 8 (got {})", s.msaa);
    const std::string tonemap = options.tonemap.value_or(file.tonemap.value_or("neutral"));
    const auto parsedTonemap = render::parseTonemap(tonemap);
    if (!parsedTonemap) throw Error("unknown tone mapper '{}' (none, reinhard, reinhard-ext, aces, neutral, agx)", tonemap);
    s.tonemap = *parsedTonemap;
    const std::string g = options.brdfG.value_or(file.brdfG.value_or("smith-ggx"));
    const auto geometry = render::parseBrdfGeometry(g);
    if (!geometry) throw Error("unknown --brdf-g '{}' ({})", g, scene::brdfGeometryNames());
    s.brdfGeometry = *geometry;
    applyMaterialOverrides(document, options, s);
    s.gizmos = options.gizmos;
    if (options.energyCompensation) {
        if (*options.energyCompensation != "on" && *options.energyCompensation != "off")
            throw Error("--energy-compensation wants on or off (got '{}')", *options.energyCompensation);
        s.energyCompensation = *options.energyCompensation == "on";
    }
    s.environment.intensity = options.envIntensity.value_or(document.environment.intensity);
    s.environment.rotationDegrees = options.envRotation.value_or(document.environment.rotationDegrees);
    if (!(s.environment.intensity >= 0.0f) || !std::isfinite(s.environment.intensity))
        throw Error("--env-intensity must be a finite number, not negative");
    if (!std::isfinite(s.environment.rotationDegrees)) throw Error("--env-rotation must be a finite number");
    if (!std::isfinite(s.exposureEv)) throw Error("--exposure must be a finite number");
    if (const std::optional<std::string>& ibl = options.ibl ? options.ibl : document.environment.ibl) {
        const auto mode = render::parseIblSpecular(*ibl);
        if (!mode) throw Error("--ibl must be split-sum or importance (got '{}')", *ibl);
        s.environment.specular = *mode;
    }
    if (options.skybox) {
        const std::string& sky = *options.skybox;
        float blur = 0.0f;
        char extra = 0;
        if (sky == "on") {
            s.environment.skybox = true;
        } else if (sky == "off") {
            s.environment.skybox = false;
        } else if (std::sscanf(sky.c_str(), "blur=%f%c", &blur, &extra) == 1 && blur >= 0.0f && blur <= 1.0f) {
            s.environment.skyboxBlur = blur;
        } else {
            throw Error("--skybox wants on, off or blur=R with R a roughness in [0, 1] (got '{}')", sky);
        }
    }
    if (file.ambient) s.ambient = *file.ambient;
    resolvePostSettings(document, options, s);
    if (s.materialOverride.model == scene::ShadingModel::Doom) {
        // Doom's 8-bit frame holds palette colours only (render::Renderer leaves out whatever
        // would blend or curve them): say so when they were asked for, rather than drop them quietly.
        std::string ignored;
        auto add = [&](bool asked, const char* what) { if (asked) ignored += (ignored.empty() ? "" : ", ") + std::string(what); };
        add(options.msaa && *options.msaa > 1, "MSAA");
        add(s.bloom.enabled, "bloom");
        add(s.fxaa.enabled, "FXAA");
        add(s.autoExposure.enabled, "automatic exposure");
        add(options.tonemap.has_value() || options.exposure.has_value(), "exposure and tone mapping");
        if (!ignored.empty()) log::warn("a Doom frame is palette colours only: {} left out", ignored);
    }
    return s;
}

namespace {

glm::vec3 parseColor(const std::string& text)
{
    glm::vec3 c;
    char extra = 0;
    // sscanf reads "nan" and "inf" too; !(c >= 0) and isfinite reject them.
    if (std::sscanf(text.c_str(), "%f,%f,%f%c", &c.x, &c.y, &c.z, &extra) != 3 ||
        !glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))) ||
        !(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)))
        throw Error("--env-color wants three non-negative numbers R,G,B (got '{}')", text);
    return c;
}

} // namespace

namespace {

std::optional<render::EnvironmentMap> loadMap(const scene::SceneDocument& document, const FrameOptions& options)
{
    if (options.envColor) return render::constantEnvironment(parseColor(*options.envColor));
    if (options.env) {
        if (*options.env == "none") return std::nullopt;
        if (*options.env == "sky") return render::proceduralSky();
        return render::loadEnvironmentMap(*options.env);
    }
    if (!document.environment.file.empty()) return render::loadEnvironmentMap(document.environment.file);
    if (document.environment.color) return render::constantEnvironment(*document.environment.color);
    if (!document.environment.skyByDefault) return std::nullopt;
    return render::proceduralSky();
}

} // namespace

bool extractsSun(const std::string& mode)
{
    if (mode != "extract" && mode != "keep") throw Error("--env-sun must be extract or keep (got '{}')", mode);
    return mode == "extract";
}

bool extractsSun(const scene::SceneDocument& document, const FrameOptions& options)
{
    return extractsSun(options.envSun.value_or(document.environment.sun.value_or("keep")));
}

render::PlacedLight environmentSunLight(const render::ExtractedSun& sun, float rotationDegrees, float intensity)
{
    render::PlacedLight placed;
    placed.light.name = kEnvironmentSunName;
    placed.light.type = scene::Light::Type::Directional;
    const float lux = std::max({sun.illuminance.r, sun.illuminance.g, sun.illuminance.b});
    placed.light.intensity = lux * intensity;
    placed.light.color = lux > 0.0f ? sun.illuminance / lux : glm::vec3(1.0f);
    placed.light.angularDiameter = sun.angularDiameter;
    // World direction: the environment turned by its rotation; the light points away from the sun.
    placed.direction = -(render::environmentRotation(rotationDegrees) * sun.direction);
    return placed;
}

std::optional<render::PlacedLight> extractEnvironmentSun(render::EnvironmentMap& map, float rotationDegrees, float intensity)
{
    const std::optional<render::ExtractedSun> sun = render::extractSun(map);
    if (!sun) {
        log::info("--env-sun extract: the environment has no sun (no compact region far brighter than the rest)");
        return std::nullopt;
    }
    const render::PlacedLight placed = environmentSunLight(*sun, rotationDegrees, intensity);
    const glm::vec3 toSun = -placed.direction;
    log::info("--env-sun extract: sun of {:.0f} lux, {:.2f}° across, {} texels, towards ({:.4f}, {:.4f}, {:.4f}) ({:.1f}° above "
              "the horizon), now a directional light",
              placed.light.intensity, glm::degrees(sun->angularDiameter), sun->texels, toSun.x, toSun.y, toSun.z,
              glm::degrees(std::asin(std::clamp(toSun.y, -1.0f, 1.0f))));
    return placed;
}

std::optional<render::EnvironmentMap> loadEnvironment(scene::SceneDocument& document, const FrameOptions& options)
{
    std::optional<render::EnvironmentMap> map = loadMap(document, options);
    if (!extractsSun(document, options) || !map) return map;
    const float rotation = options.envRotation.value_or(document.environment.rotationDegrees);
    const float intensity = options.envIntensity.value_or(document.environment.intensity);
    if (const auto placed = extractEnvironmentSun(*map, rotation, intensity))
        scene::addLight(document.scene, placed->light, placed->position, placed->direction);
    return map;
}

render::BakeSettings resolveBakeSettings(const FrameOptions& options)
{
    const auto preset = render::bakePreset(options.bakePreset);
    if (!preset) throw Error("unknown --bake-preset '{}' (default, reference)", options.bakePreset);
    return *preset;
}

std::filesystem::path cacheDirectory(const FrameOptions& options)
{
    return options.noCache ? std::filesystem::path() : render::defaultCacheDirectory();
}

void fitSizeToCamera(render::FrameSettings& settings, const scene::SceneDocument& document, const FrameOptions& options)
{
    const std::vector<scene::CameraInstance> cameras = document.scene.cameraInstances();
    const int index = options.camera >= 0 ? options.camera : cameras.empty() ? -1 : 0;
    if (index < 0 || size_t(index) >= cameras.size()) return; // the framed view, or an error prepareView reports
    const scene::Camera& camera = document.scene.cameras[size_t(cameras[size_t(index)].camera)];
    if (camera.type != scene::Camera::Type::Perspective || !(camera.aspectRatio > 0.0f)) return;
    const std::optional<int> width = options.width ? options.width : document.render.width;
    const std::optional<int> height = options.height ? options.height : document.render.height;
    if (width && height) return; // the size asked for: the viewport's aspect wins (render::cameraView)
    const auto clampSide = [](double side) { return int(std::clamp(std::lround(side), 1L, 16384L)); };
    if (width) settings.height = clampSide(*width / double(camera.aspectRatio));
    else settings.width = clampSide(settings.height * double(camera.aspectRatio));
}

render::View prepareView(scene::SceneDocument& document, const FrameOptions& options,
                         const render::FrameSettings& settings, int* added, bool hasEnvironment, const AnimationChoice& animation)
{
    const float aspect = float(settings.width) / float(settings.height);
    const scene::Pose pose = scene::poseAt(document.scene, animation.index, animation.seconds);
    const render::View view = render::defaultView(document.scene, options.camera, aspect, &pose);
    int count = 0;
    const bool allowed = !options.noDefaultLights && document.render.defaultLights.value_or(true);
    if (document.scene.lights.empty() && !hasEnvironment && allowed) {
        // The rig follows the viewer: from the scene's centre towards the camera.
        const glm::vec3 center = document.scene.worldBounds().empty() ? glm::vec3(0.0f) : document.scene.worldBounds().center();
        glm::vec3 toViewer = view.position - center;
        if (glm::length(toViewer) < 1e-6f) toViewer = glm::vec3(0, 0, 1);
        count = scene::addDefaultLightRig(document.scene, toViewer);
    }
    if (added) *added = count;
    return view;
}

} // namespace specula::setup
