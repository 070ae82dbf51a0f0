// The scene file's post-processing and camera-exposure keys (docs/scene-format.md, "post",
// "camera" aperture/shutter/iso, "render" ev100): values parsed, errors one line.
#include <gtest/gtest.h>

#include <string>

#include "TestFiles.h"
#include "scene/SceneFile.h"

using namespace specula;

namespace {

scene::SceneDocument load(const std::string& text)
{
    return test::loadSceneText(text);
}

} // namespace

TEST(PostFile, PassesAsObjectsAndBooleans)
{
    const auto d = load(R"({"post": {
        "bloom": {"intensity": 0.1, "levels": 5, "radius": 1.5, "threshold": 1, "knee": 0.25, "fireflyFilter": false},
        "ssao": {"radius": 0.3, "bias": 0.01, "power": 2, "samples": 32},
        "autoExposure": {"enabled": false, "minEv100": 0, "maxEv100": 12, "lowPercentile": 0.2, "highPercentile": 0.9,
                         "speedUp": 2, "speedDown": 0.5},
        "fxaa": true}})");
    EXPECT_EQ(d.post.bloom.get(&BloomSettings::enabled), true);
    EXPECT_EQ(d.post.bloom.get(&BloomSettings::intensity), 0.1f);
    EXPECT_EQ(d.post.bloom.get(&BloomSettings::levels), 5);
    EXPECT_EQ(d.post.bloom.get(&BloomSettings::radius), 1.5f);
    EXPECT_EQ(d.post.bloom.get(&BloomSettings::threshold), 1.0f);
    EXPECT_EQ(d.post.bloom.get(&BloomSettings::knee), 0.25f);
    EXPECT_EQ(d.post.bloom.get(&BloomSettings::fireflyFilter), false);
    EXPECT_EQ(d.post.ssao.get(&SsaoSettings::enabled), true);
    EXPECT_EQ(d.post.ssao.get(&SsaoSettings::radius), 0.3f);
    EXPECT_EQ(d.post.ssao.get(&SsaoSettings::bias), 0.01f);
    EXPECT_EQ(d.post.ssao.get(&SsaoSettings::power), 2.0f);
    EXPECT_EQ(d.post.ssao.get(&SsaoSettings::samples), 32);
    EXPECT_EQ(d.post.autoExposure.get(&AutoExposureSettings::enabled), false);
    EXPECT_EQ(d.post.autoExposure.get(&AutoExposureSettings::minEv100), 0.0f);
    EXPECT_EQ(d.post.autoExposure.get(&AutoExposureSettings::maxEv100), 12.0f);
    EXPECT_EQ(d.post.autoExposure.get(&AutoExposureSettings::lowPercentile), 0.2f);
    EXPECT_EQ(d.post.autoExposure.get(&AutoExposureSettings::highPercentile), 0.9f);
    EXPECT_EQ(d.post.autoExposure.get(&AutoExposureSettings::speedUp), 2.0f);
    EXPECT_EQ(d.post.autoExposure.get(&AutoExposureSettings::speedDown), 0.5f);
    EXPECT_EQ(d.post.fxaa.get(&FxaaSettings::enabled), true);

    const auto off = load(R"({"post": {"bloom": false, "ssao": true}})");
    EXPECT_EQ(off.post.bloom.get(&BloomSettings::enabled), false);
    EXPECT_EQ(off.post.ssao.get(&SsaoSettings::enabled), true);
    EXPECT_FALSE(off.post.ssao.get(&SsaoSettings::radius).has_value());
    EXPECT_FALSE(off.post.fxaa.get(&FxaaSettings::enabled).has_value());
    EXPECT_FALSE(off.post.autoExposure.get(&AutoExposureSettings::enabled).has_value());
}

TEST(PostFile, CameraExposure)
{
    const auto camera = load(R"({"camera": {"position": [0, 0, 5], "aperture": 2.8, "shutter": 0.004, "iso": 400}})");
    ASSERT_TRUE(camera.render.cameraExposure.has_value());
    EXPECT_EQ(camera.render.cameraExposure->aperture, 2.8f);
    EXPECT_EQ(camera.render.cameraExposure->shutter, 0.004f);
    EXPECT_EQ(camera.render.cameraExposure->iso, 400.0f);
    EXPECT_FALSE(camera.render.ev100.has_value());
    // Render settings after the camera do not drop it.
    const auto both = load(R"({"camera": {"position": [0, 0, 5], "aperture": 8, "shutter": 0.01, "iso": 100},
                              "render": {"width": 64}})");
    EXPECT_TRUE(both.render.cameraExposure.has_value());
    const auto ev = load(R"({"render": {"ev100": 9.5, "tonemap": "agx"}})");
    EXPECT_EQ(ev.render.ev100, 9.5f);
    EXPECT_EQ(ev.render.tonemap, "agx");
}

TEST(PostFile, Errors)
{
    struct Case {
        const char* text;
        const char* expected;
    };
    for (const Case c : {
             Case{R"({"post": {"blom": true}})", "unknown key 'blom' in post (did you mean 'bloom'?)"},
             Case{R"({"post": {"bloom": {"intensty": 1}}})", "unknown key 'intensty' in post.bloom (did you mean 'intensity'?)"},
             Case{R"({"post": {"bloom": 1}})", "post.bloom must be true, false or an object"},
             Case{R"({"post": {"bloom": {"levels": 9}}})", "post.bloom.levels must be between 1 and 8"},
             Case{R"({"post": {"bloom": {"intensity": -1}}})", "post.bloom.intensity must not be negative"},
             Case{R"({"post": {"bloom": {"knee": 2}}})", "post.bloom.knee must be between 0 and 1"},
             Case{R"({"post": {"ssao": {"radius": 0}}})", "post.ssao.radius must be positive"},
             Case{R"({"post": {"ssao": {"samples": 65}}})", "post.ssao.samples must be between 1 and 64"},
             Case{R"({"post": {"ssao": {"enabled": "yes"}}})", "post.ssao.enabled must be true or false"},
             Case{R"({"post": {"autoExposure": {"minEv100": 10, "maxEv100": 5}}})", "post.autoExposure.minEv100 must be less than maxEv100"},
             Case{R"({"post": {"autoExposure": {"highPercentile": 1.5}}})", "post.autoExposure.highPercentile must be between 0 and 1"},
             Case{R"({"post": {"fxaa": {"quality": 1}}})", "unknown key 'quality' in post.fxaa"},
             Case{R"({"camera": {"position": [0, 0, 1], "aperture": 2.8}})", "camera needs 'aperture', 'shutter' and 'iso' together"},
             Case{R"({"camera": {"position": [0, 0, 1], "aperture": 2.8, "shutter": 0, "iso": 100}})", "camera.shutter must be positive"},
             Case{R"({"camera": {"position": [0, 0, 1], "aperture": 2.8, "shutter": 0.01, "iso": 100}, "render": {"ev100": 3}})",
                  "render.ev100 and the camera's aperture, shutter and iso both set the exposure; give one"},
             Case{R"({"render": {"tonemap": "filmic"}})", "render.tonemap must be none, reinhard, reinhard-ext, aces, neutral or agx"},
         }) {
        const std::string message = test::sceneError(c.text);
        EXPECT_NE(message.find(c.expected), std::string::npos) << c.text << "\n  gave: " << message;
    }
}
