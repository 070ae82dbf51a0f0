#include "render/passes/ForwardPass.h"

#include <algorithm>
#include <iterator>
#include <string>
#include <type_traits>

#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "render/FrameContext.h"
#include "render/GpuScene.h"
#include "render/graph/GlGraphBackend.h"
#include "gl/Debug.h"
#include "render/passes/BillboardPass.h"
#include "render/passes/DoomPass.h"
#include "render/passes/Fullscreen.h"
#include "render/passes/LightCullPass.h"
#include "render/passes/ShadowPass.h"
#include "shaders/shared/Bindings.h"
#include "shading/VariantKey.h"

namespace specula::render {
namespace {

/// The forward program of one variant, with its uniform locations looked up once.
struct ForwardProgram {
    gl::Program program;
    int model = -1;
    int normalMatrix = -1;
    int receiveShadows = -1;
    ResolvedShading shading;
    bool readsDfg = false; ///< samples the DFG table of `shading` (image-based light or energy compensation)
    bool readsSheenAlbedo = false; ///< the SHEEN variant: samples the sheen lobe's albedo table
};

bool iblOn(const FrameContext& frame)
{
    return frame.stores.ibl.hasEnvironment() && frame.settings.environment.lighting;
}

/// A material's shading under the frame's (`--shading`, the viewer's model menu). The unlit
/// copies of lines and points without normals (MaterialBinding::unlitCopy) keep theirs: they
/// have no normal to be lit by.
ResolvedShading materialShading(const FrameSettings& s, const MaterialBinding& material)
{
    return resolveShading(material.unlitCopy ? scene::MaterialShading{} : s.materialOverride, s.brdfGeometry, material.features);
}

IblVariant iblVariant(const FrameContext& frame)
{
    if (!iblOn(frame)) return IblVariant::None;
    return frame.settings.environment.specular == IblSpecular::Importance ? IblVariant::Importance : IblVariant::SplitSum;
}

/// Writes one field of the environment block and uploads it, if it changed. The CPU copy
/// always mirrors the buffer (made from it, and every edit uploaded), so comparing with it is
/// comparing with what the GPU holds.
template <typename Field>
void setEnvironmentField(gl::UniformBuffer<shared::EnvironmentData>& environment, Field shared::EnvironmentData::*field,
                         const Field& value)
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

/// Uploads what changed of the environment block: the view every frame the camera moves, the
/// rotation and parameters when the settings change, the SH when the environment does (its
/// bright sources are constants of the forward programs: ForwardPass::Impl::updateSources).
void updateEnvironment(const FrameContext& frame)
{
    const ImageBasedLighting& ibl = frame.stores.ibl;
    if (!ibl.hasEnvironment()) return;
    auto& environment = frame.stores.environment;
    const FrameSettings& settings = frame.settings;
    using shared::EnvironmentData;
    glm::vec4 sh[9];
    for (size_t i = 0; i < 9; ++i) sh[i] = glm::vec4(ibl.sh()[i], 0.0f);
    setEnvironmentField(environment, &EnvironmentData::sh, sh);
    setEnvironmentField(environment, &EnvironmentData::worldToEnvironment,
                        glm::mat4(environmentRotation(-settings.environment.rotationDegrees)));
    setEnvironmentField(environment, &EnvironmentData::inverseViewProjection,
                        glm::inverse(frame.view.projection * frame.view.view));
    const float blur = std::clamp(settings.environment.skyboxBlur, 0.0f, 1.0f);
    setEnvironmentField(environment, &EnvironmentData::params,
                        glm::vec4(settings.environment.intensity, float(ibl.prefiltered().levels()),
                                  SkyboxPass::blurred(frame) ? blur * float(ibl.prefiltered().levels() - 1) : -1.0f,
                                  settings.environment.skybox ? 1.0f : 0.0f));
}

} // namespace

struct ForwardPass::Impl {
    std::map<uint64_t, ForwardProgram> programs; // node-based: pointers stay valid
    std::vector<DrawProgram> materialPrograms;   // this frame's, by material
    SkyboxPass skybox;
    ShadowVariant shadows;                       // this frame's SHADOWS variants
    LightVariant lights;                         // this frame's kinds of light, LIGHTS_ALL, LIGHT_COUNT
    // The environment's bright sources, written into every forward program as constants
    // (ibl/ibl.glsl's IBL_SOURCE_*): the programs are made again when they change.
    std::vector<IrradianceSource> sources;
    int specularSources = 0; // IBL_SOURCE_SPECULAR_COUNT: the specular lobe takes the first as lights too
    bool unrotated = true;   // IBL_UNROTATED: the map is not turned (SkyboxPass::unrotated)
    std::vector<std::string> sourceDefines{"IBL_SOURCE_COUNT 0", "IBL_UNROTATED"};
    // LIGHT_VALUES of the programs that hold the lights as constants (LightVariant::constants),
    // and what decides when they may: the light buffer's revision last seen, whether it has
    // changed since the first frame, and for how many frames it has not.
    std::string lightValues;
    uint64_t lightRevision = 0, valuesRevision = 0;
    bool lightsSeen = false, lightsEdited = false, valuesMade = false;
    int stillFrames = 0;
    // Frames the lights must stay still after an edit before the programs take them as
    // constants again: a light dragged in the viewer changes every frame, and each new set of
    // constants is a compile.
    static constexpr int kSettleFrames = 16;

