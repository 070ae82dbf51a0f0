// The shading models as forward-pass variants: each renders without a GL error; Gouraud
// matches the per-vertex CPU value at the vertices of a low-polygon sphere and differs from
// Phong between them; flat shading uses the face normal; switching one material's model or a
// parameter at run time changes the next frame for that material only.
#include "GlTestContext.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/Brdf.h"
#include "render/GpuScene.h"
#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;
using specula::test::pixel;
using glm::dvec3;

namespace {

constexpr int kSize = 400;
const glm::vec3 kEye(0.0f, 0.0f, 4.0f);
const glm::vec3 kLightDirection = glm::normalize(glm::vec3(-0.4f, -0.3f, -1.0f)); // towards the scene, from front right
constexpr float kLightLux = 3.0f;

render::View testView()
{
    return render::lookAtView(kEye, {0, 0, 0}, {0, 1, 0}, glm::radians(40.0f), 1.0f, 0.1f, 20.0f);
}

scene::Material testMaterial(glm::vec3 color = {0.8f, 0.3f, 0.2f})
{
    scene::Material m;
    m.baseColorFactor = glm::vec4(color, 1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.3f; // shininess 2/α² − 2 = 245: a highlight smaller than a facet
    return m;
}

void addTestLight(scene::Scene& s)
{
    scene::Light light;
    light.type = scene::Light::Type::Directional;
    light.intensity = kLightLux;
    scene::addLight(s, light, {0, 0, 0}, kLightDirection);
}

/// Pixel (x, y), image row 0 at the top, of a point in world space.
glm::ivec2 project(const render::View& view, const glm::vec3& p)
{
    return test::projectToPixel(view, p, kSize, kSize);
}

ImageFloat renderSphere(scene::ShadingModel model, const scene::Primitive& sphere)
{
    scene::Scene s;
    scene::Material m = testMaterial();
    m.shading.model = model;
    scene::addShape(s, sphere, m, glm::mat4(1.0f), "sphere");
    addTestLight(s);
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(testView(), test::radianceFrame(kSize, kSize, test::Brdf::Exact));
    return renderer.readRadiance();
}

} // namespace

TEST_F(GlTest, EveryShadingModelRenders)
{
    scene::Scene s;
    scene::addShape(s, scene::makeUvSphere(1.0f, 24, 12), testMaterial(), glm::mat4(1.0f), "sphere");
    addTestLight(s);
    render::Renderer renderer;
    renderer.setScene(s);
    for (int model = 0; model < scene::kShadingModelCount; ++model) {
        render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
        settings.width = settings.height = 64;
        settings.materialOverride.model = scene::ShadingModel(model);
        renderer.render(testView(), settings);
        const ImageFloat image = renderer.readRadiance();
        const glm::vec3 centre = pixel(image, {32, 32});
        EXPECT_GT(centre.r, 0.01f) << scene::shadingModelName(scene::ShadingModel(model));
    }
    // Debug views too: base colour shows the base colour exactly.
    render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
    settings.width = settings.height = 64;
    settings.debugView = DebugView::BaseColor;
    renderer.render(testView(), settings);
    EXPECT_NEAR(pixel(renderer.readRadiance(), {32, 32}).g, 0.3f, 1e-3f);
    // Normal: the sphere's centre faces the camera (+Z): bytes (128, 128, 255), ± 4 because
    // pixel (32, 32)'s centre is half a pixel off the image centre (n.x, n.y ≈ ±0.02).
    settings.debugView = DebugView::Normal;
    renderer.render(testView(), settings);
    const ImageRGBA8 normal = renderer.readImage();
    const uint8_t* centre = &normal.pixels[(32u * 64u + 32u) * 4u];
    EXPECT_NEAR(centre[0], 128, 4);
    EXPECT_NEAR(centre[1], 128, 4);
    EXPECT_EQ(centre[2], 255);
    for (auto view : {DebugView::Roughness, DebugView::Metallic, DebugView::Occlusion,
                      DebugView::Emissive, DebugView::BrdfD, DebugView::BrdfG, DebugView::BrdfF}) {
        settings.debugView = view;
        renderer.render(testView(), settings);
    }
    // Roughness 0.3 as a byte (the last frame but six: render it again).
    settings.debugView = DebugView::Roughness;
    renderer.render(testView(), settings);
    EXPECT_NEAR(renderer.readImage().pixels[(32u * 64u + 32u) * 4u], 77, 1); // 0.3 × 255
}

TEST_F(GlTest, GouraudMatchesPerVertexCpuAndDiffersFromPhong)
{
    // 16 × 8 facets: a vertex every 22.5°, wider than the highlight.
    const scene::Primitive sphere = scene::makeUvSphere(1.0f, 16, 8);
    const ImageFloat gouraud = renderSphere(scene::ShadingModel::Gouraud, sphere);
    const ImageFloat phong = renderSphere(scene::ShadingModel::Phong, sphere);
    const render::View view = testView();

    const dvec3 kd(0.8, 0.3, 0.2), ks(0.5);
    const double shininess = render::brdf::classicShininess(0.3);
    const dvec3 l = -dvec3(kLightDirection);
    int checked = 0;
    for (const scene::Vertex& vertex : sphere.vertices) {
        const dvec3 p(vertex.position), n = glm::normalize(dvec3(vertex.normal));
        const dvec3 v = glm::normalize(dvec3(kEye) - p);
        if (glm::dot(n, v) < 0.3) continue; // hidden or on the silhouette
        const glm::ivec2 at = project(view, vertex.position);
        const dvec3 expected = render::brdf::evaluateClassic(kd, ks, shininess, false, n, v, l) * double(kLightLux);
        const glm::vec3 got = pixel(gouraud, at);
        // The pixel centre lies up to 0.7 px from the vertex, about 1% of a facet (70 px): the
        // interpolated value moves by at most that fraction of the facet's range, < 4% here.
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c], expected[c], 0.04 * expected[c] + 3e-3) << "vertex at pixel " << at.x << ", " << at.y;
        ++checked;
    }
    EXPECT_GT(checked, 15);

    // Between the vertices Phong keeps the highlight that Gouraud's interpolation loses.
    float maxPhong = 0.0f, maxDifference = 0.0f;
    for (size_t i = 0; i < phong.pixels.size(); i += 4) {
        maxPhong = std::max(maxPhong, phong.pixels[i + 1]);
        maxDifference = std::max(maxDifference, std::abs(phong.pixels[i + 1] - gouraud.pixels[i + 1]));
    }
    EXPECT_GT(maxDifference, 0.25f * maxPhong) << "Gouraud should differ visibly from Phong between vertices";
}

