// Scene files set each material's shading model, BRDF terms, IOR and shininess
// (docs/scene-format.md); unknown names are one-line errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "core/Error.h"
#include "scene/SceneFile.h"

namespace fs = std::filesystem;
using namespace specula;
using namespace specula::scene;

namespace {

SceneDocument loadText(const std::string& text)
{
    std::random_device random;
    const fs::path path = fs::temp_directory_path() / ("specula-materials-" + std::to_string(random()) + ".json");
    std::ofstream(path) << text;
    struct Remove {
        fs::path p;
        ~Remove() { fs::remove(p); }
    } remove{path};
    return loadSceneFile(path);
}

} // namespace

TEST(SceneFileMaterials, ShadingAndBrdfPerMaterial)
{
    const SceneDocument d = loadText(R"({"shapes": [
        {"type": "sphere", "material": {"shading": "blinn-phong", "shininess": 64}},
        {"type": "sphere", "material": {"brdfD": "beckmann", "brdfG": "kelemen", "brdfF": "schlick-sg",
                                        "brdfDiffuse": "oren-nayar", "ior": 1.33}},
        {"type": "sphere"}]})");
    ASSERT_EQ(d.scene.materials.size(), 3u);
    const Material& a = d.scene.materials[0];
    EXPECT_EQ(a.shading.model, ShadingModel::BlinnPhong);
    EXPECT_FLOAT_EQ(a.shininess, 64.0f);
    EXPECT_FALSE(a.shading.distribution);
    const Material& b = d.scene.materials[1];
    EXPECT_FALSE(b.shading.model);
    EXPECT_EQ(b.shading.distribution, BrdfDistribution::Beckmann);
    EXPECT_EQ(b.shading.geometry, BrdfGeometry::Kelemen);
    EXPECT_EQ(b.shading.fresnel, BrdfFresnel::SchlickSG);
    EXPECT_EQ(b.shading.diffuse, BrdfDiffuse::OrenNayar);
    ASSERT_TRUE(b.ior);
    EXPECT_FLOAT_EQ(*b.ior, 1.33f);
    const Material& c = d.scene.materials[2];
    EXPECT_FALSE(c.shading.model || c.shading.geometry || c.ior);
}

TEST(SceneFileMaterials, BadNamesAreErrors)
{
    auto error = [](const std::string& material) {
        try {
            loadText(R"({"shapes": [{"type": "sphere", "material": )" + material + "}]}");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(error(R"({"shading": "toon"})").find("shading"), std::string::npos);
    EXPECT_NE(error(R"({"brdfG": "smith"})").find("brdfG"), std::string::npos);
    EXPECT_NE(error(R"({"ior": 0.5})").find("ior"), std::string::npos);
    EXPECT_NE(error(R"({"brdfd": "ggx"})").find("brdfd"), std::string::npos); // strict keys
}

// "render": {"shading"} is the frame's override, as --shading (the Doom model makes the frame
// Doom's 8-bit frame).
TEST(SceneFileMaterials, RenderShadingIsTheFramesModel)
{
    EXPECT_EQ(loadText(R"({"render": {"shading": "doom"}})").render.shading, std::string("doom"));
    EXPECT_FALSE(loadText(R"({"render": {"msaa": 4}})").render.shading);
    try {
        loadText(R"({"render": {"shading": "quake"}})");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("render.shading"), std::string::npos) << e.what();
    }
}
