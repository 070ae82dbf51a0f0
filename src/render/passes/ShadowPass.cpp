#include "render/passes/ShadowPass.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "core/Hash.h"
#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "render/DrawList.h"
#include "render/FrameContext.h"
#include "render/GpuScene.h"
#include "render/graph/GlGraphBackend.h"
#include "shading/ShadowMaps.h"
#include "shaders/shared/Bindings.h"
#include "shaders/shared/MaterialData.h"
#include "shaders/shared/ShadowData.h"

namespace specula::render {
namespace {

struct QualityParams {
    int atlas;   ///< atlas size, texels
    int cascade; ///< a cascade's tile
    int maxTile; ///< a spot light's or a cube face's largest tile
    int minTile;
    int tent;    ///< the PCF filter's tent, texels across (lights/shadow.glsl: 3 or 5)
    int taps;    ///< PCSS's disc taps (16 or 32)
};

QualityParams qualityParams(ShadowQuality quality)
{
    switch (quality) {
    case ShadowQuality::Low: return {2048, 512, 512, 32, 3, 16};
    case ShadowQuality::Medium: return {4096, 1024, 1024, 64, 3, 16};
    case ShadowQuality::High: return {8192, 2048, 2048, 64, 5, 32};
    }
    return {4096, 1024, 1024, 64, 3, 16};
}

int filterId(ShadowFilter filter)
{
    switch (filter) {
    case ShadowFilter::Hard: return SPECULA_SHADOW_FILTER_HARD;
    case ShadowFilter::Pcf: return SPECULA_SHADOW_FILTER_PCF;
    case ShadowFilter::Pcss: return SPECULA_SHADOW_FILTER_PCSS;
    }
    return SPECULA_SHADOW_FILTER_PCF;
}

// Where a light with no range still matters: where a surface facing it would receive less
// than 1e-3 lux (a moonless night sky gives 1e-3 to 1e-4). Beyond, its map would cover
// nothing visible. Only for the map's far plane and the light's importance, not its shading.
constexpr float kIlluminanceCutoff = 1e-3f;

float reach(const scene::Light& light, const scene::Bounds& scene, const glm::vec3& position)
{
    float far = light.range > 0.0f ? light.range : std::sqrt(std::max(light.intensity, 0.0f) / kIlluminanceCutoff);
    // Never past the scene's farthest corner: nothing there to cast or receive.
    if (!scene.empty()) {
        float farthest = 0.0f;
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 p((i & 1) ? scene.max.x : scene.min.x, (i & 2) ? scene.max.y : scene.min.y,
                              (i & 4) ? scene.max.z : scene.min.z);
            farthest = std::max(farthest, glm::length(p - position));
        }
        far = std::min(far, farthest * 1.01f + 0.01f);
    }
    return std::max(far, 0.1f);
}

// The depth-only program of a material's cut-out features.
struct CasterProgram {
    gl::Program program;
    int model = -1, normalMatrix = -1, viewProjection = -1;
};

struct PlannedView {
    ShadowView view;
    int kind = SPECULA_SHADOW_SPOT;
    uint64_t key = 0;
    bool render = false;
};

struct PlannedLight {
    int light = 0;
    int kind = SPECULA_SHADOW_SPOT;
    float size = 0.0f;
    std::vector<float> splits;
    std::vector<PlannedView> views;
};

using TileKey = std::tuple<int, int, int>;

template <typename T>
void appendBytes(std::string& bytes, const T& value)
{
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// The tint map's size: the atlas's up to 4096² (128 MiB of RGBA16F), half of it above (the
// high quality's 8192² atlas).
int tintSize(int atlasSize)
{
    return atlasSize > 4096 ? atlasSize / 2 : atlasSize;
}

// A program of the shadow pass (shadow/shadow_depth.frag with `defines`): the forward vertex
// shader, projecting into the light's view.
CasterProgram makeCasterProgram(const std::vector<std::string>& defines, const char* label)
{
    CasterProgram p;
    p.program = gl::Program({.vertex = "forward/pbr.vert", .fragment = "shadow/shadow_depth.frag", .defines = defines, .label = label});
    p.model = p.program.uniformLocation("uModel");
    p.normalMatrix = p.program.uniformLocation("uNormalMatrix");
    p.viewProjection = p.program.uniformLocation("uShadowViewProjection");
    return p;
}

bool overlaps(const AtlasTile& a, const AtlasTile& b)
{
    return a.x < b.x + b.size && b.x < a.x + a.size && a.y < b.y + b.size && b.y < a.y + a.size;
}

} // namespace

struct ShadowPass::Impl {
    gl::Texture atlas;
    gl::Framebuffer framebuffer;
    gl::Sampler compare{{.minFilter = gl::Filter::Linear, .magFilter = gl::Filter::Linear, .mipFilter = gl::MipFilter::None,
                         .wrapS = gl::Wrap::ClampToEdge, .wrapT = gl::Wrap::ClampToEdge, .compareDepth = true},
                        "shadow compare"};
    gl::Sampler raw{{.minFilter = gl::Filter::Nearest, .magFilter = gl::Filter::Nearest, .mipFilter = gl::MipFilter::None,
                     .wrapS = gl::Wrap::ClampToEdge, .wrapT = gl::Wrap::ClampToEdge},
                    "shadow depth"};
    gl::Buffer recordBuffer;
    gl::Texture recordTexels;
    uint32_t retiredRecords = 0;
    std::vector<glm::vec4> uploaded; ///< the records' texels as last uploaded
    std::map<uint64_t, CasterProgram> programs;
    std::vector<DrawProgram> drawPrograms; ///< by material
    std::map<TileKey, uint64_t> tileContents; ///< what each tile of the atlas holds now
    std::vector<PlannedLight> planned;
    /// The tint map (lights/shadow.glsl), at the atlas's resolution up to 4096² (tintSize), its
    /// tiles where the atlas's are: rgb what the surfaces over a texel let through, alpha the nearest one's
    /// depth. Made when a scene first has such a surface (render::tintsShadow).
    gl::Texture tint;
    gl::Framebuffer tintFramebuffer;
    std::map<uint64_t, CasterProgram> tintPrograms;
    std::vector<DrawProgram> tintDrawPrograms; ///< by material
    bool tinted = false;                       ///< this frame draws the tint map
    ShadowVariant variant; // of the last addTo: no kind when no light has a map

