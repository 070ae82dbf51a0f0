#include "shading/VariantKey.h"

#include <array>

#include <fmt/format.h>

#include "shading/EnvironmentMap.h"
#include "shaders/shared/MaterialData.h"
#include "shaders/shared/ShadowData.h"

namespace specula::render {
namespace {

// Layout of the key.
constexpr uint64_t kFeatureMask = 0x1ffu; // SPECULA_MATERIAL_* bits 0–8
constexpr uint64_t kIbl = 1u << 9;
constexpr uint64_t kEnergyCompensation = 1u << 10;
constexpr uint64_t kSsao = 1u << 11;
constexpr uint64_t kDoomIndexed = 1u << 12;
constexpr uint64_t kShadows = 1u << 13;
constexpr uint64_t kLightsAll = 1u << 14;
constexpr uint64_t kIblImportance = 1u << 15;
constexpr uint64_t kShadowDirectional = uint64_t(1) << 32, kShadowSpot = uint64_t(1) << 33, kShadowPoint = uint64_t(1) << 34;
constexpr int kShadowFilterShift = 35, kShadowTapsShift = 37;
// Material features above the first nine bits, and the transparency choices.
constexpr uint64_t kBlendTransparent = uint64_t(1) << 39, kTransmission = uint64_t(1) << 40, kOit = uint64_t(1) << 41;
constexpr uint64_t kClearcoat = uint64_t(1) << 42;
constexpr uint64_t kSheen = uint64_t(1) << 43, kAnisotropy = uint64_t(1) << 44, kIridescence = uint64_t(1) << 45;
constexpr uint64_t kDispersion = uint64_t(1) << 46;
// The extension textures a variant samples (after LIGHT_COUNT's field, bits 52-56).
constexpr uint64_t kSpecularTextures = uint64_t(1) << 57, kTransmissionTextures = uint64_t(1) << 58;
// KHR_materials_diffuse_transmission's lobe and its textures.
constexpr uint64_t kDiffuseTransmission = uint64_t(1) << 59, kDiffuseTransmissionTextures = uint64_t(1) << 60;
// The shadows' tint map (surfaces that let light through cast coloured or partial shadows).
constexpr uint64_t kShadowTint = uint64_t(1) << 61;
// The kinds of light a frame has not; then LIGHT_CONSTANTS (bit 19: the debug view's field was
// there while it had 4 bits).
constexpr uint64_t kNoDirectional = 1u << 16, kNoPoint = 1u << 17, kNoSpot = 1u << 18, kLightConstants = 1u << 19;
// LIGHT_COUNT: 0 = none (the count is read from the light buffer), else the count + 1.
constexpr int kLightCountShift = 52, kLightCountBits = 5;
static_assert(LightVariant::kMaxConstantCount + 1 < (1 << kLightCountBits));
constexpr int kDebugShift = 47, kModelShift = 20, kDistributionShift = 23, kGeometryShift = 25, kFresnelShift = 28,
              kDiffuseShift = 30;
constexpr uint64_t field(int shift, int bits) { return ((uint64_t(1) << bits) - 1) << shift; }
constexpr uint64_t kDebugMask = field(kDebugShift, 5), kModelMask = field(kModelShift, 3),
                   kDistributionMask = field(kDistributionShift, 2), kGeometryMask = field(kGeometryShift, 3),
                   kFresnelMask = field(kFresnelShift, 2), kDiffuseMask = field(kDiffuseShift, 2),
                   kShadowFilterMask = field(kShadowFilterShift, 2), kShadowTapsMask = field(kShadowTapsShift, 2),
                   kLightCountMask = field(kLightCountShift, kLightCountBits);
// The shadow filter's field: PCF (the default) is 0 and has no define; the size's field: the
// default (PCF's 3 × 3 tent, PCSS's 16 taps) is 0.
constexpr uint64_t kFilterHard = 1, kFilterPcss = 2, kTent5 = 1, kTaps32 = 2;
template <typename E>
constexpr uint64_t at(int shift, E value) { return uint64_t(value) << shift; }

using K = VariantDefine::Kind;
using scene::BrdfDiffuse, scene::BrdfDistribution, scene::BrdfFresnel, scene::BrdfGeometry, scene::ShadingModel;

constexpr std::array kTable = {
    VariantDefine{kModelMask, at(kModelShift, ShadingModel::Unlit), "SHADING_UNLIT", K::ShadingModel},
    VariantDefine{kModelMask, at(kModelShift, ShadingModel::Flat), "SHADING_FLAT", K::ShadingModel},
    VariantDefine{kModelMask, at(kModelShift, ShadingModel::Gouraud), "SHADING_GOURAUD", K::ShadingModel},
    VariantDefine{kModelMask, at(kModelShift, ShadingModel::Phong), "SHADING_PHONG", K::ShadingModel},
    VariantDefine{kModelMask, at(kModelShift, ShadingModel::BlinnPhong), "SHADING_BLINN_PHONG", K::ShadingModel},
    VariantDefine{kModelMask, at(kModelShift, ShadingModel::Doom), "SHADING_DOOM", K::ShadingModel},
    VariantDefine{kDistributionMask, at(kDistributionShift, BrdfDistribution::Beckmann), "BRDF_D_BECKMANN", K::Brdf},
    VariantDefine{kDistributionMask, at(kDistributionShift, BrdfDistribution::BlinnPhong), "BRDF_D_BLINN_PHONG", K::Brdf},
    VariantDefine{kGeometryMask, at(kGeometryShift, BrdfGeometry::SchlickGGX), "BRDF_G_SCHLICK_GGX", K::Brdf},
    VariantDefine{kGeometryMask, at(kGeometryShift, BrdfGeometry::SmithGGXCorrelated), "BRDF_G_SMITH_GGX_CORRELATED", K::Brdf},
    VariantDefine{kGeometryMask, at(kGeometryShift, BrdfGeometry::Neumann), "BRDF_G_NEUMANN", K::Brdf},
    VariantDefine{kGeometryMask, at(kGeometryShift, BrdfGeometry::Kelemen), "BRDF_G_KELEMEN", K::Brdf},
    VariantDefine{kGeometryMask, at(kGeometryShift, BrdfGeometry::CookTorrance), "BRDF_G_COOK_TORRANCE", K::Brdf},
    VariantDefine{kGeometryMask, at(kGeometryShift, BrdfGeometry::Implicit), "BRDF_G_IMPLICIT", K::Brdf},
    VariantDefine{kFresnelMask, at(kFresnelShift, BrdfFresnel::SchlickSG), "BRDF_F_SCHLICK_SG", K::Brdf},
    VariantDefine{kFresnelMask, at(kFresnelShift, BrdfFresnel::None), "BRDF_F_NONE", K::Brdf},
    VariantDefine{kDiffuseMask, at(kDiffuseShift, BrdfDiffuse::OrenNayar), "BRDF_DIFFUSE_OREN_NAYAR", K::Brdf},
    VariantDefine{kDiffuseMask, at(kDiffuseShift, BrdfDiffuse::Burley), "BRDF_DIFFUSE_BURLEY", K::Brdf},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::BaseColor), "DEBUG_VIEW_BASE_COLOR", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Normal), "DEBUG_VIEW_NORMAL", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Roughness), "DEBUG_VIEW_ROUGHNESS", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Metallic), "DEBUG_VIEW_METALLIC", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Occlusion), "DEBUG_VIEW_OCCLUSION", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Emissive), "DEBUG_VIEW_EMISSIVE", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::BrdfD), "DEBUG_VIEW_BRDF_D", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::BrdfG), "DEBUG_VIEW_BRDF_G", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::BrdfF), "DEBUG_VIEW_BRDF_F", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Cascades), "DEBUG_VIEW_CASCADES", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::LightCount), "DEBUG_VIEW_LIGHT_COUNT", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Sheen), "DEBUG_VIEW_SHEEN", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Anisotropy), "DEBUG_VIEW_ANISOTROPY", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Iridescence), "DEBUG_VIEW_IRIDESCENCE", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::Clearcoat), "DEBUG_VIEW_CLEARCOAT", K::DebugView},
    VariantDefine{kDebugMask, at(kDebugShift, DebugView::ClearcoatNormal), "DEBUG_VIEW_CLEARCOAT_NORMAL", K::DebugView},
    VariantDefine{kIbl, kIbl, "IBL", K::FrameFeature},
    VariantDefine{kIblImportance, kIblImportance, "IBL_IMPORTANCE", K::FrameFeature},
    VariantDefine{kEnergyCompensation, kEnergyCompensation, "ENERGY_COMPENSATION", K::FrameFeature},
    VariantDefine{kSsao, kSsao, "SSAO", K::FrameFeature},
    VariantDefine{kDoomIndexed, kDoomIndexed, "DOOM_INDEXED", K::FrameFeature},
    VariantDefine{kShadows, kShadows, "SHADOWS", K::FrameFeature},
    VariantDefine{kLightsAll, kLightsAll, "LIGHTS_ALL", K::FrameFeature},
    VariantDefine{kNoDirectional, kNoDirectional, "NO_DIRECTIONAL_LIGHTS", K::FrameFeature},
    VariantDefine{kNoPoint, kNoPoint, "NO_POINT_LIGHTS", K::FrameFeature},
    VariantDefine{kNoSpot, kNoSpot, "NO_SPOT_LIGHTS", K::FrameFeature},
    VariantDefine{kShadowDirectional, kShadowDirectional, "SHADOW_DIRECTIONAL", K::FrameFeature},
    VariantDefine{kShadowSpot, kShadowSpot, "SHADOW_SPOT", K::FrameFeature},
    VariantDefine{kShadowPoint, kShadowPoint, "SHADOW_POINT", K::FrameFeature},
    VariantDefine{kShadowTint, kShadowTint, "SHADOW_TINT", K::FrameFeature},
    VariantDefine{kShadowFilterMask, at(kShadowFilterShift, kFilterHard), "SHADOW_FILTER_HARD", K::Shadow},
    VariantDefine{kShadowFilterMask, at(kShadowFilterShift, kFilterPcss), "SHADOW_FILTER_PCSS", K::Shadow},
    VariantDefine{kShadowTapsMask, at(kShadowTapsShift, kTent5), "SHADOW_TENT 5", K::Shadow},
    VariantDefine{kShadowTapsMask, at(kShadowTapsShift, kTaps32), "SHADOW_TAPS 32", K::Shadow},
    VariantDefine{SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE, SPECULA_MATERIAL_HAS_BASE_COLOR_TEXTURE, "HAS_BASE_COLOR_TEXTURE", K::MaterialFeature},
    VariantDefine{SPECULA_MATERIAL_HAS_METALLIC_ROUGHNESS_TEXTURE, SPECULA_MATERIAL_HAS_METALLIC_ROUGHNESS_TEXTURE,
                  "HAS_METALLIC_ROUGHNESS_TEXTURE", K::MaterialFeature},
    VariantDefine{SPECULA_MATERIAL_HAS_NORMAL_TEXTURE, SPECULA_MATERIAL_HAS_NORMAL_TEXTURE, "HAS_NORMAL_TEXTURE", K::MaterialFeature},
    VariantDefine{SPECULA_MATERIAL_HAS_OCCLUSION_TEXTURE, SPECULA_MATERIAL_HAS_OCCLUSION_TEXTURE, "HAS_OCCLUSION_TEXTURE", K::MaterialFeature},
    VariantDefine{SPECULA_MATERIAL_HAS_EMISSIVE_TEXTURE, SPECULA_MATERIAL_HAS_EMISSIVE_TEXTURE, "HAS_EMISSIVE_TEXTURE", K::MaterialFeature},
    VariantDefine{SPECULA_MATERIAL_DOUBLE_SIDED, SPECULA_MATERIAL_DOUBLE_SIDED, "DOUBLE_SIDED", K::MaterialFeature},
    VariantDefine{SPECULA_MATERIAL_ALPHA_MASK, SPECULA_MATERIAL_ALPHA_MASK, "ALPHA_MASK", K::MaterialFeature},
    VariantDefine{SPECULA_MATERIAL_ALPHA_BLEND, SPECULA_MATERIAL_ALPHA_BLEND, "ALPHA_BLEND", K::MaterialFeature},
    VariantDefine{SPECULA_MATERIAL_USE_VERTEX_COLOR, SPECULA_MATERIAL_USE_VERTEX_COLOR, "VERTEX_COLOR", K::MaterialFeature},
    VariantDefine{kBlendTransparent, kBlendTransparent, "BLEND_TRANSPARENT", K::MaterialFeature},
    VariantDefine{kTransmission, kTransmission, "TRANSMISSION", K::MaterialFeature},
    VariantDefine{kClearcoat, kClearcoat, "CLEARCOAT", K::MaterialFeature},
    VariantDefine{kDispersion, kDispersion, "DISPERSION", K::MaterialFeature},
    VariantDefine{kSheen, kSheen, "SHEEN", K::MaterialFeature},
    VariantDefine{kAnisotropy, kAnisotropy, "ANISOTROPY", K::MaterialFeature},
    VariantDefine{kIridescence, kIridescence, "IRIDESCENCE", K::MaterialFeature},
    VariantDefine{kSpecularTextures, kSpecularTextures, "SPECULAR_TEXTURES", K::MaterialFeature},
    VariantDefine{kTransmissionTextures, kTransmissionTextures, "TRANSMISSION_TEXTURES", K::MaterialFeature},
    VariantDefine{kDiffuseTransmission, kDiffuseTransmission, "DIFFUSE_TRANSMISSION", K::MaterialFeature},
    VariantDefine{kDiffuseTransmissionTextures, kDiffuseTransmissionTextures, "DIFFUSE_TRANSMISSION_TEXTURES", K::MaterialFeature},
    VariantDefine{kOit, kOit, "OIT", K::FrameFeature},
};
static_assert((kFeatureMask & (kIbl | kIblImportance | kEnergyCompensation | kSsao | kDoomIndexed | kShadows | kLightsAll | kDebugMask)) == 0);
static_assert(((kNoDirectional | kNoPoint | kNoSpot) & (kFeatureMask | kIbl | kIblImportance | kLightsAll | kModelMask)) == 0);
static_assert((kLightCountMask & (kDebugMask | kDispersion | kIridescence)) == 0 && kLightCountShift + kLightCountBits <= 57);
static_assert(uint64_t(kLastDebugView) < (uint64_t(1) << 5)); // the debug field's 5 bits
static_assert((kDebugMask & (kBlendTransparent | kTransmission | kOit | kClearcoat | kSheen | kAnisotropy | kIridescence | kDispersion)) == 0);
static_assert(((kShadowTapsMask | kShadowFilterMask) & (kBlendTransparent | kTransmission | kOit)) == 0);
static_assert((kDiffuseMask & (kShadowDirectional | kShadowSpot | kShadowPoint | kShadowFilterMask | kShadowTapsMask)) == 0);

} // namespace