TEST_F(GlTest, FlatShadesWithTheFaceNormal)
{
    const scene::Primitive sphere = scene::makeUvSphere(1.0f, 16, 8);
    const ImageFloat flat = renderSphere(scene::ShadingModel::Flat, sphere);
    const render::View view = testView();
    const dvec3 kd(0.8, 0.3, 0.2), ks(0.5);
    const double shininess = render::brdf::classicShininess(0.3);
    const dvec3 l = -dvec3(kLightDirection);
    int checked = 0;
    for (size_t t = 0; t + 2 < sphere.indices.size(); t += 3) {
        const glm::vec3 a = sphere.vertices[sphere.indices[t]].position, b = sphere.vertices[sphere.indices[t + 1]].position,
                        c = sphere.vertices[sphere.indices[t + 2]].position;
        const glm::vec3 cross = glm::cross(b - a, c - a);
        if (glm::length(cross) < 1e-4f) continue; // degenerate triangles at the poles
        const glm::vec3 centroid = (a + b + c) / 3.0f;
        const dvec3 n = glm::normalize(dvec3(cross)), v = glm::normalize(dvec3(kEye) - dvec3(centroid));
        if (glm::dot(n, v) < 0.4) continue;
        // Sample at the centroid, where view direction and pixel agree best.
        const dvec3 expected = render::brdf::evaluateClassic(kd, ks, shininess, false, n, v, l) * double(kLightLux);
        const glm::vec3 got = pixel(flat, project(view, centroid));
        // 3%: the pixel centre is up to 0.7 px from the centroid; v, hence (R·V)^245, moves with it.
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(got[ch], expected[ch], 0.03 * expected[ch] + 3e-3) << "triangle " << t / 3;
        ++checked;
    }
    EXPECT_GT(checked, 20);
}

