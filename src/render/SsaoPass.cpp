#include "render/SsaoPass.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "gl/UniformBuffer.h"
#include "render/Frustum.h"
#include "render/GpuScene.h"
#include "shaders/shared/Bindings.h"
#include "shaders/shared/MaterialData.h"
#include "shaders/shared/PostData.h"

namespace specula::render {
namespace {

constexpr int kGroupSize = 8; // local_size of the SSAO shaders
constexpr float kPi = 3.14159265358979f;

uint32_t groups(int size)
{
    return uint32_t((size + kGroupSize - 1) / kGroupSize);
}

/// Van der Corput radical inverse in base 2: a permutation of [0, 1) with no correlation to i.
float radicalInverse(uint32_t i)
{
    i = (i << 16u) | (i >> 16u);
    i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
    i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
    i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
    i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
    return float(i) * 2.3283064365386963e-10f;
}

struct PrepassProgram {
    gl::Program program;
    int model = -1;
    int normalMatrix = -1;
};

struct ComputeProgram {
    gl::Program program;
};

} // namespace

std::vector<glm::vec4> SsaoPass::makeKernel(int count)
{
    count = std::clamp(count, 1, SPECULA_SSAO_MAX_SAMPLES);
    std::vector<glm::vec4> kernel;
    for (int i = 0; i < count; ++i) {
        // Directions: stratified in cos²θ, golden-angle azimuths (a Fibonacci hemisphere),
        // cosine-distributed like the irradiance integral that ambient occlusion weights.
        // The flattest lies ~7° above the tangent plane at 16 samples, well clear of the
        // surface's own depth.
        const float u = (float(i) + 0.5f) / float(count);
        const float phi = 2.0f * kPi * std::fmod(float(i) * 0.6180339887f, 1.0f);
        const float sinTheta = std::sqrt(u), cosTheta = std::sqrt(1.0f - u);
        const glm::vec3 direction(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
        // Lengths: more samples close to the point, where occluders matter most (LearnOpenGL's
        // lerp(0.1, 1, t²)), in an order unrelated to the direction's.
        const float t = radicalInverse(uint32_t(i) + 1u);
        kernel.emplace_back(direction * (0.1f + 0.9f * t * t), 0.0f);
    }
    return kernel;
}

struct SsaoPass::Impl {
    std::map<std::string, PrepassProgram> prepassPrograms;
    gl::Program ssaoProgram, blurProgram;
    gl::UniformBuffer<shared::SsaoData> data{"ssao"};
    gl::Texture noise;
    int kernelCount = 0;

    int width = 0, height = 0;
    gl::Texture depth, normal, raw, blurred;
    gl::Framebuffer framebuffer;

    Impl()
    {
        // 16 rotations about the normal, 22.5° apart, in a dithered order so neighbours differ
        // by large angles (a 4×4 Bayer matrix's ranks); the blur averages one tile exactly.
        static constexpr int kBayer[16] = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
        float pixels[2 * 16];
        for (int i = 0; i < 16; ++i) {
            const float angle = 2.0f * kPi * (float(kBayer[i]) + 0.5f) / 16.0f;
            pixels[2 * i] = std::cos(angle);
            pixels[2 * i + 1] = std::sin(angle);
        }
        gl::TextureDesc desc;
        desc.width = desc.height = SPECULA_SSAO_NOISE_SIZE;
        desc.format = gl::Format::RG16F;
        desc.label = "ssao noise";
        noise = gl::Texture(desc);
        noise.upload(0, 0, 2, gl::PixelType::Float, pixels);
    }

    PrepassProgram& prepassProgram(uint32_t features)
    {
        std::vector<std::string> defines;
        if (features & SPECULA_MATERIAL_ALPHA_MASK) {
            defines.push_back("ALPHA_MASK");
            if (features & SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE) defines.push_back("HAS_BASE_COLOR_TEXTURE");
            if (features & SPECULA_MATERIAL_USE_VERTEX_COLOR) defines.push_back("VERTEX_COLOR");
        }
        std::string key;
        for (const auto& d : defines) key += d + ";";
        PrepassProgram& p = prepassPrograms[key];
        if (!p.program) {
            p.program = gl::Program({.vertex = "forward/pbr.vert", .fragment = "forward/prepass.frag", .defines = defines,
                                     .label = "depth/normal prepass " + key});
            p.model = p.program.uniformLocation("uModel");
            p.normalMatrix = p.program.uniformLocation("uNormalMatrix");
        }
        return p;
    }

    void ensureComputePrograms()
    {
        if (!ssaoProgram) ssaoProgram = gl::Program({.compute = "post/ssao.comp", .label = "ssao"});
        if (!blurProgram) blurProgram = gl::Program({.compute = "post/ssao_blur.comp", .label = "ssao blur"});
    }

    void ensureTargets(gl::State& state, int w, int h)
    {
        if (w == width && h == height) return;
        width = w;
        height = h;
        // Names of deleted objects may be reused: the binding cache must forget them.
        state.reset();
        gl::TextureDesc desc;
        desc.width = w;
        desc.height = h;
        desc.format = gl::Format::Depth32F;
        desc.label = "ssao depth";
        depth = gl::Texture(desc);
        desc.format = gl::Format::RGBA32F;
        desc.label = "ssao view normal and z";
        normal = gl::Texture(desc);
        desc.format = gl::Format::R16F;
        desc.label = "ssao raw";
        raw = gl::Texture(desc);
        desc.label = "ssao";
        blurred = gl::Texture(desc);
        framebuffer = gl::Framebuffer("ssao prepass");
        framebuffer.attachColor(0, normal).attachDepth(depth).check();
    }
};

SsaoPass::SsaoPass() : mImpl(std::make_unique<Impl>()) {}
SsaoPass::~SsaoPass() = default;

const gl::Texture& SsaoPass::occlusion() const
{
    return mImpl->blurred;
}

void SsaoPass::prepare(const GpuScene* scene)
{
    if (scene)
        for (const MaterialBinding& m : scene->materials())
            if (m.alphaMode != scene::AlphaMode::Blend) mImpl->prepassProgram(m.features);
    mImpl->ensureComputePrograms();
}

void SsaoPass::drawDepthNormals(gl::State& state, const GpuScene* gpuScene, const View& view, int width, int height)
{
    Impl& r = *mImpl;
    r.ensureTargets(state, width, height);
    state.bindFramebuffer(&r.framebuffer);
    state.viewport(0, 0, width, height);
    state.apply({}); // depth writes on, so that the clear reaches the depth buffer
    // Where nothing is drawn the view z is positive (behind the eye): what the SSAO passes test.
    r.framebuffer.clearColor(0, 0.0f, 0.0f, 1.0f, 1.0f);
    r.framebuffer.clearDepth(1.0f);
    if (!gpuScene) return;
    const GpuScene& scene = *gpuScene;

    const Frustum frustum(view.projection * view.view);
    int boundMaterial = -1;
    for (const DrawItem& item : scene.draws()) {
        const GpuPrimitive& p = scene.primitives()[size_t(item.primitive)];
        const MaterialBinding& m = scene.materials()[size_t(p.material)];
        if (m.alphaMode == scene::AlphaMode::Blend) continue;
        if (!frustum.intersects(p.bounds.transformed(item.world))) continue;
        PrepassProgram& program = r.prepassProgram(m.features);
        state.useProgram(program.program);
        gl::PipelineDesc pipeline;
        pipeline.cull = m.doubleSided ? gl::CullMode::None : gl::CullMode::Back;
        pipeline.frontFaceClockwise = item.mirrored;
        state.apply(pipeline);
        if (m.features & SPECULA_MATERIAL_ALPHA_MASK) {
            const size_t slot = size_t(TextureSlot::BaseColor);
            if (m.textures[slot]) {
                state.bindTexture(SPECULA_UNIT_BASE_COLOR, *m.textures[slot]);
                state.bindSampler(SPECULA_UNIT_BASE_COLOR, m.samplers[slot]);
            }
            if (p.material != boundMaterial) {
                gl::bindUniformBufferRange(SPECULA_BINDING_MATERIAL, scene.materialBuffer(), scene.materialOffset(p.material),
                                           sizeof(shared::GpuMaterial));
                boundMaterial = p.material;
            }
        }
        program.program.set(program.model, item.world);
        program.program.set(program.normalMatrix, item.normalMatrix);
        state.bindVertexArray(p.vertexArray);
        state.drawTriangles(p.count, p.indexed);
    }
}

void SsaoPass::computeOcclusion(gl::State& state, const View& view, const SsaoSettings& settings)
{
    Impl& r = *mImpl;
    r.ensureComputePrograms();
    const int samples = std::clamp(settings.samples, 1, SPECULA_SSAO_MAX_SAMPLES);
    auto& d = r.data.data();
    if (samples != r.kernelCount) {
        const std::vector<glm::vec4> kernel = makeKernel(samples);
        std::copy(kernel.begin(), kernel.end(), d.kernel);
        r.kernelCount = samples;
    }
    d.projection = view.projection;
    d.params = glm::vec4(std::max(settings.radius, 1e-4f), std::max(settings.bias, 0.0f), std::max(settings.power, 0.0f),
                         float(samples));
    d.size = glm::vec4(float(r.width), float(r.height), 1.0f / float(r.width), 1.0f / float(r.height));
    // A perspective projection has w = -z (row 3 = 0 0 -1 0); an orthographic one w = 1.
    d.options = glm::vec4(view.projection[3][3] == 1.0f ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
    r.data.upload();
    r.data.bind(SPECULA_BINDING_SSAO);
    // The pre-pass rendered into the depth and normal textures we now sample.
    state.memoryBarrier(gl::Barrier::TextureFetch);

    // texelFetch only: samplers do not matter, but a stale sampler object must not either.
    state.bindTexture(SPECULA_UNIT_POST_INPUT, r.normal);
    state.bindSampler(SPECULA_UNIT_POST_INPUT, nullptr);
    state.bindTexture(SPECULA_UNIT_POST_INPUT_2, r.noise);
    state.bindSampler(SPECULA_UNIT_POST_INPUT_2, nullptr);
    state.useProgram(r.ssaoProgram);
    state.bindImage(SPECULA_IMAGE_POST_OUTPUT, r.raw, 0, gl::ImageAccess::WriteOnly);
    state.dispatchCompute(groups(r.width), groups(r.height));
    state.memoryBarrier(gl::Barrier::TextureFetch);
}

void SsaoPass::blur(gl::State& state)
{
    Impl& r = *mImpl;
    r.data.bind(SPECULA_BINDING_SSAO);
    state.bindTexture(SPECULA_UNIT_POST_INPUT, r.normal);
    state.bindSampler(SPECULA_UNIT_POST_INPUT, nullptr);
    state.bindTexture(SPECULA_UNIT_POST_INPUT_2, r.raw);
    state.bindSampler(SPECULA_UNIT_POST_INPUT_2, nullptr);
    state.useProgram(r.blurProgram);
    state.bindImage(SPECULA_IMAGE_POST_OUTPUT, r.blurred, 0, gl::ImageAccess::WriteOnly);
    state.dispatchCompute(groups(r.width), groups(r.height));
    // Read next by the forward pass's fragment shader (or read back for the debug view).
    state.memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::TextureUpdate);
}

} // namespace specula::render
