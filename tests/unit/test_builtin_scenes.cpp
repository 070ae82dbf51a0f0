// The built-in scenes carry their look as data of their documents (scene/BuiltinScenes.h), which
// setup::resolveSettings and setup::loadEnvironment read like any scene file's; no layer asks a
// scene's name.
#include <gtest/gtest.h>

#include "TestFiles.h"
#include "scene/BuiltinScenes.h"
#include "setup/SceneSetup.h"

using namespace specula;

TEST(BuiltinScenes, Names)
{
    for (const char* name : {"", "demo", "learnopengl", "learnopengl-ibl", "doom"}) EXPECT_TRUE(scene::builtinScene(name)) << name;
    EXPECT_FALSE(scene::builtinScene("scene.json"));
    EXPECT_FALSE(scene::builtinScene("Demo"));
}

TEST(BuiltinScenes, TheirLookIsData)
{
    const setup::FrameOptions none;
    const scene::SceneDocument demo = *scene::builtinScene("demo");
    EXPECT_TRUE(demo.environment.skyByDefault);
    EXPECT_EQ(setup::resolveSettings(demo, none).ambient, glm::vec3(0.0f));
    EXPECT_EQ(setup::resolveSettings(demo, none).tonemap, render::Tonemap::Neutral);

    // The lighting tutorial: Reinhard, Schlick-GGX, ambient 0.03 × albedo, no environment, no rig.
    scene::SceneDocument lighting = *scene::builtinScene("learnopengl");
    const render::FrameSettings s = setup::resolveSettings(lighting, none);
    EXPECT_EQ(s.ambient, glm::vec3(0.03f));
    EXPECT_EQ(s.tonemap, render::Tonemap::Reinhard);
    EXPECT_EQ(s.brdfGeometry, render::BrdfGeometry::SchlickGGX);
    EXPECT_FALSE(setup::loadEnvironment(lighting, none).has_value());
    EXPECT_EQ(lighting.render.defaultLights, false);
    // --env sky still gives it one.
    setup::FrameOptions sky;
    sky.env = "sky";
    EXPECT_TRUE(setup::loadEnvironment(lighting, sky).has_value());

    // Its image-based sibling keeps the sky and has no constant ambient.
    const scene::SceneDocument ibl = *scene::builtinScene("learnopengl-ibl");
    EXPECT_TRUE(ibl.environment.skyByDefault);
    EXPECT_EQ(setup::resolveSettings(ibl, none).ambient, glm::vec3(0.0f));

    // The Doom level is indoors: no sky; its frame is the Doom model's.
    scene::SceneDocument doom = *scene::builtinScene("doom");
    EXPECT_FALSE(setup::loadEnvironment(doom, none).has_value());
    EXPECT_EQ(setup::resolveSettings(doom, none).materialOverride.model, scene::ShadingModel::Doom);
}

TEST(BuiltinScenes, AFileNamedLikeOneIsAFile)
{
    // A scene file's name is no policy: learnopengl.json gets the defaults of any file.
    test::TempDir dir("builtin");
    const scene::SceneDocument file = setup::loadSceneOrBuiltin(dir.write("learnopengl.json", R"({"shapes": [{"type": "sphere"}]})").string());
    EXPECT_EQ(file.scene.name, "learnopengl");
    EXPECT_TRUE(file.environment.skyByDefault);
    EXPECT_EQ(setup::resolveSettings(file, setup::FrameOptions{}).ambient, glm::vec3(0.0f));
}
