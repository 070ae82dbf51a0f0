#include "render/Renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <map>
#include <type_traits>

#include <epoxy/gl.h>

#include "core/Error.h"
#include "core/Log.h"
#include "core/Timer.h"
#include "gl/Debug.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "gl/TimerQuery.h"
#include "gl/UniformBuffer.h"
#include "gl/VertexArray.h"
#include "render/BillboardPass.h"
#include "render/BloomPass.h"
#include "render/CameraExposure.h"
#include "render/DoomPass.h"
#include "render/ExposurePass.h"
#include "render/Frustum.h"
#include "render/FxaaPass.h"
#include "render/GpuScene.h"
#include "render/ImageBasedLighting.h"
#include "render/LightBuffer.h"
#include "render/ShadingVariant.h"
#include "render/SsaoPass.h"
#include "shaders/shared/Bindings.h"
#include "shaders/shared/EnvironmentData.h"
#include "shaders/shared/FrameData.h"
#include "shaders/shared/MaterialData.h"

namespace specula::render {

std::optional<BrdfGeometry> parseBrdfGeometry(std::string_view name)
{
    return scene::parseBrdfGeometryName(name);
}

namespace {

uint32_t tonemapId(Tonemap t)
{
    switch (t) {
    case Tonemap::None: return SPECULA_TONEMAP_NONE;
    case Tonemap::Reinhard: return SPECULA_TONEMAP_REINHARD;
    case Tonemap::ReinhardExtended: return SPECULA_TONEMAP_REINHARD_EXT;
    case Tonemap::Aces: return SPECULA_TONEMAP_ACES;
    case Tonemap::Neutral: return SPECULA_TONEMAP_NEUTRAL;
    case Tonemap::Agx: return SPECULA_TONEMAP_AGX;
    }
    return SPECULA_TONEMAP_NONE;
}

/// The forward program of one variant, with its uniform locations looked up once.
struct ForwardProgram {
    gl::Program program;
    int model = -1;
    int normalMatrix = -1;
    ResolvedShading shading;
    bool readsDfg = false; ///< samples the DFG table of `shading` (image-based light or energy compensation)
};

/// The forward pass's define for a material or BRDF debug view (shaders/forward/debug_views.glsl).
const char* debugViewDefine(DebugView view)
{
    switch (view) {
    case DebugView::BaseColor: return "DEBUG_VIEW_BASE_COLOR";
    case DebugView::Normal: return "DEBUG_VIEW_NORMAL";
    case DebugView::Roughness: return "DEBUG_VIEW_ROUGHNESS";
    case DebugView::Metallic: return "DEBUG_VIEW_METALLIC";
    case DebugView::Occlusion: return "DEBUG_VIEW_OCCLUSION";
    case DebugView::Emissive: return "DEBUG_VIEW_EMISSIVE";
    case DebugView::BrdfD: return "DEBUG_VIEW_BRDF_D";
    case DebugView::BrdfG: return "DEBUG_VIEW_BRDF_G";
    case DebugView::BrdfF: return "DEBUG_VIEW_BRDF_F";
    default: return nullptr;
    }
}

/// A Doom frame (the override is the Doom model, and no material or BRDF view replaces it):
/// forward and billboard passes write palette indices and levels, the colour-map pass colours.
bool doomFrame(const FrameSettings& s)
{
    return s.materialOverride.model == scene::ShadingModel::Doom && !debugViewDefine(s.debugView);
}

/// What a frame actually runs: a debug view needs its pass on.
FrameSettings effectiveSettings(const FrameSettings& requested)
{
    FrameSettings s = requested;
    if (s.debugView == DebugView::Ssao) s.ssao.enabled = true;
    if (s.debugView == DebugView::Bloom) s.bloom.enabled = true;
    const bool doom = s.materialOverride.model == scene::ShadingModel::Doom;
    // The Doom model's frame holds only palette colours: one sample a pixel (a resolve would
    // blend them) and, as for the views below, nothing that scales or curves values.
    if (doom) s.msaa = 1;
    if (debugViewDefine(s.debugView) || doom) {
        // Material and BRDF views show values, not light: nothing may scale or curve them.
        s.exposureEv = 0.0f;
        s.ev100.reset();
        s.tonemap = Tonemap::None;
        s.bloom.enabled = false;
        s.autoExposure.enabled = false;
        s.fxaa.enabled = false;
        s.environment.skybox = false; // black where no surface is: the sky is no material
    }
    return s;
}

} // namespace

struct Renderer::Impl {
    gl::State state;
    std::filesystem::path cacheDirectory; // of the bakes (Renderer::setCacheDirectory)
    gl::UniformBuffer<shared::FrameData> frame{"frame"};
    LightBuffer lights;
    std::unique_ptr<GpuScene> scene;
    BillboardPass billboards;

    std::map<std::string, ForwardProgram> forwardPrograms; // node-based: pointers stay valid
    /// This frame's program and DFG table (null when it reads none) of each material, resolved
    /// once a frame by prepareMaterials so a draw does not build define lists.
    std::vector<ForwardProgram*> materialPrograms;
    std::vector<const gl::Texture*> materialDfg;
    std::map<int, gl::Program> tonemapPrograms; ///< by MSAA sample count (1 = no resolve), auto exposure, encoding
    ImageBasedLighting ibl;
    gl::UniformBuffer<shared::EnvironmentData> environment{"environment"};
    gl::Program skyboxProgram;
    gl::VertexArray emptyVertexArray{"fullscreen triangle"};
    gl::Texture white;
    gl::Texture flatNormal;

