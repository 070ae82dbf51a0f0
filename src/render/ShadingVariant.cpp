#include "render/ShadingVariant.h"

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
std::optional<E> unpackField(uint32_t features, int field)
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

scene::MaterialShading unpackShading(uint32_t features)
{
    scene::MaterialShading s;
    s.model = unpackField<scene::ShadingModel>(features, 0);
    s.distribution = unpackField<scene::BrdfDistribution>(features, 1);
    s.geometry = unpackField<scene::BrdfGeometry>(features, 2);
    s.fresnel = unpackField<scene::BrdfFresnel>(features, 3);
    s.diffuse = unpackField<scene::BrdfDiffuse>(features, 4);
    return s;
}

ResolvedShading resolveShading(const scene::MaterialShading& frame, scene::BrdfGeometry defaultGeometry, uint32_t features)
{
    const scene::MaterialShading material = unpackShading(features);
    ResolvedShading r;
    r.model = pick(frame.model, material.model, r.model);
    r.distribution = pick(frame.distribution, material.distribution, r.distribution);
    r.geometry = pick(frame.geometry, material.geometry, defaultGeometry);
    r.fresnel = pick(frame.fresnel, material.fresnel, r.fresnel);
    r.diffuse = pick(frame.diffuse, material.diffuse, r.diffuse);
    return r;
}

void appendShadingDefines(const ResolvedShading& s, std::vector<std::string>& defines)
{
    using scene::ShadingModel;
    switch (s.model) {
    case ShadingModel::Pbr: break;
    case ShadingModel::Unlit: defines.push_back("SHADING_UNLIT"); return; // no BRDF: one variant
    case ShadingModel::Flat: defines.push_back("SHADING_FLAT"); return;
    case ShadingModel::Gouraud: defines.push_back("SHADING_GOURAUD"); return;
    case ShadingModel::Phong: defines.push_back("SHADING_PHONG"); return;
    case ShadingModel::BlinnPhong: defines.push_back("SHADING_BLINN_PHONG"); return;
    case ShadingModel::Doom: defines.push_back("SHADING_DOOM"); return;
    }
    switch (s.distribution) {
    case scene::BrdfDistribution::GGX: break;
    case scene::BrdfDistribution::Beckmann: defines.push_back("BRDF_D_BECKMANN"); break;
    case scene::BrdfDistribution::BlinnPhong: defines.push_back("BRDF_D_BLINN_PHONG"); break;
    }
    switch (s.geometry) {
    case scene::BrdfGeometry::SmithGGX: break;
    case scene::BrdfGeometry::SchlickGGX: defines.push_back("BRDF_G_SCHLICK_GGX"); break;
    case scene::BrdfGeometry::SmithGGXCorrelated: defines.push_back("BRDF_G_SMITH_GGX_CORRELATED"); break;
    case scene::BrdfGeometry::Neumann: defines.push_back("BRDF_G_NEUMANN"); break;
    case scene::BrdfGeometry::Kelemen: defines.push_back("BRDF_G_KELEMEN"); break;
    case scene::BrdfGeometry::CookTorrance: defines.push_back("BRDF_G_COOK_TORRANCE"); break;
    case scene::BrdfGeometry::Implicit: defines.push_back("BRDF_G_IMPLICIT"); break;
    }
    switch (s.fresnel) {
    case scene::BrdfFresnel::Schlick: break;
    case scene::BrdfFresnel::SchlickSG: defines.push_back("BRDF_F_SCHLICK_SG"); break;
    case scene::BrdfFresnel::None: defines.push_back("BRDF_F_NONE"); break;
    }
    switch (s.diffuse) {
    case scene::BrdfDiffuse::Lambert: break;
    case scene::BrdfDiffuse::OrenNayar: defines.push_back("BRDF_DIFFUSE_OREN_NAYAR"); break;
    case scene::BrdfDiffuse::Burley: defines.push_back("BRDF_DIFFUSE_BURLEY"); break;
    }
}

} // namespace specula::render
