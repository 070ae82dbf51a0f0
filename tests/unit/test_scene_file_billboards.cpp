// The "billboards" key of JSON scene files (docs/scene-format.md, "Billboards"): groups parsed
// exactly, scattered fields reproducible, images loaded, and errors one line naming the value.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "TestFiles.h"
#include "core/ImageIO.h"
#include "scene/SceneFile.h"

namespace fs = std::filesystem;
using namespace specula;
using namespace specula::scene;
using test::sceneError;
using test::TempDir;

namespace {

Scene load(const std::string& text)
{
    return test::loadSceneText(text).scene;
}

void expectVec(glm::vec3 a, glm::vec3 b)
{
    EXPECT_NEAR(a.x, b.x, 1e-6f);
    EXPECT_NEAR(a.y, b.y, 1e-6f);
    EXPECT_NEAR(a.z, b.z, 1e-6f);
}

} // namespace

TEST(SceneFileBillboards, ParsesEveryField)
{
    const Scene s = load(R"({
      "billboards": [
        {"name": "trees", "kind": "axis-aligned", "sprite": "tree", "size": [1.5, 3], "anchor": [0.5, 0],
         "tint": [0.8, 1, 0.7], "alphaMode": "mask", "alphaCutoff": 0.3,
         "billboards": [{"position": [1, 0, -2]}, {"position": [3, 0, -4], "scale": 1.5, "tint": [0.5, 0.5, 0.5]}]},
        {"kind": "point-sprite", "size": 16, "sizeInPixels": true, "tint": [50, 40, 30], "alphaMode": "blend",
         "sectorLight": 96, "position": [0, 2, 0]},
        {"kind": "arbitrary-axis", "axis": [0, 0, 2], "alphaMode": "opaque",
         "billboards": [{"position": [0, 0, 0]}, {"position": [1, 1, 1], "axis": [1, 0, 0]}]}
      ]
    })");
    ASSERT_EQ(s.billboards.size(), 3u);
    const BillboardGroup& trees = s.billboards[0];
    EXPECT_EQ(trees.name, "trees");
    EXPECT_EQ(trees.kind, BillboardKind::AxisAligned);
    EXPECT_EQ(trees.sprite, BuiltinSprite::Tree);
    EXPECT_EQ(trees.image, -1);
    EXPECT_EQ(trees.size, glm::vec2(1.5f, 3.0f));
    EXPECT_FALSE(trees.sizeInPixels);
    EXPECT_EQ(trees.anchor, glm::vec2(0.5f, 0.0f));
    expectVec(trees.tint, {0.8f, 1.0f, 0.7f});
    EXPECT_EQ(trees.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(trees.alphaCutoff, 0.3f);
    ASSERT_EQ(trees.billboards.size(), 2u);
    expectVec(trees.billboards[0].position, {1, 0, -2});
    EXPECT_EQ(trees.billboards[0].scale, 1.0f);
    expectVec(trees.billboards[0].tint, glm::vec3(1.0f));
    expectVec(trees.billboards[1].position, {3, 0, -4});
    EXPECT_EQ(trees.billboards[1].scale, 1.5f);
    expectVec(trees.billboards[1].tint, glm::vec3(0.5f));

    const BillboardGroup& glow = s.billboards[1];
    EXPECT_EQ(glow.name, "billboards1");
    EXPECT_EQ(glow.kind, BillboardKind::PointSprite);
    EXPECT_EQ(glow.sprite, BuiltinSprite::Disc);
    EXPECT_EQ(glow.size, glm::vec2(16.0f));
    EXPECT_TRUE(glow.sizeInPixels);
    EXPECT_EQ(glow.anchor, glm::vec2(0.5f));
    expectVec(glow.tint, {50, 40, 30}); // HDR radiance is allowed
    EXPECT_EQ(glow.alphaMode, AlphaMode::Blend);
    EXPECT_EQ(glow.sectorLight, 96);
    EXPECT_EQ(trees.sectorLight, 255); // the default: full bright
    ASSERT_EQ(glow.billboards.size(), 1u);
    expectVec(glow.billboards[0].position, {0, 2, 0});

    const BillboardGroup& beams = s.billboards[2];
    EXPECT_EQ(beams.kind, BillboardKind::ArbitraryAxis);
    EXPECT_EQ(beams.alphaMode, AlphaMode::Opaque);
    ASSERT_EQ(beams.billboards.size(), 2u);
    expectVec(beams.billboards[0].axis, {0, 0, 1}); // the group's axis, normalised
    expectVec(beams.billboards[1].axis, {1, 0, 0}); // its own
}

