#include "ViewerScript.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <fstream>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <type_traits>
#include <variant>

#include "Viewer.h"
#include "core/Error.h"
#include "core/Log.h"
#include "core/ProcessMemory.h"
#include "gl/ObjectCounts.h"
#include "platform/Context.h"
#include "settings/PassSettings.h"

namespace specula::viewer {

namespace {

/// The words of a line, with typed access that names what was expected.
class Words {
public:
    explicit Words(const std::string& line)
    {
        std::istringstream in(line);
        for (std::string word; in >> word;) mWords.push_back(word);
    }
    const std::string& action() const { return mWords[0]; }
    size_t size() const { return mWords.size(); }
    const std::string& text(size_t i) const
    {
        if (i >= mWords.size()) throw Error("'{}' wants {} argument(s)", action(), i);
        return mWords[i];
    }
    float number(size_t i) const
    {
        const std::string& word = text(i);
        size_t used = 0;
        float value = 0.0f;
        try {
            value = std::stof(word, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        // stof reads "nan" and "inf"; neither is a position, a size or an angle.
        if (used != word.size() || !std::isfinite(value)) throw Error("'{}': '{}' is not a finite number", action(), word);
        return value;
    }
    int integer(size_t i) const { return int(number(i)); }
    glm::vec3 vec3(size_t i) const { return {number(i), number(i + 1), number(i + 2)}; }

private:
    std::vector<std::string> mWords;
};

/// A pass's switch by its flag's name ("bloom", "auto-exposure": settings/PassSettings.h).
bool* passSwitch(render::FrameSettings& s, const std::string& name)
{
    bool* target = nullptr;
    forEachPass(
        [&](auto& pass) {
            if (flagName(settingsTable<std::decay_t<decltype(pass)>>().key, "enabled") == name) target = &pass.enabled;
        },
        s);
    return target;
}

bool* toggleTarget(Viewer& viewer, const std::string& name)
{
    render::FrameSettings& s = viewer.settings();
    if (bool* pass = passSwitch(s, name)) return pass;
    if (name == "skybox") return &s.environment.skybox;
    if (name == "ibl") return &s.environment.lighting;
    if (name == "gizmos") return &s.gizmos;
    if (name == "energy-compensation") return &s.energyCompensation;
    if (name == "ui") return &viewer.showUi;
    if (name == "fly") return &viewer.flyMode;
    return nullptr;
}

/// "bloom, ssao, fxaa, auto-exposure, skybox, ...": what `toggle` takes.
std::string toggleNames()
{
    std::string names;
    render::FrameSettings s;
    forEachPass([&](auto& pass) { names += flagName(settingsTable<std::decay_t<decltype(pass)>>().key, "enabled") + ", "; }, s);
    return names + "skybox, ibl, gizmos, energy-compensation, ui, fly";
}

/// What `set NAME` writes: a frame value, or any number of a pass by its flag's name
/// ("bloom-intensity", "ssao-samples"). Empty when there is none.
std::function<void(float)> valueTarget(Viewer& viewer, const std::string& name)
{
    render::FrameSettings& s = viewer.settings();
    auto number = [](float& target) { return [&target](float value) { target = value; }; };
    if (name == "exposure") return number(s.exposureEv);
    if (name == "env-intensity") return number(s.environment.intensity);
    if (name == "env-rotation") return number(s.environment.rotationDegrees);
    if (name == "skybox-blur") return number(s.environment.skyboxBlur);
    std::function<void(float)> target;
    forEachPass(
        [&](auto& pass) {
            using T = std::decay_t<decltype(pass)>;
            const SettingField<T>* field = settingsTable<T>().findFlag(name);
            if (!field || field->kind() == SettingKind::Bool) return;
            std::visit(
                [&](auto member) {
                    using V = SettingValue<decltype(member)>;
                    if constexpr (!std::is_same_v<V, bool>) target = [&pass, member](float value) { pass.*member = V(value); };
                },
                field->member);
        },
        s);
    return target;
}

render::PlacedLight lightAt(Viewer& viewer, int index)
{
    const render::Renderer& renderer = viewer.renderer();
    if (index < 0 || index >= renderer.lightCount()) throw Error("no light {} (there are {})", index, renderer.lightCount());
    return renderer.light(index);
}

} // namespace

ViewerScript::ViewerScript(const std::filesystem::path& path) : mPath(path)
{
    std::ifstream in(path);
    if (!in) throw Error("cannot read script {}", path.string());
    for (std::string line; std::getline(in, line);) mLines.push_back(line);
}

int ViewerScript::runUntilFrames(Viewer& viewer)
{
    while (mNext < mLines.size()) {
        const size_t number = ++mNext;
        try {
            const int frames = run(viewer, mLines[number - 1]);
            if (frames > 0) return frames;
        } catch (const std::exception& e) {
            throw Error("{}:{}: {}", mPath.string(), number, e.what());
        }
    }
    return 0;
}

int ViewerScript::run(Viewer& viewer, const std::string& line)
{
    const size_t hash = line.find('#');
    const Words w(hash == std::string::npos ? line : line.substr(0, hash));
    if (w.size() == 0) return 0;
    const std::string& a = w.action();
    log::info("script: {}", line);

    if (a == "frames") {
        const int n = w.integer(1);
        if (n < 1) throw Error("frames wants a count of at least 1");
        return n;
    }
    // Camera.
    if (a == "orbit") { viewer.camera().orbit(w.number(1), w.number(2)); viewer.useCamera(-1); return 0; }
    if (a == "pan") { viewer.camera().pan(w.number(1), w.number(2)); viewer.useCamera(-1); return 0; }
    if (a == "zoom") { viewer.camera().zoom(w.number(1)); viewer.useCamera(-1); return 0; }
    if (a == "look") { viewer.camera().look(w.number(1), w.number(2)); viewer.useCamera(-1); return 0; }
    if (a == "fly-move") { viewer.camera().move(w.vec3(1)); viewer.useCamera(-1); return 0; }
    if (a == "frame" || a == "reset-camera") { viewer.resetCamera(); return 0; }
    if (a == "camera") { viewer.useCamera(w.integer(1)); return 0; }
    // The animation timeline.
    if (a == "animation") {
        setup::FrameOptions options;
        options.animation = w.text(1);
        viewer.timeline.animation = setup::resolveAnimation(viewer.document().scene, options).index;
        viewer.timeline.time = 0.0f;
        return 0;
    }
    if (a == "time") { viewer.timeline.time = w.number(1); return 0; }
    // KHR_materials_variants.
    if (a == "variant") {
        setup::FrameOptions options;
        options.variant = w.text(1);
        viewer.setVariant(setup::resolveVariant(viewer.document().scene, options));
        return 0;
    }
    if (a == "play") { viewer.timeline.playing = true; return 0; }
    if (a == "pause") { viewer.timeline.playing = false; return 0; }
    if (a == "speed") { viewer.timeline.speed = w.number(1); return 0; }
    // Lights.
    if (a == "select-light") { lightAt(viewer, w.integer(1)); viewer.selectedLight = w.integer(1); return 0; }
    if (a == "add-light") {
        const std::string& type = w.text(1);
        if (type == "point") viewer.addLight(scene::Light::Type::Point);
        else if (type == "spot") viewer.addLight(scene::Light::Type::Spot);
        else if (type == "directional") viewer.addLight(scene::Light::Type::Directional);
        else throw Error("add-light wants point, spot or directional (got '{}')", type);
        return 0;
    }
    if (a == "remove-light") { viewer.removeLight(w.integer(1)); return 0; }
    if (a == "scatter-lights") { viewer.scatterLights(w.integer(1)); return 0; }
    if (a.starts_with("light-")) {
        const int i = w.integer(1);
        render::PlacedLight l = lightAt(viewer, i);
        if (a == "light-color") l.light.color = w.vec3(2);
        else if (a == "light-intensity") l.light.intensity = w.number(2);
        else if (a == "light-position") l.position = w.vec3(2);
        else if (a == "light-direction") l.direction = w.vec3(2);
        else if (a == "light-range") l.light.range = w.number(2);
        else if (a == "light-cone") {
            l.light.innerConeAngle = glm::radians(w.number(2));
            l.light.outerConeAngle = glm::radians(w.number(3));
        } else throw Error("unknown action '{}'", a);
        viewer.editLight(i, l);
        return 0;
    }
    if (a == "expect-light-upload") {
        const LightUpload& u = viewer.lastLightUpload();
        const int i = w.integer(1);
        // One line a test can read: what the last light edit wrote, and where the light lives.
        log::info("light upload: light {} wrote {} bytes, last range [{}, {}); light {} is [{}, {})", u.light, u.bytes, u.offset,
                  u.offset + u.size, i, u.lightOffset, u.lightOffset + u.lightSize);
        if (u.light != i || !u.onlyThatLight())
            throw Error("the last light edit did not rewrite exactly light {}'s bytes", i);
        return 0;
    }
    // Materials.
    if (a == "pick") {
        // pick X Y [EXPECTED]: click at window pixel (X, Y); with EXPECTED, fail unless that
        // material is picked.
        const int picked = viewer.pickMaterial(w.number(1), w.number(2));
        if (w.size() > 3 && picked != w.integer(3)) throw Error("picked material {}, expected {}", picked, w.integer(3));
        return 0;
    }
    if (a == "select-material") {
        const int index = w.integer(1);
        if (index < 0 || index >= viewer.renderer().materialCount())
            throw Error("no material {} (there are {})", index, viewer.renderer().materialCount());
        viewer.selectedMaterial = index;
        return 0;
    }
    if (a == "material-model") {
        const auto model = scene::parseShadingModel(w.text(2));
        if (!model) throw Error("unknown shading model '{}' ({})", w.text(2), scene::shadingModelNames());
        viewer.setMaterialModel(w.integer(1), *model);
        return 0;
    }
    if (a == "material-brdf") {
        // material-brdf I d|g|f|diffuse NAME|default
        const int i = w.integer(1);
        const std::string& term = w.text(2);
        const std::string& name = w.text(3);
        if (i < 0 || i >= viewer.renderer().materialCount()) throw Error("no material {}", i);
        scene::MaterialShading shading = viewer.renderer().materialShading(i);
        const bool unset = name == "default";
        auto pick = [&](auto& field, auto parsed, const char* names) {
            if (unset) {
                field.reset();
            } else if (parsed) {
                field = *parsed;
            } else {
                throw Error("unknown {} term '{}' ({})", term, name, names);
            }
        };
        if (term == "d") pick(shading.distribution, scene::parseBrdfDistribution(name), scene::brdfDistributionNames());
        else if (term == "g") pick(shading.geometry, scene::parseBrdfGeometryName(name), scene::brdfGeometryNames());
        else if (term == "f") pick(shading.fresnel, scene::parseBrdfFresnel(name), scene::brdfFresnelNames());
        else if (term == "diffuse") pick(shading.diffuse, scene::parseBrdfDiffuse(name), scene::brdfDiffuseNames());
        else throw Error("material-brdf wants d, g, f or diffuse (got '{}')", term);
        viewer.setMaterialShading(i, shading);
        return 0;
    }
    if (a == "material-color") {
        viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::BaseColor, glm::vec4(w.vec3(2), w.size() > 5 ? w.number(5) : 1.0f));
        return 0;
    }
    if (a == "material-roughness") { viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::Roughness, glm::vec4(w.number(2))); return 0; }
    if (a == "material-anisotropy") {
        viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::AnisotropyStrength, glm::vec4(w.number(2)));
        if (w.size() > 3) viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::AnisotropyRotation, glm::vec4(w.number(3)));
        return 0;
    }
    if (a == "material-clearcoat") {
        viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::ClearcoatFactor, glm::vec4(w.number(2)));
        if (w.size() > 3) viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::ClearcoatRoughness, glm::vec4(w.number(3)));
        return 0;
    }
    if (a == "material-dispersion") { viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::Dispersion, glm::vec4(w.number(2))); return 0; }
    if (a == "material-sheen") {
        viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::SheenColor, glm::vec4(w.vec3(2), 0.0f));
        if (w.size() > 5) viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::SheenRoughness, glm::vec4(w.number(5)));
        return 0;
    }
    if (a == "material-iridescence") {
        // material-iridescence I FACTOR [IOR [MIN_NM MAX_NM]]
        const int i = w.integer(1);
        viewer.setMaterialParameter(i, render::MaterialParameter::IridescenceFactor, glm::vec4(w.number(2)));
        if (w.size() > 3) viewer.setMaterialParameter(i, render::MaterialParameter::IridescenceIor, glm::vec4(w.number(3)));
        if (w.size() > 5)
            viewer.setMaterialParameter(i, render::MaterialParameter::IridescenceThickness, glm::vec4(w.number(4), w.number(5), 0.0f, 0.0f));
        return 0;
    }
    if (a == "material-diffuse-transmission") {
        // material-diffuse-transmission I FACTOR [R G B]
        viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::DiffuseTransmission, glm::vec4(w.number(2)));
        if (w.size() > 5)
            viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::DiffuseTransmissionColor, glm::vec4(w.vec3(3), 0.0f));
        return 0;
    }
    if (a == "material-metallic") { viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::Metallic, glm::vec4(w.number(2))); return 0; }
    if (a == "material-emissive") { viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::Emissive, glm::vec4(w.vec3(2), 0.0f)); return 0; }
    if (a == "material-ior") { viewer.setMaterialIor(w.integer(1), w.number(2)); return 0; }
    if (a == "material-ks") { viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::PhongSpecular, glm::vec4(w.vec3(2), 0.0f)); return 0; }
    if (a == "material-shininess") { viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::Shininess, glm::vec4(w.number(2))); return 0; }
    if (a == "material-sector-light") {
        const float level = w.number(2);
        if (level < 0.0f || level > 255.0f) throw Error("a sector light level is 0 to 255 (got {})", level);
        viewer.setMaterialParameter(w.integer(1), render::MaterialParameter::SectorLight, glm::vec4(level));
        return 0;
    }
    // Frame settings.
    if (a == "toggle") {
        bool* flag = toggleTarget(viewer, w.text(1));
        if (!flag) throw Error("cannot toggle '{}' ({})", w.text(1), toggleNames());
        *flag = !*flag;
        return 0;
    }
    if (a == "set") {
        const std::function<void(float)> set = valueTarget(viewer, w.text(1));
        if (!set) throw Error("cannot set '{}'", w.text(1));
        set(w.number(2));
        return 0;
    }
    if (a == "tonemap") {
        const auto tonemap = render::parseTonemap(w.text(1));
        if (!tonemap) throw Error("unknown tone mapper '{}'", w.text(1));
        viewer.settings().tonemap = *tonemap;
        return 0;
    }
    if (a == "debug-view") {
        const auto view = parseDebugView(w.text(1));
        if (!view) throw Error("unknown debug view '{}'", w.text(1));
        viewer.settings().debugView = *view;
        return 0;
    }
    // Files and tools.
    if (a == "open") { viewer.openFile(w.text(1)); return 0; }
    if (a == "env") {
        if (w.text(1) == "sky") {
            viewer.loadEnvironment("sky");
        } else {
            viewer.openFile(w.text(1));
        }
        return 0;
    }
    if (a == "env-sun") {
        viewer.setSunExtraction(setup::extractsSun(w.text(1)));
        return 0;
    }
    if (a == "expect-error") {
        if (viewer.lastError.empty()) throw Error("expected the UI to show an error; it shows none");
        log::info("UI error: {}", viewer.lastError);
        viewer.lastError.clear();
        return 0;
    }
    if (a == "expect-no-error") {
        if (!viewer.lastError.empty()) throw Error("the UI shows an error: {}", viewer.lastError);
        return 0;
    }
    if (a == "resize") {
        // As a user dragging the window's corner: the next frames render at the new size.
        const int width = w.integer(1), height = w.integer(2);
        if (width < 1 || height < 1) throw Error("resize wants a positive width and height");
        glfwSetWindowSize(static_cast<GLFWwindow*>(viewer.context().nativeWindow()), width, height);
        return 0;
    }
    if (a == "panel") {
        // panel NAME open|closed: arranges the panels (for screenshots with the UI).
        static const std::map<std::string, std::string> kPanels = {
            {"statistics", "Statistics"}, {"scene", "Scene"}, {"animation", "Animation"}, {"lights", "Lights"}, {"materials", "Materials"},
            {"brdf", "BRDF explorer"}, {"environment", "Environment"}, {"post", "Post-processing"}};
        const auto panel = kPanels.find(w.text(1));
        if (panel == kPanels.end()) throw Error("no panel '{}' (statistics, scene, lights, materials, brdf, environment, post)", w.text(1));
        if (w.text(2) != "open" && w.text(2) != "closed") throw Error("panel wants open or closed (got '{}')", w.text(2));
        viewer.panelRequests[panel->second] = w.text(2) == "open";
        return 0;
    }
    if (a == "log-memory") {
        // The soak's figures (docs/testing.md#soak): resident memory and the GL objects held.
        const gl::ObjectCounts objects = gl::liveObjects();
        log::info("memory: resident {:.1f} MiB, heap in use {:.1f} MiB, GL objects {} ({})", residentMebibytes(), heapInUseMebibytes(), objects.total(), objects.describe());
        return 0;
    }
    if (a == "log-stats") {
        // What the Statistics panel shows of the last frame, as one line.
        const render::FrameStats& stats = viewer.renderer().stats();
        std::string passes;
        for (const render::PassTiming& pass : stats.passes) passes += fmt::format(", {} {:.3f} ms", pass.name, pass.gpuMs);
        log::info("frame stats: {} draw calls, {} triangles{}", stats.drawCalls, stats.triangles, passes);
        if (stats.clusters.slices > 0)
            log::info("light clusters: {} lights in view, {} directional, per cluster max {}, mean {:.2f}", stats.clusters.lightsInView,
                      stats.clusters.directional, stats.clusters.maxPerCluster, stats.clusters.meanPerCluster);
        return 0;
    }
    if (a == "reload-shaders") { viewer.reloadShaders(); return 0; }
    if (a == "poll-shaders") {
        // What the interactive viewer does twice a second: reload if a shader file changed.
        if (!viewer.reloadChangedShaders()) log::info("shader files unchanged");
        return 0;
    }
    if (a == "copy-file") {
        // As an editor saving a file: lets a script change a shader between frames.
        std::filesystem::copy_file(w.text(1), w.text(2), std::filesystem::copy_options::overwrite_existing);
        return 0;
    }
    if (a == "screenshot") { viewer.screenshot(w.text(1)); return 0; }
    if (a == "screenshot-window") {
        // The window as shown, panels included: needs a frame drawn with the UI.
        viewer.screenshotWindow(w.text(1));
        return 1;
    }
    throw Error("unknown action '{}'", a);
}

} // namespace specula::viewer