    // Targets, rebuilt when size or sample count changes.
    int width = 0, height = 0, msaa = 0;
    gl::Texture msaaColor, msaaDepth, hdrColor, hdrDepth, ldrColor;
    gl::Framebuffer msaaFramebuffer, hdrFramebuffer, ldrFramebuffer;
    float lastExposureScale = 1.0f;

    // Post-processing passes, made on first use: a pass that is off costs nothing.
    std::unique_ptr<SsaoPass> ssao;
    std::unique_ptr<BloomPass> bloom;
    std::unique_ptr<ExposurePass> autoExposure;
    std::unique_ptr<FxaaPass> fxaa;
    std::unique_ptr<DoomPass> doom; ///< the colour tables and a Doom frame's targets, made on first use
    gl::Framebuffer doomOutput;     ///< hdr colour + ldr colour: what the colour-map pass writes
    gl::Texture fxaaInput; ///< the tone-mapped, sRGB-encoded frame FXAA reads (made when FXAA is on)
    gl::Framebuffer fxaaFramebuffer;
    gl::Program debugProgram;
    bool lastAutoExposure = false;
    DebugView lastDebugView = DebugView::None;

    bool timing = false;
    bool wallClock = false;
    bool hdrResolved = false; ///< hdrColor holds the last frame (MSAA resolves lazily)
    std::map<std::string, gl::TimerQuery> timers; ///< one per pass name, reused every frame
    struct Timed {
        const char* name;
        gl::TimerQuery* timer;
        double wallMs;
    };
    std::vector<Timed> timed; ///< this frame's, in order
    FrameStats stats;

    /// One pass of the frame: a debug group and, when timing, a timer query.
    template <typename Body>
    void pass(const char* name, Body&& body)
    {
        gl::DebugGroup group(name);
        gl::TimerQuery* timer = nullptr;
        Stopwatch wall;
        if (timing) {
            if (wallClock) {
                gl::finish();
                wall.reset();
            }
            timer = &timers[name];
            timer->begin();
        }
        try {
            body();
        } catch (...) {
            // A program that fails to compile on first use: the query must not stay active
            // into the next frame (the debug group closes itself).
            if (timer) timer->end();
            throw;
        }
        if (timer) {
            timer->end();
            if (wallClock) gl::finish();
            timed.push_back({name, timer, wallClock ? wall.elapsedMs() : 0.0});
        }
    }

    Impl()
    {
        gl::TextureDesc desc;
        desc.label = "white";
        white = gl::Texture(desc);
        const uint8_t whitePixel[4] = {255, 255, 255, 255};
        white.upload(0, 0, 4, gl::PixelType::UnsignedByte, whitePixel);
        desc.label = "flat normal";
        flatNormal = gl::Texture(desc);
        const uint8_t normalPixel[4] = {128, 128, 255, 255};
        flatNormal.upload(0, 0, 4, gl::PixelType::UnsignedByte, normalPixel);
    }

    /// The forward program for a BRDF choice and a material's features, compiled on first
    /// use and cached for the run. Variants are defines of one source, never copies.
    bool iblOn(const FrameSettings& settings) const { return ibl.hasEnvironment() && settings.environment.lighting; }

    ForwardProgram& forwardProgram(const FrameSettings& settings, uint32_t features)
    {
        std::vector<std::string> defines;
        const ResolvedShading shading = resolveShading(settings.materialOverride, settings.brdfGeometry, features);
        appendShadingDefines(shading, defines);
        const char* debug = debugViewDefine(settings.debugView);
        if (debug) defines.push_back(debug);
        if (iblOn(settings)) defines.push_back("IBL");
        if (settings.energyCompensation) defines.push_back("ENERGY_COMPENSATION");
        if (settings.ssao.enabled) defines.push_back("SSAO");
        if (doomFrame(settings)) defines.push_back("DOOM_INDEXED");
        const std::pair<uint32_t, const char*> featureDefines[] = {
            {SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE, "HAS_BASE_COLOR_TEXTURE"},
            {SPECULA_MATERIAL_HAS_METALLIC_ROUGHNESS_TEXTURE, "HAS_METALLIC_ROUGHNESS_TEXTURE"},
            {SPECULA_MATERIAL_HAS_NORMAL_TEXTURE, "HAS_NORMAL_TEXTURE"},
            {SPECULA_MATERIAL_HAS_OCCLUSION_TEXTURE, "HAS_OCCLUSION_TEXTURE"},
            {SPECULA_MATERIAL_HAS_EMISSIVE_TEXTURE, "HAS_EMISSIVE_TEXTURE"},
            {SPECULA_MATERIAL_DOUBLE_SIDED, "DOUBLE_SIDED"},
            {SPECULA_MATERIAL_ALPHA_MASK, "ALPHA_MASK"},
            {SPECULA_MATERIAL_ALPHA_BLEND, "ALPHA_BLEND"},
            {SPECULA_MATERIAL_USE_VERTEX_COLOR, "VERTEX_COLOR"},
        };
        for (const auto& [bit, define] : featureDefines)
            if (features & bit) defines.push_back(define);
        std::string key;
        for (const auto& d : defines) key += d + ";";
        auto it = forwardPrograms.find(key);
        if (it != forwardPrograms.end()) return it->second;
        ForwardProgram p;
        p.program = gl::Program({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = defines,
                                 .label = "forward " + key});
        p.model = p.program.uniformLocation("uModel");
        p.normalMatrix = p.program.uniformLocation("uNormalMatrix");
        p.shading = shading;
        // Debug views and the classic models return before the split sum (pbr.frag).
        p.readsDfg = shading.model == scene::ShadingModel::Pbr && !debug && (iblOn(settings) || settings.energyCompensation);
        return forwardPrograms.emplace(key, std::move(p)).first->second;
    }