TEST(SceneFileBillboards, DefaultsAndEmptyFile)
{
    EXPECT_TRUE(load("{}").billboards.empty());
    const Scene s = load(R"({"billboards": [{"position": [1, 2, 3]}]})");
    ASSERT_EQ(s.billboards.size(), 1u);
    const BillboardGroup& g = s.billboards[0];
    EXPECT_EQ(g.name, "billboards0");
    EXPECT_EQ(g.kind, BillboardKind::PointSprite);
    EXPECT_EQ(g.sprite, BuiltinSprite::Disc);
    EXPECT_EQ(g.size, glm::vec2(1.0f));
    EXPECT_EQ(g.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(g.alphaCutoff, 0.5f);
    expectVec(g.tint, glm::vec3(1.0f));
    // Billboards are not meshes: the scene's instance count does not change.
    EXPECT_TRUE(s.meshInstances().empty());
}

TEST(SceneFileBillboards, ScatterIsReproducibleAndInsideTheBox)
{
    const std::string text = R"({"billboards": [{"kind": "axis-aligned", "sprite": "tree",
        "scatter": {"count": 500, "min": [-10, 0, -20], "max": [10, 0, -5], "scale": [0.7, 1.3], "seed": 7}}]})";
    const Scene a = load(text);
    const Scene b = load(text);
    ASSERT_EQ(a.billboards.at(0).billboards.size(), 500u);
    float minScale = 10.0f, maxScale = 0.0f;
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (size_t i = 0; i < 500; ++i) {
        const Billboard& x = a.billboards[0].billboards[i];
        EXPECT_EQ(x.position, b.billboards[0].billboards[i].position) << "same seed, same field";
        lo = glm::min(lo, x.position);
        hi = glm::max(hi, x.position);
        minScale = std::min(minScale, x.scale);
        maxScale = std::max(maxScale, x.scale);
    }
    EXPECT_GE(lo.x, -10.0f);
    EXPECT_LE(hi.x, 10.0f);
    EXPECT_EQ(lo.y, 0.0f);
    EXPECT_EQ(hi.y, 0.0f);
    EXPECT_GE(lo.z, -20.0f);
    EXPECT_LE(hi.z, -5.0f);
    // 500 samples spread over the box and the scale range.
    EXPECT_LT(lo.x, -9.0f);
    EXPECT_GT(hi.x, 9.0f);
    EXPECT_GE(minScale, 0.7f);
    EXPECT_LE(maxScale, 1.3f);
    EXPECT_LT(minScale, 0.75f);
    EXPECT_GT(maxScale, 1.25f);

    const Scene other = load(R"({"billboards": [{"scatter": {"count": 5, "min": [0, 0, 0], "max": [1, 1, 1], "seed": 8}}]})");
    const Scene seven = load(R"({"billboards": [{"scatter": {"count": 5, "min": [0, 0, 0], "max": [1, 1, 1], "seed": 7}}]})");
    EXPECT_NE(other.billboards[0].billboards[0].position, seven.billboards[0].billboards[0].position);
}

TEST(SceneFileBillboards, ImageIsLoadedRelativeToTheSceneFile)
{
    TempDir dir;
    ImageRGBA8 image;
    image.width = 2;
    image.height = 3;
    image.pixels.assign(2 * 3 * 4, 200);
    fs::create_directories(dir / "sprites");
    writePng(dir / "sprites" / "smoke.png", image);
    const fs::path path = dir.write("scene.json", R"({"billboards": [{"image": "sprites/smoke.png", "alphaMode": "blend",
                                                      "position": [0, 0, 0]}]})");
    const Scene s = loadSceneFile(path).scene;
    ASSERT_EQ(s.billboards.size(), 1u);
    ASSERT_EQ(s.billboards[0].image, 0);
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].width, 2);
    EXPECT_EQ(s.images[0].height, 3);
    EXPECT_EQ(s.images[0].pixels.size(), 24u);
    EXPECT_EQ(s.images[0].name, "smoke.png");
}

