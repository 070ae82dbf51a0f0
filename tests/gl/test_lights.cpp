// Lights in a std430 storage buffer with no fixed count: editing one touches only its bytes,
// the buffer grows by doubling (a new buffer only when the count outgrows it), and every
// light of a thousand reaches the shading of every reflection model.
#include "GlTestContext.h"

#include <cmath>
#include <cstring>
#include <utility>

#include <glm/gtc/constants.hpp>

#include "render/LightBuffer.h"
#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/Procedural.h"

using namespace specula;
using specula::test::GlTest;

namespace {

std::vector<render::PlacedLight> numberedLights(int count)
{
    std::vector<render::PlacedLight> placed;
    for (int i = 0; i < count; ++i) {
        render::PlacedLight p;
        p.light.type = scene::Light::Type(i % 3);
        p.light.intensity = float(i);
        p.position = glm::vec3(float(i), 1.0f, 2.0f);
        placed.push_back(p);
    }
    return placed;
}

shared::GpuLight gpuLightAt(const std::vector<std::byte>& bytes, size_t offset)
{
    shared::GpuLight gpu;
    std::memcpy(&gpu, bytes.data() + offset, sizeof gpu);
    return gpu;
}

} // namespace

TEST_F(GlTest, EditingOneLightRewritesOnlyItsBytes)
{
    // 1,000 lights, four times the 255 a 16 KiB uniform block held; the edited one is past them.
    constexpr int kCount = 1000, kEdited = 737;
    render::LightBuffer lights;
    const std::vector<render::PlacedLight> placed = numberedLights(kCount);
    lights.setAll(placed);
    ASSERT_EQ(lights.count(), kCount);
    const auto before = lights.buffer().read(0, lights.buffer().size());
    const size_t updatedBefore = lights.buffer().bytesUpdated();

    render::PlacedLight edited = placed[kEdited];
    edited.light.color = {0.1f, 0.2f, 0.3f};
    edited.light.intensity = 999.0f;
    lights.set(kEdited, edited);

    // The upload was exactly one GpuLight at its offset...
    EXPECT_EQ(lights.buffer().bytesUpdated() - updatedBefore, sizeof(shared::GpuLight));
    EXPECT_EQ(lights.buffer().lastUpdate().offset, lights.offsetOf(kEdited));
    EXPECT_EQ(lights.buffer().lastUpdate().size, sizeof(shared::GpuLight));
    EXPECT_EQ(lights.offsetOf(kEdited), sizeof(shared::LightHeader) + kEdited * sizeof(shared::GpuLight));
    // ...and reading the GPU copy back, no other byte changed.
    const auto after = lights.buffer().read(0, lights.buffer().size());
    const size_t begin = lights.offsetOf(kEdited), end = begin + sizeof(shared::GpuLight);
    size_t changed = 0;
    for (size_t i = 0; i < after.size(); ++i) {
        if (before[i] != after[i]) {
            ++changed;
            EXPECT_TRUE(i >= begin && i < end) << "byte " << i << " outside light " << kEdited << " changed";
        }
    }
    EXPECT_GT(changed, 0u);
    EXPECT_EQ(gpuLightAt(after, begin).colorIntensity, glm::vec4(0.1f, 0.2f, 0.3f, 999.0f));
    EXPECT_EQ(lights.light(kEdited).light.intensity, 999.0f);
}