    /// The DFG table of a BRDF variant (ImageBasedLighting::dfg), baked on first use. A bake
    /// runs compute programs behind the binding cache's back, so the cache is reset after one.
    const gl::Texture& dfgTable(const ResolvedShading& shading)
    {
        if (ibl.hasDfg(shading)) return ibl.dfg(shading);
        const gl::Texture& table = ibl.dfg(shading);
        state.reset();
        return table;
    }

    /// Resolves (compiling on first use) the forward program of every material for these
    /// settings and bakes the DFG tables they read, so that no compile or bake lands inside the
    /// forward pass (or its timing) and a draw only indexes materialPrograms.
    void prepareMaterials(const FrameSettings& settings)
    {
        materialPrograms.clear();
        materialDfg.clear();
        if (!scene) return;
        for (const MaterialBinding& m : scene->materials()) {
            ForwardProgram& p = forwardProgram(settings, m.features);
            materialPrograms.push_back(&p);
            materialDfg.push_back(p.readsDfg ? &dfgTable(p.shading) : nullptr);
        }
    }

    gl::Program& tonemap(int samples, bool automaticExposure, bool encodeSrgb)
    {
        gl::Program& program = tonemapPrograms[4 * samples + (automaticExposure ? 1 : 0) + (encodeSrgb ? 2 : 0)];
        if (!program) {
            std::vector<std::string> defines;
            if (samples > 1) defines.push_back("MSAA_SAMPLES " + std::to_string(samples));
            if (automaticExposure) defines.push_back("AUTO_EXPOSURE");
            if (encodeSrgb) defines.push_back("ENCODE_SRGB");
            program = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "post/tonemap.frag", .defines = defines,
                                   .label = "tonemap"});
        }
        return program;
    }

    void ensureTargets(int w, int h, int samples)
    {
        if (w == width && h == height && samples == msaa) return;
        if (samples > 1) {
            // Asking for more samples than the implementation has is a GL error and an
            // incomplete framebuffer: say so in one line instead (llvmpipe stops at 4).
            GLint colorSamples = 0, depthSamples = 0;
            glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &colorSamples);
            glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &depthSamples);
            const int supported = std::min(colorSamples, depthSamples);
            if (samples > supported)
                throw Error("{} MSAA samples asked for; this OpenGL implementation supports at most {}", samples, supported);
        }
        // Deleted GL objects free their names and new ones may reuse them: the binding cache
        // must not mistake a new framebuffer for the old one it thinks is bound.
        state.reset();
        width = w;
        height = h;
        msaa = samples;
        gl::TextureDesc desc;
        desc.width = w;
        desc.height = h;
        desc.format = gl::Format::RGBA16F;
        desc.label = "hdr colour";
        hdrColor = gl::Texture(desc);
        desc.format = gl::Format::SRGB8_ALPHA8;
        desc.label = "ldr colour";
        ldrColor = gl::Texture(desc);
        doomOutput = {}; // made again, on the new targets, by the next Doom frame
        hdrFramebuffer = gl::Framebuffer("hdr");
        hdrFramebuffer.attachColor(0, hdrColor);
        ldrFramebuffer = gl::Framebuffer("ldr");
        ldrFramebuffer.attachColor(0, ldrColor);
        ldrFramebuffer.check();
        if (samples > 1) {
            desc.type = gl::TextureType::Texture2DMultisample;
            desc.samples = samples;
            desc.format = gl::Format::RGBA16F;
            desc.label = "msaa colour";
            msaaColor = gl::Texture(desc);
            desc.format = gl::Format::Depth32F;
            desc.label = "msaa depth";
            msaaDepth = gl::Texture(desc);
            msaaFramebuffer = gl::Framebuffer("msaa");
            msaaFramebuffer.attachColor(0, msaaColor).attachDepth(msaaDepth).check();
            hdrDepth = {};
            hdrFramebuffer.check();
        } else {
            desc.format = gl::Format::Depth32F;
            desc.label = "depth";
            hdrDepth = gl::Texture(desc);
            hdrFramebuffer.attachDepth(hdrDepth).check();
            msaaColor = {};
            msaaDepth = {};
            msaaFramebuffer = {};
        }
    }

    void bindMaterial(const MaterialBinding& m)
    {
        for (size_t slot = 0; slot < size_t(TextureSlot::Count); ++slot) {
            const gl::Texture* texture = m.textures[slot];
            if (!texture) texture = slot == size_t(TextureSlot::Normal) ? &flatNormal : &white;
            state.bindTexture(int(slot), *texture);
            state.bindSampler(int(slot), m.samplers[slot]);
        }
    }

    void bindEnvironment()
    {
        if (ibl.hasEnvironment()) {
            state.bindTexture(SPECULA_UNIT_PREFILTERED, ibl.prefiltered());
            state.bindSampler(SPECULA_UNIT_PREFILTERED, nullptr);
            environment.bind(SPECULA_BINDING_ENVIRONMENT);
        }
    }

    /// Writes one field of the environment block and uploads it, if it changed. The CPU copy
    /// always mirrors the buffer (made from it, and every edit uploaded), so comparing with it
    /// is comparing with what the GPU holds.
    template <typename Field>
    void setEnvironmentField(Field shared::EnvironmentData::*field, const Field& value)
    {
        Field& current = environment.data().*field;
        if constexpr (std::is_array_v<Field>) {
            if (std::equal(std::begin(current), std::end(current), std::begin(value))) return;
            std::copy(std::begin(value), std::end(value), std::begin(current));
        } else {
            if (current == value) return;
            current = value;
        }
        environment.upload(field);
    }

    /// Uploads what changed of the environment block: the view every frame the camera moves,
    /// the rotation and parameters when the settings change, the SH when the environment does.
    void updateEnvironment(const View& view, const FrameSettings& settings)
    {
        if (!ibl.hasEnvironment()) return;
        using shared::EnvironmentData;
        glm::vec4 sh[9];
        for (size_t i = 0; i < 9; ++i) sh[i] = glm::vec4(ibl.sh()[i], 0.0f);
        setEnvironmentField(&EnvironmentData::sh, sh);
        setEnvironmentField(&EnvironmentData::worldToEnvironment, glm::mat4(environmentRotation(-settings.environment.rotationDegrees)));
        setEnvironmentField(&EnvironmentData::inverseViewProjection, glm::inverse(view.projection * view.view));
        const float blur = std::clamp(settings.environment.skyboxBlur, 0.0f, 1.0f);
        setEnvironmentField(&EnvironmentData::params,
                            glm::vec4(settings.environment.intensity, float(ibl.prefiltered().levels()),
                                      blur > 0.0f ? blur * float(ibl.prefiltered().levels() - 1) : -1.0f,
                                      settings.environment.skybox ? 1.0f : 0.0f));
    }

    void drawSkybox(const FrameSettings& settings)
    {
        if (!ibl.hasEnvironment() || !settings.environment.skybox) return;
        gl::DebugGroup group("skybox");
        if (!skyboxProgram)
            skyboxProgram = gl::Program({.vertex = "ibl/skybox.vert", .fragment = "ibl/skybox.frag", .label = "skybox"});
        state.useProgram(skyboxProgram);
        // Depth 1 passes only where nothing was drawn (the clear value), and writes nothing.
        state.apply({.noDepthWrite = true, .depthCompare = gl::CompareOp::LessEqual, .cull = gl::CullMode::None});
        state.bindTexture(0, ibl.cube());
        state.bindSampler(0, nullptr);
        state.bindVertexArray(emptyVertexArray);
        state.drawTriangles(3, false);
    }

    /// Whether any material of the scene is shaded with the Doom model this frame.
    bool anyDoomMaterial(const FrameSettings& settings) const
    {
        if (!scene) return false;
        return std::any_of(scene->materials().begin(), scene->materials().end(), [&](const MaterialBinding& m) {
            return resolveShading(settings.materialOverride, settings.brdfGeometry, m.features).model == scene::ShadingModel::Doom;
        });
    }

    /// The passes after the frame's colours are made (the SSAO view), and the frame's stats.
    void finishFrame(const FrameSettings& settings);

    DoomPass& doomPass()
    {
        if (!doom) doom = std::make_unique<DoomPass>();
        return *doom;
    }

    void drawScene(const View& view, const FrameSettings& settings)
    {
        frame.bind(SPECULA_BINDING_FRAME);
        const size_t environmentBytes = environment.buffer().bytesUpdated();
        updateEnvironment(view, settings);
        stats.environmentBytesUploaded = environment.buffer().bytesUpdated() - environmentBytes;
        bindEnvironment();
        lights.bind();
        const bool indexed = doomFrame(settings);
        // Doom materials look their colours up in the tables, inline or for the colour-map pass.
        if (indexed || anyDoomMaterial(settings)) doomPass().bindTables(state);
        if (!scene) return;
        int boundMaterial = -1;

        const Frustum frustum(view.projection * view.view);
        struct Blended {
            const DrawItem* item;
            float depth;
        };
        std::vector<Blended> blended;
        auto draw = [&](const DrawItem& item, bool blend) {
            const GpuPrimitive& p = scene->primitives()[size_t(item.primitive)];
            const MaterialBinding& m = scene->materials()[size_t(p.material)];
            ForwardProgram& program = *materialPrograms[size_t(p.material)];
            if (const gl::Texture* dfg = materialDfg[size_t(p.material)]) {
                // Each draw reads the table of its own variant (docs/ibl.md).
                state.bindTexture(SPECULA_UNIT_DFG, *dfg);
                state.bindSampler(SPECULA_UNIT_DFG, nullptr);
            }
            state.useProgram(program.program);
            gl::PipelineDesc pipeline;
            pipeline.cull = m.doubleSided ? gl::CullMode::None : gl::CullMode::Back;
            pipeline.frontFaceClockwise = item.mirrored;
            // A Doom frame's indices cannot be blended: blended materials are cut out there
            // (pbr.frag), so they are drawn and depth-written as cutouts.
            if (blend && !indexed) {
                pipeline.blend = gl::BlendMode::Alpha;
                pipeline.noDepthWrite = true;
            }
            state.apply(pipeline);
            bindMaterial(m);
            program.program.set(program.model, item.world);
            program.program.set(program.normalMatrix, item.normalMatrix);
            if (p.material != boundMaterial) {
                gl::bindUniformBufferRange(SPECULA_BINDING_MATERIAL, scene->materialBuffer(),
                                           scene->materialOffset(p.material), sizeof(shared::GpuMaterial));
                boundMaterial = p.material;
            }
            state.bindVertexArray(p.vertexArray);
            state.drawTriangles(p.count, p.indexed);
            stats.triangles += p.count / 3;
        };
        for (const DrawItem& item : scene->draws()) {
            const GpuPrimitive& p = scene->primitives()[size_t(item.primitive)];
            if (!frustum.intersects(p.bounds.transformed(item.world))) continue;
            if (scene->materials()[size_t(p.material)].alphaMode == scene::AlphaMode::Blend) {
                const glm::vec3 center = glm::vec3(item.world * glm::vec4(p.bounds.center(), 1.0f));
                blended.push_back({&item, (view.view * glm::vec4(center, 1.0f)).z});
                continue;
            }
            draw(item, false);
        }
        // Cutout billboards belong to the opaque phase: depth-tested and written like surfaces.
        stats.triangles += billboards.drawOpaque(state, height, indexed);
        // The sky after the opaque surfaces (it fills only what they left) and before anything blended.
        drawSkybox(settings);
        // Back to front: view-space z is negative in front of the camera, most negative = farthest.
        std::stable_sort(blended.begin(), blended.end(), [](const Blended& a, const Blended& b) { return a.depth < b.depth; });
        for (const Blended& b : blended) draw(*b.item, true);
        // Blended billboards after the blended surfaces (sorted apart from them), gizmos last.
        stats.triangles += billboards.drawBlended(state, view, height, settings.gizmos ? &lights : nullptr,
                                                  settings.selectedLight, indexed);
    }
};