std::span<const VariantDefine> forwardVariantTable()
{
    return kTable;
}

bool isMaterialDebugView(DebugView view)
{
    return view != DebugView::None && view != DebugView::Ssao && view != DebugView::Bloom && view != DebugView::ShadowAtlas;
}

ForwardVariant ForwardVariant::make(uint64_t features, const ResolvedShading& shading, DebugView debugView, IblVariant ibl,
                                    bool energyCompensation, bool ssao, bool doomIndexed, const ShadowVariant& shadows,
                                    const LightVariant& lights, bool oit)
{
    uint64_t key = features & kFeatureMask;
    key |= at(kModelShift, shading.model);
    if (shading.model == ShadingModel::Pbr) {
        key |= at(kDistributionShift, shading.distribution) | at(kGeometryShift, shading.geometry) |
               at(kFresnelShift, shading.fresnel) | at(kDiffuseShift, shading.diffuse);
        // Only the physically based model has lobes to blend apart and a dielectric to refract
        // through; a Doom frame's indices and the debug views have neither.
        if (features & SPECULA_MATERIAL_BLEND_TRANSPARENT) key |= kBlendTransparent;
        if ((features & SPECULA_MATERIAL_TRANSMISSION) && !doomIndexed && !isMaterialDebugView(debugView)) {
            key |= kTransmission;
            // KHR_materials_dispersion: three refractions, one per channel, where a volume has it.
            if (features & SPECULA_MATERIAL_DISPERSION) key |= kDispersion;
            // The transmission and thickness textures scale their factors.
            if (features & SPECULA_MATERIAL_TRANSMISSION_TEXTURES) key |= kTransmissionTextures;
        }
        // KHR_materials_diffuse_transmission: the lobe through the surface, in the lit frame only.
        if ((features & SPECULA_MATERIAL_DIFFUSE_TRANSMISSION) && !doomIndexed && !isMaterialDebugView(debugView)) {
            key |= kDiffuseTransmission;
            if (features & SPECULA_MATERIAL_DIFFUSE_TRANSMISSION_TEXTURES) key |= kDiffuseTransmissionTextures;
        }
        // KHR_materials_specular's textures: the dielectric's F0 and F90, in the lit frame and in
        // the views that show Fresnel; an indexed Doom frame reads only the colour.
        const bool fresnelView = debugView == DebugView::BrdfF || debugView == DebugView::Iridescence;
        if ((features & SPECULA_MATERIAL_SPECULAR_TEXTURES) && !doomIndexed && (!isMaterialDebugView(debugView) || fresnelView))
            key |= kSpecularTextures;
        // KHR_materials_clearcoat: the layer, in the lit frame and in its own debug views.
        const bool coatView = debugView == DebugView::Clearcoat || debugView == DebugView::ClearcoatNormal;
        if ((features & SPECULA_MATERIAL_CLEARCOAT) && !doomIndexed && (!isMaterialDebugView(debugView) || coatView)) key |= kClearcoat;
        // KHR_materials_sheen: the lobe in the lit frame, and its own debug view.
        if ((features & SPECULA_MATERIAL_SHEEN) && !doomIndexed && (!isMaterialDebugView(debugView) || debugView == DebugView::Sheen))
            key |= kSheen;
        // KHR_materials_anisotropy: the GGX lobe only (other D terms stay isotropic); the
        // debug views keep it, for the anisotropy view and the anisotropic D.
        if ((features & SPECULA_MATERIAL_ANISOTROPY) && anisotropic(shading) && !doomIndexed) key |= kAnisotropy;
        // KHR_materials_iridescence: the film, in the lit frame and in its own debug view.
        if ((features & SPECULA_MATERIAL_IRIDESCENCE) && !doomIndexed &&
            (!isMaterialDebugView(debugView) || debugView == DebugView::Iridescence))
            key |= kIridescence;
    }
    // OIT's accumulation is for the blended list only (transmissive draws, blended or not, are
    // drawn sorted before it), and never in an indexed frame.
    if (oit && (features & SPECULA_MATERIAL_ALPHA_BLEND) && !(features & SPECULA_MATERIAL_TRANSMISSION) && !doomIndexed) key |= kOit;
    if (isMaterialDebugView(debugView)) key |= at(kDebugShift, debugView);
    if (ibl != IblVariant::None) key |= kIbl;
    if (ibl == IblVariant::Importance) key |= kIblImportance;
    if (energyCompensation) key |= kEnergyCompensation;
    if (ssao) key |= kSsao;
    if (doomIndexed) key |= kDoomIndexed;
    if (lights.all) {
        key |= kLightsAll;
        if (lights.count >= 0 && lights.count <= LightVariant::kMaxConstantCount) {
            key |= uint64_t(lights.count + 1) << kLightCountShift;
            if (lights.constants && lights.count > 0) key |= kLightConstants;
        }
    }
    if (!lights.directional) key |= kNoDirectional;
    if (!lights.point) key |= kNoPoint;
    if (!lights.spot) key |= kNoSpot;
    if (shadows.active()) {
        key |= kShadows;
        if (shadows.directional) key |= kShadowDirectional;
        if (shadows.spot) key |= kShadowSpot;
        if (shadows.point) key |= kShadowPoint;
        if (shadows.tint) key |= kShadowTint;
        if (shadows.filter == SPECULA_SHADOW_FILTER_HARD) key |= at(kShadowFilterShift, kFilterHard);
        if (shadows.filter == SPECULA_SHADOW_FILTER_PCSS) key |= at(kShadowFilterShift, kFilterPcss);
        if (shadows.filter == SPECULA_SHADOW_FILTER_PCF && shadows.tent >= 5) key |= at(kShadowTapsShift, kTent5);
        if (shadows.filter == SPECULA_SHADOW_FILTER_PCSS && shadows.taps >= 32) key |= at(kShadowTapsShift, kTaps32);
    }
    return {key};
}

