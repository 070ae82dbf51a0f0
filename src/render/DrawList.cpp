#include "render/DrawList.h"

#include <algorithm>
#include <bit>

#include "gl/Program.h"
#include "gl/State.h"
#include "shading/Frustum.h"
#include "render/GpuScene.h"
#include "shaders/shared/Bindings.h"
#include "shaders/shared/MaterialData.h"

namespace specula::render {
namespace {

// An extension's texture slots are bound only for the variant that samples them.
bool sampledByVariant(const MaterialBinding& m, TextureSlot slot)
{
    const auto has = [&](uint64_t bit) { return (m.features & bit) != 0; };
    switch (slot) {
    case TextureSlot::Clearcoat:
    case TextureSlot::ClearcoatRoughness:
    case TextureSlot::ClearcoatNormal: return has(SPECULA_MATERIAL_CLEARCOAT);
    case TextureSlot::SheenColor:
    case TextureSlot::SheenRoughness: return has(SPECULA_MATERIAL_SHEEN);
    case TextureSlot::Anisotropy: return has(SPECULA_MATERIAL_ANISOTROPY);
    case TextureSlot::Iridescence:
    case TextureSlot::IridescenceThickness: return has(SPECULA_MATERIAL_IRIDESCENCE);
    case TextureSlot::Specular:
    case TextureSlot::SpecularColor: return has(SPECULA_MATERIAL_SPECULAR_TEXTURES);
    case TextureSlot::Transmission:
    case TextureSlot::Thickness: return has(SPECULA_MATERIAL_TRANSMISSION_TEXTURES);
    case TextureSlot::DiffuseTransmission:
    case TextureSlot::DiffuseTransmissionColor:
        return has(SPECULA_MATERIAL_DIFFUSE_TRANSMISSION) && has(SPECULA_MATERIAL_DIFFUSE_TRANSMISSION_TEXTURES);
    default: return true;
    }
}

} // namespace

uint32_t DrawList::orderedBits(float value)
{
    if (value == 0.0f) value = 0.0f; // -0 and +0 are equal, as the comparison says
    const uint32_t bits = std::bit_cast<uint32_t>(value);
    // Negative floats order backwards as integers: flip them all; positive ones: set the sign.
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}

bool DrawList::passes(const GpuScene& scene, const DrawItem& item, DrawFilter filter)
{
    if (!item.visible) return false;
    const GpuPrimitive& p = scene.primitives()[size_t(item.primitive)];
    const MaterialBinding& material = scene.materials()[size_t(p.material)];
    const bool blended = material.alphaMode == scene::AlphaMode::Blend;
    const bool transmissive = (material.features & SPECULA_MATERIAL_TRANSMISSION) != 0;
    // A line or a point stops no light (it has no area).
    const bool surface = item.castShadows && p.topology == scene::Topology::Triangles;
    switch (filter) {
    case DrawFilter::Opaque: return !blended && !transmissive;
    case DrawFilter::Blended: return blended && !transmissive;
    case DrawFilter::Transmissive: return transmissive;
    case DrawFilter::ShadowCasters: return surface && castsShadow(material);
    case DrawFilter::ShadowTinters: return surface && tintsShadow(material);
    }
    return false;
}

DrawList DrawList::build(const GpuScene& scene, const glm::mat4& view, const glm::mat4& viewProjection, DrawFilter filter,
                         const std::vector<DrawProgram>& programs, const scene::LodView& lod)
{
    DrawList list;
    list.mFilter = filter;
    const Frustum frustum(viewProjection);
    for (const DrawItem& item : scene.draws()) {
        if (!passes(scene, item, filter)) continue;
        const GpuPrimitive& p = scene.primitives()[size_t(item.primitive)];
        const scene::Bounds world = p.bounds.transformed(item.world);
        if (!frustum.intersects(world)) continue;
        const glm::vec3 center = glm::vec3(item.world * glm::vec4(p.bounds.center(), 1.0f));
        int level = 0;
        if (p.lods.size() > 1) {
            const glm::mat3 linear(item.world);
            const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
            level = scene::selectLod(p.lods, scale, world.center(), world.radius(), lod);
        }
        // View-space z: negative in front of the camera, most negative farthest.
        const float z = (view * glm::vec4(center, 1.0f)).z;
        uint64_t key = 0;
        if (filter == DrawFilter::Blended || filter == DrawFilter::Transmissive) {
            key = orderedBits(z); // back to front
        } else {
            const gl::Program* program = programs[size_t(p.material)].program;
            const uint64_t programBits = program ? program->id() & 0xffffu : 0u;
            key = programBits << 48 | uint64_t(uint32_t(p.material) & 0xffffu) << 32 | orderedBits(-z); // front to back
        }
        list.mCommands.push_back({key, &item, p.material, level});
    }
    std::stable_sort(list.mCommands.begin(), list.mCommands.end(),
                     [](const DrawCommand& a, const DrawCommand& b) { return a.key < b.key; });
    return list;
}

size_t DrawList::submit(gl::State& state, const GpuScene& scene, const std::vector<DrawProgram>& programs,
                        const SubmitOptions& options) const
{
    size_t triangles = 0;
    int boundMaterial = -1;
    const bool blendList = mFilter == DrawFilter::Blended || mFilter == DrawFilter::Transmissive;
    for (const DrawCommand& command : mCommands) {
        const DrawItem& item = *command.item;
        const GpuPrimitive& p = scene.primitives()[size_t(item.primitive)];
        const MaterialBinding& m = scene.materials()[size_t(p.material)];
        const DrawProgram& program = programs[size_t(p.material)];
        if (program.dfg) {
            // Each draw reads the table of its own BRDF variant (docs/ibl.md).
            state.bindTexture(SPECULA_UNIT_DFG, *program.dfg);
            state.bindSampler(SPECULA_UNIT_DFG, nullptr);
        }
        if (program.sheenAlbedo) {
            state.bindTexture(SPECULA_UNIT_SHEEN_ALBEDO, *program.sheenAlbedo);
            state.bindSampler(SPECULA_UNIT_SHEEN_ALBEDO, nullptr);
        }
        state.useProgram(*program.program);
        gl::PipelineDesc pipeline;
        pipeline.cull = m.doubleSided || options.shadowCasters ? gl::CullMode::None : gl::CullMode::Back;
        pipeline.frontFaceClockwise = item.mirrored;
        pipeline.depthBiasSlope = options.depthBiasSlope;
        pipeline.depthBiasConstant = options.depthBiasConstant;
        // A double-sided blended surface "over" the frame: its back faces first, then its front
        // faces (two draws), so that a closed mesh's far side is under its near side.
        bool backFacesFirst = false;
        if (blendList && options.blend && m.alphaMode == scene::AlphaMode::Blend) {
            pipeline.blend = options.blendOutput == BlendOutput::WeightedOit ? gl::BlendMode::WeightedOit
                                                                             : gl::BlendMode::PremultipliedAlpha;
            pipeline.noDepthWrite = true;
            backFacesFirst = m.doubleSided && options.blendOutput == BlendOutput::Premultiplied;
        }
        if (backFacesFirst) pipeline.cull = gl::CullMode::Front;
        if (options.shadowTint) {
            pipeline.blend = gl::BlendMode::ShadowTint;
            pipeline.noDepthTest = pipeline.noDepthWrite = true;
        }
        state.apply(pipeline);
        if (options.textures == MaterialTextures::All) {
            // An extension's slots only for the variant that samples them.
            for (size_t slot = 0; slot < size_t(TextureSlot::Count); ++slot) {
                if (!sampledByVariant(m, TextureSlot(slot))) continue;
                const gl::Texture* texture = m.textures[slot];
                const bool normal = slot == size_t(TextureSlot::Normal) || slot == size_t(TextureSlot::ClearcoatNormal);
                if (!texture) texture = normal ? options.flatNormal : options.white;
                const int unit = textureUnit(TextureSlot(slot));
                state.bindTexture(unit, *texture);
                state.bindSampler(unit, m.samplers[slot]);
            }
        } else {
            const auto bind = [&](TextureSlot slot) {
                if (!m.textures[size_t(slot)]) return;
                state.bindTexture(textureUnit(slot), *m.textures[size_t(slot)]);
                state.bindSampler(textureUnit(slot), m.samplers[size_t(slot)]);
            };
            if (m.features & SPECULA_MATERIAL_ALPHA_MASK) bind(TextureSlot::BaseColor);
            if (transmissionCutout(m)) bind(TextureSlot::Transmission);
        }
        program.program->set(program.model, item.world);
        program.program->set(program.normalMatrix, item.normalMatrix);
        if (program.receiveShadows >= 0) program.program->set(program.receiveShadows, item.receiveShadows ? 1 : 0);
        if (p.material != boundMaterial) {
            gl::bindUniformBufferRange(SPECULA_BINDING_MATERIAL, scene.materialBuffer(), scene.materialOffset(p.material),
                                       sizeof(shared::GpuMaterial));
            boundMaterial = p.material;
        }
        state.bindVertexArray(p.geometry->vertexArray);
        const uint32_t first = p.indexed && !p.lods.empty() ? p.lods[size_t(command.lod)].first : 0u;
        const uint32_t count = p.indexed && !p.lods.empty() ? p.lods[size_t(command.lod)].count : p.count;
        const gl::PrimitiveType type = p.topology == scene::Topology::Lines    ? gl::PrimitiveType::Lines
                                       : p.topology == scene::Topology::Points ? gl::PrimitiveType::Points
                                                                               : gl::PrimitiveType::Triangles;
        state.draw(type, count, p.indexed, first);
        if (backFacesFirst) {
            pipeline.cull = gl::CullMode::Back;
            state.apply(pipeline);
            state.draw(type, count, p.indexed, first);
        }
        if (type == gl::PrimitiveType::Triangles) triangles += count / 3;
    }
    return triangles;
}

} // namespace specula::render
