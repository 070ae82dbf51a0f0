#include "scene/MaterialModel.h"

#include <array>
#include <utility>

namespace specula::scene {
namespace {

template <typename E, size_t N>
std::optional<E> lookup(const std::array<std::pair<const char*, E>, N>& table, std::string_view name)
{
    for (const auto& [text, value] : table)
        if (name == text) return value;
    return std::nullopt;
}

template <typename E, size_t N>
const char* nameOf(const std::array<std::pair<const char*, E>, N>& table, E value)
{
    for (const auto& [text, v] : table)
        if (v == value) return text;
    return "?";
}

constexpr std::array<std::pair<const char*, ShadingModel>, kShadingModelCount> kModels{{
    {"pbr", ShadingModel::Pbr},
    {"unlit", ShadingModel::Unlit},
    {"flat", ShadingModel::Flat},
    {"gouraud", ShadingModel::Gouraud},
    {"phong", ShadingModel::Phong},
    {"blinn-phong", ShadingModel::BlinnPhong},
    {"doom", ShadingModel::Doom},
}};
constexpr std::array<std::pair<const char*, BrdfDistribution>, 3> kDistributions{{
    {"ggx", BrdfDistribution::GGX},
    {"beckmann", BrdfDistribution::Beckmann},
    {"blinn-phong", BrdfDistribution::BlinnPhong},
}};
constexpr std::array<std::pair<const char*, BrdfGeometry>, 7> kGeometries{{
    {"smith-ggx", BrdfGeometry::SmithGGX},
    {"smith-ggx-correlated", BrdfGeometry::SmithGGXCorrelated},
    {"schlick-ggx", BrdfGeometry::SchlickGGX},
    {"neumann", BrdfGeometry::Neumann},
    {"kelemen", BrdfGeometry::Kelemen},
    {"cook-torrance", BrdfGeometry::CookTorrance},
    {"implicit", BrdfGeometry::Implicit},
}};
constexpr std::array<std::pair<const char*, BrdfFresnel>, 3> kFresnels{{
    {"schlick", BrdfFresnel::Schlick},
    {"schlick-sg", BrdfFresnel::SchlickSG},
    {"none", BrdfFresnel::None},
}};
constexpr std::array<std::pair<const char*, BrdfDiffuse>, 3> kDiffuses{{
    {"lambert", BrdfDiffuse::Lambert},
    {"oren-nayar", BrdfDiffuse::OrenNayar},
    {"burley", BrdfDiffuse::Burley},
}};

} // namespace

std::optional<ShadingModel> parseShadingModel(std::string_view name) { return lookup(kModels, name); }
std::optional<BrdfDistribution> parseBrdfDistribution(std::string_view name) { return lookup(kDistributions, name); }
std::optional<BrdfGeometry> parseBrdfGeometryName(std::string_view name) { return lookup(kGeometries, name); }
std::optional<BrdfFresnel> parseBrdfFresnel(std::string_view name) { return lookup(kFresnels, name); }
std::optional<BrdfDiffuse> parseBrdfDiffuse(std::string_view name) { return lookup(kDiffuses, name); }
const char* shadingModelName(ShadingModel model) { return nameOf(kModels, model); }
const char* brdfDistributionName(BrdfDistribution d) { return nameOf(kDistributions, d); }
const char* brdfGeometryName(BrdfGeometry g) { return nameOf(kGeometries, g); }
const char* brdfFresnelName(BrdfFresnel f) { return nameOf(kFresnels, f); }
const char* brdfDiffuseName(BrdfDiffuse d) { return nameOf(kDiffuses, d); }
const char* shadingModelNames() { return "pbr, unlit, flat, gouraud, phong, blinn-phong, doom"; }
const char* brdfDistributionNames() { return "ggx, beckmann, blinn-phong"; }
const char* brdfGeometryNames() { return "smith-ggx, smith-ggx-correlated, schlick-ggx, neumann, kelemen, cook-torrance, implicit"; }
const char* brdfFresnelNames() { return "schlick, schlick-sg, none"; }
const char* brdfDiffuseNames() { return "lambert, oren-nayar, burley"; }

float f0FromIor(float ior)
{
    const float r = (ior - 1.0f) / (ior + 1.0f);
    return r * r;
}

} // namespace specula::scene
