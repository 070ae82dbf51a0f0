// The whole post-processing chain (SSAO, bloom, auto exposure, FXAA, debug views) on a real
// scene at several sizes, odd ones included: no GL error (GlTest fails on any), finite
// radiance, every pass timed in frame order; and with every pass off, the frame is the fused
// resolve + tone map it always was.
#include "GlTestContext.h"
#include "RadianceFrame.h"

#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;

namespace {

std::vector<std::string> passNames(const render::Renderer& renderer)
{
    std::vector<std::string> names;
    for (const auto& pass : renderer.stats().passes) names.emplace_back(pass.name);
    return names;
}

render::FrameSettings everything(int width, int height, int msaa)
{
    render::FrameSettings s;
    s.width = width;
    s.height = height;
    s.msaa = msaa;
    s.shadows.enabled = false; // the post chain alone (shadows: test_shadows.cpp)
    s.bloom.enabled = true;
    s.ssao.enabled = true;
    s.autoExposure.enabled = true;
    s.fxaa.enabled = true;
    return s;
}

} // namespace

TEST_F(GlTest, EveryPassAtSeveralSizes)
{
    scene::Scene demo = scene::makeDemoScene();
    scene::addDefaultLightRig(demo);
    render::Renderer renderer;
    renderer.setScene(demo);
    renderer.setGpuTiming(true);
    struct Size {
        int width, height, msaa;
    };
    for (const Size size : {Size{1, 1, 1}, Size{2, 3, 4}, Size{17, 9, 1}, Size{64, 64, 4}, Size{1023, 577, 4}, Size{577, 1023, 1},
                            Size{320, 180, 2}}) {
        const float aspect = float(size.width) / float(size.height);
        const render::View view = render::defaultView(demo, -1, aspect);
        render::FrameSettings s = everything(size.width, size.height, size.msaa);
        renderer.render(view, s);
        const std::vector<std::string> expected = {"light culling", "ssao prepass", "ssao", "ssao blur", "forward", "resolve",
                                                   "bloom", "exposure", "tonemap", "fxaa"};
        std::vector<std::string> names = passNames(renderer);
        if (size.msaa == 1) {
            // Nothing to resolve.
            std::vector<std::string> without = expected;
            without.erase(without.begin() + 5);
            EXPECT_EQ(names, without) << size.width << "x" << size.height;
        } else {
            EXPECT_EQ(names, expected) << size.width << "x" << size.height;
        }
        const ImageFloat radiance = renderer.readRadiance();
        for (float v : radiance.pixels) ASSERT_TRUE(std::isfinite(v)) << size.width << "x" << size.height;
        EXPECT_EQ(renderer.readImage().width, size.width);
        for (DebugView view : {DebugView::Ssao, DebugView::Bloom}) {
            render::FrameSettings d = s;
            d.debugView = view;
            renderer.render(render::defaultView(demo, -1, aspect), d);
            for (float v : renderer.readRadiance().pixels) ASSERT_TRUE(std::isfinite(v));
        }
        EXPECT_EQ(debug().errorCount(), 0) << size.width << "x" << size.height;
    }
}

TEST_F(GlTest, PassesOffCostNothing)
{
    // Every pass off: the two passes the renderer always had, the fused MSAA resolve in the
    // tone mapper included, after the light culling that the forward pass reads; switching
    // passes on and off again returns to exactly that frame.
    scene::Scene demo = scene::makeDemoScene();
    render::Renderer renderer;
    renderer.setScene(demo);
    renderer.setGpuTiming(true);
    const render::View view = render::defaultView(demo, -1, 16.0f / 9.0f);
    render::FrameSettings plain;
    plain.width = 160;
    plain.height = 90;
    plain.shadows.enabled = false;
    renderer.render(view, plain);
    EXPECT_EQ(passNames(renderer), (std::vector<std::string>{"light culling", "forward", "resolve+tonemap"}));
    const ImageRGBA8 before = renderer.readImage();
    renderer.render(view, everything(160, 90, 4));
    renderer.render(view, plain);
    EXPECT_EQ(passNames(renderer), (std::vector<std::string>{"light culling", "forward", "resolve+tonemap"}));
    EXPECT_EQ(renderer.readImage().pixels, before.pixels);
}

