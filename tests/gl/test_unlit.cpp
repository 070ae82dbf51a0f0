// KHR_materials_unlit through every path of the forward pass: a glTF file's unlit quad shows
// its base colour term (factor × vertex colour), and nothing else, under punctual lights, under
// image-based light, at any light intensity; the debug views show its inputs and no BRDF; the
// frame's --shading override still wins. The lit quad beside it, with the same factors, is the
// control: it must change where the unlit one must not.
#include "GlTestContext.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"

#include <cmath>

#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/GltfImporter.h"
#include "shading/EnvironmentMap.h"

using namespace specula;
using specula::test::GlTest;
using specula::test::pixel;

namespace {

constexpr int kSize = 200;
const std::string kQuads = std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/unlit_quads.gltf";

render::View quadsView()
{
    return render::lookAtView({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, {0, 1, 0}, glm::radians(50.0f), 1.0f, 0.1f, 20.0f);
}

glm::ivec2 project(const render::View& view, const glm::vec3& p)
{
    return test::projectToPixel(view, p, kSize, kSize);
}

/// Points on each quad's diagonal from its corner (x0, -0.5) to (x0 + 1, 0.5), where both of its
/// triangles interpolate the vertex colours alike: red goes from 1 to 0.5 along it.
struct Sample {
    glm::vec3 position;
    glm::vec3 unlitColor; ///< the base colour term there: (0.5, 0.8, 0.2) × (1 − t / 2, 1, 1)
};
std::vector<Sample> diagonal(float x0)
{
    std::vector<Sample> out;
    for (float t : {0.25f, 0.5f, 0.75f})
        out.push_back({{x0 + t, t - 0.5f, 0.0f}, glm::vec3(0.5f * (1.0f - 0.5f * t), 0.8f, 0.2f)});
    return out;
}

void addSun(scene::Scene& s, float lux)
{
    scene::Light light;
    light.type = scene::Light::Type::Directional;
    light.intensity = lux;
    scene::addLight(s, light, {0, 0, 0}, glm::normalize(glm::vec3(-0.3f, -0.2f, -1.0f)));
}

} // namespace

TEST_F(GlTest, UnlitGltfMaterialShowsItsBaseColourInEveryPath)
{
    scene::Scene s = scene::loadGltf(kQuads);
    ASSERT_EQ(s.materials.size(), 2u);
    ASSERT_EQ(s.materials[0].shading.model, scene::ShadingModel::Unlit);
    ASSERT_FALSE(s.materials[1].shading.model);
    addSun(s, 3.0f);
    const render::View view = quadsView();
    render::Renderer renderer;
    renderer.setScene(s);
    const auto unlit = diagonal(-1.1f), lit = diagonal(0.1f);
    // The gradient moves red by 0.5 per unit along x; a pixel centre is within 0.007 of the point.
    constexpr float kTolerance = 4e-3f;

    // Punctual light.
    renderer.render(view, test::radianceFrame(kSize, kSize));
    const ImageFloat sun = renderer.readRadiance();
    for (const Sample& p : unlit) {
        const glm::vec3 got = pixel(sun, project(view, p.position));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], p.unlitColor[c], kTolerance) << "channel " << c;
    }
    // The control: the lit quad with the same factors is not its base colour (it has the sun,
    // and its emission (1, 0, 1)).
    for (const Sample& p : lit) EXPECT_GT(glm::length(pixel(sun, project(view, p.position)) - p.unlitColor), 0.5f);

    // Ten times the light and an environment of radiance 2: the unlit quad does not change at all.
    scene::Scene brighter = scene::loadGltf(kQuads);
    addSun(brighter, 30.0f);
    renderer.setScene(brighter);
    renderer.setEnvironment(render::constantEnvironment(glm::vec3(2.0f)));
    renderer.render(view, test::radianceFrame(kSize, kSize));
    const ImageFloat both = renderer.readRadiance();
    for (const Sample& p : unlit) EXPECT_EQ(pixel(both, project(view, p.position)), pixel(sun, project(view, p.position)));
    for (const Sample& p : lit)
        EXPECT_GT(glm::length(pixel(both, project(view, p.position)) - pixel(sun, project(view, p.position))), 1.0f);

    // Debug views: its inputs as for any material, no BRDF, no emission.
    auto debugFrame = [&](DebugView debugView) {
        render::FrameSettings d = test::radianceFrame(kSize, kSize);
        d.debugView = debugView;
        renderer.render(view, d);
        return renderer.readRadiance();
    };
    const ImageFloat baseColor = debugFrame(DebugView::BaseColor);
    for (const Sample& p : unlit) {
        const glm::vec3 got = pixel(baseColor, project(view, p.position));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], p.unlitColor[c], kTolerance) << "channel " << c;
    }
    for (DebugView term : {DebugView::BrdfD, DebugView::BrdfG, DebugView::BrdfF, DebugView::Emissive}) {
        const ImageFloat image = debugFrame(term);
        SCOPED_TRACE(debugViewName(term));
        for (const Sample& p : unlit) EXPECT_EQ(pixel(image, project(view, p.position)), glm::vec3(0.0f));
        for (const Sample& p : lit) EXPECT_GT(glm::length(pixel(image, project(view, p.position))), 1e-4f);
    }

    // The frame's override wins over the file (--shading pbr shows the fallback material).
    render::FrameSettings pbr = test::radianceFrame(kSize, kSize);
    pbr.materialOverride.model = scene::ShadingModel::Pbr;
    renderer.render(view, pbr);
    const ImageFloat overridden = renderer.readRadiance();
    for (const Sample& p : unlit) EXPECT_GT(glm::length(pixel(overridden, project(view, p.position)) - p.unlitColor), 0.5f);
}
