#pragma once
// A material's shading (scene::MaterialShading) as part of the forward pass's variant key:
// packed into the high bits of MaterialBinding::features, resolved against the frame's
// settings; shading/VariantKey turns it into the defines of shaders/forward/ and shaders/brdf/.
#include <cstdint>

#include "scene/MaterialModel.h"

namespace specula::render {

/// What one draw is shaded with, every choice made.
struct ResolvedShading {
    scene::ShadingModel model = scene::ShadingModel::Pbr;
    scene::BrdfDistribution distribution = scene::BrdfDistribution::GGX;
    scene::BrdfGeometry geometry = scene::BrdfGeometry::SmithGGX;
    scene::BrdfFresnel fresnel = scene::BrdfFresnel::Schlick;
    scene::BrdfDiffuse diffuse = scene::BrdfDiffuse::Lambert;
    bool operator==(const ResolvedShading&) const = default;
};

/// Bits 16 to 30 of MaterialBinding::features (3 bits a field, value + 1, 0 = unset); the
/// SPECULA_MATERIAL_* feature bits stay below.
constexpr uint32_t kShadingFeatureMask = 0x7fff0000u;
uint32_t packShading(const scene::MaterialShading& shading);
scene::MaterialShading unpackShading(uint64_t features);

/// Whether KHR_materials_anisotropy's lobe applies: the physically based model with GGX's D
/// (the extension defines no other); elsewhere the material stays isotropic.
bool anisotropic(const ResolvedShading& shading);

/// The frame's override, else the material's choice, else the frame's default geometry and
/// the glTF BRDF.
ResolvedShading resolveShading(const scene::MaterialShading& frameOverride, scene::BrdfGeometry defaultGeometry,
                               uint64_t features);

} // namespace specula::render