    // The lights as constants while they stay still: from the first frame (a render, a bench,
    // a viewer before any edit), and again kSettleFrames after the last edit; meanwhile the
    // programs that read the light buffer. Only for the constant-count programs of a frame
    // without shadow maps.
    void updateLightConstants(const FrameContext& frame, const ShadowVariant& shadows)
    {
        const LightBuffer& buffer = frame.stores.lights;
        if (!lightsSeen || buffer.revision() != lightRevision) {
            lightsEdited = lightsSeen;
            lightsSeen = true;
            lightRevision = buffer.revision();
            stillFrames = 0;
        } else if (stillFrames < kSettleFrames) {
            ++stillFrames;
        }
        lights.constants = lights.all && lights.count > 0 && !shadows.active() && (!lightsEdited || stillFrames >= kSettleFrames);
        // The values change only with the revision (a shadow slot may change without it, but a
        // frame without shadow maps compiles out what reads it).
        if (!lights.constants || (valuesMade && valuesRevision == lightRevision)) return;
        valuesMade = true;
        valuesRevision = lightRevision;
        std::string values;
        for (int i = 0; i < buffer.count(); ++i) {
            const shared::GpuLight g = LightBuffer::pack(buffer.light(i), buffer.shadowSlot(i), buffer.cutoff());
            // Nine significant digits give back every float exactly.
            const auto v = [](const glm::vec4& x) { return fmt::format("vec4({:.9g}, {:.9g}, {:.9g}, {:.9g})", x.x, x.y, x.z, x.w); };
            values += fmt::format("{}GpuLight({}, {}, {}, {})", values.empty() ? "" : ", ", v(g.positionRange), v(g.directionType),
                                  v(g.colorIntensity), v(g.spot));
        }
        if (values == lightValues) return;
        lightValues = std::move(values);
        // The programs made with the old values; those that read the buffer stay.
        std::erase_if(programs, [](const auto& entry) { return ForwardVariant{entry.first}.lightConstants(); });
    }

    // The environment's constants of the forward programs: its bright sources and whether it
    // is turned. The programs are made again when they change.
    void updateSources(const FrameContext& frame)
    {
        static const std::vector<IrradianceSource> none;
        const std::vector<IrradianceSource>& all = frame.stores.ibl.hasEnvironment() ? frame.stores.ibl.brightSources() : none;
        const size_t count = std::min<size_t>(all.size(), SPECULA_IBL_BRIGHT_SOURCES);
        const bool same = count == sources.size() && std::equal(sources.begin(), sources.end(), all.begin(), [](const auto& a, const auto& b) {
            return a.direction == b.direction && a.flux == b.flux;
        });
        const int specular = frame.stores.ibl.hasEnvironment() ? std::min(frame.stores.ibl.specularSourceCount(), int(count)) : 0;
        const bool notTurned = SkyboxPass::unrotated(frame);
        if (same && specular == specularSources && notTurned == unrotated) return;
        sources.assign(all.begin(), all.begin() + std::ptrdiff_t(count));
        specularSources = specular;
        unrotated = notTurned;
        sourceDefines = irradianceSourceDefines(sources);
        if (unrotated) sourceDefines.push_back("IBL_UNROTATED");
        if (specularSources > 0) {
            sourceDefines.push_back("IBL_SOURCE_SPECULAR");
            sourceDefines.push_back(fmt::format("IBL_SOURCE_SPECULAR_COUNT {}", specularSources));
            sourceDefines.push_back(fmt::format("IBL_RESIDUAL_FIRST_LEVEL {}", ImageBasedLighting::kResidualFirstLevel));
        }
        programs.clear(); // made with the old constants; this frame's materials take new ones
    }