    CasterProgram& casterProgram(const MaterialBinding& m)
    {
        const uint64_t features = m.features;
        uint64_t key = 0;
        std::vector<std::string> defines{"SHADOW_PASS"};
        if (features & SPECULA_MATERIAL_ALPHA_MASK) {
            key = features & (SPECULA_MATERIAL_ALPHA_MASK | SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE | SPECULA_MATERIAL_USE_VERTEX_COLOR);
            defines.push_back("ALPHA_MASK");
            if (features & SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE) defines.push_back("HAS_BASE_COLOR_TEXTURE");
            if (features & SPECULA_MATERIAL_USE_VERTEX_COLOR) defines.push_back("VERTEX_COLOR");
        }
        if (transmissionCutout(m)) {
            key |= uint64_t(1) << 63; // above every feature bit
            defines.push_back("TRANSMISSION_CUTOUT");
        }
        CasterProgram& p = programs[key];
        if (!p.program) p = makeCasterProgram(defines, "shadow caster");
        return p;
    }

    CasterProgram& tintProgram(const MaterialBinding& m)
    {
        const uint64_t features = m.features;
        const bool blended = m.declaredAlphaMode == scene::AlphaMode::Blend;
        const uint64_t key = (features & (SPECULA_MATERIAL_ALPHA_MASK | SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE | SPECULA_MATERIAL_USE_VERTEX_COLOR |
                                          SPECULA_MATERIAL_TRANSMISSION | SPECULA_MATERIAL_TRANSMISSION_TEXTURES)) |
                             (blended ? uint64_t(1) << 63 : 0u);
        CasterProgram& p = tintPrograms[key];
        if (!p.program) {
            std::vector<std::string> defines{"SHADOW_PASS", "SHADOW_TINT"};
            if (features & SPECULA_MATERIAL_ALPHA_MASK) defines.push_back("ALPHA_MASK");
            if (blended) defines.push_back("ALPHA_BLEND");
            if (features & SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE) defines.push_back("HAS_BASE_COLOR_TEXTURE");
            if (features & SPECULA_MATERIAL_USE_VERTEX_COLOR) defines.push_back("VERTEX_COLOR");
            if (features & SPECULA_MATERIAL_TRANSMISSION) defines.push_back("TRANSMISSION");
            if (features & SPECULA_MATERIAL_TRANSMISSION_TEXTURES) defines.push_back("TRANSMISSION_TEXTURES");
            p = makeCasterProgram(defines, "shadow tint");
        }
        return p;
    }