TEST_F(GlTest, SwitchedOffPassesGiveTheirTargetsBack)
{
    // The frame graph's pool keeps a pass's targets while frames use them and deletes them
    // once they have been idle for two frames: the plain frame's count comes back.
    scene::Scene demo = scene::makeDemoScene();
    render::Renderer renderer;
    renderer.setScene(demo);
    const render::View view = render::defaultView(demo, -1, 16.0f / 9.0f);
    render::FrameSettings plain;
    plain.width = 160;
    plain.height = 90;
    renderer.render(view, plain);
    const size_t plainTextures = renderer.stats().transientTextures;
    EXPECT_EQ(plainTextures, 3u) << "msaa colour, msaa depth, ldr colour";
    renderer.render(view, everything(160, 90, 4));
    const size_t allTextures = renderer.stats().transientTextures;
    EXPECT_GT(allTextures, plainTextures + 8) << "ssao's four, bloom's levels, the resolved frame, fxaa's input";
    renderer.render(view, everything(160, 90, 4));
    EXPECT_EQ(renderer.stats().transientTextures, allTextures) << "a frame like the last makes nothing new";
    for (int frame = 0; frame < 3; ++frame) renderer.render(view, plain);
    EXPECT_EQ(renderer.stats().transientTextures, plainTextures);
    // A new size: new targets, and the old ones go after their idle frames.
    plain.width = 200;
    for (int frame = 0; frame < 4; ++frame) renderer.render(view, plain);
    EXPECT_EQ(renderer.stats().transientTextures, plainTextures);
    EXPECT_EQ(renderer.readImage().width, 200);
    EXPECT_EQ(debug().errorCount(), 0);
}

TEST_F(GlTest, FxaaSmoothsAliasedEdgesOnly)
{
    // One sample per pixel: a tilted white square on black has staircase edges. FXAA puts
    // intermediate values along them and leaves flat areas exactly as they were.
    scene::Scene s;
    scene::Material m;
    m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    m.emissiveFactor = glm::vec3(0.5f);
    const glm::mat4 tilt = glm::rotate(glm::mat4(1.0f), glm::radians(12.0f), glm::vec3(0, 0, 1)) *
                           glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0));
    scene::addShape(s, scene::makePlane(1.0f), m, tilt, "square");
    render::Renderer renderer;
    renderer.setScene(s);
    const render::View view = render::lookAtView({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 10.0f);
    render::FrameSettings settings = test::radianceFrame(97, 97);
    renderer.render(view, settings);
    const ImageRGBA8 aliased = renderer.readImage();
    settings.fxaa.enabled = true;
    renderer.render(view, settings);
    const ImageRGBA8 smoothed = renderer.readImage();
    const uint8_t inside = aliased.pixels[(48 * 97 + 48) * 4];
    int intermediateBefore = 0, intermediateAfter = 0, changedFlat = 0;
    for (int y = 1; y < 96; ++y) {
        for (int x = 1; x < 96; ++x) {
            const size_t i = (size_t(y) * 97 + size_t(x)) * 4;
            const auto between = [&](uint8_t v) { return v > 8 && v < inside - 8; };
            intermediateBefore += between(aliased.pixels[i]);
            intermediateAfter += between(smoothed.pixels[i]);
            // A pixel whose 3x3 neighbourhood is flat must not change.
            bool flat = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    flat &= aliased.pixels[(size_t(y + dy) * 97 + size_t(x + dx)) * 4] == aliased.pixels[i];
            // (±1: FXAA's input is encoded by the shader, the plain frame by GL; they may round apart.)
            if (flat && std::abs(int(smoothed.pixels[i]) - int(aliased.pixels[i])) > 1) ++changedFlat;
        }
    }
    EXPECT_EQ(intermediateBefore, 0) << "one sample per pixel: only inside or outside";
    EXPECT_GT(intermediateAfter, 100) << "FXAA blends along the square's four edges";
    EXPECT_EQ(changedFlat, 0);
}