TEST(SceneFileBillboards, Errors)
{
    const struct {
        const char* text;
        const char* error;
    } cases[] = {
        {R"({"billboards": {}})", "scene.json: billboards must be an array"},
        {R"({"billboards": [{"position": [0, 0, 0], "sise": 2}]})",
         "scene.json: unknown key 'sise' in billboards[0] (did you mean 'size'?)"},
        {R"({"billboards": [{"kind": "sphere", "position": [0, 0, 0]}]})",
         "scene.json: billboards[0].kind must be point-sprite, axis-aligned or arbitrary-axis (got 'sphere')"},
        {R"({"billboards": [{"sprite": "cloud", "position": [0, 0, 0]}]})",
         "scene.json: billboards[0].sprite must be disc, tree or bar (got 'cloud')"},
        {R"({"billboards": [{"sprite": "tree", "image": "a.png", "position": [0, 0, 0]}]})",
         "scene.json: billboards[0] has both 'sprite' and 'image'; give one"},
        {R"({"billboards": [{"name": "empty"}]})", "scene.json: billboards[0] needs 'position', 'billboards' or 'scatter'"},
        {R"({"billboards": [{"size": 0, "position": [0, 0, 0]}]})", "scene.json: billboards[0].size must be positive"},
        {R"({"billboards": [{"size": [1, 2, 3], "position": [0, 0, 0]}]})",
         "scene.json: billboards[0].size must be an array of 2 numbers"},
        {R"({"billboards": [{"anchor": [0.5, 1.5], "position": [0, 0, 0]}]})",
         "scene.json: billboards[0].anchor must be between 0 and 1 in both coordinates"},
        {R"({"billboards": [{"tint": [1, -1, 1], "position": [0, 0, 0]}]})",
         "scene.json: billboards[0].tint must not have negative components"},
        {R"({"billboards": [{"alphaMode": "blend", "alphaCutoff": 0.2, "position": [0, 0, 0]}]})",
         "scene.json: billboards[0].alphaCutoff only applies to alphaMode \"mask\""},
        {R"({"billboards": [{"axis": [0, 1, 0], "position": [0, 0, 0]}]})",
         "scene.json: billboards[0].axis only applies to arbitrary-axis billboards"},
        {R"({"billboards": [{"kind": "arbitrary-axis", "axis": [0, 0, 0], "position": [0, 0, 0]}]})",
         "scene.json: billboards[0].axis must not be the zero vector"},
        {R"({"billboards": [{"sectorLight": 256, "position": [0, 0, 0]}]})",
         "scene.json: billboards[0].sectorLight must be between 0 and 255"},
        {R"({"billboards": [{"billboards": [{"scale": 2}]}]})", "scene.json: billboards[0].billboards[0] needs 'position'"},
        {R"({"billboards": [{"billboards": [{"position": [0, 0, 0], "scale": -1}]}]})",
         "scene.json: billboards[0].billboards[0].scale must be positive"},
        {R"({"billboards": [{"billboards": [{"position": [0, 0, 0], "axis": [1, 0, 0]}]}]})",
         "scene.json: billboards[0].billboards[0].axis only applies to arbitrary-axis billboards"},
        {R"({"billboards": [{"scatter": {"count": 10, "min": [0, 0, 0]}}]})", "scene.json: billboards[0].scatter needs 'max'"},
        {R"({"billboards": [{"scatter": {"count": 0, "min": [0, 0, 0], "max": [1, 1, 1]}}]})",
         "scene.json: billboards[0].scatter.count must be between 1 and 1000000"},
        {R"({"billboards": [{"scatter": {"count": 3, "min": [0, 0, 0], "max": [1, -1, 1]}}]})",
         "scene.json: billboards[0].scatter.max must not be below min in any coordinate"},
        {R"({"billboards": [{"scatter": {"count": 3, "min": [0, 0, 0], "max": [1, 1, 1], "scale": [2, 1]}}]})",
         "scene.json: billboards[0].scatter.scale must be positive, [smallest, largest]"},
    };
    for (const auto& c : cases) EXPECT_EQ(sceneError(c.text), c.error) << c.text;

    // A missing image names the entry and the file it looked for.
    const std::string missing = sceneError(R"({"billboards": [{"image": "nope.png", "position": [0, 0, 0]}]})");
    EXPECT_TRUE(missing.starts_with("scene.json: billboards[0].image: cannot read ")) << missing;
    EXPECT_NE(missing.find("nope.png"), std::string::npos) << missing;
}

TEST(SceneFileBillboards, DocumentedExampleHasBillboards)
{
    // The first example in docs/scene-format.md (also loaded by test_scene_file.cpp) carries a
    // billboard group, so the documented schema stays valid.
    const std::string doc = test::readFile(fs::path(SPECULA_SOURCE_DIR) / "docs" / "scene-format.md");
    const size_t begin = doc.find("```json\n");
    ASSERT_NE(begin, std::string::npos);
    const size_t end = doc.find("```", begin + 8);
    TempDir dir;
    fs::create_directory_symlink(fs::absolute(SPECULA_ASSETS_DIR), dir / "assets");
    const Scene s = loadSceneFile(dir.write("example.json", doc.substr(begin + 8, end - begin - 8)), test::kAllowExternal).scene;
    ASSERT_EQ(s.billboards.size(), 2u);
    EXPECT_EQ(s.billboards[0].kind, BillboardKind::AxisAligned);
    EXPECT_EQ(s.billboards[0].billboards.size(), 40u);
    EXPECT_EQ(s.billboards[1].kind, BillboardKind::PointSprite);
}
