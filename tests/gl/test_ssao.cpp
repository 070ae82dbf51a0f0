// SSAO (render/SsaoPass) through the Renderer's SSAO debug view, which reads back the blurred
// occlusion: flat surfaces stay open, inside corners darken, silhouettes cast no halo, the
// result barely depends on resolution, and direct light is never darkened.
#include "GlTestContext.h"
#include "RadianceFrame.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/Renderer.h"
#include "render/passes/SsaoPass.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;

namespace {

scene::Material grey(bool doubleSided = false)
{
    scene::Material m;
    m.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.7f;
    m.doubleSided = doubleSided;
    return m;
}

/// Occlusion (1 = open) of the last frame at normalised device coordinates, averaged over
/// the pixels within `radius` pixels.
struct AoImage {
    ImageFloat image;
    float at(glm::vec2 ndc, int radius = 1) const
    {
        const int cx = int((ndc.x * 0.5f + 0.5f) * float(image.width));
        const int cy = int((0.5f - ndc.y * 0.5f) * float(image.height)); // top row first
        double sum = 0;
        int count = 0;
        for (int y = cy - radius; y <= cy + radius; ++y)
            for (int x = cx - radius; x <= cx + radius; ++x) {
                if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
                sum += image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
                ++count;
            }
        return float(sum / count);
    }
};

AoImage renderAo(render::Renderer& renderer, const render::View& view, int width, int height, float radius = 0.5f)
{
    render::FrameSettings s;
    s.width = width;
    s.height = height;
    s.msaa = 1;
    s.debugView = DebugView::Ssao;
    s.ssao.radius = radius;
    renderer.render(view, s);
    return {renderer.readRadiance()};
}

glm::vec2 project(const render::View& view, glm::vec3 world)
{
    const glm::vec4 clip = view.projection * view.view * glm::vec4(world, 1.0f);
    return glm::vec2(clip) / clip.w;
}

/// A closed box seen from inside (double-sided, so its inner faces are drawn).
scene::Scene insideOfBox()
{
    scene::Scene s;
    scene::addShape(s, scene::makeCube(1.0f), grey(true), glm::mat4(1.0f), "room");
    return s;
}

render::View cornerView(float aspect)
{
    return render::lookAtView({0.4f, 0.3f, 0.5f}, {-1.0f, -1.0f, -1.0f}, {0, 1, 0}, glm::radians(70.0f), aspect, 0.05f, 20.0f);
}

} // namespace

TEST_F(GlTest, SsaoLeavesFlatSurfacesOpen)
{
    render::Renderer renderer;
    // A plane facing the camera, and a floor seen at a grazing angle: no self-occlusion.
    scene::Scene wall;
    scene::addShape(wall, scene::makePlane(20.0f), grey(),
                    glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0)), "wall");
    renderer.setScene(wall);
    const render::View front = render::lookAtView({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 4.0f / 3.0f, 0.1f, 50.0f);
    AoImage ao = renderAo(renderer, front, 128, 96);
    float minimum = 1.0f;
    for (int y = 4; y < 92; ++y)
        for (int x = 4; x < 124; ++x) minimum = std::min(minimum, ao.image.pixels[(size_t(y) * 128 + size_t(x)) * 4]);
    EXPECT_GT(minimum, 0.99f) << "a plane facing the camera occludes itself";

    scene::Scene floor;
    scene::addShape(floor, scene::makePlane(200.0f), grey(), glm::mat4(1.0f), "floor");
    renderer.setScene(floor);
    const render::View grazing = render::lookAtView({0, 1.5f, 0}, {0, 0, -10}, {0, 1, 0}, glm::radians(60.0f), 4.0f / 3.0f, 0.1f, 200.0f);
    ao = renderAo(renderer, grazing, 128, 96);
    minimum = 1.0f;
    // The lower half of the image is floor (the horizon is at the image centre, far away).
    for (int y = 52; y < 92; ++y)
        for (int x = 4; x < 124; ++x) minimum = std::min(minimum, ao.image.pixels[(size_t(y) * 128 + size_t(x)) * 4]);
    EXPECT_GT(minimum, 0.98f) << "a floor at a grazing angle occludes itself";
}

TEST_F(GlTest, SsaoDarkensTheInsideCornerOfABox)
{
    render::Renderer renderer;
    renderer.setScene(insideOfBox());
    const render::View view = cornerView(4.0f / 3.0f);
    const AoImage ao = renderAo(renderer, view, 160, 120);
    const float corner = ao.at(project(view, {-0.97f, -0.97f, -0.97f}));
    const float edge = ao.at(project(view, {-0.97f, -0.97f, 0.0f}));   // where two faces meet
    const float floor = ao.at(project(view, {0.0f, -1.0f, 0.0f}));     // a face, far from walls
    const float wall = ao.at(project(view, {-1.0f, 0.0f, 0.2f}));
    EXPECT_LT(corner, edge);
    EXPECT_LT(edge, floor);
    EXPECT_LT(corner, 0.7f);
    EXPECT_GT(floor, 0.95f);
    EXPECT_GT(wall, 0.95f);
}

