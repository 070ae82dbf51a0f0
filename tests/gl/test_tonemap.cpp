// Exposure, tone mapping and sRGB encoding on the GPU against the CPU operators:
// a camera-filling emissive plane of known radiance renders the expected bytes.
#include "GlTestContext.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Error.h"
#include "render/Renderer.h"
#include "shading/Tonemap.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;

namespace {

scene::Scene emissivePlane(glm::vec3 radiance)
{
    scene::Scene s;
    scene::Material m;
    m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    m.metallicFactor = 0.0f;
    m.emissiveFactor = glm::vec3(1.0f);
    m.emissiveStrength = 1.0f;
    // Radiance beyond 1 needs KHR_materials_emissive_strength: factor x strength.
    const float strength = std::max({radiance.x, radiance.y, radiance.z, 1.0f});
    m.emissiveFactor = radiance / strength;
    m.emissiveStrength = strength;
    // Plane facing +Z (the camera), large enough to fill the view.
    const glm::mat4 toCamera = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0));
    scene::addShape(s, scene::makePlane(10.0f), m, toCamera, "plane");
    return s;
}

} // namespace

TEST_F(GlTest, TonemappersMatchCpu)
{
    const glm::vec3 radiances[] = {{0.02f, 0.18f, 0.5f}, {0.9f, 0.4f, 0.1f}, {3.0f, 1.5f, 0.7f}, {40.0f, 20.0f, 2.0f}};
    const render::Tonemap operators[] = {render::Tonemap::None, render::Tonemap::Reinhard, render::Tonemap::ReinhardExtended,
                                         render::Tonemap::Aces, render::Tonemap::Neutral, render::Tonemap::Agx};
    render::Renderer renderer;
    const render::View view = render::lookAtView({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 10.0f);
    for (const glm::vec3& radiance : radiances) {
        renderer.setScene(emissivePlane(radiance));
        for (render::Tonemap op : operators) {
            for (float ev : {-1.0f, 0.0f, 1.5f}) {
                render::FrameSettings settings;
                settings.width = settings.height = 8;
                settings.msaa = 1;
                settings.tonemap = op;
                settings.exposureEv = ev;
                renderer.render(view, settings);
                const ImageRGBA8 image = renderer.readImage();
                const ImageFloat hdr = renderer.readRadiance();
                const glm::vec3 exposed = radiance * std::exp2(ev);
                const glm::vec3 mapped = render::applyTonemap(op, exposed);
                for (int ch = 0; ch < 3; ++ch) {
                    // One 8-bit step: GPU rounding of the sRGB curve may differ from the CPU's by one.
                    const float expected = 255.0f * render::linearToSrgb(mapped[ch]);
                    EXPECT_NEAR(float(image.pixels[4 * 27 + ch]), expected, 1.0f)
                        << render::tonemapName(op) << " EV " << ev << " radiance " << radiance[ch];
                    // The HDR output is radiance x 2^EV, before tone mapping (half-float precision).
                    EXPECT_NEAR(hdr.pixels[4 * 27 + ch], exposed[ch], exposed[ch] * 1e-3f + 1e-4f);
                }
            }
        }
    }
}

TEST_F(GlTest, MsaaOneSamplesPixelCentres)
{
    // The plane's edge at x = -0.1 cuts pixel 3 of an 8-pixel view spanning [-1, 1] (pixel 3
    // spans [-0.25, 0], centre -0.125). One sample at the centre: pixel 3 is fully in. Four
    // samples: it is partly covered, so its value lies strictly between 0 and 1.
    scene::Scene s = emissivePlane({1.0f, 1.0f, 1.0f});
    s.nodes.back().matrix = glm::translate(glm::mat4(1.0f), {-5.1f, 0.0f, 0.0f}) * *s.nodes.back().matrix;
    render::Renderer renderer;
    renderer.setScene(s);
    render::View view;
    view.view = glm::lookAt(glm::vec3(0, 0, 2), glm::vec3(0), glm::vec3(0, 1, 0));
    view.projection = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f);
    view.position = {0, 0, 2};
    render::FrameSettings settings;
    settings.width = settings.height = 8;
    settings.tonemap = render::Tonemap::None;
    auto row = [&](int msaa) {
        settings.msaa = msaa;
        renderer.render(view, settings);
        const ImageFloat hdr = renderer.readRadiance();
        std::vector<float> values;
        for (int x = 0; x < 8; ++x) values.push_back(hdr.pixels[size_t(4 * (4 * 8 + x))]);
        return values;
    };
    const auto single = row(1);
    for (int x = 0; x < 8; ++x) EXPECT_NEAR(single[size_t(x)], x <= 3 ? 1.0f : 0.0f, 1e-3f) << "x " << x;
    const auto multi = row(4);
    EXPECT_GT(multi[3], 0.05f);
    EXPECT_LT(multi[3], 0.95f);
    EXPECT_NEAR(multi[2], 1.0f, 1e-3f);
    EXPECT_NEAR(multi[4], 0.0f, 1e-3f);
}

TEST_F(GlTest, TooManyMsaaSamplesIsAClearError)
{
    render::Renderer renderer;
    renderer.setScene(emissivePlane({1.0f, 1.0f, 1.0f}));
    render::FrameSettings settings;
    settings.width = settings.height = 8;
    settings.msaa = 64; // beyond every implementation's GL_MAX_COLOR_TEXTURE_SAMPLES
    const render::View view = render::lookAtView({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 10.0f);
    try {
        renderer.render(view, settings);
        FAIL() << "rendered with 64 samples";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("supports at most"), std::string::npos) << e.what();
    }
}