    // The transparent phase's programs and sampler (made on first use).
    struct CopyProgram {
        gl::Program program;
        int samples = -1; // uSamples
    };
    std::map<std::string, CopyProgram> copyPrograms; // by variant: "", "MULTISAMPLE;", ...
    std::map<bool, gl::Program> compositePrograms;   // by multisampling
    // Trilinear, clamped: a refracted ray that leaves the screen sees the frame's edge.
    gl::Sampler transmissionSampler{{.wrapS = gl::Wrap::ClampToEdge, .wrapT = gl::Wrap::ClampToEdge, .wrapR = gl::Wrap::ClampToEdge},
                                    "opaque frame trilinear clamp"};

    CopyProgram& copyProgram(bool multisample, bool environmentBehind)
    {
        std::vector<std::string> defines;
        if (multisample) defines.push_back("MULTISAMPLE");
        if (environmentBehind) defines.push_back("ENVIRONMENT_BEHIND");
        std::string key;
        for (const std::string& d : defines) key += d + ";";
        CopyProgram& p = copyPrograms[key];
        if (!p.program) {
            p.program = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "transparency/opaque_copy.frag",
                                     .defines = defines, .label = "opaque frame copy " + key});
            p.samples = p.program.uniformLocation("uSamples");
        }
        return p;
    }

    gl::Program& compositeProgram(bool multisample)
    {
        gl::Program& p = compositePrograms[multisample];
        if (!p) p = gl::Program({.vertex = "post/fullscreen.vert", .fragment = "transparency/oit_composite.frag",
                                 .defines = multisample ? std::vector<std::string>{"MULTISAMPLE"} : std::vector<std::string>{},
                                 .label = multisample ? "oit composite MULTISAMPLE" : "oit composite"});
        return p;
    }

    ForwardProgram& program(const FrameContext& frame, const MaterialBinding& material)
    {
        const FrameSettings& s = frame.settings;
        uint64_t features = material.features;
        if (s.blendModeOverride && (features & SPECULA_MATERIAL_ALPHA_BLEND)) {
            features &= ~uint64_t(SPECULA_MATERIAL_BLEND_TRANSPARENT);
            if (*s.blendModeOverride == scene::BlendMode::Transparent) features |= SPECULA_MATERIAL_BLEND_TRANSPARENT;
        }
        const ResolvedShading shading = materialShading(s, material);
        const ForwardVariant variant =
            ForwardVariant::make(features, shading, s.debugView, iblVariant(frame), s.energyCompensation, s.ssao.enabled, isDoomFrame(s),
                                 shadows, lights, s.transparency == Transparency::Oit);
        auto it = programs.find(variant.key);
        if (it != programs.end()) return it->second;
        ForwardProgram p;
        std::vector<std::string> defines = variant.defines();
        defines.insert(defines.end(), sourceDefines.begin(), sourceDefines.end());
        if (variant.lightConstants()) defines.push_back("LIGHT_VALUES " + lightValues);
        p.program = gl::Program({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = defines,
                                 .label = "forward " + variant.name()});
        p.model = p.program.uniformLocation("uModel");
        p.normalMatrix = p.program.uniformLocation("uNormalMatrix");
        p.receiveShadows = p.program.uniformLocation("uReceiveShadows");
        p.shading = shading;
        // Debug views and the classic models return before the split sum (pbr.frag).
        p.readsDfg = shading.model == scene::ShadingModel::Pbr && !variant.debugView() && (iblOn(frame) || s.energyCompensation);
        p.readsSheenAlbedo = variant.sheen();
        return programs.emplace(variant.key, std::move(p)).first->second;
    }
};

ForwardPass::ForwardPass() : mImpl(std::make_unique<Impl>()) {}
ForwardPass::~ForwardPass() = default;

bool ForwardPass::anyDoomMaterial(const FrameContext& frame)
{
    const GpuScene* scene = frame.stores.scene.get();
    if (!scene) return false;
    const FrameSettings& s = frame.settings;
    return std::any_of(scene->materials().begin(), scene->materials().end(), [&](const MaterialBinding& m) {
        return materialShading(s, m).model == scene::ShadingModel::Doom;
    });
}

