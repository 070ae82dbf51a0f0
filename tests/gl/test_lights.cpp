// Lights in one buffer with no fixed count: editing one touches only its bytes, the buffer
// grows by doubling (a new buffer only when the count outgrows it), both ways shaders read it
// (the std430 storage block, the texel view) see every light as packed, and every light of a
// thousand reaches the shading of every reflection model.
#include "GlTestContext.h"
#include "RadianceFrame.h"

#include <unistd.h>
#include <epoxy/gl.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>

#include <glm/gtc/constants.hpp>

#include "gl/Program.h"
#include "gl/State.h"
#include "render/LightBuffer.h"
#include "shaders/shared/Bindings.h"
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

// A compute program that copies every light, as lights/light_list.glsl reads it, to a storage
// buffer at binding 0 (a count, then the GpuLights): through the std430 block when `storage`,
// else through the texel view the shading passes use. Built from a copy of the shader tree.
gl::Program lightReader(bool storage)
{
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / ("specula-light-reader-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::copy(gl::shaderRoot(), root, fs::copy_options::recursive);
    std::ofstream(root / "lights" / "read_lights.comp")
        << "#version 450 core\n"
           "layout(local_size_x = 64) in;\n"
           "#include \"light_list.glsl\"\n"
           "layout(std430, binding = 0) writeonly buffer Copy { uvec4 count; GpuLight lights[]; } copy;\n"
           "void main() {\n"
           "  uint k = gl_GlobalInvocationID.x;\n"
           "  LightList list = lightList(vec3(0.0));\n"
           "  if (k == 0u) copy.count = uvec4(frameLightCount(), list.count, 0u, 0u);\n"
           "  if (k < list.count) copy.lights[k] = lightAt(lightListIndex(list, k));\n"
           "}\n";
    std::vector<std::string> defines;
    // Every light, not a cluster's list: this reads the buffer, it culls nothing.
    defines.push_back(storage ? "SPECULA_LIGHTS_STORAGE" : "LIGHTS_ALL");
    gl::Program program({.compute = "lights/read_lights.comp", .defines = defines, .label = "read lights", .root = root});
    fs::remove_all(root);
    return program;
}

GLint resource(GLuint program, GLenum interface, const char* name, GLenum property)
{
    const GLuint index = glGetProgramResourceIndex(program, interface, name);
    if (index == GL_INVALID_INDEX) return -1;
    GLint value = -1;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

} // namespace

// The storage block as a compute pass compiles it: a LightHeader, then GpuLight records every
// sizeof(GpuLight) bytes from sizeof(LightHeader), the array runtime-sized; the offsets
// render::LightBuffer writes at.
TEST_F(GlTest, LightBufferMatchesGlslStd430Layout)
{
    using shared::GpuLight;
    using shared::LightHeader;
    const gl::Program program = lightReader(true);
    const GLuint id = program.id();
    constexpr GLenum kBlock = GL_SHADER_STORAGE_BLOCK, kVariable = GL_BUFFER_VARIABLE;
    EXPECT_EQ(resource(id, kBlock, "LightsBlock", GL_BUFFER_BINDING), SPECULA_BINDING_LIGHTS);
    // A runtime-sized last member counts as one element (GL 4.5, 7.6.2.3).
    EXPECT_EQ(resource(id, kBlock, "LightsBlock", GL_BUFFER_DATA_SIZE), GLint(sizeof(LightHeader) + sizeof(GpuLight)));
    EXPECT_EQ(resource(id, kVariable, "LightsBlock.header.count", GL_OFFSET), GLint(offsetof(LightHeader, count)));
    const struct {
        const char* name;
        size_t offset;
    } members[] = {{"LightsBlock.lights[0].positionRange", offsetof(GpuLight, positionRange)},
                   {"LightsBlock.lights[0].directionType", offsetof(GpuLight, directionType)},
                   {"LightsBlock.lights[0].colorIntensity", offsetof(GpuLight, colorIntensity)},
                   {"LightsBlock.lights[0].spot", offsetof(GpuLight, spot)}};
    for (const auto& m : members) {
        EXPECT_EQ(resource(id, kVariable, m.name, GL_OFFSET), GLint(sizeof(LightHeader) + m.offset)) << m.name;
        EXPECT_EQ(resource(id, kVariable, m.name, GL_TOP_LEVEL_ARRAY_STRIDE), GLint(sizeof(GpuLight))) << m.name;
        EXPECT_EQ(resource(id, kVariable, m.name, GL_TOP_LEVEL_ARRAY_SIZE), 0) << m.name << ": not runtime-sized";
    }
}

// Both read paths return every light exactly as LightBuffer::pack made it, bit for bit, also
// after the buffer has grown twice (a new buffer and a new texel view each time), and the
// shading passes read the texel view (pbr and, per vertex, Gouraud).
TEST_F(GlTest, BothLightReadPathsSeeEveryLightAsPacked)
{
    render::LightBuffer lights;
    gl::State state;
    const gl::Program readers[] = {lightReader(true), lightReader(false)};
    for (const int count : {3, 300, 5000}) {
        std::vector<render::PlacedLight> placed = numberedLights(count);
        for (int i = 0; i < count; ++i) {
            placed[size_t(i)].light.color = glm::vec3(0.25f * float(i % 4), 1.0f / float(i + 1), 0.5f);
            placed[size_t(i)].light.range = float(i % 7);
            placed[size_t(i)].direction = glm::vec3(std::cos(float(i)), std::sin(float(i)), 0.5f);
            placed[size_t(i)].light.outerConeAngle = 0.01f * float(i % 50 + 1);
        }
        lights.setAll(placed);
        ASSERT_GE(lights.capacity(), count);
        EXPECT_EQ(lights.texels().desc().type, gl::TextureType::Buffer);
        EXPECT_EQ(lights.texels().width(), 1 + 4 * lights.capacity());
        lights.bind(state);
        for (const gl::Program& reader : readers) {
            const bool storage = &reader == &readers[0];
            SCOPED_TRACE(std::string(storage ? "storage block" : "texel view") + ", " + std::to_string(count) + " lights");
            const size_t bytes = sizeof(glm::uvec4) + size_t(count) * sizeof(shared::GpuLight);
            const std::vector<std::byte> poison(bytes, std::byte{0xAB});
            gl::Buffer copy(bytes, poison.data(), "light copy");
            gl::bindStorageBuffer(0, copy);
            state.useProgram(reader);
            state.dispatchCompute(uint32_t((count + 63) / 64), 1);
            gl::State::memoryBarrier(gl::Barrier::BufferUpdate);
            const std::vector<std::byte> got = copy.read(0, bytes);
            glm::uvec4 header;
            std::memcpy(&header, got.data(), sizeof header);
            EXPECT_EQ(header.x, uint32_t(count)) << "frameLightCount";
            EXPECT_EQ(header.y, uint32_t(count)) << "lightList count";
            int wrong = 0;
            for (int i = 0; i < count; ++i) {
                const shared::GpuLight expected = render::LightBuffer::pack(placed[size_t(i)]);
                if (std::memcmp(got.data() + sizeof header + size_t(i) * sizeof expected, &expected, sizeof expected) != 0 &&
                    wrong++ < 3)
                    ADD_FAILURE() << "light " << i << " reads back different bytes";
            }
            EXPECT_EQ(wrong, 0);
        }
    }
    // The shading passes sample the texel view on its unit, Gouraud from its vertex shader.
    const gl::Program pbr({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag"});
    const gl::Program gouraud({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = {"SHADING_GOURAUD"}});
    for (const gl::Program* program : {&pbr, &gouraud}) {
        EXPECT_EQ(glGetProgramResourceIndex(program->id(), GL_SHADER_STORAGE_BLOCK, "LightsBlock"), GL_INVALID_INDEX);
        const GLint location = glGetUniformLocation(program->id(), "lightTexels");
        ASSERT_GE(location, 0);
        GLint unit = -1;
        glGetUniformiv(program->id(), location, &unit);
        EXPECT_EQ(unit, SPECULA_UNIT_LIGHTS);
    }
    EXPECT_EQ(resource(gouraud.id(), GL_UNIFORM, "lightTexels", GL_REFERENCED_BY_VERTEX_SHADER), 1);
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
    render::FrameSettings settings = test::radianceFrame(32, 32, test::Brdf::Exact);
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