Renderer::Renderer() : mImpl(std::make_unique<Impl>()) {}
Renderer::~Renderer() = default;

void Renderer::setScene(const scene::Scene& scene)
{
    mImpl->state.reset(); // textures and vertex arrays are replaced: forget cached bindings
    mImpl->scene = std::make_unique<GpuScene>(scene);
    mImpl->billboards.setScene(scene);
    mImpl->lights.setAll(placeLights(scene));
}

BakeReport Renderer::setEnvironment(const EnvironmentMap& map, const BakeSettings& settings, const std::filesystem::path& cacheDirectory)
{
    mImpl->state.reset();
    setCacheDirectory(cacheDirectory);
    return mImpl->ibl.setEnvironment(map, settings, cacheDirectory);
}

void Renderer::clearEnvironment()
{
    mImpl->state.reset();
    mImpl->ibl = ImageBasedLighting();
    mImpl->ibl.setLutCacheDirectory(mImpl->cacheDirectory);
}

void Renderer::setCacheDirectory(const std::filesystem::path& directory)
{
    mImpl->cacheDirectory = directory;
    mImpl->ibl.setLutCacheDirectory(directory);
}

const Sh9* Renderer::environmentSh() const
{
    return mImpl->ibl.hasEnvironment() ? &mImpl->ibl.sh() : nullptr;
}