const std::vector<DrawProgram>& ForwardPass::prepareMaterials(const FrameContext& frame, const ShadowVariant& shadows,
                                                             const LightVariant& lights)
{
    Impl& r = *mImpl;
    r.shadows = shadows;
    r.lights = lights;
    r.materialPrograms.clear();
    r.updateLightConstants(frame, shadows);
    frame.stats.lightConstants = r.lights.constants;
    r.updateSources(frame);
    r.skybox.prepare(frame);
    const GpuScene* scene = frame.stores.scene.get();
    if (!scene) return r.materialPrograms;
    for (const MaterialBinding& m : scene->materials()) {
        ForwardProgram& p = r.program(frame, m);
        const gl::Texture* dfg = p.readsDfg ? &frame.stores.ibl.dfg(frame.state(), p.shading) : nullptr;
        const gl::Texture* sheenAlbedo = p.readsSheenAlbedo ? &frame.stores.ibl.sheenAlbedo(frame.state()) : nullptr;
        r.materialPrograms.push_back({&p.program, p.model, p.normalMatrix, dfg, p.receiveShadows, sheenAlbedo});
    }
    return r.materialPrograms;
}

FrameDrawLists ForwardPass::drawLists(const FrameContext& frame) const
{
    FrameDrawLists lists;
    const GpuScene* scene = frame.stores.scene.get();
    if (!scene) return lists;
    const glm::mat4 viewProjection = frame.view.projection * frame.view.view;
    // The camera's levels of detail; the pre-pass draws these lists too, so its depth is the
    // forward pass's to the bit.
    const scene::LodView lod = scene::lodView(frame.view.view, frame.view.projection, frame.height, frame.settings.lodPixels);
    const std::vector<DrawProgram>& programs = mImpl->materialPrograms;
    lists.opaque = DrawList::build(*scene, frame.view.view, viewProjection, DrawFilter::Opaque, programs, lod);
    lists.transmissive = DrawList::build(*scene, frame.view.view, viewProjection, DrawFilter::Transmissive, programs, lod);
    lists.blended = DrawList::build(*scene, frame.view.view, viewProjection, DrawFilter::Blended, programs, lod);
    return lists;
}