TEST_F(GlTest, SsaoDoesNotDependOnResolution)
{
    // The kernel lives in metres, so twice the pixels sample the same geometry: at matching
    // points the occlusion agrees within 0.06 (sampling noise: 16 directions at one rotation
    // per pixel, blurred over 4×4), and the image means within 0.02.
    render::Renderer renderer;
    renderer.setScene(insideOfBox());
    const render::View view = cornerView(4.0f / 3.0f);
    const AoImage low = renderAo(renderer, view, 120, 90);
    const AoImage high = renderAo(renderer, view, 240, 180);
    double meanLow = 0, meanHigh = 0;
    for (size_t i = 0; i < low.image.pixels.size(); i += 4) meanLow += low.image.pixels[i];
    for (size_t i = 0; i < high.image.pixels.size(); i += 4) meanHigh += high.image.pixels[i];
    meanLow /= double(low.image.pixels.size() / 4);
    meanHigh /= double(high.image.pixels.size() / 4);
    EXPECT_NEAR(meanLow, meanHigh, 0.02);
    for (const glm::vec3 point : {glm::vec3(-0.9f, -0.9f, -0.9f), glm::vec3(-0.95f, -0.95f, -0.2f), glm::vec3(-0.95f, -0.5f, -0.95f),
                                  glm::vec3(-0.3f, -1.0f, -0.95f), glm::vec3(0.0f, -1.0f, 0.0f)}) {
        const glm::vec2 ndc = project(view, point);
        EXPECT_NEAR(low.at(ndc, 2), high.at(ndc, 4), 0.06) << point.x << "," << point.y << "," << point.z;
    }
}

TEST_F(GlTest, SsaoCastsNoHaloAtDepthDiscontinuities)
{
    // A ball 3 m in front of a wall: far beyond the 0.5 m radius, so the wall around its
    // silhouette stays open, and the ball (convex) is open too.
    scene::Scene s;
    scene::addShape(s, scene::makePlane(40.0f), grey(), glm::translate(glm::mat4(1.0f), {0, 0, -3}) *
                    glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0)), "wall");
    scene::addShape(s, scene::makeUvSphere(0.4f, 64, 32), grey(), glm::mat4(1.0f), "ball");
    render::Renderer renderer;
    renderer.setScene(s);
    const render::View view = render::lookAtView({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, glm::radians(45.0f), 1.0f, 0.1f, 50.0f);
    const AoImage ao = renderAo(renderer, view, 128, 128);
    // The ball's silhouette seen from 2 m: radius angle asin(0.4 / 2).
    const float silhouette = std::tan(std::asin(0.2f)) / std::tan(glm::radians(22.5f));
    for (int i = 0; i < 16; ++i) {
        const float a = 2.0f * 3.14159265f * float(i) / 16.0f;
        const glm::vec2 direction(std::cos(a), std::sin(a));
        EXPECT_GT(ao.at(direction * silhouette * 1.12f, 0), 0.97f) << "wall beside the silhouette, angle " << i;
        EXPECT_GT(ao.at(direction * silhouette * 0.5f, 0), 0.97f) << "on the ball, angle " << i;
    }
}

TEST_F(GlTest, SsaoDarkensAmbientLightOnly)
{
    // Direct light only: SSAO on or off renders the same bytes. With a constant ambient term
    // the inside corner gets darker with SSAO, and nothing gets brighter.
    render::Renderer renderer;
    scene::Scene s = insideOfBox();
    scene::Light light;
    light.type = scene::Light::Type::Point;
    light.intensity = 2.0f;
    scene::Node node;
    node.translation = glm::vec3(0.3f, 0.5f, 0.3f);
    s.lights.push_back(light);
    node.light = 0;
    s.addNode(std::move(node));
    renderer.setScene(s);
    const render::View view = cornerView(4.0f / 3.0f);
    render::FrameSettings settings = test::radianceFrame(160, 120);
    renderer.render(view, settings);
    const ImageFloat direct = renderer.readRadiance();
    settings.ssao.enabled = true;
    renderer.render(view, settings);
    EXPECT_EQ(renderer.readRadiance().pixels, direct.pixels);

    settings.ambient = glm::vec3(0.5f);
    settings.ssao.enabled = false;
    renderer.render(view, settings);
    const ImageFloat open = renderer.readRadiance();
    settings.ssao.enabled = true;
    renderer.render(view, settings);
    const ImageFloat occluded = renderer.readRadiance();
    const glm::vec2 ndc = project(view, {-0.97f, -0.97f, -0.97f});
    const size_t corner = (size_t((0.5f - ndc.y * 0.5f) * 120.0f) * 160 + size_t((ndc.x * 0.5f + 0.5f) * 160.0f)) * 4;
    EXPECT_LT(occluded.pixels[corner], open.pixels[corner] - 0.05f);
    for (size_t i = 0; i < open.pixels.size(); i += 4) ASSERT_LE(occluded.pixels[i], open.pixels[i] + 1e-3f) << i / 4;
}

TEST_F(GlTest, SsaoKernelIsAHemisphereDenserNearTheCentre)
{
    for (int count : {1, 8, 16, 64}) {
        const auto kernel = render::SsaoPass::makeKernel(count);
        ASSERT_EQ(int(kernel.size()), count);
        float meanLength = 0;
        for (const glm::vec4& k : kernel) {
            EXPECT_GT(k.z, 0.0f);
            EXPECT_LE(glm::length(glm::vec3(k)), 1.0f + 1e-5f);
            meanLength += glm::length(glm::vec3(k)) / float(count);
        }
        if (count >= 16) {
            EXPECT_LT(meanLength, 0.55f); // 0.1 + 0.9 E[t²] = 0.4 for uniform t
        }
    }
}
