#include "SceneSetup.h"

#include "core/Error.h"
#include "scene/DemoScenes.h"

namespace specula::cli {

scene::SceneDocument loadSceneOrBuiltin(const std::string& name)
{
    if (name.empty() || name == "demo") {
        scene::SceneDocument document;
        document.scene = scene::makeDemoScene();
        document.render.tonemap = "neutral";
        return document;
    }
    if (name == "learnopengl") {
        // The tutorial's look: Reinhard, Schlick-GGX, constant ambient 0.03 x albedo.
        scene::SceneDocument document;
        document.scene = scene::makeLearnOpenGlScene();
        document.render.tonemap = "reinhard";
        document.render.brdfG = "schlick-ggx";
        document.render.defaultLights = false;
        return document;
    }
    return scene::loadScene(name);
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
    if (!parsedTonemap) throw Error("unknown tone mapper '{}' (none, reinhard, reinhard-ext, aces, neutral)", tonemap);
    s.tonemap = *parsedTonemap;
    const std::string g = options.brdfG.value_or(file.brdfG.value_or("smith-ggx"));
    const auto geometry = render::parseBrdfGeometry(g);
    if (!geometry) throw Error("unknown --brdf-g '{}' (smith-ggx, schlick-ggx)", g);
    s.brdfGeometry = *geometry;
    if (document.environment.color) s.background = *document.environment.color * document.environment.intensity;
    if (document.scene.name == "learnopengl") s.ambient = glm::vec3(0.03f);
    return s;
}

render::View prepareView(scene::SceneDocument& document, const FrameOptions& options,
                         const render::FrameSettings& settings, int* added)
{
    const float aspect = float(settings.width) / float(settings.height);
    const render::View view = render::defaultView(document.scene, options.camera, aspect);
    int count = 0;
    const bool allowed = !options.noDefaultLights && document.render.defaultLights.value_or(true);
    if (document.scene.lights.empty() && allowed) {
        // The rig follows the viewer: from the scene's centre towards the camera.
        const glm::vec3 center = document.scene.worldBounds().empty() ? glm::vec3(0.0f) : document.scene.worldBounds().center();
        glm::vec3 toViewer = view.position - center;
        if (glm::length(toViewer) < 1e-6f) toViewer = glm::vec3(0, 0, 1);
        count = scene::addDefaultLightRig(document.scene, toViewer);
    }
    if (added) *added = count;
    return view;
}

} // namespace specula::cli
