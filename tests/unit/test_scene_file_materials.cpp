// Scene files set each material's shading model, BRDF terms, IOR and shininess
// (docs/scene-format.md); unknown names are one-line errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "TestFiles.h"
#include "scene/SceneFile.h"

namespace fs = std::filesystem;
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

// A model's materials keep their glTF parameters and textures; the scene file overrides the
// keys it gives, for every material ("*") and then by name or "#index".
TEST(SceneFileMaterials, ModelMaterialsByName)
{
    const std::string model = (fs::path(SPECULA_ASSETS_DIR) / "models/AlphaBlendModeTest/AlphaBlendModeTest.glb").string();
    const SceneDocument plain = test::loadSceneText(R"({"models": [{"path": ")" + model + R"("}]})");
    const SceneDocument d = test::loadSceneText(R"({"models": [{"path": ")" + model + R"(", "materials": {
        "MatBlend": {"shading": "phong", "shininess": 32},
        "#5": {"brdfD": "beckmann", "roughness": 0.25},
        "*": {"shading": "gouraud", "brdfDiffuse": "burley"}}}]})");
    ASSERT_EQ(d.scene.materials.size(), plain.scene.materials.size());
    for (size_t i = 0; i < d.scene.materials.size(); ++i) {
        const Material &m = d.scene.materials[i], &p = plain.scene.materials[i];
        SCOPED_TRACE(m.name);
        EXPECT_EQ(m.shading.diffuse, BrdfDiffuse::Burley); // "*"
        EXPECT_EQ(m.baseColorTexture.image, p.baseColorTexture.image); // textures kept
        EXPECT_EQ(m.alphaMode, p.alphaMode);
        if (m.name == "MatBlend") {
            EXPECT_EQ(m.shading.model, ShadingModel::Phong); // the name wins over "*"
            EXPECT_FLOAT_EQ(m.shininess, 32.0f);
        } else {
            EXPECT_EQ(m.shading.model, ShadingModel::Gouraud);
        }
        if (i == 5) {
            EXPECT_EQ(m.shading.distribution, BrdfDistribution::Beckmann);
            EXPECT_FLOAT_EQ(m.roughnessFactor, 0.25f);
        } else {
            EXPECT_FALSE(m.shading.distribution);
            EXPECT_FLOAT_EQ(m.roughnessFactor, p.roughnessFactor);
        }
    }

    auto error = [&](const std::string& materials) {
        return test::sceneError(R"({"models": [{"path": ")" + model + R"(", "materials": )" + materials + "}]}");
    };
    const std::string unknown = error(R"({"MatBlnd": {"shading": "phong"}})");
    EXPECT_NE(unknown.find("'MatBlnd'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("'MatBlend'"), std::string::npos) << unknown; // lists the names it has
    EXPECT_NE(error(R"({"#6": {}})").find("has 6 materials"), std::string::npos);
    EXPECT_NE(error(R"({"*": {"name": "x"}})").find("unknown key 'name'"), std::string::npos);
    EXPECT_NE(error(R"({"*": {"shading": "toon"}})").find("models[0].materials.*.shading"), std::string::npos);
    EXPECT_NE(error(R"([1])").find("must be an object"), std::string::npos);
}

// "render": {"shading"} is the frame's override, as --shading (the Doom model makes the frame
// Doom's 8-bit frame).
TEST(SceneFileMaterials, RenderShadingIsTheFramesModel)
{
    EXPECT_EQ(test::loadSceneText(R"({"render": {"shading": "doom"}})").render.shading, std::string("doom"));
    EXPECT_FALSE(test::loadSceneText(R"({"render": {"msaa": 4}})").render.shading);
    const std::string error = test::sceneError(R"({"render": {"shading": "quake"}})");
    EXPECT_NE(error.find("render.shading"), std::string::npos) << error;
}

// Transparent surfaces (docs/transparency.md): blendMode on blended materials only, and the
// transmission and volume keys of KHR_materials_transmission and KHR_materials_volume.
TEST(SceneFileMaterials, BlendModeAndTransmission)
{
    const SceneDocument d = test::loadSceneText(R"({"shapes": [
        {"type": "sphere", "material": {"baseColor": [1, 1, 1, 0.1], "alphaMode": "blend", "blendMode": "transparent"}},
        {"type": "sphere", "material": {"alphaMode": "blend"}},
        {"type": "sphere", "material": {"transmission": 0.9, "ior": 1.45, "thickness": 0.2, "attenuationDistance": 0.5,
                                        "attenuationColor": [0.9, 0.8, 0.7], "dispersion": 0.33}}],
        "render": {"transparency": "oit"}})");
    ASSERT_EQ(d.scene.materials.size(), 3u);
    EXPECT_EQ(d.scene.materials[0].blendMode, BlendMode::Transparent);
    EXPECT_EQ(d.scene.materials[1].blendMode, BlendMode::Fade); // the glTF specification's behaviour
    const Material& glass = d.scene.materials[2];
    EXPECT_FLOAT_EQ(glass.transmissionFactor, 0.9f);
    EXPECT_FLOAT_EQ(glass.thickness, 0.2f);
    EXPECT_FLOAT_EQ(glass.dispersion, 0.33f); // KHR_materials_dispersion
    EXPECT_FLOAT_EQ(glass.attenuationDistance, 0.5f);
    EXPECT_EQ(glass.attenuationColor, glm::vec3(0.9f, 0.8f, 0.7f));
    EXPECT_FLOAT_EQ(glass.ior.value_or(0.0f), 1.45f);
    EXPECT_EQ(d.render.transparency, "oit");

    auto error = [](const std::string& material) {
        return test::sceneError(R"({"shapes": [{"type": "sphere", "material": )" + material + "}]}");
    };
    EXPECT_NE(error(R"({"blendMode": "transparent"})").find("alphaMode \"blend\""), std::string::npos);
    EXPECT_NE(error(R"({"alphaMode": "blend", "blendMode": "additive"})").find("blendMode"), std::string::npos);
    EXPECT_NE(error(R"({"transmission": 1.5})").find("transmission"), std::string::npos);
    EXPECT_NE(error(R"({"thickness": -1})").find("thickness"), std::string::npos);
    EXPECT_NE(error(R"({"dispersion": -0.5})").find("dispersion"), std::string::npos);
    EXPECT_NE(error(R"({"attenuationColor": [2, 1, 1]})").find("attenuationColor"), std::string::npos);
    EXPECT_NE(test::sceneError(R"({"render": {"transparency": "depth-peeling"}})").find("transparency"), std::string::npos);
}

// KHR_materials_clearcoat's factors in a scene file (docs/scene-format.md), on a shape and on a
// glTF model's material (its textures stay), and their range errors.
TEST(SceneFileMaterials, Clearcoat)
{
    const SceneDocument d = test::loadSceneText(R"({"shapes": [
        {"type": "sphere", "material": {"clearcoat": 0.75, "clearcoatRoughness": 0.2}},
        {"type": "sphere", "material": {}}]})");
    ASSERT_EQ(d.scene.materials.size(), 2u);
    EXPECT_FLOAT_EQ(d.scene.materials[0].clearcoatFactor, 0.75f);
    EXPECT_FLOAT_EQ(d.scene.materials[0].clearcoatRoughnessFactor, 0.2f);
    EXPECT_EQ(d.scene.materials[1].clearcoatFactor, 0.0f); // no layer by default
    auto error = [](const std::string& material) {
        return test::sceneError(R"({"shapes": [{"type": "sphere", "material": )" + material + "}]}");
    };
    EXPECT_NE(error(R"({"clearcoat": 1.5})").find("clearcoat"), std::string::npos);
    EXPECT_NE(error(R"({"clearcoatRoughness": -0.1})").find("clearcoatRoughness"), std::string::npos);
}

