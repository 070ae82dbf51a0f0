#include "render/passes/BillboardPass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "core/Log.h"
#include "gl/Buffer.h"
#include "gl/Debug.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "shading/Billboard.h"
#include "render/LightBuffer.h"
#include "shaders/shared/BillboardData.h"
#include "shaders/shared/Bindings.h"

namespace specula::render {

static_assert(uint32_t(scene::BillboardKind::PointSprite) == SPECULA_BILLBOARD_POINT_SPRITE);
static_assert(uint32_t(scene::BillboardKind::AxisAligned) == SPECULA_BILLBOARD_AXIS_ALIGNED);
static_assert(uint32_t(scene::BillboardKind::ArbitraryAxis) == SPECULA_BILLBOARD_ARBITRARY_AXIS);

LightGizmos makeLightGizmos(const std::vector<PlacedLight>& lights, const scene::Bounds& sceneBounds, int selected)
{
    LightGizmos gizmos;
    scene::BillboardGroup& discs = gizmos.discs;
    discs.name = "light gizmos";
    discs.kind = scene::BillboardKind::PointSprite;
    discs.size = glm::vec2(kGizmoSizePixels);
    discs.sizeInPixels = true;
    discs.tint = glm::vec3(kGizmoRadiance);
    discs.alphaMode = scene::AlphaMode::Blend;
    discs.sprite = scene::BuiltinSprite::Disc;
    discs.sectorLight = 255; // they mark lights: full bright in Doom frames too
    scene::BillboardGroup& rods = gizmos.rods;
    rods.name = "light gizmo rods";
    rods.kind = scene::BillboardKind::ArbitraryAxis;
    rods.spanAxis = true;
    rods.size = glm::vec2(kGizmoRodPixels, 1.0f);
    rods.sizeInPixels = true;
    rods.anchor = glm::vec2(0.5f, 0.0f); // from the light outwards
    rods.tint = glm::vec3(kGizmoRodRadiance);
    rods.alphaMode = scene::AlphaMode::Blend;
    rods.sprite = scene::BuiltinSprite::Bar;
    rods.sectorLight = 255;

    const glm::vec3 center = sceneBounds.empty() ? glm::vec3(0.0f) : sceneBounds.center();
    const float radius = sceneBounds.empty() ? 1.0f : std::max(sceneBounds.radius(), 1e-3f);
    for (size_t i = 0; i < lights.size(); ++i) {
        const PlacedLight& placed = lights[i];
        if (!placed.visible) continue; // KHR_node_visibility
        const float scale = int(i) == selected ? kGizmoSelectedScale : 1.0f;
        const glm::vec3 color = placed.light.color;
        const float directionLength = glm::length(placed.direction);
        const glm::vec3 direction = directionLength > 0.0f ? placed.direction / directionLength : glm::vec3(0, 0, -1);
        scene::Billboard disc{placed.position, scale, color};
        switch (placed.light.type) {
        case scene::Light::Type::Point: break;
        case scene::Light::Type::Directional:
            disc.position = center - direction * radius;
            rods.billboards.push_back({disc.position, scale, color, direction * radius});
            break;
        case scene::Light::Type::Spot: {
            const float length = placed.light.range > 0.0f ? placed.light.range
                                                           : std::max(glm::distance(placed.position, center), radius);
            // Edges of the cones: unit vectors at the cone angle from the direction, evenly
            // round it, from any basis perpendicular to it.
            const glm::vec3 helper = std::abs(direction.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            const glm::vec3 u = glm::normalize(glm::cross(direction, helper));
            const glm::vec3 v = glm::cross(direction, u);
            auto cone = [&](float angle, int count, float tint) {
                for (int k = 0; k < count; ++k) {
                    const float phi = 2.0f * glm::pi<float>() * float(k) / float(count);
                    const glm::vec3 edge = std::cos(angle) * direction + std::sin(angle) * (std::cos(phi) * u + std::sin(phi) * v);
                    rods.billboards.push_back({placed.position, scale, color * tint, edge * length});
                }
            };
            // Dim rods first: rods of one light are drawn in this order, and a dim rod blended
            // over a bright one would darken it where they cross near the apex.
            cone(placed.light.innerConeAngle, kGizmoInnerConeRods, kGizmoInnerConeTint);
            cone(placed.light.outerConeAngle, kGizmoOuterConeRods, 1.0f);
            rods.billboards.push_back({placed.position, scale, color, direction * length});
            break;
        }
        }
        discs.billboards.push_back(disc);
    }
    return gizmos;
}

namespace {

/// What one draw of a group needs besides its instances.
struct GroupState {
    scene::BillboardKind kind = scene::BillboardKind::PointSprite;
    glm::vec2 size{1.0f};
    glm::vec2 anchor{0.5f};
    bool sizeInPixels = false;
    scene::AlphaMode alphaMode = scene::AlphaMode::Mask;
    float alphaCutoff = 0.5f;
    bool spanAxis = false;
    const gl::Texture* texture = nullptr;
    uint32_t first = 0; ///< Opaque and Mask groups: their range in the static part of the buffer
    uint32_t count = 0;
};

shared::GpuBillboard pack(const scene::BillboardGroup& group, const scene::Billboard& b)
{
    return {glm::vec4(b.position, b.scale), glm::vec4(group.tint * b.tint, float(std::clamp(group.sectorLight, 0, 255)) / 255.0f),
            glm::vec4(b.axis, 0.0f)};
}

} // namespace

struct BillboardPass::Impl {
    /// The program of one output (radiance, or a Doom frame's index and level) and its uniforms.
    struct Variant {
        gl::Program program;
        int uFirstInstance = -1, uKind = -1, uSize = -1, uAnchor = -1, uSizeInPixels = -1, uViewportHeight = -1,
            uAlphaCutoff = -1, uBlend = -1, uSpanAxis = -1;
    };
    std::array<Variant, 2> variants; // [0] radiance, [1] DOOM_INDEXED
    Variant* current = &variants[0];
    gl::VertexArray quad{"billboard quad"}; // vertices come from gl_VertexID; GL core still wants a VAO
    gl::Sampler sampler;
    gl::Sampler nearestSampler; // Doom frames: texels as they are, as Doom drew sprites
    std::array<gl::Texture, 3> builtins; // by scene::BuiltinSprite
    std::map<int, gl::Texture> images;   // by scene image index

    std::vector<GroupState> groups; // one per scene group
    GroupState gizmoDiscs, gizmoRods;
    // Blended billboards stay on the CPU and are sorted every frame into the dynamic part.
    std::vector<shared::GpuBillboard> blended;
    std::vector<uint32_t> blendedGroup;
    scene::Bounds sceneBounds;

    // One storage buffer: [static: Opaque and Mask groups | dynamic: sorted blended + gizmos].
    gl::Buffer instances;
    std::vector<shared::GpuBillboard> staticRecords; // kept to refill a grown buffer
    uint32_t dynamicFirst = 0;
    uint32_t dynamicCapacity = 0;

    /// Makes the dynamic part hold at least `records` (a new buffer, its capacity doubled or
    /// more, when it does not): there is no limit to the lights, so none to their gizmos.
    void reserveDynamic(size_t records)
    {
        if (instances && records <= dynamicCapacity) return;
        dynamicCapacity = uint32_t(std::max(records, 2 * size_t(dynamicCapacity)));
        instances = gl::Buffer((size_t(dynamicFirst) + dynamicCapacity) * sizeof(shared::GpuBillboard), nullptr, "billboards");
        instances.update(0, staticRecords.size() * sizeof(shared::GpuBillboard), staticRecords.data());
    }

    Impl()
    {
        gl::SamplerDesc desc;
        // Clamp: a sprite is one picture, and repeating would bleed the opposite edge into it.
        desc.wrapS = desc.wrapT = gl::Wrap::ClampToEdge;
        sampler = gl::Sampler(desc, "billboard sprite");
        desc.minFilter = desc.magFilter = gl::Filter::Nearest;
        desc.mipFilter = gl::MipFilter::Nearest;
        nearestSampler = gl::Sampler(desc, "billboard sprite (nearest)");
    }

    Variant& ensureProgram(bool doomIndexed)
    {
        Variant& v = variants[doomIndexed ? 1 : 0];
        if (!v.program) {
            std::vector<std::string> defines;
            if (doomIndexed) defines.push_back("DOOM_INDEXED");
            v.program = gl::Program({.vertex = "billboard/billboard.vert", .fragment = "billboard/billboard.frag", .defines = defines,
                                     .label = doomIndexed ? "billboards (doom)" : "billboards"});
            v.uFirstInstance = v.program.uniformLocation("uFirstInstance");
            v.uKind = v.program.uniformLocation("uKind");
            v.uSize = v.program.uniformLocation("uSize");
            v.uAnchor = v.program.uniformLocation("uAnchor");
            v.uSizeInPixels = v.program.uniformLocation("uSizeInPixels");
            v.uViewportHeight = v.program.uniformLocation("uViewportHeight");
            v.uAlphaCutoff = v.program.uniformLocation("uAlphaCutoff");
            v.uBlend = v.program.uniformLocation("uBlend");
            v.uSpanAxis = v.program.uniformLocation("uSpanAxis");
        }
        return v;
    }

    static gl::Texture makeTexture(const scene::Image& image, const std::string& label)
    {
        gl::TextureDesc desc;
        desc.format = gl::Format::SRGB8_ALPHA8; // sprite colours are sRGB like base colour textures
        desc.width = image.width;
        desc.height = image.height;
        desc.levels = 0;
        desc.label = label;
        gl::Texture texture(desc);
        // Top row first, so t = 0 is the image's top (the shader samples at 1 − v).
        texture.upload(0, 0, 4, gl::PixelType::UnsignedByte, image.pixels.data());
        texture.generateMipmaps();
        return texture;
    }

    const gl::Texture* builtin(scene::BuiltinSprite sprite)
    {
        gl::Texture& slot = builtins[size_t(sprite) < builtins.size() ? size_t(sprite) : 0];
        if (!slot) {
            const scene::Image image = makeBuiltinSprite(sprite, 64);
            slot = makeTexture(image, image.name);
        }
        return &slot;
    }

    const gl::Texture* sprite(const scene::Scene& scene, const scene::BillboardGroup& group)
    {
        if (group.image < 0) return builtin(group.sprite);
        if (size_t(group.image) >= scene.images.size()) {
            log::warn("billboard group '{}': image {} does not exist, using the built-in sprite", group.name, group.image);
            return builtin(group.sprite);
        }
        const scene::Image& image = scene.images[size_t(group.image)];
        if (image.width <= 0 || image.height <= 0 || image.pixels.size() < size_t(image.width) * size_t(image.height) * 4) {
            log::warn("billboard group '{}': image '{}' has no pixels, using the built-in sprite", group.name, image.name);
            return builtin(group.sprite);
        }
        auto it = images.find(group.image);
        if (it == images.end())
            it = images.emplace(group.image, makeTexture(image, image.name.empty() ? "billboard image" : image.name)).first;
        return &it->second;
    }

    static GroupState describe(const scene::BillboardGroup& group, const gl::Texture* texture)
    {
        GroupState g;
        g.kind = group.kind;
        g.size = group.size;
        g.anchor = group.anchor;
        g.sizeInPixels = group.sizeInPixels;
        g.alphaMode = group.alphaMode;
        g.alphaCutoff = group.alphaCutoff;
        g.spanAxis = group.spanAxis && group.kind == scene::BillboardKind::ArbitraryAxis;
        g.texture = texture;
        g.count = uint32_t(group.billboards.size());
        return g;
    }

    void setState(gl::State& state, const GroupState& g, int viewportHeight)
    {
        Variant& v = *current;
        state.bindTexture(SPECULA_UNIT_SPRITE, *g.texture);
        state.bindSampler(SPECULA_UNIT_SPRITE, current == &variants[1] ? &nearestSampler : &sampler);
        v.program.set(v.uKind, uint32_t(g.kind));
        v.program.set(v.uSize, g.size);
        v.program.set(v.uAnchor, g.anchor);
        v.program.set(v.uSizeInPixels, int(g.sizeInPixels));
        v.program.set(v.uViewportHeight, float(viewportHeight));
        // Only cutout discards; -1 keeps every texel (alpha is never negative).
        v.program.set(v.uAlphaCutoff, g.alphaMode == scene::AlphaMode::Mask ? g.alphaCutoff : -1.0f);
        v.program.set(v.uBlend, int(g.alphaMode == scene::AlphaMode::Blend));
        v.program.set(v.uSpanAxis, int(g.spanAxis));
    }

    void begin(gl::State& state, bool doomIndexed)
    {
        current = &ensureProgram(doomIndexed);
        state.useProgram(current->program);
        state.bindVertexArray(quad);
        gl::bindStorageBuffer(SPECULA_BINDING_BILLBOARDS, instances);
    }

    /// Sorts `records` (of `groupOf` groups) back to front, uploads them at `offset` in the
    /// dynamic part and draws each run of one group with one call. Returns triangles.
    size_t drawSorted(gl::State& state, const View& view, int viewportHeight, const std::vector<shared::GpuBillboard>& records,
                      const std::vector<const GroupState*>& groupOf, uint32_t offset)
    {
        if (records.empty()) return 0;
        std::vector<uint32_t> order(records.size());
        std::iota(order.begin(), order.end(), 0u);
        std::vector<float> depth(records.size());
        for (size_t i = 0; i < records.size(); ++i) depth[i] = (view.view * glm::vec4(glm::vec3(records[i].positionScale), 1.0f)).z;
        // View-space z is negative in front of the camera: most negative = farthest = first.
        std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return depth[a] < depth[b]; });
        std::vector<shared::GpuBillboard> sorted(records.size());
        for (size_t i = 0; i < order.size(); ++i) sorted[i] = records[order[i]];
        const uint32_t first = dynamicFirst + offset;
        instances.update(size_t(first) * sizeof(shared::GpuBillboard), sorted.size() * sizeof(shared::GpuBillboard), sorted.data());

        size_t triangles = 0;
        for (size_t start = 0; start < order.size();) {
            const GroupState* g = groupOf[order[start]];
            size_t end = start + 1;
            while (end < order.size() && groupOf[order[end]] == g) ++end;
            setState(state, *g, viewportHeight);
            current->program.set(current->uFirstInstance, uint32_t(first + start));
            state.drawTrianglesInstanced(6, uint32_t(end - start));
            triangles += 2 * (end - start);
            start = end;
        }
        return triangles;
    }
};