TEST_F(GlTest, SwitchingOneMaterialChangesOnlyIt)
{
    scene::Scene s;
    scene::addShape(s, scene::makeUvSphere(0.8f, 32, 16), testMaterial({0.8f, 0.3f, 0.2f}),
                    glm::translate(glm::mat4(1.0f), {-1.0f, 0.0f, 0.0f}), "left");
    scene::addShape(s, scene::makeUvSphere(0.8f, 32, 16), testMaterial({0.2f, 0.5f, 0.8f}),
                    glm::translate(glm::mat4(1.0f), {1.0f, 0.0f, 0.0f}), "right");
    addTestLight(s);
    render::Renderer renderer;
    renderer.setScene(s);
    ASSERT_EQ(renderer.materialCount(), 3); // two, and glTF's default material
    const render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
    const render::View view = testView();
    renderer.render(view, settings);
    const ImageFloat before = renderer.readRadiance();

    // Half of the image each: x < kSize / 2 is the left sphere, material 0.
    auto compareHalves = [&](const ImageFloat& a, const ImageFloat& b, int& changedLeft, int& changedRight) {
        changedLeft = changedRight = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                if (pixel(a, {x, y}) != pixel(b, {x, y})) ++(x < kSize / 2 ? changedLeft : changedRight);
    };
    renderer.setMaterialShading(0, {.model = scene::ShadingModel::Unlit});
    EXPECT_EQ(renderer.materialShading(0).model, scene::ShadingModel::Unlit);
    EXPECT_FALSE(renderer.materialShading(1).model);
    renderer.render(view, settings);
    const ImageFloat unlit = renderer.readRadiance();
    int left = 0, right = 0;
    compareHalves(before, unlit, left, right);
    EXPECT_GT(left, 1000);
    EXPECT_EQ(right, 0);
    // Unlit shows the base colour.
    EXPECT_NEAR(pixel(unlit, project(view, {-1.0f, 0.0f, 0.8f})).r, 0.8f, 1e-3f);

    // A parameter: material 1's base colour, only its record's bytes.
    renderer.setMaterialParameter(1, render::MaterialParameter::BaseColor, {0.1f, 0.9f, 0.1f, 1.0f});
    EXPECT_EQ(renderer.materialParameter(1, render::MaterialParameter::BaseColor), glm::vec4(0.1f, 0.9f, 0.1f, 1.0f));
    EXPECT_EQ(renderer.materialParameter(0, render::MaterialParameter::Roughness).x, 0.3f);
    renderer.render(view, settings);
    const ImageFloat recoloured = renderer.readRadiance();
    compareHalves(unlit, recoloured, left, right);
    EXPECT_EQ(left, 0);
    EXPECT_GT(right, 1000);

    // Back to the physically based model: the first frame again, bit for bit, on the left.
    renderer.setMaterialShading(0, {});
    renderer.render(view, settings);
    compareHalves(before, renderer.readRadiance(), left, right);
    EXPECT_EQ(left, 0);
}

// The registry writes by offset: a parameter change rewrites that field of that material's
// record and no other byte of the material buffer.
TEST_F(GlTest, MaterialParameterWritesOnlyItsBytes)
{
    scene::Scene s;
    for (int i = 0; i < 3; ++i)
        scene::addShape(s, scene::makeUvSphere(0.5f, 8, 4), testMaterial(), glm::translate(glm::mat4(1.0f), {float(i), 0, 0}), "s");
    render::GpuScene gpu(s);
    const std::vector<std::byte> before = gpu.materialBuffer().read(0, gpu.materialBuffer().size());
    const float roughness = 0.75f;
    gpu.writeMaterial(1, offsetof(shared::GpuMaterial, params) + sizeof(float), sizeof(float), &roughness);
    const std::vector<std::byte> after = gpu.materialBuffer().read(0, gpu.materialBuffer().size());
    ASSERT_EQ(before.size(), after.size());
    const size_t field = gpu.materialOffset(1) + offsetof(shared::GpuMaterial, params) + sizeof(float);
    for (size_t i = 0; i < before.size(); ++i) {
        if (i >= field && i < field + sizeof(float)) continue;
        ASSERT_EQ(before[i], after[i]) << "byte " << i << " changed";
    }
    float written = 0.0f;
    std::memcpy(&written, after.data() + field, sizeof(float));
    EXPECT_EQ(written, roughness);
    EXPECT_EQ(gpu.record(1).params.y, roughness);
    EXPECT_EQ(gpu.record(0).params.y, 0.3f);
}

