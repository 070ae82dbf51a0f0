// Exposure: automatic (render/ExposurePass, a luminance histogram in compute shaders) on a
// uniform grey frame of known luminance converges to the meter's exposure; adaptation over
// time follows its exponential law; physical camera exposure (EV100) scales as specified.
#include "GlTestContext.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/CameraExposure.h"
#include "render/Renderer.h"
#include "shading/Tonemap.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;

namespace {

/// Nothing but a uniform background of radiance `luminance`: every pixel has that luminance.
render::FrameSettings greyFrame(float luminance)
{
    render::FrameSettings s;
    s.width = 67; // odd, and not a multiple of the histogram's 16×16 work groups
    s.height = 45;
    s.msaa = 1;
    s.background = glm::vec3(luminance);
    s.autoExposure.enabled = true;
    return s;
}

const render::View kView = render::lookAtView({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 1.0f, 1.0f, 0.1f, 10.0f);

} // namespace

TEST(Exposure, CameraFormulas)
{
    // "Sunny 16": f/16, 1/100 s, ISO 100 is EV100 = log2(16² × 100) = 14.64.
    EXPECT_NEAR(render::ev100FromCamera(16.0f, 0.01f, 100.0f), std::log2(25600.0f), 1e-4f);
    // Doubling ISO is one stop less light needed.
    EXPECT_NEAR(render::ev100FromCamera(16.0f, 0.01f, 200.0f), std::log2(25600.0f) - 1.0f, 1e-4f);
    EXPECT_NEAR(render::exposureFromEv100(0.0f), 1.0f / 1.2f, 1e-6f);
    EXPECT_NEAR(render::exposureFromEv100(10.0f), 1.0f / (1.2f * 1024.0f), 1e-9f);
    // The meter: L = 12.5 / 100 × 2^EV100, so 1 cd/m² is EV100 = 3.
    EXPECT_NEAR(render::ev100FromLuminance(1.0f), 3.0f, 1e-5f);
}

TEST_F(GlTest, AutoExposureConvergesOnUniformGrey)
{
    // EV100 = log2(L × 100 / 12.5), exposure = 1 / (1.2 × 2^EV100) = 1 / (9.6 L): every grey
    // is exposed to 1/9.6, whatever its luminance, within the histogram's resolution (1/16 of
    // a 0.094-EV bin) and half-float rounding.
    render::Renderer renderer;
    renderer.setScene({});
    for (float luminance : {0.05f, 1.0f, 18.0f, 300.0f, 20000.0f}) {
        const render::FrameSettings s = greyFrame(luminance);
        renderer.render(kView, s);
        const float expected = 1.0f / (9.6f * luminance);
        EXPECT_NEAR(renderer.exposureScale() / expected, 1.0f, 0.01f) << "luminance " << luminance;
        const ImageFloat radiance = renderer.readRadiance();
        EXPECT_NEAR(radiance.pixels[4 * 100], 1.0f / 9.6f, 0.01f / 9.6f) << "luminance " << luminance;
        // The tone mapper used the same exposure (PBR Neutral is the identity below 0.76,
        // less its toe offset for dark colours).
        const ImageRGBA8 image = renderer.readImage();
        const glm::vec3 mapped = render::applyTonemap(render::Tonemap::Neutral, glm::vec3(1.0f / 9.6f));
        EXPECT_NEAR(float(image.pixels[4 * 100]), 255.0f * render::linearToSrgb(mapped.x), 1.5f) << "luminance " << luminance;
    }
}

TEST_F(GlTest, AutoExposureCompensationAndClamp)
{
    render::Renderer renderer;
    renderer.setScene({});
    // --exposure is compensation on top of the automatic exposure.
    render::FrameSettings s = greyFrame(2.0f);
    s.exposureEv = 1.0f;
    renderer.render(kView, s);
    EXPECT_NEAR(renderer.exposureScale() * 9.6f * 2.0f, 2.0f, 0.02f);
    // Beyond the EV100 range the exposure stops following: 10^6 cd/m² is EV100 22.9 > 18.
    s = greyFrame(1e6f);
    renderer.render(kView, s);
    EXPECT_NEAR(renderer.exposureScale(), render::exposureFromEv100(18.0f), render::exposureFromEv100(18.0f) * 0.01f);
    s = greyFrame(1e-4f); // EV100 -10.3 < -6
    renderer.render(kView, s);
    EXPECT_NEAR(renderer.exposureScale(), render::exposureFromEv100(-6.0f), render::exposureFromEv100(-6.0f) * 0.01f);
}

TEST_F(GlTest, AutoExposureAdaptsOverTime)
{
    // From a converged 1 cd/m² (EV100 3) to 16 cd/m² (EV100 7): with dt = 0.1 s and the
    // "up" speed 3/s, each frame closes 1 - e^-0.3 of the remaining gap.
    render::Renderer renderer;
    renderer.setScene({});
    render::FrameSettings s = greyFrame(1.0f);
    renderer.render(kView, s); // dt = 0: converges at once
    s = greyFrame(16.0f);
    s.autoExposure.deltaTime = 0.1f;
    float ev = 3.0f;
    for (int frame = 0; frame < 10; ++frame) {
        renderer.render(kView, s);
        ev += (7.0f - ev) * (1.0f - std::exp(-0.3f));
        const float measured = std::log2(1.0f / (1.2f * renderer.exposureScale()));
        EXPECT_NEAR(measured, ev, 0.02f) << "frame " << frame;
    }
    // Back down to 1 cd/m²: the "down" speed, 1/s.
    s = greyFrame(1.0f);
    s.autoExposure.deltaTime = 0.5f;
    renderer.render(kView, s);
    ev += (3.0f - ev) * (1.0f - std::exp(-0.5f));
    EXPECT_NEAR(std::log2(1.0f / (1.2f * renderer.exposureScale())), ev, 0.02f);
}

TEST_F(GlTest, AutoExposureIgnoresBlackAndTheBrightestPixels)
{
    // Black background, a grey emitter on the left half, and a tiny blinding one: black
    // pixels are not metered and the brightest (< 5% of the metered ones) lie above the high
    // percentile, so the grey alone sets the exposure.
    auto emitter = [](float radiance) {
        scene::Material m;
        m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        m.emissiveFactor = glm::vec3(1.0f);
        m.emissiveStrength = radiance;
        return m;
    };
    scene::Scene s;
    const glm::mat4 facing = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0));
    scene::addShape(s, scene::makePlane(2.0f), emitter(3.0f), glm::translate(glm::mat4(1.0f), {-1.0f, 0, 0}) * facing, "grey");
    scene::addShape(s, scene::makeUvSphere(0.02f, 16, 8), emitter(5e4f), glm::translate(glm::mat4(1.0f), {-0.3f, 0, 0.2f}), "spark");
    render::Renderer renderer;
    renderer.setScene(s);
    render::FrameSettings settings = greyFrame(0.0f);
    settings.width = settings.height = 64;
    renderer.render(kView, settings);
    const ImageFloat radiance = renderer.readRadiance();
    int sparks = 0, greys = 0;
    for (size_t i = 0; i < radiance.pixels.size(); i += 4) {
        if (radiance.pixels[i] > 1.0f) ++sparks;
        else if (radiance.pixels[i] > 0.05f) ++greys;
    }
    ASSERT_GT(sparks, 0);
    ASSERT_LT(sparks * 20, greys) << "the spark must stay under the 5% the high percentile cuts";
    EXPECT_NEAR(renderer.exposureScale() * 9.6f * 3.0f, 1.0f, 0.01f);

    // Nothing to meter: the exposure stays where it was, or, before any measurement, is
    // that of the darkest scene allowed.
    renderer.setScene({});
    const float before = renderer.exposureScale();
    renderer.render(kView, greyFrame(0.0f));
    EXPECT_FLOAT_EQ(renderer.exposureScale(), before);
    render::Renderer fresh;
    fresh.setScene({});
    fresh.render(kView, greyFrame(0.0f));
    EXPECT_NEAR(fresh.exposureScale(), render::exposureFromEv100(-6.0f), 1e-3f);
}

TEST_F(GlTest, PhysicalCameraExposure)
{
    render::Renderer renderer;
    renderer.setScene({});
    render::FrameSettings s = greyFrame(500.0f);
    s.autoExposure.enabled = false;
    s.ev100 = 12.0f;
    renderer.render(kView, s);
    EXPECT_FLOAT_EQ(renderer.exposureScale(), 1.0f / (1.2f * 4096.0f));
    EXPECT_NEAR(renderer.readRadiance().pixels[0], 500.0f / (1.2f * 4096.0f), 1e-3f);
    s.exposureEv = -1.0f; // compensation halves it
    renderer.render(kView, s);
    EXPECT_FLOAT_EQ(renderer.exposureScale(), 0.5f / (1.2f * 4096.0f));
    // Without a camera: 2^EV only (EV 0 = radiance unchanged), as before.
    s.ev100.reset();
    s.exposureEv = 0.0f;
    renderer.render(kView, s);
    EXPECT_FLOAT_EQ(renderer.exposureScale(), 1.0f);
}
