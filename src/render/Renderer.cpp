#include "render/Renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/Error.h"
#include "gl/Framebuffer.h"
#include "gl/Info.h"
#include "gl/TimerQuery.h"
#include "shading/CameraExposure.h"
#include "shading/LightClusters.h"
#include "render/FrameContext.h"
#include "render/GpuScene.h"
#include "render/graph/GlGraphBackend.h"
#include "scene/Pose.h"
#include "render/passes/TonemapPass.h"
#include "render/pipelines/FramePipelines.h"
#include "shading/VariantKey.h"
#include "shaders/shared/Bindings.h"

namespace specula::render {

std::optional<BrdfGeometry> parseBrdfGeometry(std::string_view name)
{
    return scene::parseBrdfGeometryName(name);
}

const char* iblSpecularName(IblSpecular mode)
{
    return mode == IblSpecular::Importance ? "importance" : "split-sum";
}

std::optional<IblSpecular> parseIblSpecular(std::string_view name)
{
    if (name == "split-sum") return IblSpecular::SplitSum;
    if (name == "importance") return IblSpecular::Importance;
    return std::nullopt;
}

const char* transparencyName(Transparency transparency)
{
    return transparency == Transparency::Oit ? "oit" : "sorted";
}

std::optional<Transparency> parseTransparency(std::string_view name)
{
    if (name == "sorted") return Transparency::Sorted;
    if (name == "oit") return Transparency::Oit;
    return std::nullopt;
}

bool isDoomFrame(const FrameSettings& s)
{
    return s.materialOverride.model == scene::ShadingModel::Doom && !isMaterialDebugView(s.debugView);
}

FrameStores::FrameStores()
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

FrameStores::~FrameStores() = default;

namespace {

/// What a frame actually runs: a debug view needs its pass on.
FrameSettings effectiveSettings(const FrameSettings& requested)
{
    FrameSettings s = requested;
    s.width = std::max(s.width, 1);
    s.height = std::max(s.height, 1);
    s.msaa = std::max(s.msaa, 1);
    if (s.debugView == DebugView::Ssao) s.ssao.enabled = true;
    if (s.debugView == DebugView::Bloom) s.bloom.enabled = true;
    if (s.debugView == DebugView::ShadowAtlas) s.shadows.enabled = true;
    const bool doom = s.materialOverride.model == scene::ShadingModel::Doom;
    // The Doom model's frame holds only palette colours: one sample a pixel (a resolve would
    // blend them) and, as for the views below, nothing that scales or curves values.
    if (doom) s.msaa = 1;
    // Weighted blended OIT needs blending, which indices cannot do; the views show values, one layer.
    if (isMaterialDebugView(s.debugView) || doom) s.transparency = Transparency::Sorted;
    if (isMaterialDebugView(s.debugView) || doom) {
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

/// Rows of a GL image (first row at the bottom) in file order (top row first).
template <typename T>
std::vector<T> flipRows(const std::vector<T>& pixels, int width, int height, int channels)
{
    std::vector<T> out(pixels.size());
    const size_t row = size_t(width) * size_t(channels);
    for (int y = 0; y < height; ++y)
        std::copy_n(pixels.begin() + ptrdiff_t(size_t(height - 1 - y) * row), row, out.begin() + ptrdiff_t(size_t(y) * row));
    return out;
}

} // namespace

struct Renderer::Impl {
    FrameStores stores;
    GlGraphBackend backend{stores.state};
    FramePasses passes;
    std::filesystem::path cacheDirectory; // of the bakes (Renderer::setCacheDirectory)
    int maxSamples = 0;                   // of colour and depth targets, asked once
    FrameStats stats;
    bool timing = false;
    bool wallClock = false;
    /// The node that places each light, while the lights are the scene's (setScene; setLights
    /// replaces them): setPose moves them with their nodes.
    std::vector<int> lightNodes;
    std::vector<int> lightIndices; ///< per buffer slot: the scene's light (with lightNodes)
    /// Per scene light: the fields KHR_animation_pointer animates (bits of scene::AnimatedField
    /// from LightColor on). setPose writes those only: a viewer's edit of the others stays.
    std::vector<uint32_t> animatedLightFields;

    /// The last frame: its exported textures stay readable until the next one.
    std::unique_ptr<Frame> last;
    FrameSettings lastSettings;
    float lastExposureScale = 1.0f;
    gl::Texture atlasImage; // Renderer::shadowAtlasImage
    gl::Framebuffer atlasImageTarget;

    ~Impl()
    {
        if (last) last->graph.releaseExported(backend);
    }

    /// Checks what the settings ask of the implementation: more MSAA samples than it has is a
    /// GL error and an incomplete framebuffer; say so in one line instead (llvmpipe stops at 4).
    void checkSupport(const FrameSettings& s)
    {
        if (s.msaa <= 1) return;
        if (maxSamples == 0) maxSamples = std::min(gl::maxColorSamples(), gl::maxDepthSamples());
        if (s.msaa > maxSamples)
            throw Error("{} MSAA samples asked for; this OpenGL implementation supports at most {}", s.msaa, maxSamples);
    }

    /// The frame constants: view, exposure, tone curve.
    float uploadFrameData(const View& view, const FrameSettings& s)
    {
        auto& f = stores.frame.data();
        f.view = view.view;
        f.projection = view.projection;
        f.viewProjection = view.projection * view.view;
        f.cameraPosition = glm::vec4(view.position, 1.0f);
        // 2^EV is compensation on top of the camera's exposure (docs/units.md); automatic
        // exposure replaces the camera's on the GPU.
        float exposure = std::exp2(s.exposureEv);
        if (s.ev100 && !s.autoExposure.enabled) exposure *= exposureFromEv100(*s.ev100);
        f.exposure = glm::vec4(exposure, s.reinhardWhite, 0.0f, 0.0f);
        f.ambient = glm::vec4(s.ambient, 0.0f);
        f.options = glm::uvec4(tonemapId(s.tonemap), uint32_t(stores.lights.count()), 0u, 0u);
        const ClusterGrid grid = ClusterGrid::make(s.width, s.height, view.projection);
        f.clusterGrid = glm::uvec4(uint32_t(grid.tilesX), uint32_t(grid.tilesY), uint32_t(grid.slices),
                                   uint32_t(grid.tileWidth) | uint32_t(grid.tileHeight) << 16);
        f.clusterDepth = glm::vec4(grid.sliceScale(), grid.sliceBias(), float(s.width), float(s.height));
        // What the culling's header will say, known here: shading reads it as uniforms.
        f.clusterLists = glm::uvec4(uint32_t(stores.lights.directionalCount()),
                                    uint32_t(SPECULA_CLUSTER_HEADER_WORDS + 2 * grid.count()), 0u, 0u);
        f.clusterTiles = glm::vec4(1.0f / float(grid.tileWidth), 1.0f / float(grid.tileHeight), 0.0f, 0.0f);
        stores.frame.upload();
        return exposure;
    }

    gl::Texture& lastTexture(GraphTexture t) const { return backend.pooled(last->graph.physical(t)); }

    /// Builds and compiles the frame `requested` asks for, without running it.
    void buildOnly(const View& view, const FrameSettings& requested, Frame& frame)
    {
        const FrameSettings settings = effectiveSettings(requested);
        checkSupport(settings);
        FrameStats unused;
        const FrameContext context{view, settings, settings.width, settings.height, settings.msaa, 1.0f, stores, backend, unused};
        buildFrame(frame, passes, context);
        frame.graph.compile();
    }
};

Renderer::Renderer() : mImpl(std::make_unique<Impl>())
{
    // The forward pass binds units up to SPECULA_UNIT_RESIDUAL_PREFILTERED (shaders/shared/Bindings.h).
    static_assert(SPECULA_UNIT_RESIDUAL_PREFILTERED > SPECULA_UNIT_RESIDUAL_CUBE && SPECULA_UNIT_RESIDUAL_CUBE > SPECULA_UNIT_SHEEN_ALBEDO && SPECULA_UNIT_SHEEN_ALBEDO > SPECULA_UNIT_IRIDESCENCE_THICKNESS &&
                  SPECULA_UNIT_IRIDESCENCE_THICKNESS > SPECULA_UNIT_IRIDESCENCE && SPECULA_UNIT_IRIDESCENCE > SPECULA_UNIT_ANISOTROPY &&
                  SPECULA_UNIT_ANISOTROPY > SPECULA_UNIT_SHEEN_ROUGHNESS &&
                  SPECULA_UNIT_SHEEN_ROUGHNESS > SPECULA_UNIT_CLEARCOAT_NORMAL &&
                  SPECULA_UNIT_CLEARCOAT_NORMAL > SPECULA_UNIT_ENVIRONMENT_CUBE && SPECULA_UNIT_ENVIRONMENT_CUBE > SPECULA_UNIT_TRANSMISSION &&
                  SPECULA_UNIT_TRANSMISSION > SPECULA_UNIT_IRRADIANCE);
    if (gl::maxTextureUnits() <= SPECULA_UNIT_RESIDUAL_PREFILTERED)
        throw Error("this OpenGL implementation has {} texture units; Specula needs {}", gl::maxTextureUnits(),
                    SPECULA_UNIT_RESIDUAL_PREFILTERED + 1);
    // The extension textures' units above the fragment stage's count (shaders/shared/Bindings.h).
    static_assert(SPECULA_UNIT_SHADOW_TINT > SPECULA_UNIT_DIFFUSE_TRANSMISSION_COLOR &&
                  SPECULA_UNIT_DIFFUSE_TRANSMISSION_COLOR > SPECULA_UNIT_DIFFUSE_TRANSMISSION &&
                  SPECULA_UNIT_DIFFUSE_TRANSMISSION > SPECULA_UNIT_THICKNESS &&
                  SPECULA_UNIT_THICKNESS > SPECULA_UNIT_TRANSMISSION_FACTOR && SPECULA_UNIT_TRANSMISSION_FACTOR > SPECULA_UNIT_SPECULAR_COLOR &&
                  SPECULA_UNIT_SPECULAR_COLOR > SPECULA_UNIT_SPECULAR && SPECULA_UNIT_SPECULAR > SPECULA_UNIT_RESIDUAL_PREFILTERED);
    if (gl::maxCombinedTextureUnits() <= SPECULA_UNIT_SHADOW_TINT)
        throw Error("this OpenGL implementation has {} combined texture units; Specula needs {}", gl::maxCombinedTextureUnits(),
                    SPECULA_UNIT_SHADOW_TINT + 1);
}
Renderer::~Renderer() = default;

void Renderer::setScene(const scene::Scene& scene)
{
    mImpl->stores.state.reset(); // textures and vertex arrays are replaced: forget cached bindings
    mImpl->stores.scene = std::make_unique<GpuScene>(scene);
    ++mImpl->stores.casterVersion;
    mImpl->passes.billboards.setScene(scene);
    const scene::HiddenNodes hidden = scene.hiddenNodesToKeep(); // as GpuScene keeps their draws
    mImpl->stores.lights.setAll(placeLights(scene, hidden));
    mImpl->lightNodes.clear();
    mImpl->lightIndices.clear();
    for (const scene::LightInstance& instance : scene.lightInstances(hidden)) {
        mImpl->lightNodes.push_back(instance.node);
        mImpl->lightIndices.push_back(instance.light);
    }
    mImpl->animatedLightFields.assign(scene.lights.size(), 0u);
    for (const scene::AnimatedProperty& p : scene::animatedProperties(scene))
        if (scene::isLightField(p.field) && size_t(p.index) < scene.lights.size())
            mImpl->animatedLightFields[size_t(p.index)] |= 1u << (int(p.field) - int(scene::AnimatedField::LightColor));
}

void Renderer::setVariant(int variant)
{
    GpuScene* gpu = mImpl->stores.scene.get();
    if (gpu && gpu->setVariant(variant)) ++mImpl->stores.casterVersion; // casters' materials changed
}

void Renderer::setPose(int animation, float seconds)
{
    GpuScene* gpu = mImpl->stores.scene.get();
    if (!gpu || !gpu->animated()) return;
    gpu->setPose(animation, seconds);
    ++mImpl->stores.casterVersion; // the casters may have moved: no shadow map is kept
    // Lights on animated nodes move with them (as Scene::lightInstances places them), and take
    // the properties KHR_animation_pointer gives them.
    const std::vector<glm::mat4>& world = gpu->nodeWorlds();
    const std::vector<bool>& visible = gpu->nodeVisible();
    const std::vector<scene::Light>& posed = gpu->posedLights();
    LightBuffer& lights = mImpl->stores.lights;
    for (size_t i = 0; i < mImpl->lightNodes.size() && int(i) < lights.count(); ++i) {
        const size_t node = size_t(mImpl->lightNodes[i]);
        if (node >= world.size()) continue;
        PlacedLight placed = lights.light(int(i));
        const PlacedLight before = placed;
        placed.position = glm::vec3(world[node][3]);
        placed.direction = glm::normalize(glm::vec3(world[node] * glm::vec4(0, 0, -1, 0)));
        if (node < visible.size()) placed.visible = visible[node];
        if (const size_t light = size_t(mImpl->lightIndices[i]); light < posed.size() && light < mImpl->animatedLightFields.size()) {
            const uint32_t animated = mImpl->animatedLightFields[light];
            const auto has = [&](scene::AnimatedField f) { return (animated >> (int(f) - int(scene::AnimatedField::LightColor))) & 1u; };
            if (has(scene::AnimatedField::LightColor)) placed.light.color = posed[light].color;
            if (has(scene::AnimatedField::LightIntensity)) placed.light.intensity = posed[light].intensity;
            if (has(scene::AnimatedField::LightRange)) placed.light.range = posed[light].range;
            if (has(scene::AnimatedField::SpotInnerConeAngle)) placed.light.innerConeAngle = posed[light].innerConeAngle;
            if (has(scene::AnimatedField::SpotOuterConeAngle)) placed.light.outerConeAngle = posed[light].outerConeAngle;
        }
        const scene::Light& a = before.light;
        const scene::Light& b = placed.light;
        if (before.position == placed.position && before.direction == placed.direction && before.visible == placed.visible && a.color == b.color &&
            a.intensity == b.intensity && a.range == b.range && a.innerConeAngle == b.innerConeAngle && a.outerConeAngle == b.outerConeAngle)
            continue;
        lights.set(int(i), placed);
    }
}

BakeReport Renderer::setEnvironment(const EnvironmentMap& map, const BakeSettings& settings, const std::filesystem::path& cacheDirectory,
                                    BakeMode mode)
{
    setCacheDirectory(cacheDirectory);
    return mImpl->stores.ibl.setEnvironment(mImpl->stores.state, map, settings, cacheDirectory, mode);
}

BakeProgress Renderer::advanceEnvironmentBake(double budgetMs)
{
    FrameStores& stores = mImpl->stores;
    const BakeProgress progress = stores.ibl.advanceBake(stores.state, budgetMs);
    if (progress.finished) stores.state.reset(); // the preview's textures are deleted
    return progress;
}

void Renderer::clearEnvironment()
{
    FrameStores& stores = mImpl->stores;
    stores.state.reset(); // the environment's textures are deleted
    stores.ibl = ImageBasedLighting();
    stores.ibl.setLutCacheDirectory(mImpl->cacheDirectory);
}

void Renderer::setCacheDirectory(const std::filesystem::path& directory)
{
    mImpl->cacheDirectory = directory;
    mImpl->stores.ibl.setLutCacheDirectory(directory);
}

const Sh9* Renderer::environmentSh() const
{
    return mImpl->stores.ibl.hasEnvironment() ? &mImpl->stores.ibl.sh() : nullptr;
}

void Renderer::invalidateGlState()
{
    mImpl->stores.state.reset();
}

void Renderer::prepare(const FrameSettings& settings)
{
    // Programs are compiled and tables baked as the frame is built; nothing runs.
    Frame frame;
    mImpl->buildOnly(View{}, settings, frame);
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

std::string Renderer::frameGraphDot(const View& view, const FrameSettings& settings)
{
    Frame frame;
    mImpl->buildOnly(view, settings, frame);
    return frame.graph.toDot();
}

void Renderer::render(const View& view, const FrameSettings& requested)
{
    Impl& r = *mImpl;
    const FrameSettings settings = effectiveSettings(requested);
    r.checkSupport(settings);
    r.stats = {};
    r.stores.state.resetCounters();
    r.stores.lights.setCutoff(std::max(settings.lightCutoff, 0.0f));
    const float exposure = r.uploadFrameData(view, settings);
    const FrameContext context{view, settings, settings.width, settings.height, settings.msaa, exposure,
                               r.stores, r.backend, r.stats};
    auto frame = std::make_unique<Frame>();
    // A program that does not compile throws here, before anything runs: the last frame stays.
    buildFrame(*frame, r.passes, context);
    frame->graph.compile();
    // Last frame's exported targets go back to the pool: this frame takes them again.
    if (r.last) r.last->graph.releaseExported(r.backend);
    r.last.reset();
    r.backend.setTiming(r.timing, r.wallClock);
    r.backend.beginFrame(frame->graph);
    frame->graph.execute(r.backend);
    r.backend.endFrame();
    r.stats.drawCalls = r.stores.state.drawCalls();
    r.stats.transientTextures = r.backend.liveTextures();
    for (const GraphPassTiming& t : r.backend.timings()) r.stats.passes.push_back({t.name, t.timer->elapsedMs(), t.wallMs});
    if (frame->outputs.clusters) {
        const LightCullPass& culling = r.passes.lightCull;
        const ClusterCounts counts = culling.counts();
        FrameStats::Clusters& c = r.stats.clusters;
        c.tilesX = culling.grid().tilesX;
        c.tilesY = culling.grid().tilesY;
        c.slices = culling.grid().slices;
        c.lightsInView = int(counts.visible);
        c.directional = int(counts.directional);
        c.maxPerCluster = int(counts.longest);
        c.entries = counts.entries;
        c.meanPerCluster = double(counts.entries) / double(std::max(culling.grid().count(), 1));
        c.bufferBytes = culling.capacityWords() * sizeof(uint32_t);
        c.everyLight = frame->outputs.everyLight;
    }
    r.last = std::move(frame);
    r.lastSettings = settings;
    r.lastExposureScale = exposure;
}

ImageRGBA8 Renderer::readImage() const
{
    const Impl& r = *mImpl;
    ImageRGBA8 image;
    if (!r.last) return image;
    if (!r.last->outputs.ldr) throw Error("the last frame went straight to the window (toWindow): no image to read");
    const gl::Texture& ldr = r.lastTexture(r.last->outputs.ldr);
    image.width = ldr.width();
    image.height = ldr.height();
    image.pixels = flipRows(ldr.readBytes(0, 4), image.width, image.height, 4);
    return image;
}

void Renderer::present(int width, int height)
{
    Impl& r = *mImpl;
    if (!r.last) return;
    // The default framebuffer stays bound for what the window draws on top (a UI), with no
    // sRGB encoding and no scissor: the bytes are sRGB already and copied as they are.
    r.stores.state.bindFramebuffer(nullptr);
    r.stores.state.viewport(0, 0, width, height);
    r.stores.state.apply({.noDepthTest = true, .noDepthWrite = true});
    if (!r.last->outputs.ldr) return; // the frame is there already (toWindow)
    gl::Texture& ldr = r.lastTexture(r.last->outputs.ldr);
    r.backend.framebufferOf({&ldr}).blitColorToDefault(ldr.width(), ldr.height(), width, height);
}

bool Renderer::lastFrameInWindow() const
{
    return mImpl->last && !mImpl->last->outputs.ldr;
}

float Renderer::exposureScale() const
{
    const Impl& r = *mImpl;
    ExposurePass* autoExposure = r.passes.exposureIfMade();
    if (r.lastSettings.autoExposure.enabled && autoExposure) return r.lastExposureScale * autoExposure->read().exposure;
    return r.lastExposureScale;
}

ImageFloat Renderer::readRadiance() const
{
    Impl& r = *mImpl;
    ImageFloat image;
    if (!r.last) return image;
    const FrameOutputs& out = r.last->outputs;
    const int width = r.lastSettings.width, height = r.lastSettings.height;
    image.width = width;
    image.height = height;
    if (out.occlusion) {
        const std::vector<float> ao = flipRows(r.lastTexture(out.occlusion).readFloat(0, 1), width, height, 1);
        image.pixels.resize(ao.size() * 4);
        for (size_t i = 0; i < ao.size(); ++i) {
            float* pixel = &image.pixels[i * 4];
            pixel[0] = pixel[1] = pixel[2] = ao[i];
            pixel[3] = 1.0f;
        }
        return image;
    }
    std::vector<float> pixels;
    if (out.hdr) {
        pixels = r.lastTexture(out.hdr).readFloat(0, 4);
    } else {
        // The tone mapper resolved MSAA as it read: resolve now, into a texture of the pool's.
        GraphTextureDesc desc;
        desc.width = width;
        desc.height = height;
        desc.format = gl::Format::RGBA16F;
        const int resolved = r.backend.acquirePooled(desc, "hdr colour");
        gl::Texture& target = r.backend.pooled(resolved);
        r.backend.framebufferOf({&r.lastTexture(out.msaaColor)}).blitColorTo(r.backend.framebufferOf({&target}), width, height);
        pixels = target.readFloat(0, 4);
        r.backend.releasePooled(resolved);
    }
    const float scale = exposureScale();
    image.pixels = flipRows(pixels, width, height, 4);
    // Alpha stays coverage; colour channels carry the exposure like the PNG does.
    for (size_t i = 0; i < image.pixels.size(); ++i)
        if (i % 4 != 3) image.pixels[i] *= scale;
    return image;
}

int Renderer::materialCount() const
{
    return mImpl->stores.scene ? mImpl->stores.scene->materialCount() : 0;
}

scene::MaterialShading Renderer::materialShading(int material) const
{
    if (material < 0 || material >= materialCount()) return {};
    return unpackShading(mImpl->stores.scene->materials()[size_t(material)].features);
}

std::vector<uint32_t> Renderer::materialTextureNames(int material) const
{
    std::vector<uint32_t> names(size_t(TextureSlot::Count), 0u); // slot order = scene::kMaterialTextures'
    if (material < 0 || material >= materialCount()) return names;
    const MaterialBinding& binding = mImpl->stores.scene->materials()[size_t(material)];
    for (size_t i = 0; i < names.size(); ++i) names[i] = binding.textures[i] ? binding.textures[i]->id() : 0u;
    return names;
}

uint32_t Renderer::shadowAtlasImage(int size)
{
    Impl& r = *mImpl;
    const gl::Texture* atlas = r.passes.shadows.atlas();
    if (!atlas || !r.passes.shadows.variant().active() || size <= 0) return 0;
    if (!r.atlasImage || r.atlasImage.width() != size) {
        r.atlasImage = gl::Texture({.format = gl::Format::RGBA8, .width = size, .height = size, .label = "shadow atlas image"});
        r.atlasImageTarget = gl::Framebuffer("shadow atlas image");
        r.atlasImageTarget.attachColor(0, r.atlasImage);
        r.atlasImageTarget.check();
    }
    r.passes.debugView().drawShadowAtlas(r.stores.state, *atlas, r.atlasImageTarget, size, size, r.stores.emptyVertexArray);
    return r.atlasImage.id();
}

void Renderer::setMaterialShading(int material, const scene::MaterialShading& shading)
{
    if (material < 0 || material >= materialCount()) return;
    mImpl->stores.scene->setShading(material, shading);
}

scene::BlendMode Renderer::materialBlendMode(int material) const
{
    if (material < 0 || material >= materialCount()) return scene::BlendMode::Fade;
    // The record's flags: the declared mode, also while alpha 1 has the material drawn opaque.
    return mImpl->stores.scene->record(material).flags.x & SPECULA_MATERIAL_BLEND_TRANSPARENT
               ? scene::BlendMode::Transparent
               : scene::BlendMode::Fade;
}

void Renderer::setMaterialBlendMode(int material, scene::BlendMode mode)
{
    if (material < 0 || material >= materialCount()) return;
    mImpl->stores.scene->setBlendMode(material, mode);
}

glm::vec4 Renderer::materialParameter(int material, MaterialParameter parameter) const
{
    if (material < 0 || material >= materialCount()) return glm::vec4(0.0f);
    const shared::GpuMaterial& r = mImpl->stores.scene->record(material);
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
    case MaterialParameter::ClearcoatFactor: return glm::vec4(r.clearcoat.x, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::ClearcoatRoughness: return glm::vec4(r.clearcoat.y, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::Dispersion: return glm::vec4(r.attenuation.w, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::SheenColor: return glm::vec4(glm::vec3(r.sheen), 0.0f);
    case MaterialParameter::SheenRoughness: return glm::vec4(r.sheen.w, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::AnisotropyStrength: return glm::vec4(r.anisotropy.x, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::AnisotropyRotation: return glm::vec4(std::atan2(r.anisotropy.z, r.anisotropy.y), 0.0f, 0.0f, 0.0f);
    case MaterialParameter::IridescenceFactor: return glm::vec4(r.iridescence.x, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::IridescenceIor: return glm::vec4(r.iridescence.y, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::IridescenceThickness: return glm::vec4(r.iridescence.z, r.iridescence.w, 0.0f, 0.0f);
    case MaterialParameter::DiffuseTransmission: return glm::vec4(r.diffuseTransmission.w, 0.0f, 0.0f, 0.0f);
    case MaterialParameter::DiffuseTransmissionColor: return glm::vec4(glm::vec3(r.diffuseTransmission), 0.0f);
    }
    return glm::vec4(0.0f);
}

void Renderer::setMaterialParameter(int material, MaterialParameter parameter, const glm::vec4& value)
{
    if (material < 0 || material >= materialCount()) return;
    GpuScene& gpu = *mImpl->stores.scene;
    ++mImpl->stores.casterVersion; // a masked material's alpha or cutoff changes its shadow
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
    case MaterialParameter::ClearcoatFactor: {
        const glm::vec4 v(std::clamp(value.x, 0.0f, 1.0f));
        gpu.writeMaterial(material, offsetof(GpuMaterial, clearcoat), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::ClearcoatRoughness: {
        const glm::vec4 v(std::clamp(value.x, 0.0f, 1.0f));
        gpu.writeMaterial(material, offsetof(GpuMaterial, clearcoat) + sizeof(float), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::Dispersion: {
        const glm::vec4 v(std::max(value.x, 0.0f));
        gpu.writeMaterial(material, offsetof(GpuMaterial, attenuation) + 3 * sizeof(float), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::SheenColor: {
        const glm::vec3 v = glm::clamp(glm::vec3(value), 0.0f, 1.0f);
        gpu.writeMaterial(material, offsetof(GpuMaterial, sheen), 3 * sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::SheenRoughness: {
        const glm::vec4 v(std::clamp(value.x, 0.0f, 1.0f));
        gpu.writeMaterial(material, offsetof(GpuMaterial, sheen) + 3 * sizeof(float), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::AnisotropyStrength: {
        const glm::vec4 v(std::clamp(value.x, 0.0f, 1.0f));
        gpu.writeMaterial(material, offsetof(GpuMaterial, anisotropy), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::AnisotropyRotation: {
        const glm::vec2 v(std::cos(value.x), std::sin(value.x)); // the record holds cos and sin
        gpu.writeMaterial(material, offsetof(GpuMaterial, anisotropy) + sizeof(float), 2 * sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::IridescenceFactor: {
        const glm::vec4 v(std::clamp(value.x, 0.0f, 1.0f));
        gpu.writeMaterial(material, offsetof(GpuMaterial, iridescence), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::IridescenceIor: {
        const glm::vec4 v(std::max(value.x, 1.0f));
        gpu.writeMaterial(material, offsetof(GpuMaterial, iridescence) + sizeof(float), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::IridescenceThickness: {
        const glm::vec4 v = glm::max(value, glm::vec4(0.0f));
        gpu.writeMaterial(material, offsetof(GpuMaterial, iridescence) + 2 * sizeof(float), 2 * sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::DiffuseTransmission: {
        const glm::vec4 v(std::clamp(value.x, 0.0f, 1.0f));
        gpu.writeMaterial(material, offsetof(GpuMaterial, diffuseTransmission) + 3 * sizeof(float), sizeof(float), &v.x);
        break;
    }
    case MaterialParameter::DiffuseTransmissionColor: {
        const glm::vec3 v = glm::clamp(glm::vec3(value), 0.0f, 1.0f);
        gpu.writeMaterial(material, offsetof(GpuMaterial, diffuseTransmission), 3 * sizeof(float), &v.x);
        break;
    }
    }
}

void Renderer::setClusterShrinkForTesting(float fraction)
{
    mImpl->passes.lightCull.setShrinkForTesting(fraction);
}

// The lights (render/LightBuffer).

int Renderer::lightCount() const
{
    return mImpl->stores.lights.count();
}

const PlacedLight& Renderer::light(int index) const
{
    return mImpl->stores.lights.light(index);
}

void Renderer::setLights(const std::vector<PlacedLight>& lights)
{
    mImpl->lightNodes.clear(); // no longer the scene's: an animation does not move them
    mImpl->lightIndices.clear();
    mImpl->stores.lights.setAll(lights);
}

LightWrite Renderer::setLight(int index, const PlacedLight& light)
{
    LightBuffer& lights = mImpl->stores.lights;
    const size_t before = lights.buffer().bytesUpdated();
    lights.set(index, light);
    const gl::Buffer::Range range = lights.buffer().lastUpdate();
    return {range.offset, range.size, lights.buffer().bytesUpdated() - before, LightBuffer::offsetOf(index), sizeof(shared::GpuLight)};
}

} // namespace specula::render