LightBuffer& Renderer::lights()
{
    return mImpl->lights;
}

void Renderer::prepare(const FrameSettings& requested)
{
    Impl& r = *mImpl;
    const FrameSettings settings = effectiveSettings(requested);
    r.prepareMaterials(settings);
    const int samples = std::max(settings.msaa, 1);
    const bool hdrPasses = settings.bloom.enabled || settings.autoExposure.enabled;
    if (doomFrame(settings)) {
        r.doomPass().prepare();
    } else {
        r.tonemap(hdrPasses ? 1 : samples, settings.autoExposure.enabled, settings.fxaa.enabled);
        if (r.anyDoomMaterial(settings)) r.doomPass();
    }
    r.billboards.prepare(doomFrame(settings));
    if (settings.ssao.enabled) {
        if (!r.ssao) r.ssao = std::make_unique<SsaoPass>();
        r.ssao->prepare(r.scene.get());
    }
    if (settings.bloom.enabled) {
        if (!r.bloom) r.bloom = std::make_unique<BloomPass>();
        r.bloom->prepare(settings.bloom);
    }
    if (settings.autoExposure.enabled) {
        if (!r.autoExposure) r.autoExposure = std::make_unique<ExposurePass>();
        r.autoExposure->prepare();
    }
    if (settings.fxaa.enabled) {
        if (!r.fxaa) r.fxaa = std::make_unique<FxaaPass>();
        r.fxaa->prepare();
    }
}

