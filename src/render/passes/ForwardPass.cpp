#include "render/passes/ForwardPass.h"

#include <algorithm>
#include <iterator>
#include <type_traits>

#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "render/FrameContext.h"
#include "render/GpuScene.h"
#include "render/graph/GlGraphBackend.h"
#include "render/passes/BillboardPass.h"
#include "render/passes/DoomPass.h"
#include "render/passes/LightCullPass.h"
#include "render/passes/ShadowPass.h"
#include "shaders/shared/Bindings.h"

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
};

bool iblOn(const FrameContext& frame)
{
    return frame.stores.ibl.hasEnvironment() && frame.settings.environment.lighting;
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
/// rotation and parameters when the settings change, the SH and the bright sources when the environment does.
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
    glm::vec4 brightDirection[SPECULA_IBL_BRIGHT_SOURCES] = {}, brightFlux[SPECULA_IBL_BRIGHT_SOURCES] = {};
    for (size_t i = 0; i < ibl.brightSources().size() && i < SPECULA_IBL_BRIGHT_SOURCES; ++i) {
        brightDirection[i] = glm::vec4(ibl.brightSources()[i].direction, 0.0f);
        brightFlux[i] = glm::vec4(ibl.brightSources()[i].flux, 0.0f);
    }
    setEnvironmentField(environment, &EnvironmentData::brightDirection, brightDirection);
    setEnvironmentField(environment, &EnvironmentData::brightFlux, brightFlux);
    setEnvironmentField(environment, &EnvironmentData::worldToEnvironment,
                        glm::mat4(environmentRotation(-settings.environment.rotationDegrees)));
    setEnvironmentField(environment, &EnvironmentData::inverseViewProjection,
                        glm::inverse(frame.view.projection * frame.view.view));
    const float blur = std::clamp(settings.environment.skyboxBlur, 0.0f, 1.0f);
    setEnvironmentField(environment, &EnvironmentData::params,
                        glm::vec4(settings.environment.intensity, float(ibl.prefiltered().levels()),
                                  blur > 0.0f ? blur * float(ibl.prefiltered().levels() - 1) : -1.0f,
                                  settings.environment.skybox ? 1.0f : 0.0f));
}

} // namespace

struct ForwardPass::Impl {
    std::map<uint64_t, ForwardProgram> programs; // node-based: pointers stay valid
    std::vector<DrawProgram> materialPrograms;   // this frame's, by material
    SkyboxPass skybox;
    ShadowVariant shadows;                       // this frame's SHADOWS variants
    bool allLights = false;                      // this frame's LIGHTS_ALL

    ForwardProgram& program(const FrameContext& frame, uint32_t features)
    {
        const FrameSettings& s = frame.settings;
        const ResolvedShading shading = resolveShading(s.materialOverride, s.brdfGeometry, features);
        const ForwardVariant variant =
            ForwardVariant::make(features, shading, s.debugView, iblVariant(frame), s.energyCompensation, s.ssao.enabled, isDoomFrame(s),
                                 shadows, allLights);
        auto it = programs.find(variant.key);
        if (it != programs.end()) return it->second;
        ForwardProgram p;
        p.program = gl::Program({.vertex = "forward/pbr.vert", .fragment = "forward/pbr.frag", .defines = variant.defines(),
                                 .label = "forward " + variant.name()});
        p.model = p.program.uniformLocation("uModel");
        p.normalMatrix = p.program.uniformLocation("uNormalMatrix");
        p.receiveShadows = p.program.uniformLocation("uReceiveShadows");
        p.shading = shading;
        // Debug views and the classic models return before the split sum (pbr.frag).
        p.readsDfg = shading.model == scene::ShadingModel::Pbr && !variant.debugView() && (iblOn(frame) || s.energyCompensation);
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
        return resolveShading(s.materialOverride, s.brdfGeometry, m.features).model == scene::ShadingModel::Doom;
    });
}

const std::vector<DrawProgram>& ForwardPass::prepareMaterials(const FrameContext& frame, const ShadowVariant& shadows, bool allLights)
{
    Impl& r = *mImpl;
    r.shadows = shadows;
    r.allLights = allLights;
    r.materialPrograms.clear();
    r.skybox.prepare();
    const GpuScene* scene = frame.stores.scene.get();
    if (!scene) return r.materialPrograms;
    for (const MaterialBinding& m : scene->materials()) {
        ForwardProgram& p = r.program(frame, m.features);
        const gl::Texture* dfg = p.readsDfg ? &frame.stores.ibl.dfg(frame.state(), p.shading) : nullptr;
        r.materialPrograms.push_back({&p.program, p.model, p.normalMatrix, dfg, p.receiveShadows});
    }
    return r.materialPrograms;
}