ResolvedShading ForwardVariant::shading() const
{
    ResolvedShading s;
    s.model = ShadingModel((key & kModelMask) >> kModelShift);
    s.distribution = BrdfDistribution((key & kDistributionMask) >> kDistributionShift);
    s.geometry = BrdfGeometry((key & kGeometryMask) >> kGeometryShift);
    s.fresnel = BrdfFresnel((key & kFresnelMask) >> kFresnelShift);
    s.diffuse = BrdfDiffuse((key & kDiffuseMask) >> kDiffuseShift);
    return s;
}

bool ForwardVariant::sheen() const
{
    return (key & kSheen) != 0;
}

bool ForwardVariant::debugView() const
{
    return (key & kDebugMask) != 0;
}

std::vector<std::string> ForwardVariant::defines() const
{
    std::vector<std::string> out;
    for (const VariantDefine& row : kTable)
        if ((key & row.mask) == row.value) out.emplace_back(row.define);
    if (const uint64_t count = (key & kLightCountMask) >> kLightCountShift; count > 0) out.push_back(fmt::format("LIGHT_COUNT {}u", count - 1));
    if (lightConstants()) out.emplace_back("LIGHT_CONSTANTS");
    return out;
}

bool ForwardVariant::lightConstants() const
{
    return (key & kLightConstants) != 0;
}

std::string ForwardVariant::name() const
{
    std::string out;
    for (const std::string& d : defines()) out += d + ";";
    return out;
}

std::vector<std::string> irradianceSourceDefines(std::span<const IrradianceSource> sources)
{
    auto list = [&](glm::vec3 IrradianceSource::*field) {
        std::string out;
        for (const IrradianceSource& source : sources) {
            const glm::vec3 v = source.*field;
            // Nine significant digits give back every float exactly.
            out += fmt::format("{}vec3({:.9g}, {:.9g}, {:.9g})", out.empty() ? "" : ", ", v.x, v.y, v.z);
        }
        return out;
    };
    std::vector<std::string> defines{fmt::format("IBL_SOURCE_COUNT {}", sources.size())};
    if (!sources.empty()) {
        defines.push_back("IBL_SOURCE_DIRECTIONS " + list(&IrradianceSource::direction));
        defines.push_back("IBL_SOURCE_FLUXES " + list(&IrradianceSource::flux));
        std::string spreads;
        for (const IrradianceSource& source : sources) spreads += fmt::format("{}{:.9g}", spreads.empty() ? "" : ", ", source.spread);
        defines.push_back("IBL_SOURCE_SPREADS " + spreads);
    }
    return defines;
}

} // namespace specula::render