void Renderer::setGpuTiming(bool enabled)
{
    mImpl->timing = enabled;
}

void Renderer::setPassWallClock(bool enabled)
{
    mImpl->wallClock = enabled;
}

const FrameStats& Renderer::stats() const
{
    return mImpl->stats;
}

gl::State& Renderer::state()
{
    return mImpl->state;
}

void Renderer::render(const View& view, const FrameSettings& requested)
{
    Impl& r = *mImpl;
    const FrameSettings settings = effectiveSettings(requested);
    const int samples = std::max(settings.msaa, 1);
    r.ensureTargets(std::max(settings.width, 1), std::max(settings.height, 1), samples);
    r.stats = {};
    r.timed.clear();
    r.prepareMaterials(settings);
    r.state.resetCounters();

    auto& f = r.frame.data();
    f.view = view.view;
    f.projection = view.projection;
    f.viewProjection = view.projection * view.view;
    f.cameraPosition = glm::vec4(view.position, 1.0f);
    // 2^EV is compensation on top of the camera's exposure (docs/units.md); automatic
    // exposure replaces the camera's on the GPU.
    r.lastAutoExposure = settings.autoExposure.enabled;
    r.lastDebugView = settings.debugView;
    r.lastExposureScale = std::exp2(settings.exposureEv);
    if (settings.ev100 && !settings.autoExposure.enabled) r.lastExposureScale *= exposureFromEv100(*settings.ev100);
    f.exposure = glm::vec4(r.lastExposureScale, settings.reinhardWhite, 0.0f, 0.0f);
    f.ambient = glm::vec4(settings.ambient, 0.0f);
    f.options = glm::uvec4(tonemapId(settings.tonemap), uint32_t(r.lights.count()), 0u, 0u);
    r.frame.upload();

    if (settings.ssao.enabled) {
        // Before the forward pass, which reads the occlusion for its ambient term.
        if (!r.ssao) r.ssao = std::make_unique<SsaoPass>();
        r.frame.bind(SPECULA_BINDING_FRAME);
        r.pass("ssao prepass", [&] { r.ssao->drawDepthNormals(r.state, r.scene.get(), view, r.width, r.height); });
        r.pass("ssao", [&] { r.ssao->computeOcclusion(r.state, view, settings.ssao); });
        r.pass("ssao blur", [&] { r.ssao->blur(r.state); });
        r.state.bindTexture(SPECULA_UNIT_SSAO, r.ssao->occlusion());
        r.state.bindSampler(SPECULA_UNIT_SSAO, nullptr);
    }

    if (doomFrame(settings)) {
        // Doom's 8-bit frame: indices and levels, then the colour-map pass writes the palette
        // colours to both the HDR and the 8-bit target. Nothing else touches them (no tone
        // curve, exposure, bloom or FXAA: effectiveSettings), so the image is the palette's bytes.
        DoomPass& doom = r.doomPass();
        r.pass("forward", [&] {
            doom.beginFrame(r.state, r.width, r.height, settings.background);
            r.drawScene(view, settings);
        });
        if (r.doomOutput.id() == 0) {
            r.doomOutput = gl::Framebuffer("doom colour-map output");
            r.doomOutput.attachColor(0, r.hdrColor).attachColor(1, r.ldrColor).check();
        }
        r.pass("colour map", [&] { doom.resolve(r.state, r.doomOutput); });
        r.hdrResolved = true;
        r.finishFrame(settings);
        return;
    }

    r.pass("forward", [&] {
        gl::Framebuffer& target = samples > 1 ? r.msaaFramebuffer : r.hdrFramebuffer;
        r.state.bindFramebuffer(&target);
        r.state.viewport(0, 0, r.width, r.height);
        // Depth writes must be on for the clear to reach the depth buffer.
        r.state.apply({});
        target.clearColor(0, settings.background.x, settings.background.y, settings.background.z, 1.0f);
        target.clearDepth(1.0f);
        r.drawScene(view, settings);
    });
    r.hdrResolved = samples == 1;

    // Passes on the HDR frame need it resolved. Without them the tone mapper resolves as it
    // reads (one pass instead of a blit and a pass), and the resolved HDR image is made only
    // when someone asks (readRadiance): with every post pass off the frame costs what it did.
    const bool hdrPasses = settings.bloom.enabled || settings.autoExposure.enabled;
    if (hdrPasses && !r.hdrResolved) {
        r.pass("resolve", [&] { r.msaaFramebuffer.blitColorTo(r.hdrFramebuffer, r.width, r.height); });
        r.hdrResolved = true;
    }
    if (settings.bloom.enabled) {
        if (!r.bloom) r.bloom = std::make_unique<BloomPass>();
        r.pass("bloom", [&] {
            r.bloom->apply(r.state, r.hdrColor, settings.bloom, r.lastExposureScale, settings.debugView == DebugView::Bloom);
        });
    }
    if (settings.autoExposure.enabled) {
        if (!r.autoExposure) r.autoExposure = std::make_unique<ExposurePass>();
        r.pass("exposure", [&] { r.autoExposure->apply(r.state, r.hdrColor, settings.autoExposure); });
    }

    if (settings.fxaa.enabled && (r.fxaaInput.width() != r.width || r.fxaaInput.height() != r.height || !r.fxaaInput)) {
        r.state.reset(); // names of the deleted target may be reused
        gl::TextureDesc desc;
        desc.width = r.width;
        desc.height = r.height;
        desc.format = gl::Format::RGBA8;
        desc.label = "fxaa input";
        r.fxaaInput = gl::Texture(desc);
        r.fxaaFramebuffer = gl::Framebuffer("fxaa input");
        r.fxaaFramebuffer.attachColor(0, r.fxaaInput).check();
    }
    const bool fused = !r.hdrResolved;
    r.pass(fused ? "resolve+tonemap" : "tonemap", [&] {
        r.state.bindFramebuffer(settings.fxaa.enabled ? &r.fxaaFramebuffer : &r.ldrFramebuffer);
        r.state.viewport(0, 0, r.width, r.height);
        // Into FXAA's UNORM input the shader encodes; into the sRGB target GL does.
        r.state.apply({.noDepthTest = true, .noDepthWrite = true, .framebufferSrgb = !settings.fxaa.enabled});
        r.state.useProgram(r.tonemap(fused ? samples : 1, settings.autoExposure.enabled, settings.fxaa.enabled));
        r.frame.bind(SPECULA_BINDING_FRAME);
        if (settings.autoExposure.enabled) r.autoExposure->bind();
        r.state.bindTexture(SPECULA_UNIT_POST_INPUT, fused ? r.msaaColor : r.hdrColor);
        r.state.bindSampler(SPECULA_UNIT_POST_INPUT, nullptr);
        r.state.bindVertexArray(r.emptyVertexArray);
        r.state.drawTriangles(3, false);
    });
    if (settings.fxaa.enabled) {
        if (!r.fxaa) r.fxaa = std::make_unique<FxaaPass>();
        r.pass("fxaa", [&] { r.fxaa->apply(r.state, r.fxaaInput, r.ldrFramebuffer); });
    }
    r.finishFrame(settings);
}