FrameDrawLists ForwardPass::drawLists(const FrameContext& frame) const
{
    FrameDrawLists lists;
    const GpuScene* scene = frame.stores.scene.get();
    if (!scene) return lists;
    const glm::mat4 viewProjection = frame.view.projection * frame.view.view;
    lists.opaque = DrawList::build(*scene, frame.view.view, viewProjection, DrawFilter::Opaque, mImpl->materialPrograms);
    lists.blended = DrawList::build(*scene, frame.view.view, viewProjection, DrawFilter::Blended, mImpl->materialPrograms);
    return lists;
}

void ForwardPass::addTo(FrameGraph& graph, const FrameContext& frame, const FrameDrawLists& lists, const Targets& targets,
                        BillboardPass& billboards, DoomPass* doom, const ShadowPass* shadows, const LightCullPass* culling)
{
    Impl& r = *mImpl;
    const bool indexed = isDoomFrame(frame.settings);
    billboards.prepare(indexed);
    graph.addPass(
        "forward",
        [&](FrameGraph::Builder& b) {
            if (targets.occlusion) b.read(targets.occlusion, Use::Sample);
            if (targets.shadows) b.read(targets.shadows, Use::Sample);
            if (targets.clusters) b.read(targets.clusters, Use::Sample);
            b.write(targets.color, Use::ColorAttachment);
            b.write(targets.depth, Use::DepthAttachment);
        },
        [&frame, &lists, &r, &billboards, doom, shadows, culling, targets, indexed] {
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

            if (targets.occlusion) {
                state.bindTexture(SPECULA_UNIT_SSAO, frame.backend.texture(targets.occlusion));
                state.bindSampler(SPECULA_UNIT_SSAO, nullptr);
            }
            stores.frame.bind(SPECULA_BINDING_FRAME);
            const size_t environmentBytes = stores.environment.buffer().bytesUpdated();
            updateEnvironment(frame);
            frame.stats.environmentBytesUploaded = stores.environment.buffer().bytesUpdated() - environmentBytes;
            if (stores.ibl.hasEnvironment()) {
                state.bindTexture(SPECULA_UNIT_PREFILTERED, stores.ibl.prefiltered());
                state.bindSampler(SPECULA_UNIT_PREFILTERED, nullptr);
                state.bindTexture(SPECULA_UNIT_IRRADIANCE, stores.ibl.irradiance());
                state.bindSampler(SPECULA_UNIT_IRRADIANCE, nullptr);
                // The importance-sampled specular reads the unfiltered cube's box mips (ibl/importance.glsl).
                state.bindTexture(SPECULA_UNIT_ENVIRONMENT_CUBE, stores.ibl.cube());
                state.bindSampler(SPECULA_UNIT_ENVIRONMENT_CUBE, nullptr);
                stores.environment.bind(SPECULA_BINDING_ENVIRONMENT);
            }
            stores.lights.bind(state);
            if (targets.shadows && shadows) shadows->bind(state);
            if (targets.clusters && culling) culling->bind(state);
            // Doom materials look their colours up in the tables, inline or for the colour-map pass.
            if (doom) doom->bindTables(state);
            if (!stores.scene) return;
            const GpuScene& scene = *stores.scene;
            // A Doom frame's indices cannot be blended: blended materials are cut out there
            // (pbr.frag), so they are drawn and depth-written as cutouts.
            const SubmitOptions options{.blend = !indexed, .white = &stores.white, .flatNormal = &stores.flatNormal};
            frame.stats.triangles += lists.opaque.submit(state, scene, r.materialPrograms, options);
            // Cutout billboards belong to the opaque phase: depth-tested and written like surfaces.
            frame.stats.triangles += billboards.drawOpaque(state, frame.height, indexed);
            // The sky after the opaque surfaces (it fills only what they left) and before anything blended.
            r.skybox.draw(frame);
            frame.stats.triangles += lists.blended.submit(state, scene, r.materialPrograms, options);
            // Blended billboards after the blended surfaces (sorted apart from them), gizmos last.
            frame.stats.triangles += billboards.drawBlended(state, frame.view, frame.height,
                                                            settings.gizmos ? &stores.lights : nullptr,
                                                            settings.selectedLight, indexed);
        });
}

} // namespace specula::render
