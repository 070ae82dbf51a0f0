#include "scene/BuiltinScenes.h"

#include "scene/DemoScenes.h"
#include "scene/DoomLevel.h"

namespace specula::scene {

std::optional<SceneDocument> builtinScene(std::string_view name, std::optional<int> lights)
{
    SceneDocument document;
    if (name.empty() || name == "demo") {
        document.scene = makeDemoScene();
        document.render.tonemap = "neutral";
        return document;
    }
    if (name == "learnopengl" || name == "learnopengl-ibl") {
        // The tutorial's look: Reinhard, Schlick-GGX (k = r^2/2 for the environment), and for
        // the lighting demo a constant ambient 0.03 x albedo and no environment, as the tutorial has.
        const bool lighting = name == "learnopengl";
        document.scene = lighting ? makeLearnOpenGlScene() : makeLearnOpenGlIblScene();
        document.render.tonemap = "reinhard";
        document.render.brdfG = "schlick-ggx";
        document.render.defaultLights = false;
        if (lighting) {
            document.render.ambient = glm::vec3(0.03f);
            document.environment.skyByDefault = false;
        }
        return document;
    }
    if (name == "many-lights") {
        // Clustered shading's benchmark: lights only where they are placed, no sky, no rig; a
        // faint ambient so that the unlit floor reads as a floor.
        document.scene = makeManyLightsScene(lights.value_or(kManyLightsDefault));
        document.render.defaultLights = false;
        document.render.ambient = glm::vec3(0.01f);
        document.environment.skyByDefault = false;
        return document;
    }
    if (name == "doom") {
        // The Doom-era demo level (scene/DoomLevel.h): its materials use the Doom model, and
        // its frame is Doom's 8-bit frame (render/DoomPass) unless --shading says otherwise.
        // Its lamps hold point lights for the other models; it needs no default rig. It is
        // indoors: a sky would light its rooms through their walls under the image-based models.
        document.scene = doom::makeDemoLevel();
        document.render.defaultLights = false;
        document.render.shading = "doom";
        document.environment.skyByDefault = false;
        return document;
    }
    return std::nullopt;
}

} // namespace specula::scene