// The parameters the viewer's Materials panel edits besides the glTF factors: the index of
// refraction (the record's specular colour), the classic models' ks and the Doom sector light.
// Each reads back as written and changes the next frame the way its model says.
TEST_F(GlTest, IorClassicSpecularAndSectorLightAreLiveParameters)
{
    scene::Scene s;
    scene::addShape(s, scene::makeUvSphere(0.8f, 48, 24), testMaterial(), glm::mat4(1.0f), "sphere");
    addTestLight(s);
    render::Renderer renderer;
    renderer.setScene(s);
    const render::View view = testView();
    const render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
    using render::MaterialParameter;
    auto frame = [&] {
        renderer.render(view, settings);
        return renderer.readRadiance();
    };
    auto brightest = [](const ImageFloat& image) {
        float best = 0.0f;
        for (size_t i = 0; i < image.pixels.size(); i += 4)
            best = std::max(best, 0.2126f * image.pixels[i] + 0.7152f * image.pixels[i + 1] + 0.0722f * image.pixels[i + 2]);
        return best;
    };
    auto mean = [](const ImageFloat& image) {
        double sum = 0.0;
        for (size_t i = 0; i < image.pixels.size(); i += 4) sum += image.pixels[i] + image.pixels[i + 1] + image.pixels[i + 2];
        return sum / double(image.pixels.size() / 4);
    };
    // Defaults as GpuScene packs them.
    EXPECT_EQ(renderer.materialParameter(0, MaterialParameter::SpecularColor), glm::vec4(1.0f, 1.0f, 1.0f, 0.0f));
    EXPECT_EQ(renderer.materialParameter(0, MaterialParameter::SpecularFactor).x, 1.0f);
    EXPECT_EQ(renderer.materialParameter(0, MaterialParameter::PhongSpecular), glm::vec4(0.5f, 0.5f, 0.5f, 0.0f));
    EXPECT_NEAR(renderer.materialParameter(0, MaterialParameter::SectorLight).x, float(testMaterial().sectorLight), 1e-3f);

    // ior 2.5: F0 = (1.5 / 3.5)² = 0.18 instead of 0.04, a brighter highlight on the same sphere.
    const float pbrHighlight = brightest(frame());
    const float f0Scale = scene::f0FromIor(2.5f) / 0.04f;
    renderer.setMaterialParameter(0, MaterialParameter::SpecularColor, glm::vec4(f0Scale));
    EXPECT_EQ(renderer.materialParameter(0, MaterialParameter::SpecularColor), glm::vec4(glm::vec3(f0Scale), 0.0f));
    EXPECT_GT(brightest(frame()), 2.0f * pbrHighlight);

    // Blinn-Phong: ks 0 takes the highlight away, leaving the diffuse term's brightest pixel.
    renderer.setMaterialShading(0, {.model = scene::ShadingModel::BlinnPhong});
    const float blinnHighlight = brightest(frame());
    renderer.setMaterialParameter(0, MaterialParameter::PhongSpecular, glm::vec4(0.0f));
    EXPECT_EQ(renderer.materialParameter(0, MaterialParameter::PhongSpecular), glm::vec4(0.0f));
    const float diffuseOnly = brightest(frame());
    EXPECT_LT(diffuseOnly, 0.8f * blinnHighlight);
    // What is left is the diffuse peak, kd E / π where the sphere faces the light (within 2%: the
    // sphere's facets and the pixel grid may miss the exact point).
    const float diffusePeak = (0.2126f * 0.8f + 0.7152f * 0.3f + 0.0722f * 0.2f) * kLightLux / float(render::brdf::kPi);
    EXPECT_NEAR(diffuseOnly, diffusePeak, 0.02f * diffusePeak);

    // Doom: a darker sector is darker.
    renderer.setMaterialShading(0, {.model = scene::ShadingModel::Doom});
    const double lit = mean(frame());
    renderer.setMaterialParameter(0, MaterialParameter::SectorLight, glm::vec4(96.0f));
    EXPECT_NEAR(renderer.materialParameter(0, MaterialParameter::SectorLight).x, 96.0f, 1e-3f);
    EXPECT_LT(mean(frame()), 0.7 * lit);
}
