// KHR_materials_variants at run time: tests/assets/gltf/variants.gltf (make_variants.py) has two
// unlit quads whose materials change with the variant, so each frame must show, at each quad's
// centre, exactly the base colour the file gives that quad under that variant (the expectation is
// the file's numbers, nothing the renderer computes). The "Hidden" variant cuts the left quad
// out (alpha mask, alpha 0), which must also take its shadow off the lit floor behind it:
// switching variants in one renderer redraws the cached shadow maps.
// Broken on purpose: GpuScene::setVariant not changing the draws' materials fails every
// variant's colours; Renderer::setVariant not invalidating the shadow maps fails "Hidden"'s
// floor (still shadowed).
#include "GlTestContext.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"

#include <glm/gtc/matrix_transform.hpp>

#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/GltfImporter.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;
using specula::test::pixel;

namespace {

constexpr int kSize = 160;
const std::string kVariants = std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/variants.gltf";

const glm::vec3 kRed(0.8f, 0.1f, 0.1f), kGreen(0.1f, 0.8f, 0.1f), kBlue(0.1f, 0.1f, 0.8f);

} // namespace

TEST_F(GlTest, MaterialVariantsSwitchTheDrawnMaterialsAndTheirShadows)
{
    scene::Scene s = scene::loadGltf(kVariants);
    ASSERT_EQ(s.variants, (std::vector<std::string>{"Green", "Blue", "Hidden"}));
    // A lit grey floor 0.5 m behind the quads, facing them, and a sun at 45° from +Z towards -X:
    // the floor point (0, 0, -0.5), seen between the quads, is in the left quad's shadow (its
    // ray to the sun crosses z = 0 at x = -0.5).
    scene::Material floor;
    floor.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    floor.metallicFactor = 0.0f;
    floor.roughnessFactor = 0.9f;
    scene::addShape(s, scene::makePlane(6.0f), floor,
                    glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0, -0.5f}), glm::radians(90.0f), glm::vec3(1, 0, 0)),
                    "floor");
    scene::Light sun;
    sun.type = scene::Light::Type::Directional;
    sun.intensity = 3.0f;
    scene::addLight(s, sun, {0, 0, 0}, glm::normalize(glm::vec3(1.0f, 0.0f, -1.0f)));

    const render::View view =
        render::lookAtView({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, {0, 1, 0}, glm::radians(50.0f), 1.0f, 0.1f, 20.0f);
    const glm::ivec2 left = test::projectToPixel(view, {-0.6f, 0.2f, 0.0f}, kSize, kSize);
    const glm::ivec2 right = test::projectToPixel(view, {0.6f, 0.2f, 0.0f}, kSize, kSize);
    const glm::ivec2 shadowed = test::projectToPixel(view, {0.0f, 0.0f, -0.5f}, kSize, kSize);

    render::Renderer renderer;
    renderer.setScene(s);
    struct Case {
        int variant;
        const char* name;
        std::optional<glm::vec3> left; ///< nullopt: cut out
        glm::vec3 right;
    };
    // Back to none at the end: a variant is undone as well as done.
    const Case cases[] = {{-1, "none", kRed, kBlue},      {0, "Green", kGreen, kGreen}, {1, "Blue", kBlue, kGreen},
                          {2, "Hidden", std::nullopt, kBlue}, {-1, "none again", kRed, kBlue}};
    float litFloor = 0.0f, shadowedFloor = 0.0f;
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        renderer.setVariant(c.variant);
        renderer.render(view, test::radianceFrame(kSize, kSize));
        const ImageFloat image = renderer.readRadiance();
        constexpr float kTolerance = 1e-3f; // unlit: the factor itself, through half floats
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(pixel(image, right)[k], c.right[k], kTolerance) << "right, channel " << k;
        const glm::vec3 behindLeft = pixel(image, left), floorPoint = pixel(image, shadowed);
        if (c.left) {
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(behindLeft[k], (*c.left)[k], kTolerance) << "left, channel " << k;
            shadowedFloor = std::max(shadowedFloor, floorPoint.g);
        } else {
            // Cut out: the grey floor shows through, lit, and the left quad casts no shadow.
            EXPECT_NEAR(behindLeft.r, behindLeft.b, 1e-3f) << "the floor is grey where the quad was";
            litFloor = floorPoint.g;
        }
    }
    // In the shadow only the floor's ambient remains (none here); lit, the sun's 3 lux on a 0.8 grey.
    EXPECT_GT(litFloor, 0.2f);
    EXPECT_LT(shadowedFloor, 0.02f * litFloor);
}