TEST_F(GlTest, LightBufferGrowsByDoublingAndHasNoCap)
{
    render::LightBuffer lights;
    const int initial = lights.capacity();
    ASSERT_GT(initial, 0);
    const uint32_t firstId = lights.buffer().id();

    // Up to capacity: the same buffer, one upload of the header and the lights.
    lights.setAll(numberedLights(initial));
    EXPECT_EQ(lights.buffer().id(), firstId);
    EXPECT_EQ(lights.buffer().lastUpdate().offset, 0u);
    EXPECT_EQ(lights.buffer().lastUpdate().size, lights.offsetOf(initial));

    // One more: a buffer of twice the capacity. Far more: doubled until they fit, every one kept.
    lights.setAll(numberedLights(initial + 1));
    EXPECT_EQ(lights.capacity(), 2 * initial);
    EXPECT_NE(lights.buffer().id(), firstId);
    constexpr int kMany = 5000;
    lights.setAll(numberedLights(kMany));
    ASSERT_EQ(lights.count(), kMany);
    int expectedCapacity = initial;
    while (expectedCapacity < kMany) expectedCapacity *= 2;
    EXPECT_EQ(lights.capacity(), expectedCapacity);
    EXPECT_EQ(lights.buffer().size(), sizeof(shared::LightHeader) + size_t(expectedCapacity) * sizeof(shared::GpuLight));
    const auto bytes = lights.buffer().read(0, lights.offsetOf(kMany));
    shared::LightHeader header;
    std::memcpy(&header, bytes.data(), sizeof header);
    EXPECT_EQ(header.count.x, uint32_t(kMany));
    for (int i : {0, 254, 255, 256, 4321, kMany - 1})
        EXPECT_EQ(gpuLightAt(bytes, lights.offsetOf(i)).colorIntensity.a, float(i)) << "light " << i;

    // Fewer again: the big buffer stays, the header says how many are in use.
    const uint32_t bigId = lights.buffer().id();
    lights.setAll(numberedLights(3));
    EXPECT_EQ(lights.buffer().id(), bigId);
    EXPECT_EQ(lights.count(), 3);
    std::memcpy(&header, lights.buffer().read(0, sizeof header).data(), sizeof header);
    EXPECT_EQ(header.count.x, 3u);
    lights.setAll({});
    std::memcpy(&header, lights.buffer().read(0, sizeof header).data(), sizeof header);
    EXPECT_EQ(header.count.x, 0u);

    // The one bound besides memory: what a shader's storage block reaches, at least 2^24 bytes
    // (GL 4.3's minimum GL_MAX_SHADER_STORAGE_BLOCK_SIZE), a quarter of a million lights.
    EXPECT_GE(lights.maxCount(), int(((1 << 24) - sizeof(shared::LightHeader)) / sizeof(shared::GpuLight)));
}