    void ensureTint(gl::State& state, int atlasSize)
    {
        const int size = tintSize(atlasSize);
        if (tint && tint.width() == size) return;
        tint = gl::Texture({.format = gl::Format::RGBA16F, .width = size, .height = size, .label = "shadow tint"});
        tintFramebuffer = gl::Framebuffer("shadow tint");
        tintFramebuffer.attachColor(0, tint);
        tintFramebuffer.check();
        state.noScissor();
        state.apply({});
        tintFramebuffer.clearColor(0, 1.0f, 1.0f, 1.0f, 1.0f); // nothing over any texel
    }

    void ensureAtlas(gl::State& state, int size)
    {
        if (atlas && atlas.width() == size) return;
        atlas = gl::Texture({.format = gl::Format::Depth32F, .width = size, .height = size, .label = "shadow atlas"});
        framebuffer = gl::Framebuffer("shadow atlas");
        framebuffer.attachDepth(atlas);
        framebuffer.check();
        // The far plane everywhere, so that a tile never drawn (the shadow-atlas view shows
        // them) reads as empty rather than as a caster at the near plane.
        state.noScissor();
        state.apply({}); // depth writes on for the clear
        framebuffer.clearDepth(1.0f);
        tileContents.clear();
    }

    void uploadRecords(gl::State& state, const std::vector<glm::vec4>& texels)
    {
        if (texels == uploaded && recordBuffer) return;
        const size_t bytes = std::max<size_t>(texels.size(), 1) * sizeof(glm::vec4);
        if (!recordBuffer || recordBuffer.size() < bytes) {
            size_t capacity = recordBuffer ? recordBuffer.size() : 64 * SPECULA_SHADOW_RECORD_TEXELS * sizeof(glm::vec4);
            while (capacity < bytes) capacity *= 2;
            if (recordTexels) retiredRecords = recordTexels.id();
            recordTexels = {};
            const std::vector<std::byte> zeros(capacity);
            recordBuffer = gl::Buffer(capacity, zeros.data(), "shadow records");
            recordTexels = gl::Texture(recordBuffer, gl::Format::RGBA32F, "shadow records");
            if (retiredRecords) state.forgetTexture(std::exchange(retiredRecords, 0u));
        }
        if (!texels.empty()) recordBuffer.update(0, texels.size() * sizeof(glm::vec4), texels.data());
        uploaded = texels;
    }

    void renderView(const FrameContext& frame, const PlannedView& v, const ShadowSettings& s)
    {
        gl::State& state = frame.state();
        const GpuScene& scene = *frame.stores.scene;
        const AtlasTile& t = v.view.tile;
        state.bindFramebuffer(&framebuffer);
        state.viewport(t.x, t.y, t.size, t.size);
        state.scissor(t.x, t.y, t.size, t.size);
        state.apply({}); // depth writes on for the clear
        framebuffer.clearDepth(1.0f);
        for (auto& [key, p] : programs) p.program.set(p.viewProjection, v.view.viewProjection);
        const DrawList casters = DrawList::build(scene, v.view.viewProjection, v.view.viewProjection, DrawFilter::ShadowCasters,
                                                 drawPrograms);
        frame.stats.triangles += casters.submit(state, scene, drawPrograms,
                                                {.textures = MaterialTextures::Cutouts,
                                                 .shadowCasters = true,
                                                 .depthBiasSlope = s.slopeBias,
                                                 .depthBiasConstant = s.constantBias});
        state.noScissor();
    }

