#include "render/passes/SsaoPass.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "gl/UniformBuffer.h"
#include "render/DrawList.h"
#include "render/FrameContext.h"
#include "render/GpuScene.h"
#include "render/graph/GlGraphBackend.h"
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

    std::vector<DrawProgram> programs; ///< this frame's pre-pass program of each material

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

    void computeOcclusion(gl::State& state, const View& view, const SsaoSettings& settings, const gl::Texture& normal,
                          const gl::Texture& raw)
    {
        const int width = raw.width(), height = raw.height();
        const int samples = std::clamp(settings.samples, 1, SPECULA_SSAO_MAX_SAMPLES);
        auto& d = data.data();
        if (samples != kernelCount) {
            const std::vector<glm::vec4> kernel = makeKernel(samples);
            std::copy(kernel.begin(), kernel.end(), d.kernel);
            kernelCount = samples;
        }
        d.projection = view.projection;
        d.params = glm::vec4(std::max(settings.radius, 1e-4f), std::max(settings.bias, 0.0f), std::max(settings.power, 0.0f),
                             float(samples));
        d.size = glm::vec4(float(width), float(height), 1.0f / float(width), 1.0f / float(height));
        // A perspective projection has w = -z (row 3 = 0 0 -1 0); an orthographic one w = 1.
        d.options = glm::vec4(view.projection[3][3] == 1.0f ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
        data.upload();
        data.bind(SPECULA_BINDING_SSAO);
        // texelFetch only: samplers do not matter, but a stale sampler object must not either.
        state.bindTexture(SPECULA_UNIT_POST_INPUT, normal);
        state.bindSampler(SPECULA_UNIT_POST_INPUT, nullptr);
        state.bindTexture(SPECULA_UNIT_POST_INPUT_2, noise);
        state.bindSampler(SPECULA_UNIT_POST_INPUT_2, nullptr);
        state.useProgram(ssaoProgram);
        state.bindImage(SPECULA_IMAGE_POST_OUTPUT, raw, 0, gl::ImageAccess::WriteOnly);
        state.dispatchCompute(groups(width), groups(height));
    }

    void blur(gl::State& state, const gl::Texture& normal, const gl::Texture& raw, const gl::Texture& blurred)
    {
        data.bind(SPECULA_BINDING_SSAO);
        state.bindTexture(SPECULA_UNIT_POST_INPUT, normal);
        state.bindSampler(SPECULA_UNIT_POST_INPUT, nullptr);
        state.bindTexture(SPECULA_UNIT_POST_INPUT_2, raw);
        state.bindSampler(SPECULA_UNIT_POST_INPUT_2, nullptr);
        state.useProgram(blurProgram);
        state.bindImage(SPECULA_IMAGE_POST_OUTPUT, blurred, 0, gl::ImageAccess::WriteOnly);
        state.dispatchCompute(groups(blurred.width()), groups(blurred.height()));
    }
};

SsaoPass::SsaoPass() : mImpl(std::make_unique<Impl>()) {}
SsaoPass::~SsaoPass() = default;

GraphTexture SsaoPass::addTo(FrameGraph& graph, const FrameContext& frame, const DrawList& opaque)
{
    Impl& r = *mImpl;
    r.ensureComputePrograms();
    const GpuScene* scene = frame.stores.scene.get();
    r.programs.clear();
    if (scene) {
        for (const MaterialBinding& m : scene->materials()) {
            // Blended materials are never in the opaque list: no program to compile for them.
            if (m.alphaMode == scene::AlphaMode::Blend) {
                r.programs.push_back({});
                continue;
            }
            PrepassProgram& p = r.prepassProgram(m.features);
            r.programs.push_back({&p.program, p.model, p.normalMatrix, nullptr});
        }
    }
    // Made before the passes: their execute steps capture the handles.
    GraphTextureDesc desc;
    desc.width = frame.width;
    desc.height = frame.height;
    desc.format = gl::Format::Depth32F;
    const GraphTexture depth = graph.createTexture("ssao depth", desc);
    desc.format = gl::Format::RGBA32F;
    const GraphTexture normal = graph.createTexture("ssao view normal and z", desc);
    desc.format = gl::Format::R16F;
    const GraphTexture raw = graph.createTexture("ssao raw", desc);
    const GraphTexture blurred = graph.createTexture("ssao", desc);
    graph.addPass(
        "ssao prepass",
        [&](FrameGraph::Builder& b) {
            b.write(depth, Use::DepthAttachment);
            b.write(normal, Use::ColorAttachment);
        },
        [&frame, &opaque, &r, depth, normal] {
            gl::State& state = frame.state();
            frame.stores.frame.bind(SPECULA_BINDING_FRAME); // view and viewProjection
            gl::Framebuffer& target = frame.backend.framebuffer({normal}, depth);
            state.bindFramebuffer(&target);
            state.viewport(0, 0, frame.width, frame.height);
            state.apply({}); // depth writes on, so that the clear reaches the depth buffer
            // Where nothing is drawn the view z is positive (behind the eye): what the SSAO passes test.
            target.clearColor(0, 0.0f, 0.0f, 1.0f, 1.0f);
            target.clearDepth(1.0f);
            if (const GpuScene* scene = frame.stores.scene.get())
                opaque.submit(state, *scene, r.programs, {.textures = MaterialTextures::Cutouts});
        });
    graph.addPass(
        "ssao",
        [&](FrameGraph::Builder& b) {
            b.read(normal, Use::Sample);
            b.write(raw, Use::ImageStore);
        },
        [&frame, &r, normal, raw] {
            r.computeOcclusion(frame.state(), frame.view, frame.settings.ssao, frame.backend.texture(normal),
                               frame.backend.texture(raw));
        });
    graph.addPass(
        "ssao blur",
        [&](FrameGraph::Builder& b) {
            b.read(normal, Use::Sample);
            b.read(raw, Use::Sample);
            b.write(blurred, Use::ImageStore);
        },
        [&frame, &r, normal, raw, blurred] {
            r.blur(frame.state(), frame.backend.texture(normal), frame.backend.texture(raw), frame.backend.texture(blurred));
        });
    return blurred;
}

} // namespace specula::render