void Renderer::Impl::finishFrame(const FrameSettings& settings)
{
    Impl& r = *this;
    if (settings.debugView == DebugView::Ssao) {
        r.pass("debug view", [&] {
            if (!r.debugProgram)
                r.debugProgram = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "post/debug.frag", .label = "debug view"});
            r.state.bindFramebuffer(&r.ldrFramebuffer);
            r.state.viewport(0, 0, r.width, r.height);
            // No sRGB encoding: the byte is the occlusion × 255.
            r.state.apply({.noDepthTest = true, .noDepthWrite = true});
            r.state.useProgram(r.debugProgram);
            r.state.bindTexture(SPECULA_UNIT_POST_INPUT, r.ssao->occlusion());
            r.state.bindSampler(SPECULA_UNIT_POST_INPUT, nullptr);
            r.state.bindVertexArray(r.emptyVertexArray);
            r.state.drawTriangles(3, false);
        });
    }
    r.stats.drawCalls = r.state.drawCalls();
    for (const Impl::Timed& t : r.timed) r.stats.passes.push_back({t.name, t.timer->elapsedMs(), t.wallMs});
}

ImageRGBA8 Renderer::readImage() const
{
    const Impl& r = *mImpl;
    ImageRGBA8 image;
    image.width = r.width;
    image.height = r.height;
    const std::vector<uint8_t> pixels = r.ldrColor.readBytes(0, 4);
    image.pixels.resize(pixels.size());
    // GL's first row is the bottom one; files want the top one first.
    const size_t row = size_t(r.width) * 4;
    for (int y = 0; y < r.height; ++y)
        std::copy_n(pixels.begin() + ptrdiff_t(size_t(r.height - 1 - y) * row), row, image.pixels.begin() + ptrdiff_t(size_t(y) * row));
    return image;
}

void Renderer::present(int width, int height)
{
    Impl& r = *mImpl;
    // No sRGB encoding and no scissor: the bytes are sRGB already and copied as they are.
    // The default framebuffer stays bound for what the window draws on top (a UI).
    r.state.bindFramebuffer(nullptr);
    r.state.viewport(0, 0, width, height);
    r.state.apply({.noDepthTest = true, .noDepthWrite = true});
    glBlitNamedFramebuffer(r.ldrFramebuffer.id(), 0, 0, 0, r.width, r.height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                           GL_LINEAR);
}

float Renderer::exposureScale() const
{
    const Impl& r = *mImpl;
    if (r.lastAutoExposure && r.autoExposure) return r.lastExposureScale * r.autoExposure->read().exposure;
    return r.lastExposureScale;
}