namespace {

// A thousand directional lights on a white-ish Lambertian plane, seen from straight above.
// With F0 = F90 = 0 (KHR_materials_specular factor 0) the physically based model is Lambert
// alone, L = (baseColor / π) Σ E_k (n · l_k); the classic models with ks = 0 give kd Σ E_k
// (n · l_k) / π, the same. Directional lights make the sum the same at every pixel and every
// vertex, so Phong (per fragment) and Gouraud (per vertex) are checked by one CPU value.
constexpr int kLightCount = 1000;
constexpr int kOldCap = 255; // what the uniform block held
const glm::vec3 kBaseColor(0.8f, 0.7f, 0.6f);

scene::Light lightNumber(int k, glm::vec3* direction)
{
    scene::Light light;
    light.type = scene::Light::Type::Directional;
    // Colour tells the lights apart: blue comes only from lights past the old cap.
    light.color = glm::vec3(1.0f, 0.25f + 0.25f * float(k % 4), k >= kOldCap ? 1.0f : 0.0f);
    light.intensity = 0.01f * float(1 + k % 5); // lux
    // Towards the surface from up to 60° off the normal (+y), around it; every tenth from
    // below, which must add nothing (n · l < 0).
    const float theta = glm::radians(60.0f) * float(k % 13) / 12.0f;
    const float phi = 2.0f * glm::pi<float>() * float(k % 17) / 17.0f;
    glm::vec3 toLight(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    if (k % 10 == 9) toLight.y = -toLight.y - 0.2f;
    *direction = -toLight;
    return light;
}

/// Σ E_k (n · l_k) over lights [0, count), per channel, in double, from the directions the
/// GPU gets (render::LightBuffer::pack normalises them).
glm::dvec3 expectedIrradiance(int count)
{
    glm::dvec3 sum(0.0);
    for (int k = 0; k < count; ++k) {
        glm::vec3 direction;
        const scene::Light light = lightNumber(k, &direction);
        const glm::dvec3 l = -glm::dvec3(glm::normalize(direction));
        const double NoL = l.y; // n = +y
        if (NoL <= 0.0) continue;
        sum += glm::dvec3(light.color) * double(light.intensity) * NoL;
    }
    return sum;
}

ImageFloat renderManyLights(scene::ShadingModel model, float* exposureScale)
{
    scene::Scene s;
    scene::Material m;
    m.baseColorFactor = glm::vec4(kBaseColor, 1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.5f;
    m.specularFactor = 0.0f; // F0 = F90 = 0: no specular lobe
    m.shading.model = model;
    scene::addShape(s, scene::makePlane(8.0f), m, glm::mat4(1.0f), "plane");
    for (int k = 0; k < kLightCount; ++k) {
        glm::vec3 direction;
        const scene::Light light = lightNumber(k, &direction);
        scene::addLight(s, light, {0, 0, 0}, direction);
    }
    render::Renderer renderer;
    renderer.setScene(s);
    EXPECT_EQ(renderer.lightCount(), kLightCount);
    renderer.setMaterialParameter(0, render::MaterialParameter::PhongSpecular, glm::vec4(0.0f)); // ks = 0
    render::FrameSettings settings;
    settings.width = settings.height = 32;
    settings.msaa = 1;
    settings.tonemap = render::Tonemap::None;
    settings.energyCompensation = false;
    const render::View view = render::lookAtView({0, 3, 0}, {0, 0, 0}, {0, 0, -1}, glm::radians(60.0f), 1.0f, 0.1f, 10.0f);
    renderer.render(view, settings);
    *exposureScale = renderer.exposureScale();
    return renderer.readRadiance();
}

} // namespace

TEST_F(GlTest, AThousandLightsAllReachEveryModel)
{
    const glm::dvec3 expected = glm::dvec3(kBaseColor) * expectedIrradiance(kLightCount) / glm::pi<double>();
    // Tolerance 0.3% relative: the target is RGBA16F (half floats, 0.05%) and the GPU sums
    // 1,000 terms in single precision (< 1e-4 relative); a wrong or missing light is far more.
    constexpr double kRelative = 3e-3;
    // The test tells: with lights past the old cap of 255 dropped, red would fall by more than
    // half and blue (only those lights are blue) would be 0. Capping the count at 255 in
    // lights/light_list.glsl fails it (both lightList overloads: pbr and phong, or gouraud), and so
    // does a shadowVisibility of 0.5 (every model).
    const glm::dvec3 capped = glm::dvec3(kBaseColor) * expectedIrradiance(kOldCap) / glm::pi<double>();
    ASSERT_EQ(capped.b, 0.0);
    ASSERT_GT(expected.b, 1.0);
    ASSERT_LT(capped.r, 0.5 * expected.r);

    // Each model on its own, so that a light loop left behind in one of them shows by name.
    const std::pair<scene::ShadingModel, const char*> models[] = {
        {scene::ShadingModel::Pbr, "pbr"}, {scene::ShadingModel::Phong, "phong"}, {scene::ShadingModel::Gouraud, "gouraud"}};
    for (const auto& [model, name] : models) {
        float scale = 0.0f;
        const ImageFloat image = renderManyLights(model, &scale);
        ASSERT_GT(scale, 0.0f);
        // Every pixel: the plane fills the view, so a background pixel fails too.
        int wrong = 0;
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                const float* p = &image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
                for (int c = 0; c < 3; ++c) {
                    const double got = double(p[c] / scale);
                    if (std::abs(got - expected[c]) <= kRelative * expected[c]) continue;
                    if (wrong++ == 0)
                        ADD_FAILURE() << name << ": pixel " << x << ", " << y << " channel " << c << " is " << got << ", expected "
                                      << expected[c] << " (with only the first " << kOldCap << " lights: " << capped[c] << ")";
                }
            }
        }
        EXPECT_EQ(wrong, 0) << name << ": wrong pixel channels of " << 3 * image.width * image.height;
    }
}