    /// The tint map's tile of a view: cleared to "nothing over it", then every surface that
    /// lets light through, blended (rgb multiplied, alpha the nearest depth), none hidden.
    /// Called for a pass's views after their depth (one change of target each way: on a CPU
    /// rasteriser each change ends a batch of work, whose memory waits for it).
    void renderTint(const FrameContext& frame, const PlannedView& v)
    {
        gl::State& state = frame.state();
        const GpuScene& scene = *frame.stores.scene;
        const AtlasTile& t = v.view.tile;
        state.bindFramebuffer(&tintFramebuffer);
        const int shift = tint.width() < atlas.width() ? 1 : 0; // the tint map's texels to the atlas's
        state.viewport(t.x >> shift, t.y >> shift, t.size >> shift, t.size >> shift);
        state.scissor(t.x >> shift, t.y >> shift, t.size >> shift, t.size >> shift);
        tintFramebuffer.clearColor(0, 1.0f, 1.0f, 1.0f, 1.0f);
        for (auto& [key, p] : tintPrograms) p.program.set(p.viewProjection, v.view.viewProjection);
        const DrawList tinters = DrawList::build(scene, v.view.viewProjection, v.view.viewProjection, DrawFilter::ShadowTinters,
                                                 tintDrawPrograms);
        frame.stats.triangles += tinters.submit(state, scene, tintDrawPrograms,
                                                {.white = &frame.stores.white,
                                                 .flatNormal = &frame.stores.flatNormal,
                                                 .shadowCasters = true,
                                                 .shadowTint = true});
        state.noScissor();
    }

    /// A tile now holds `key`; what overlapping tiles held is gone (tiles of one frame never
    /// overlap, so this only forgets earlier frames' layouts). Called as the view is drawn, not
    /// when it is planned: a frame built and not run (Renderer::prepare) draws nothing.
    void remember(const AtlasTile& t, uint64_t key)
    {
        for (auto c = tileContents.begin(); c != tileContents.end();) {
            const AtlasTile held{std::get<0>(c->first), std::get<1>(c->first), std::get<2>(c->first)};
            c = overlaps(held, t) ? tileContents.erase(c) : std::next(c);
        }
        tileContents[{t.x, t.y, t.size}] = key;
    }

