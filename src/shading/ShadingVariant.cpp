#include "shading/ShadingVariant.h"

#include "shaders/shared/MaterialData.h"

namespace specula::render {
namespace {

constexpr uint32_t kShift = 16;
constexpr uint32_t kBits = 3;
constexpr uint32_t kFieldMask = (1u << kBits) - 1u;

template <typename E>
uint32_t packField(const std::optional<E>& value, int field)
{
    return value ? (uint32_t(*value) + 1u) << (kShift + kBits * uint32_t(field)) : 0u;
}

template <typename E>
std::optional<E> unpackField(uint64_t features, int field)
{
    const uint32_t v = (features >> (kShift + kBits * uint32_t(field))) & kFieldMask;
    if (v == 0) return std::nullopt;
    return E(v - 1u);
}

template <typename E>
E pick(const std::optional<E>& frame, const std::optional<E>& material, E fallback)
{
    return frame ? *frame : material ? *material : fallback;
}

} // namespace

uint32_t packShading(const scene::MaterialShading& s)
{
    return packField(s.model, 0) | packField(s.distribution, 1) | packField(s.geometry, 2) | packField(s.fresnel, 3) |
           packField(s.diffuse, 4);
}

scene::MaterialShading unpackShading(uint64_t features)
{
    scene::MaterialShading s;
    s.model = unpackField<scene::ShadingModel>(features, 0);
    s.distribution = unpackField<scene::BrdfDistribution>(features, 1);
    s.geometry = unpackField<scene::BrdfGeometry>(features, 2);
    s.fresnel = unpackField<scene::BrdfFresnel>(features, 3);
    s.diffuse = unpackField<scene::BrdfDiffuse>(features, 4);
    return s;
}

bool anisotropic(const ResolvedShading& shading)
{
    return shading.model == scene::ShadingModel::Pbr && shading.distribution == scene::BrdfDistribution::GGX;
}

ResolvedShading resolveShading(const scene::MaterialShading& frame, scene::BrdfGeometry defaultGeometry, uint64_t features)
{
    const scene::MaterialShading material = unpackShading(features);
    ResolvedShading r;
    r.model = pick(frame.model, material.model, r.model);
    r.distribution = pick(frame.distribution, material.distribution, r.distribution);
    r.geometry = pick(frame.geometry, material.geometry, defaultGeometry);
    r.fresnel = pick(frame.fresnel, material.fresnel, r.fresnel);
    r.diffuse = pick(frame.diffuse, material.diffuse, r.diffuse);
    // KHR_materials_anisotropy gives its GGX lobe the height-correlated Smith V (anisotropic;
    // isotropic at strength 0): its variant's G is that, so its DFG table integrates the same V.
    if ((features & SPECULA_MATERIAL_ANISOTROPY) && anisotropic(r)) r.geometry = scene::BrdfGeometry::SmithGGXCorrelated;
    return r;
}

} // namespace specula::render