BillboardPass::BillboardPass() : mImpl(std::make_unique<Impl>()) {}
BillboardPass::~BillboardPass() = default;

void BillboardPass::prepare(bool doomIndexed)
{
    mImpl->ensureProgram(doomIndexed);
}

void BillboardPass::setScene(const scene::Scene& scene)
{
    Impl& p = *mImpl;
    p.groups.clear();
    p.images.clear();
    p.blended.clear();
    p.blendedGroup.clear();
    p.sceneBounds = scene.worldBounds();

    std::vector<shared::GpuBillboard>& staticRecords = p.staticRecords;
    staticRecords.clear();
    for (const scene::BillboardGroup& group : scene.billboards) {
        GroupState g = Impl::describe(group, p.sprite(scene, group));
        if (group.alphaMode == scene::AlphaMode::Blend) {
            for (const scene::Billboard& b : group.billboards) {
                p.blended.push_back(pack(group, b));
                p.blendedGroup.push_back(uint32_t(p.groups.size()));
            }
        } else {
            g.first = uint32_t(staticRecords.size());
            for (const scene::Billboard& b : group.billboards) staticRecords.push_back(pack(group, b));
        }
        p.groups.push_back(g);
    }
    const LightGizmos gizmos = makeLightGizmos({}, {});
    // Their sprites are made when gizmos are first drawn: a frame without them makes none
    // (each texture's mipmaps cost a driver shader compile on llvmpipe).
    p.gizmoDiscs = Impl::describe(gizmos.discs, nullptr);
    p.gizmoRods = Impl::describe(gizmos.rods, nullptr);

    // The dynamic part holds the blended billboards and, separately after them, the gizmos of
    // the scene's lights; drawBlended grows it when lights are added.
    p.dynamicFirst = uint32_t(staticRecords.size());
    p.dynamicCapacity = 0;
    p.instances = {};
    p.reserveDynamic(p.blended.size() + scene.lightInstances().size() * size_t(kGizmoBillboardsPerLight));
    log::debug("billboards: {} groups, {} static and {} blended billboards", p.groups.size(), staticRecords.size(), p.blended.size());
}

