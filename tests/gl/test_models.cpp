// Real glTF sample models render with no GL error and a non-empty image, lit by the default
// rig (or their own lights). The pictures themselves are reviewed by eye (docs/images).
#include "GlTestContext.h"

#include <filesystem>

#include "render/LightBuffer.h"
#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/GltfImporter.h"

using namespace specula;
using specula::test::GlTest;

namespace {

const std::string kModels = std::string(SPECULA_ASSETS_DIR) + "/models/";

struct Coverage {
    double covered = 0.0; ///< fraction of pixels not equal to the background
    double meanLuminance = 0.0;
};

Coverage renderModel(const std::string& path)
{
    scene::Scene s = scene::loadGltf(kModels + path);
    render::FrameSettings settings;
    settings.width = 320;
    settings.height = 240;
    const render::View view = render::frameBounds(s.worldBounds(), 4.0f / 3.0f);
    if (s.lights.empty()) scene::addDefaultLightRig(s, view.position - s.worldBounds().center());
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, settings);
    const ImageFloat image = renderer.readRadiance();
    // Kept for review by eye: build/test-output/models/<name>.png
    const std::filesystem::path out = std::filesystem::path(SPECULA_TEST_OUTPUT_DIR) / "models";
    std::filesystem::create_directories(out);
    writePng(out / (std::filesystem::path(path).stem().string() + ".png"), renderer.readImage());
    Coverage c;
    size_t covered = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        const float l = 0.2126f * image.pixels[i] + 0.7152f * image.pixels[i + 1] + 0.0722f * image.pixels[i + 2];
        EXPECT_TRUE(std::isfinite(l)) << path;
        if (l > 1e-4f) ++covered;
        c.meanLuminance += l;
    }
    c.covered = double(covered) / double(image.pixels.size() / 4);
    c.meanLuminance /= double(image.pixels.size() / 4);
    return c;
}

} // namespace

TEST_F(GlTest, SampleModelsRender)
{
    const char* models[] = {
        "DamagedHelmet/DamagedHelmet.glb",
        "WaterBottle/WaterBottle.gltf",
        "NormalTangentMirrorTest/NormalTangentMirrorTest.glb",
        "AlphaBlendModeTest/AlphaBlendModeTest.glb",
        "TextureSettingsTest/TextureSettingsTest.glb",
        "OrientationTest/OrientationTest.glb",
        "BoxTextured/BoxTextured.gltf",
        "Box/Box.glb",
    };
    for (const char* model : models) {
        if (!std::filesystem::exists(kModels + model)) {
            ADD_FAILURE() << "missing sample model " << model;
            continue;
        }
        const Coverage c = renderModel(model);
        EXPECT_GT(c.covered, 0.05) << model << " rendered almost nothing";
        EXPECT_GT(c.meanLuminance, 0.005) << model << " rendered black";
    }
}