// KHR_materials_sheen's factors in a scene file (docs/scene-format.md) and their range errors.
TEST(SceneFileMaterials, Sheen)
{
    const SceneDocument d = test::loadSceneText(R"({"shapes": [
        {"type": "sphere", "material": {"sheenColor": [1, 0.5, 0.25], "sheenRoughness": 0.3}},
        {"type": "sphere", "material": {}}]})");
    ASSERT_EQ(d.scene.materials.size(), 2u);
    EXPECT_EQ(d.scene.materials[0].sheenColorFactor, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_FLOAT_EQ(d.scene.materials[0].sheenRoughnessFactor, 0.3f);
    EXPECT_EQ(d.scene.materials[1].sheenColorFactor, glm::vec3(0.0f)); // no sheen by default
    auto error = [](const std::string& material) {
        return test::sceneError(R"({"shapes": [{"type": "sphere", "material": )" + material + "}]}");
    };
    EXPECT_NE(error(R"({"sheenColor": [1.5, 0, 0]})").find("sheenColor"), std::string::npos);
    EXPECT_NE(error(R"({"sheenRoughness": -0.1})").find("sheenRoughness"), std::string::npos);
}

// KHR_materials_anisotropy's factors in a scene file (docs/scene-format.md) and their errors.
TEST(SceneFileMaterials, Anisotropy)
{
    const SceneDocument d = test::loadSceneText(R"({"shapes": [
        {"type": "sphere", "material": {"anisotropyStrength": 0.8, "anisotropyRotation": -0.5}},
        {"type": "sphere", "material": {}}]})");
    ASSERT_EQ(d.scene.materials.size(), 2u);
    EXPECT_FLOAT_EQ(d.scene.materials[0].anisotropyStrength, 0.8f);
    EXPECT_FLOAT_EQ(d.scene.materials[0].anisotropyRotation, -0.5f);
    EXPECT_EQ(d.scene.materials[1].anisotropyStrength, 0.0f); // isotropic by default
    auto error = [](const std::string& material) {
        return test::sceneError(R"({"shapes": [{"type": "sphere", "material": )" + material + "}]}");
    };
    EXPECT_NE(error(R"({"anisotropyStrength": 1.5})").find("anisotropyStrength"), std::string::npos);
    EXPECT_NE(error(R"({"anisotropyRotation": "north"})").find("anisotropyRotation"), std::string::npos);
}