size_t BillboardPass::drawOpaque(gl::State& state, int viewportHeight, bool doomIndexed)
{
    Impl& p = *mImpl;
    const bool any = std::any_of(p.groups.begin(), p.groups.end(),
                                 [](const GroupState& g) { return g.alphaMode != scene::AlphaMode::Blend && g.count > 0; });
    if (!any) return 0;
    gl::DebugGroup debugGroup("billboards (opaque)");
    p.begin(state, doomIndexed);
    // No culling: a sprite seen from behind (an arbitrary-axis one, or past the pole) still shows.
    state.apply({.cull = gl::CullMode::None});
    size_t triangles = 0;
    for (const GroupState& g : p.groups) {
        if (g.alphaMode == scene::AlphaMode::Blend || g.count == 0) continue;
        p.setState(state, g, viewportHeight);
        p.current->program.set(p.current->uFirstInstance, g.first);
        state.drawTrianglesInstanced(6, g.count);
        triangles += 2 * size_t(g.count);
    }
    return triangles;
}

size_t BillboardPass::drawBlended(gl::State& state, const View& view, int viewportHeight, const LightBuffer* gizmoLights,
                                  int selectedLight, bool doomIndexed)
{
    Impl& p = *mImpl;
    const bool gizmos = gizmoLights && gizmoLights->count() > 0;
    if (!p.instances || (p.blended.empty() && !gizmos)) return 0; // no scene yet, or nothing to draw
    LightGizmos made;
    if (gizmos) {
        made = makeLightGizmos(gizmoLights->all(), p.sceneBounds, selectedLight);
        if (!p.gizmoDiscs.texture) p.gizmoDiscs.texture = p.builtin(made.discs.sprite);
        if (!p.gizmoRods.texture) p.gizmoRods.texture = p.builtin(made.rods.sprite);
        p.reserveDynamic(p.blended.size() + made.rods.billboards.size() + made.discs.billboards.size()); // before begin() binds it
    }
    gl::DebugGroup debugGroup("billboards (blended)");
    p.begin(state, doomIndexed);
    // A Doom frame's indices cannot be blended: the shader cuts these out at half coverage,
    // so they are drawn, and depth-written, as cutouts.
    const gl::BlendMode blend = doomIndexed ? gl::BlendMode::None : gl::BlendMode::Alpha;
    size_t triangles = 0;
    if (!p.blended.empty()) {
        std::vector<const GroupState*> groupOf(p.blended.size());
        for (size_t i = 0; i < groupOf.size(); ++i) groupOf[i] = &p.groups[p.blendedGroup[i]];
        state.apply({.noDepthWrite = !doomIndexed, .cull = gl::CullMode::None, .blend = blend});
        triangles += p.drawSorted(state, view, viewportHeight, p.blended, groupOf, 0);
    }
    if (gizmos) {
        // Gizmos mark where lights are, so they show through walls and lamp shades: no depth
        // test. Rods first, so that every disc sits on top of the rods leaving it.
        state.apply({.noDepthTest = true, .noDepthWrite = true, .cull = gl::CullMode::None, .blend = blend});
        uint32_t offset = uint32_t(p.blended.size());
        for (const auto& [group, groupState] : {std::pair{&made.rods, &p.gizmoRods}, std::pair{&made.discs, &p.gizmoDiscs}}) {
            std::vector<shared::GpuBillboard> records;
            for (const scene::Billboard& b : group->billboards) records.push_back(pack(*group, b));
            const std::vector<const GroupState*> groupOf(records.size(), groupState);
            triangles += p.drawSorted(state, view, viewportHeight, records, groupOf, offset);
            offset += uint32_t(records.size());
        }
    }
    return triangles;
}

} // namespace specula::render
