// Real glTF sample models render with no GL error and a non-empty image, lit by the default
// rig (or their own lights). The pictures themselves are reviewed by eye (docs/images).
#include "GlTestContext.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
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

namespace {

const std::string kTestAssets = std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/";

/// Radiance of `s` seen from `view`, lit by the default rig placed for `view` (as renderModel).
ImageFloat renderFrom(scene::Scene s, const render::View& view, const glm::vec3& rigOffset, const std::string& name)
{
    render::FrameSettings settings;
    settings.width = 320;
    settings.height = 240;
    scene::addDefaultLightRig(s, rigOffset);
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, settings);
    const std::filesystem::path out = std::filesystem::path(SPECULA_TEST_OUTPUT_DIR) / "models";
    std::filesystem::create_directories(out);
    writePng(out / (name + ".png"), renderer.readImage());
    return renderer.readRadiance();
}

} // namespace

// The compressed files render as their originals do, from the original's framing and lights.
// GltfCompression (unit tests) shows that every decoded vertex is an original one within the
// quantisation; what differs here is what the compressors did besides: quantisation moves
// normals by up to 0.24° (Draco, 10 bits) or 1° (meshopt, 8 bits); glTF-Transform's `optimize`
// simplified the Draco files (the logo from 2,696 to 1,552 triangles: its large faces' normals
// now interpolate between fewer vertices, a smooth difference across them), and the WebP logo's
// texture is a lossy 512² copy of the 2048² JPEG. Relative differences of a pixel's luminance
// where either image covers it; thresholds are the measured values (in the comments) with a
// margin. build/test-output/models/ keeps both images and |Δ| × 4 of each pair.
TEST_F(GlTest, CompressedModelsRenderLikeTheirOriginals)
{
    struct Case {
        std::string original, compressed;
        double meanTolerance;    ///< mean |ΔL| / mean L over covered pixels
        double outlierTolerance; ///< fraction of covered pixels off by more than 10 %
    };
    const Case cases[] = {
        {kModels + "PmndrsBunny/bunny.glb", kModels + "PmndrsBunny/bunny_draco.glb", 0.005, 0.01},  // 0.0010, 0.23 %
        {kModels + "PmndrsSuzi/suzi.glb", kModels + "PmndrsSuzi/suzi_draco.glb", 0.01, 0.02},      // 0.0031, 1.14 %
        {kModels + "PmndrsLogo/pmndrs.glb", kModels + "PmndrsLogo/pmndrs_draco.glb", 0.06, 0.10},  // 0.045, 7.7 %
        {kModels + "PmndrsBunny/bunny.glb", kTestAssets + "bunny_meshopt.glb", 0.01, 0.015},       // 0.0034, 0.59 %
        {kModels + "PmndrsLogo/pmndrs.glb", kTestAssets + "logo_webp_meshopt.glb", 0.005, 0.005},  // 0.0013, 0.14 %
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.compressed);
        scene::Scene original = scene::loadGltf(c.original);
        scene::Scene compressed = scene::loadGltf(c.compressed);
        // The bunny's material is BLEND with alpha 1: blended triangles are drawn in their
        // order, unsorted within a mesh, so its picture depends on the triangle order, which both
        // compressors change. Opaque, the picture is the geometry's.
        for (scene::Scene* s : {&original, &compressed})
            for (scene::Material& m : s->materials) m.alphaMode = scene::AlphaMode::Opaque;
        const render::View view = render::frameBounds(original.worldBounds(), 4.0f / 3.0f);
        const glm::vec3 rig = view.position - original.worldBounds().center();
        const std::string stem = std::filesystem::path(c.compressed).stem().string();
        const ImageFloat a = renderFrom(original, view, rig, stem + "-original");
        const ImageFloat b = renderFrom(compressed, view, rig, stem);
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        double sumDiff = 0.0, sumLuminance = 0.0;
        size_t covered = 0, outliers = 0;
        auto luminance = [](const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; };
        for (size_t i = 0; i < a.pixels.size(); i += 4) {
            const double la = luminance(&a.pixels[i]), lb = luminance(&b.pixels[i]);
            if (la <= 1e-4 && lb <= 1e-4) continue;
            ++covered;
            sumDiff += std::abs(la - lb);
            sumLuminance += la;
            outliers += std::abs(la - lb) > 0.1 * std::max(la, lb);
        }
        ImageRGBA8 diff{a.width, a.height, std::vector<uint8_t>(a.pixels.size(), 255)};
        for (size_t i = 0; i < a.pixels.size(); i += 4)
            for (size_t k = 0; k < 3; ++k)
                diff.pixels[i + k] = uint8_t(std::min(255.0f, 255.0f * 4.0f * std::abs(a.pixels[i + k] - b.pixels[i + k])));
        writePng(std::filesystem::path(SPECULA_TEST_OUTPUT_DIR) / "models" / (stem + "-diff.png"), diff);
        ASSERT_GT(covered, 5000u);
        const double mean = sumDiff / sumLuminance, fraction = double(outliers) / double(covered);
        std::printf("  %s: %zu pixels covered, mean |dL|/L %.4f, %.3f%% off by more than 10%%\n", stem.c_str(), covered,
                    mean, 100.0 * fraction);
        EXPECT_LE(mean, c.meanTolerance);
        EXPECT_LE(fraction, c.outlierTolerance);
    }
}