// KHR_materials_iridescence's factor, film IOR and thickness range in a scene file
// (docs/scene-format.md), their defaults (1.3, 100 nm, 400 nm) and their range errors.
TEST(SceneFileMaterials, Iridescence)
{
    const SceneDocument d = test::loadSceneText(R"({"shapes": [
        {"type": "sphere", "material": {"iridescence": 0.5, "iridescenceIor": 1.8, "iridescenceThicknessMinimum": 50,
                                        "iridescenceThicknessMaximum": 900}},
        {"type": "sphere", "material": {}}]})");
    ASSERT_EQ(d.scene.materials.size(), 2u);
    const Material& m = d.scene.materials[0];
    EXPECT_FLOAT_EQ(m.iridescenceFactor, 0.5f);
    EXPECT_FLOAT_EQ(m.iridescenceIor, 1.8f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMinimum, 50.0f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMaximum, 900.0f);
    const Material& plain = d.scene.materials[1];
    EXPECT_EQ(plain.iridescenceFactor, 0.0f); // no film by default
    EXPECT_FLOAT_EQ(plain.iridescenceIor, 1.3f);
    EXPECT_FLOAT_EQ(plain.iridescenceThicknessMinimum, 100.0f);
    EXPECT_FLOAT_EQ(plain.iridescenceThicknessMaximum, 400.0f);
    auto error = [](const std::string& material) {
        return test::sceneError(R"({"shapes": [{"type": "sphere", "material": )" + material + "}]}");
    };
    EXPECT_NE(error(R"({"iridescence": 1.5})").find("iridescence"), std::string::npos);
    EXPECT_NE(error(R"({"iridescenceIor": 0.9})").find("iridescenceIor"), std::string::npos);
    EXPECT_NE(error(R"({"iridescenceThicknessMaximum": -1})").find("iridescenceThicknessMaximum"), std::string::npos);
}

// The transmission golden's scene file (tests/assets/transparency/transmission.json) loads.
TEST(SceneFileMaterials, TransmissionSceneLoads)
{
    const SceneDocument d = loadScene(fs::path(SPECULA_SOURCE_DIR) / "tests/assets/transparency/transmission.json");
    int transmissive = 0, transparent = 0;
    for (const Material& m : d.scene.materials) {
        transmissive += m.transmissionFactor > 0.0f;
        transparent += m.alphaMode == AlphaMode::Blend && m.blendMode == BlendMode::Transparent;
    }
    EXPECT_EQ(transmissive, 3);
    EXPECT_EQ(transparent, 1);
}

// KHR_materials_diffuse_transmission's factor and colour in a scene file (docs/scene-format.md),
// their defaults (0, white) and their range errors.
TEST(SceneFileMaterials, DiffuseTransmission)
{
    const SceneDocument d = test::loadSceneText(R"({"shapes": [
        {"type": "plane", "material": {"diffuseTransmission": 0.4, "diffuseTransmissionColor": [1, 0.5, 0.25]}},
        {"type": "sphere", "material": {}}]})");
    ASSERT_EQ(d.scene.materials.size(), 2u);
    EXPECT_FLOAT_EQ(d.scene.materials[0].diffuseTransmissionFactor, 0.4f);
    EXPECT_EQ(d.scene.materials[0].diffuseTransmissionColorFactor, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(d.scene.materials[1].diffuseTransmissionFactor, 0.0f); // none by default
    EXPECT_EQ(d.scene.materials[1].diffuseTransmissionColorFactor, glm::vec3(1.0f));
    auto error = [](const std::string& material) {
        return test::sceneError(R"({"shapes": [{"type": "sphere", "material": )" + material + "}]}");
    };
    EXPECT_NE(error(R"({"diffuseTransmission": 1.5})").find("diffuseTransmission"), std::string::npos);
    EXPECT_NE(error(R"({"diffuseTransmissionColor": [2, 0, 0]})").find("diffuseTransmissionColor"), std::string::npos);
}