ImageFloat Renderer::readRadiance() const
{
    Impl& r = *mImpl;
    ImageFloat image;
    image.width = r.width;
    image.height = r.height;
    const size_t row = size_t(r.width) * 4;
    image.pixels.resize(row * size_t(r.height));
    if (r.lastDebugView == DebugView::Ssao && r.ssao) {
        const std::vector<float> ao = r.ssao->occlusion().readFloat(0, 1);
        for (int y = 0; y < r.height; ++y) {
            for (int x = 0; x < r.width; ++x) {
                const float value = ao[size_t(r.height - 1 - y) * size_t(r.width) + size_t(x)];
                float* pixel = &image.pixels[size_t(y) * row + size_t(x) * 4];
                pixel[0] = pixel[1] = pixel[2] = value;
                pixel[3] = 1.0f;
            }
        }
        return image;
    }
    if (!r.hdrResolved) {
        r.msaaFramebuffer.blitColorTo(r.hdrFramebuffer, r.width, r.height);
        r.hdrResolved = true;
    }
    const float scale = exposureScale();
    const std::vector<float> pixels = r.hdrColor.readFloat(0, 4);
    for (int y = 0; y < r.height; ++y) {
        for (size_t x = 0; x < row; ++x) {
            const float value = pixels[size_t(r.height - 1 - y) * row + x];
            // Alpha stays coverage; colour channels carry the exposure like the PNG does.
            image.pixels[size_t(y) * row + x] = (x % 4 == 3) ? value : value * scale;
        }
    }
    return image;
}

int Renderer::materialCount() const
{
    return mImpl->scene ? mImpl->scene->materialCount() : 0;
}

scene::MaterialShading Renderer::materialShading(int material) const
{
    if (material < 0 || material >= materialCount()) return {};
    return unpackShading(mImpl->scene->materials()[size_t(material)].features);
}

std::array<uint32_t, 5> Renderer::materialTextureNames(int material) const
{
    static_assert(size_t(TextureSlot::Count) == 5);
    std::array<uint32_t, 5> names{};
    if (material < 0 || material >= materialCount()) return names;
    const MaterialBinding& binding = mImpl->scene->materials()[size_t(material)];
    for (size_t i = 0; i < names.size(); ++i) names[i] = binding.textures[i] ? binding.textures[i]->id() : 0u;
    return names;
}

void Renderer::setMaterialShading(int material, const scene::MaterialShading& shading)
{
    if (material < 0 || material >= materialCount()) return;
    mImpl->scene->setShading(material, shading);
}

glm::vec4 Renderer::materialParameter(int material, MaterialParameter parameter) const
{
    if (material < 0 || material >= materialCount()) return glm::vec4(0.0f);
    const shared::GpuMaterial& r = mImpl->scene->record(material);
    switch (parameter) {
    case MaterialParameter::BaseColor: return r.baseColorFactor;
    case MaterialParameter::Emissive: return glm::vec4(glm::vec3(r.emissive), 0.0f);
    case MaterialParameter::Metallic: return glm::vec4(r.params.x, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::Roughness: return glm::vec4(r.params.y, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::PhongSpecular: return glm::vec4(glm::vec3(r.phong), 0.0f);
    case MaterialParameter::Shininess: return glm::vec4(r.phong.w, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::SpecularColor: return glm::vec4(glm::vec3(r.specular), 0.0f);
    case MaterialParameter::SpecularFactor: return glm::vec4(r.specular.w, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::SectorLight: return glm::vec4(r.emissive.w * 255.0f, 0.0f, 0.0f, 0.0f);
    }
    return glm::vec4(0.0f);
}

void Renderer::setMaterialParameter(int material, MaterialParameter parameter, const glm::vec4& value)
{
    if (material < 0 || material >= materialCount()) return;
    GpuScene& gpu = *mImpl->scene;
    using shared::GpuMaterial;
    // Each parameter is a run of floats inside one vec4 of the record.
    auto write = [&](size_t vectorOffset, int first, int count) {
        gpu.writeMaterial(material, vectorOffset + size_t(first) * sizeof(float), size_t(count) * sizeof(float), &value[first]);
    };
    switch (parameter) {
    case MaterialParameter::BaseColor: write(offsetof(GpuMaterial, baseColorFactor), 0, 4); break;
    case MaterialParameter::Emissive: write(offsetof(GpuMaterial, emissive), 0, 3); break;
    case MaterialParameter::Metallic: {
        const glm::vec4 v(value.x);
        gpu.writeMaterial(material, offsetof(GpuMaterial, params), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::Roughness: {
        const glm::vec4 v(value.x);
        gpu.writeMaterial(material, offsetof(GpuMaterial, params) + sizeof(float), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::PhongSpecular: write(offsetof(GpuMaterial, phong), 0, 3); break;
    case MaterialParameter::Shininess: {
        const glm::vec4 v(value.x);
        gpu.writeMaterial(material, offsetof(GpuMaterial, phong) + 3 * sizeof(float), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::SpecularColor: write(offsetof(GpuMaterial, specular), 0, 3); break;
    case MaterialParameter::SpecularFactor: {
        const glm::vec4 v(value.x);
        gpu.writeMaterial(material, offsetof(GpuMaterial, specular) + 3 * sizeof(float), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::SectorLight: {
        // The record holds level / 255 (GpuScene); the shader scales it back.
        const glm::vec4 v(std::clamp(value.x, 0.0f, 255.0f) / 255.0f);
        gpu.writeMaterial(material, offsetof(GpuMaterial, emissive) + 3 * sizeof(float), sizeof(float), &v.x);
        break;
    }
    }
}

} // namespace specula::render