    void clearSlots(LightBuffer& lights)
    {
        for (int i = 0; i < lights.count(); ++i) lights.setShadowSlot(i, -1);
    }
};

ShadowPass::ShadowPass() : mImpl(std::make_unique<Impl>()) {}
ShadowPass::~ShadowPass() = default;

const ShadowVariant& ShadowPass::variant() const
{
    return mImpl->variant;
}

const gl::Texture* ShadowPass::atlas() const
{
    return mImpl->atlas ? &mImpl->atlas : nullptr;
}

void ShadowPass::bind(gl::State& state) const
{
    const Impl& r = *mImpl;
    if (!r.variant.active()) return;
    state.bindTexture(SPECULA_UNIT_SHADOW_ATLAS, r.atlas);
    state.bindSampler(SPECULA_UNIT_SHADOW_ATLAS, &r.compare);
    state.bindTexture(SPECULA_UNIT_SHADOW_DEPTH, r.atlas);
    state.bindSampler(SPECULA_UNIT_SHADOW_DEPTH, &r.raw);
    state.bindTexture(SPECULA_UNIT_SHADOW_RECORDS, r.recordTexels);
    state.bindSampler(SPECULA_UNIT_SHADOW_RECORDS, nullptr);
    if (r.variant.tint) {
        state.bindTexture(SPECULA_UNIT_SHADOW_TINT, r.tint);
        state.bindSampler(SPECULA_UNIT_SHADOW_TINT, nullptr); // read by texelFetch
    }
}

GraphTexture ShadowPass::addTo(FrameGraph& graph, const FrameContext& frame)
{
    Impl& r = *mImpl;
    const ShadowSettings& s = frame.settings.shadows;
    LightBuffer& lights = frame.stores.lights;
    FrameStats::Shadows& stats = frame.stats.shadows;
    r.variant = {};
    r.planned.clear();
    const GpuScene* scene = frame.stores.scene.get();
    if (!s.enabled || isDoomFrame(frame.settings) || !scene || lights.count() == 0) {
        r.clearSlots(lights);
        return {};
    }
    const QualityParams q = qualityParams(s.quality);
    const scene::Bounds& sceneBounds = scene->bounds();
    const scene::Bounds& casterBounds = scene->casterBounds();

    // Who asks for a map, and how much it matters on screen.
    std::vector<ShadowCandidate> candidates;
    for (int i = 0; i < lights.count(); ++i) {
        const PlacedLight& placed = lights.light(i);
        const scene::Light& l = placed.light;
        if (!l.castShadows || l.intensity <= 0.0f || !placed.visible || casterBounds.empty()) continue;
        float importance = 1.0f;
        if (l.type != scene::Light::Type::Directional)
            importance = screenImportance(placed.position, reach(l, sceneBounds, placed.position), frame.view.view,
                                          frame.view.projection);
        if (importance > 0.0f) candidates.push_back({i, l.type, importance});
    }
    std::vector<int> dropped;
    const std::vector<ShadowCandidate> chosen = chooseShadowed(candidates, s.maxLights, s.maxDirectional, &dropped);

    stats.dropped = int(dropped.size());
    if (chosen.empty()) { // no light casts: no atlas is made (a 64 MiB clear at high quality)
        r.clearSlots(lights);
        return {};
    }

    // Tiles: cascades first (they cover the whole view), then by importance, halving a
    // light's tiles until they fit.
    r.ensureAtlas(frame.state(), q.atlas);
    // Whether any surface that may cast lets light through.
    r.tinted = s.tint && std::any_of(scene->draws().begin(), scene->draws().end(), [scene](const DrawItem& item) {
                   return DrawList::passes(*scene, item, DrawFilter::ShadowTinters);
               });
    if (r.tinted) r.ensureTint(frame.state(), q.atlas);
    ShadowAtlas atlas(q.atlas, q.minTile);
    // The camera's near and far planes (an infinite far plane: 1e30).
    const glm::mat4& P = frame.view.projection;
    float cameraNear = 0.0f, cameraFar = 0.0f;
    if (P[2][3] == 0.0f) { // orthographic
        cameraNear = (P[3][2] + 1.0f) / P[2][2];
        cameraFar = (P[3][2] - 1.0f) / P[2][2];
    } else {
        cameraNear = P[3][2] / (P[2][2] - 1.0f);
        cameraFar = P[2][2] != -1.0f ? P[3][2] / (P[2][2] + 1.0f) : 1e30f;
    }
    cameraNear = std::max(cameraNear, 1e-3f);
    for (const ShadowCandidate& c : chosen) {
        const PlacedLight& placed = lights.light(c.light);
        const scene::Light& l = placed.light;
        PlannedLight light;
        light.light = c.light;
        const int views = l.type == scene::Light::Type::Directional ? s.cascades : l.type == scene::Light::Type::Point ? 6 : 1;
        int size = l.type == scene::Light::Type::Directional ? q.cascade : tileSizeFor(c.importance, q.maxTile, q.minTile);
        std::vector<AtlasTile> tiles;
        for (; size >= q.minTile && int(tiles.size()) < views; size /= 2) {
            ShadowAtlas trial = atlas;
            tiles.clear();
            for (int v = 0; v < views; ++v) {
                const auto tile = trial.allocate(size);
                if (!tile) break;
                tiles.push_back(*tile);
            }
            if (int(tiles.size()) == views) atlas = trial;
        }
        if (int(tiles.size()) < views) {
            dropped.push_back(c.light);
            continue;
        }
        const int tileSize = tiles[0].size;
        std::vector<ShadowView> shadowViews;
        if (l.type == scene::Light::Type::Directional) {
            light.kind = SPECULA_SHADOW_DIRECTIONAL;
            light.size = std::tan(0.5f * l.angularDiameter * s.lightSize);
            // The cascades reach the shadow distance, else the far plane or the scene's far
            // side along the view, whichever is nearer.
            float far = cameraFar;
            if (!sceneBounds.empty()) {
                float farthest = 0.0f;
                const glm::mat4& view = frame.view.view;
                for (int i = 0; i < 8; ++i) {
                    const glm::vec3 p((i & 1) ? sceneBounds.max.x : sceneBounds.min.x, (i & 2) ? sceneBounds.max.y : sceneBounds.min.y,
                                      (i & 4) ? sceneBounds.max.z : sceneBounds.min.z);
                    farthest = std::max(farthest, -(view * glm::vec4(p, 1.0f)).z);
                }
                far = std::min(far, farthest);
            }
            if (s.distance > 0.0f) far = s.distance;
            far = std::max(far, cameraNear * 2.0f);
            light.splits = cascadeSplits(cameraNear, far, views, s.cascadeSplit);
            float sliceNear = cameraNear;
            for (int v = 0; v < views; ++v) {
                shadowViews.push_back(cascadeView(frame.view.view, frame.view.projection, sliceNear, light.splits[size_t(v)],
                                                  placed.direction, casterBounds, tileSize));
                sliceNear = light.splits[size_t(v)];
            }
        } else if (l.type == scene::Light::Type::Spot) {
            light.kind = SPECULA_SHADOW_SPOT;
            light.size = l.radius * s.lightSize;
            shadowViews.push_back(spotView(placed.position, placed.direction, l.outerConeAngle,
                                           reach(l, sceneBounds, placed.position), tileSize));
        } else {
            light.kind = SPECULA_SHADOW_POINT;
            light.size = l.radius * s.lightSize;
            shadowViews = pointViews(placed.position, reach(l, sceneBounds, placed.position), tileSize);
        }
        for (size_t v = 0; v < shadowViews.size(); ++v) {
            PlannedView pv;
            pv.view = shadowViews[v];
            pv.view.tile = tiles[v];
            pv.view.worldToAtlas = clipToAtlas(tiles[v], q.atlas) * pv.view.viewProjection;
            pv.kind = light.kind;
            // What the tile will hold: the view, the tile, the casters, the raster bias.
            std::string bytes;
            appendBytes(bytes, pv.view.viewProjection);
            appendBytes(bytes, pv.view.tile);
            appendBytes(bytes, frame.stores.casterVersion);
            appendBytes(bytes, s.slopeBias);
            appendBytes(bytes, s.constantBias);
            appendBytes(bytes, r.tinted);
            const uint64_t key = fnv1a64(bytes);
            pv.key = key;
            light.views.push_back(pv);
        }
        r.planned.push_back(std::move(light));
    }

    // Which tiles must be drawn again; a drawn tile spoils what overlapping tiles held.
    int rendered = 0, views = 0;
    for (PlannedLight& light : r.planned) {
        for (PlannedView& v : light.views) {
            ++views;
            const TileKey tile{v.view.tile.x, v.view.tile.y, v.view.tile.size};
            const auto it = r.tileContents.find(tile);
            v.render = !s.cache || it == r.tileContents.end() || it->second != v.key;
            if (v.render) ++rendered;
        }
    }

    // Records and slots.
    std::vector<glm::vec4> texels(r.planned.size() * SPECULA_SHADOW_RECORD_TEXELS, glm::vec4(0.0f));
    std::vector<int> slots(size_t(lights.count()), -1);
    const float blend = s.cascadeBlend;
    for (size_t slot = 0; slot < r.planned.size(); ++slot) {
        const PlannedLight& light = r.planned[slot];
        glm::vec4* t = texels.data() + slot * SPECULA_SHADOW_RECORD_TEXELS;
        // A directional light's texel 0 w is the cascade blend; a spot or point light's, its
        // views' near plane (one for all six faces), so that the lookup reads no more texels.
        const bool directional = light.kind == SPECULA_SHADOW_DIRECTIONAL;
        t[0] = glm::vec4(float(light.kind), float(light.views.size()), s.normalBias,
                         directional ? blend : light.views.front().view.near);
        for (size_t c = 0; c < light.splits.size() && c < 4; ++c) t[1][int(c)] = light.splits[c];
        t[2] = glm::vec4(light.size, 0.0f, 0.0f, 0.0f);
        for (size_t v = 0; v < light.views.size(); ++v) {
            const ShadowView& view = light.views[v].view;
            glm::vec4* w = t + 3 + v * SPECULA_SHADOW_VIEW_TEXELS;
            const glm::mat4 rows = glm::transpose(view.worldToAtlas);
            for (int c = 0; c < 4; ++c) w[c] = rows[c];
            const float inv = 1.0f / float(q.atlas);
            w[4] = glm::vec4(float(view.tile.x) * inv, float(view.tile.y) * inv, float(view.tile.size) * inv, view.texelWorld);
            w[5] = glm::vec4(view.near, view.far, view.orthographic ? 1.0f : 0.0f, 0.0f);
        }
        slots[size_t(light.light)] = int(slot);
    }
    for (int i = 0; i < lights.count(); ++i) lights.setShadowSlot(i, slots[size_t(i)]);
    r.uploadRecords(frame.state(), texels);

    stats.lights = int(r.planned.size());
    stats.views = views;
    stats.rendered = rendered;
    stats.cached = views - rendered;
    stats.atlasSize = q.atlas;
    if (r.planned.empty()) return {};
    r.variant = {.filter = filterId(s.filter), .taps = q.taps, .tent = q.tent, .tint = r.tinted};
    for (const PlannedLight& light : r.planned) {
        r.variant.directional |= light.kind == SPECULA_SHADOW_DIRECTIONAL;
        r.variant.spot |= light.kind == SPECULA_SHADOW_SPOT;
        r.variant.point |= light.kind == SPECULA_SHADOW_POINT;
    }

    // The casters' programs, by material.
    r.drawPrograms.clear();
    for (const MaterialBinding& m : scene->materials()) {
        if (!castsShadow(m)) { // blended and mostly transmissive surfaces (GpuScene.h)
            r.drawPrograms.push_back({});
            continue;
        }
        CasterProgram& p = r.casterProgram(m);
        r.drawPrograms.push_back({&p.program, p.model, p.normalMatrix, nullptr});
    }
    r.tintDrawPrograms.clear();
    for (const MaterialBinding& m : scene->materials()) {
        if (!r.tinted || !tintsShadow(m)) {
            r.tintDrawPrograms.push_back({});
            continue;
        }
        CasterProgram& p = r.tintProgram(m);
        r.tintDrawPrograms.push_back({&p.program, p.model, p.normalMatrix, nullptr});
    }

    GraphTextureDesc desc;
    desc.format = gl::Format::Depth32F;
    desc.width = desc.height = q.atlas;
    const GraphTexture atlasHandle = graph.importTexture("shadow atlas", desc, frame.backend.importTexture(r.atlas));
    static constexpr std::pair<int, const char*> kPasses[] = {{SPECULA_SHADOW_DIRECTIONAL, "shadows: cascades"},
                                                              {SPECULA_SHADOW_SPOT, "shadows: spot"},
                                                              {SPECULA_SHADOW_POINT, "shadows: point"}};
    for (const auto& pass : kPasses) {
        const int kind = pass.first; // not a structured binding: clang 14 cannot capture one
        const char* name = pass.second;
        const bool any = std::any_of(r.planned.begin(), r.planned.end(), [kind](const PlannedLight& l) {
            return l.kind == kind && std::any_of(l.views.begin(), l.views.end(), [](const PlannedView& v) { return v.render; });
        });
        if (!any) continue;
        graph.addPass(
            name, [&](FrameGraph::Builder& b) { b.write(atlasHandle, Use::DepthAttachment); },
            [&r, &frame, kind, s] {
                frame.stores.frame.bind(SPECULA_BINDING_FRAME);
                for (const PlannedLight& light : r.planned)
                    if (light.kind == kind)
                        for (const PlannedView& v : light.views)
                            if (v.render) {
                                r.renderView(frame, v, s);
                                r.remember(v.view.tile, v.key);
                            }
                if (r.tinted)
                    for (const PlannedLight& light : r.planned)
                        if (light.kind == kind)
                            for (const PlannedView& v : light.views)
                                if (v.render) r.renderTint(frame, v);
            });
    }
    return atlasHandle;
}

} // namespace specula::render
