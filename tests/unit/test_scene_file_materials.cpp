// Scene files set each material's shading model, BRDF terms, IOR and shininess
// (docs/scene-format.md); unknown names are one-line errors.
#include <gtest/gtest.h>

#include <string>

#include "TestFiles.h"
#include "scene/SceneFile.h"

using namespace specula;
using namespace specula::scene;

TEST(SceneFileMaterials, ShadingAndBrdfPerMaterial)
{
    const SceneDocument d = test::loadSceneText(R"({"shapes": [
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
        return test::sceneError(R"({"shapes": [{"type": "sphere", "material": )" + material + "}]}");
    };
    EXPECT_NE(error(R"({"shading": "toon"})").find("shading"), std::string::npos);
    EXPECT_NE(error(R"({"brdfG": "smith"})").find("brdfG"), std::string::npos);
    EXPECT_NE(error(R"({"ior": 0.5})").find("ior"), std::string::npos);
    EXPECT_NE(error(R"({"brdfd": "ggx"})").find("brdfd"), std::string::npos); // strict keys
}