void ForwardPass::addTo(FrameGraph& graph, const FrameContext& frame, const FrameDrawLists& lists, const Targets& targets,
                        BillboardPass& billboards, DoomPass* doom, const ShadowPass* shadows, const LightCullPass* culling)
{
    Impl& r = *mImpl;
    const bool indexed = isDoomFrame(frame.settings);
    billboards.prepare(indexed);
    // A Doom frame's indices can neither refract nor blend: its transmissive surfaces are drawn
    // as opaque ones, its blended ones as cutouts (pbr.frag), all in the one pass.
    const bool refract = !indexed && !lists.transmissive.empty();
    const bool oit = !indexed && frame.settings.transparency == Transparency::Oit && !lists.blended.empty();
    const bool split = refract || oit;
    const bool environmentBehind = iblOn(frame);
    const bool multisampled = frame.samples > 1;
    if (refract) r.copyProgram(multisampled, environmentBehind);
    if (oit) r.compositeProgram(multisampled);

    // The graph's side of what both passes' draws sample.
    auto readFrameResources = [&targets](FrameGraph::Builder& b) {
        if (targets.occlusion) b.read(targets.occlusion, Use::Sample);
        if (targets.shadows) b.read(targets.shadows, Use::Sample);
        if (targets.clusters) b.read(targets.clusters, Use::Sample);
    };
    // What every draw of the scene reads: frame and environment blocks, lights, shadows,
    // clusters, occlusion, Doom's tables. Bound again by the second pass: nothing keeps them.
    auto bindFrameResources = [&frame, doom, shadows, culling, targets] {
        gl::State& state = frame.state();
        FrameStores& stores = frame.stores;
        if (targets.occlusion) {
            state.bindTexture(SPECULA_UNIT_SSAO, frame.backend.texture(targets.occlusion));
            state.bindSampler(SPECULA_UNIT_SSAO, nullptr);
        }
        stores.frame.bind(SPECULA_BINDING_FRAME);
        if (stores.ibl.hasEnvironment()) {
            state.bindTexture(SPECULA_UNIT_PREFILTERED, stores.ibl.prefiltered());
            state.bindSampler(SPECULA_UNIT_PREFILTERED, nullptr);
            state.bindTexture(SPECULA_UNIT_IRRADIANCE, stores.ibl.irradiance());
            state.bindSampler(SPECULA_UNIT_IRRADIANCE, nullptr);
            // The importance-sampled specular reads the unfiltered cube's box mips (ibl/importance.glsl).
            state.bindTexture(SPECULA_UNIT_ENVIRONMENT_CUBE, stores.ibl.cube());
            state.bindSampler(SPECULA_UNIT_ENVIRONMENT_CUBE, nullptr);
            if (stores.ibl.brightSourcesSpecular()) {
                state.bindTexture(SPECULA_UNIT_RESIDUAL_CUBE, stores.ibl.residualCube());
                state.bindSampler(SPECULA_UNIT_RESIDUAL_CUBE, nullptr);
                state.bindTexture(SPECULA_UNIT_RESIDUAL_PREFILTERED, stores.ibl.residualPrefiltered());
                state.bindSampler(SPECULA_UNIT_RESIDUAL_PREFILTERED, nullptr);
            }
            stores.environment.bind(SPECULA_BINDING_ENVIRONMENT);
        }
        stores.lights.bind(state);
        if (targets.shadows && shadows) shadows->bind(state);
        if (targets.clusters && culling) culling->bind(state);
        // Doom materials look their colours up in the tables, inline or for the colour-map pass.
        if (doom) doom->bindTables(state);
    };
    // A Doom frame's indices cannot be blended: blended materials are cut out there
    // (pbr.frag), so they are drawn and depth-written as cutouts.
    const SubmitOptions options{.blend = !indexed, .white = &frame.stores.white, .flatNormal = &frame.stores.flatNormal};

    // The frame behind the transmissive surfaces: resolved, with every mip level.
    GraphTexture opaqueFrame;
    if (refract) {
        GraphTextureDesc desc;
        desc.width = frame.width;
        desc.height = frame.height;
        desc.format = gl::Format::RGBA16F;
        desc.levels = gl::Texture::fullMipChain(frame.width, frame.height);
        opaqueFrame = graph.createTexture("opaque frame", desc);
    }

    graph.addPass(
        "forward",
        [&](FrameGraph::Builder& b) {
            readFrameResources(b);
            b.write(targets.color, Use::ColorAttachment);
            b.write(targets.depth, Use::DepthAttachment);
            if (opaqueFrame) b.write(opaqueFrame, Use::ColorAttachment);
        },
        [&frame, &lists, &r, &billboards, targets, indexed, split, opaqueFrame, options, bindFrameResources, multisampled,
         environmentBehind] {
            gl::State& state = frame.state();
            FrameStores& stores = frame.stores;
            const FrameSettings& settings = frame.settings;
            gl::Framebuffer& target = frame.backend.framebuffer({targets.color}, targets.depth);
            state.bindFramebuffer(&target);
            state.viewport(0, 0, frame.width, frame.height);
            // Depth writes must be on for the clear to reach the depth buffer.
            state.apply({});
            if (indexed) {
                target.clearColorUint(0, DoomPass::clearIndex(settings.background), 0, 0, 0);
            } else {
                target.clearColor(0, settings.background.x, settings.background.y, settings.background.z, 1.0f);
            }
            target.clearDepth(1.0f);

            const size_t environmentBytes = stores.environment.buffer().bytesUpdated();
            updateEnvironment(frame);
            frame.stats.environmentBytesUploaded = stores.environment.buffer().bytesUpdated() - environmentBytes;
            bindFrameResources();
            if (!stores.scene) return;
            const GpuScene& scene = *stores.scene;
            frame.stats.triangles += lists.opaque.submit(state, scene, r.materialPrograms, options);
            // A Doom frame's transmissive surfaces are opaque ones there.
            if (indexed) frame.stats.triangles += lists.transmissive.submit(state, scene, r.materialPrograms, options);
            // Cutout billboards belong to the opaque phase: depth-tested and written like surfaces.
            frame.stats.triangles += billboards.drawOpaque(state, frame.height, indexed);
            // The sky after the opaque surfaces (it fills only what they left) and before anything blended.
            r.skybox.draw(frame);
            if (opaqueFrame) {
                // The opaque frame for refraction: resolved into level 0, then its mip chain.
                gl::DebugGroup group("opaque frame");
                gl::Texture& copy = frame.backend.texture(opaqueFrame);
                Impl::CopyProgram& program = r.copyProgram(multisampled, environmentBehind);
                if (program.samples >= 0) program.program.set(program.samples, frame.samples);
                state.bindTexture(SPECULA_UNIT_POST_INPUT_1, frame.backend.texture(targets.depth));
                state.bindSampler(SPECULA_UNIT_POST_INPUT_1, nullptr);
                drawFullscreen(state, {.target = &frame.backend.framebuffer({opaqueFrame}), .width = frame.width,
                                       .height = frame.height, .program = &program.program,
                                       .input = &frame.backend.texture(targets.color), .triangle = &stores.emptyVertexArray});
                copy.generateMipmaps();
            }
            if (split) return; // the rest is the pass "transparent"
            frame.stats.triangles += lists.blended.submit(state, scene, r.materialPrograms, options);
            // Blended billboards after the blended surfaces (sorted apart from them), gizmos last.
            frame.stats.triangles += billboards.drawBlended(state, frame.view, frame.height,
                                                            settings.gizmos ? &stores.lights : nullptr,
                                                            settings.selectedLight, indexed);
        });
    if (!split) return;

    // Weighted blended OIT's targets, as many samples as the frame's.
    GraphTexture accumulation, revealage;
    if (oit) {
        GraphTextureDesc desc = graph.desc(targets.color);
        // 32-bit floats: HDR radiance times weights up to 3 × 10³ overflows half floats.
        desc.format = gl::Format::RGBA32F;
        accumulation = graph.createTexture("oit accumulation", desc);
        desc.format = gl::Format::R16F;
        revealage = graph.createTexture("oit revealage", desc);
    }
    graph.addPass(
        "transparent",
        [&](FrameGraph::Builder& b) {
            readFrameResources(b);
            if (opaqueFrame) b.read(opaqueFrame, Use::Sample);
            if (accumulation) {
                b.write(accumulation, Use::ColorAttachment);
                b.write(revealage, Use::ColorAttachment);
            }
            b.write(targets.color, Use::ColorAttachment);
            b.write(targets.depth, Use::DepthAttachment);
        },
        [&frame, &lists, &r, &billboards, targets, opaqueFrame, accumulation, revealage, options, bindFrameResources, multisampled] {
            gl::State& state = frame.state();
            FrameStores& stores = frame.stores;
            const FrameSettings& settings = frame.settings;
            gl::Framebuffer& target = frame.backend.framebuffer({targets.color}, targets.depth);
            state.bindFramebuffer(&target);
            state.viewport(0, 0, frame.width, frame.height);
            bindFrameResources();
            if (!stores.scene) return;
            const GpuScene& scene = *stores.scene;
            if (opaqueFrame) {
                state.bindTexture(SPECULA_UNIT_TRANSMISSION, frame.backend.texture(opaqueFrame));
                state.bindSampler(SPECULA_UNIT_TRANSMISSION, &r.transmissionSampler);
                frame.stats.triangles += lists.transmissive.submit(state, scene, r.materialPrograms, options);
            }
            if (accumulation) {
                // Accumulate every blended layer in any order, depth-tested against the frame's
                // depth and writing none; then one full-screen composite over the frame.
                gl::Framebuffer& layers = frame.backend.framebuffer({accumulation, revealage}, targets.depth);
                state.bindFramebuffer(&layers);
                layers.clearColor(0, 0.0f, 0.0f, 0.0f, 0.0f);
                layers.clearColor(1, 1.0f, 1.0f, 1.0f, 1.0f);
                SubmitOptions accumulate = options;
                accumulate.blendOutput = BlendOutput::WeightedOit;
                frame.stats.triangles += lists.blended.submit(state, scene, r.materialPrograms, accumulate);
                gl::DebugGroup group("oit composite");
                state.bindTexture(SPECULA_UNIT_POST_INPUT_1, frame.backend.texture(revealage));
                state.bindSampler(SPECULA_UNIT_POST_INPUT_1, nullptr);
                drawFullscreen(state, {.target = &frame.backend.framebuffer({targets.color}), .width = frame.width,
                                       .height = frame.height,
                                       .pipeline = {.noDepthTest = true, .noDepthWrite = true, .blend = gl::BlendMode::PremultipliedAlpha},
                                       .program = &r.compositeProgram(multisampled),
                                       .input = &frame.backend.texture(accumulation), .triangle = &stores.emptyVertexArray});
                state.bindFramebuffer(&target);
            } else {
                frame.stats.triangles += lists.blended.submit(state, scene, r.materialPrograms, options);
            }
            // Blended billboards after the blended surfaces (sorted apart from them), gizmos last.
            frame.stats.triangles += billboards.drawBlended(state, frame.view, frame.height,
                                                            settings.gizmos ? &stores.lights : nullptr,
                                                            settings.selectedLight, false);
        });
}

} // namespace specula::render
