// The forward pass's variant key (shading/VariantKey): one table of bits and defines.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "shading/VariantKey.h"
#include "shaders/shared/MaterialData.h"

using namespace specula;
using namespace specula::render;

TEST(VariantKey, DefinesFollowTheTable)
{
    ResolvedShading s;
    s.geometry = scene::BrdfGeometry::SchlickGGX;
    s.diffuse = scene::BrdfDiffuse::Burley;
    const ForwardVariant v = ForwardVariant::make(SPECULA_MATERIAL_HAS_NORMAL_TEXTURE | SPECULA_MATERIAL_ALPHA_MASK, s,
                                                  DebugView::None, IblVariant::SplitSum, true, false, false);
    EXPECT_EQ(v.defines(), (std::vector<std::string>{"BRDF_G_SCHLICK_GGX", "BRDF_DIFFUSE_BURLEY", "IBL", "ENERGY_COMPENSATION",
                                                     "HAS_NORMAL_TEXTURE", "ALPHA_MASK"}));
    EXPECT_EQ(v.shading(), s);
    EXPECT_FALSE(v.debugView());
    // The importance-sampled specular keeps the split sum's IBL define and adds its own.
    EXPECT_EQ(ForwardVariant::make(0, {}, DebugView::None, IblVariant::Importance, false, false, false).defines(),
              (std::vector<std::string>{"IBL", "IBL_IMPORTANCE"}));
    // The default: the glTF BRDF, no feature, no define at all.
    EXPECT_TRUE(ForwardVariant::make(0, {}, DebugView::None, IblVariant::None, false, false, false).defines().empty());
}

TEST(VariantKey, EveryChoiceRoundTripsAndIsItsOwnKey)
{
    std::set<uint64_t> keys;
    int count = 0;
    for (int model = 0; model < scene::kShadingModelCount; ++model)
        for (int g = 0; g <= int(scene::BrdfGeometry::Implicit); ++g)
            for (int d = 0; d <= int(scene::BrdfDistribution::BlinnPhong); ++d) {
                ResolvedShading s;
                s.model = scene::ShadingModel(model);
                s.geometry = scene::BrdfGeometry(g);
                s.distribution = scene::BrdfDistribution(d);
                const ForwardVariant v = ForwardVariant::make(0, s, DebugView::None, IblVariant::None, false, false, false);
                if (s.model == scene::ShadingModel::Pbr) {
                    EXPECT_EQ(v.shading(), s);
                    ++count;
                    keys.insert(v.key);
                } else {
                    // The classic models have no BRDF choices: one program each.
                    EXPECT_EQ(v.shading().model, s.model);
                    EXPECT_EQ(v.shading().geometry, scene::BrdfGeometry::SmithGGX);
                    keys.insert(v.key);
                }
            }
    EXPECT_EQ(keys.size(), size_t(count + scene::kShadingModelCount - 1));
}

TEST(VariantKey, MaterialDebugViewsSetTheirDefineOthersDoNot)
{
    const auto view = [](DebugView d) { return ForwardVariant::make(0, {}, d, IblVariant::None, false, false, false); };
    EXPECT_EQ(view(DebugView::Normal).defines(), (std::vector<std::string>{"DEBUG_VIEW_NORMAL"}));
    EXPECT_TRUE(view(DebugView::Normal).debugView());
    EXPECT_TRUE(view(DebugView::Ssao).defines().empty()) << "the SSAO view is a pass of its own";
    EXPECT_TRUE(view(DebugView::Bloom).defines().empty());
    EXPECT_TRUE(view(DebugView::ShadowAtlas).defines().empty()) << "the atlas view is a pass of its own";
}

TEST(VariantKey, ShadowsCompileInOnlyTheKindsAndFilterTheFrameUses)
{
    const auto with = [](const ShadowVariant& s) { return ForwardVariant::make(0, {}, DebugView::None, IblVariant::None, false, false, false, s).defines(); };
    using V = std::vector<std::string>;
    EXPECT_TRUE(with({}).empty()) << "no shadowed light: no SHADOWS variant, whatever the filter";
    EXPECT_TRUE(with({.filter = 2, .taps = 32}).empty());
    // PCF with its 3 × 3 tent is the default: no define of its own.
    EXPECT_EQ(with({.point = true}), (V{"SHADOWS", "SHADOW_POINT"}));
    EXPECT_EQ(with({.point = true, .taps = 32}), (V{"SHADOWS", "SHADOW_POINT"})) << "PCF has no disc";
    EXPECT_EQ(with({.spot = true, .tent = 5}), (V{"SHADOWS", "SHADOW_SPOT", "SHADOW_TENT 5"}));
    EXPECT_EQ(with({.directional = true, .spot = true, .filter = 0, .taps = 32, .tent = 5}),
              (V{"SHADOWS", "SHADOW_DIRECTIONAL", "SHADOW_SPOT", "SHADOW_FILTER_HARD"})) << "the hard filter has neither";
    EXPECT_EQ(with({.directional = true, .spot = true, .point = true, .filter = 2, .taps = 32, .tent = 5}),
              (V{"SHADOWS", "SHADOW_DIRECTIONAL", "SHADOW_SPOT", "SHADOW_POINT", "SHADOW_FILTER_PCSS", "SHADOW_TAPS 32"}));
}

TEST(VariantKey, TableRowsAreDistinct)
{
    std::set<std::string> defines;
    for (const VariantDefine& row : forwardVariantTable()) {
        EXPECT_TRUE(defines.insert(row.define).second) << row.define;
        EXPECT_NE(row.value, 0u) << row.define << ": a default has no define";
        EXPECT_EQ(row.value & ~row.mask, 0u) << row.define;
    }
}

// KHR_materials_anisotropy: its variant only for a material that has it, with GGX's D (the
// extension defines no other), and its lobe's height-correlated V from resolveShading (so the
// DFG table integrates the same V); a material without it keeps its G and pays nothing.
TEST(VariantKey, AnisotropyOnlyForAnisotropicGgxMaterials)
{
    const uint32_t features = SPECULA_MATERIAL_ANISOTROPY;
    const ResolvedShading brushed = resolveShading({}, scene::BrdfGeometry::SmithGGX, features);
    EXPECT_EQ(brushed.geometry, scene::BrdfGeometry::SmithGGXCorrelated);
    const auto defines = ForwardVariant::make(features, brushed, DebugView::None, IblVariant::SplitSum, true, false, false).defines();
    EXPECT_EQ(defines, (std::vector<std::string>{"BRDF_G_SMITH_GGX_CORRELATED", "IBL", "ENERGY_COMPENSATION", "ANISOTROPY"}));
    const ResolvedShading plain = resolveShading({}, scene::BrdfGeometry::SmithGGX, 0u);
    EXPECT_EQ(plain.geometry, scene::BrdfGeometry::SmithGGX);
    EXPECT_TRUE(ForwardVariant::make(0u, plain, DebugView::None, IblVariant::None, false, false, false).defines().empty());
    // Beckmann's D stays isotropic, and keeps its G; so does a classic model; a Doom frame has none.
    scene::MaterialShading beckmann;
    beckmann.distribution = scene::BrdfDistribution::Beckmann;
    const ResolvedShading b = resolveShading(beckmann, scene::BrdfGeometry::SmithGGX, features);
    EXPECT_EQ(b.geometry, scene::BrdfGeometry::SmithGGX);
    EXPECT_EQ(ForwardVariant::make(features, b, DebugView::None, IblVariant::None, false, false, false).defines(),
              (std::vector<std::string>{"BRDF_D_BECKMANN"}));
    const auto doom = ForwardVariant::make(features, brushed, DebugView::None, IblVariant::None, false, false, true).defines();
    EXPECT_EQ(std::find(doom.begin(), doom.end(), "ANISOTROPY"), doom.end());
    // The anisotropy debug view keeps the variant (it shows the direction and strength).
    const auto debug = ForwardVariant::make(features, brushed, DebugView::Anisotropy, IblVariant::None, false, false, false).defines();
    EXPECT_NE(std::find(debug.begin(), debug.end(), "ANISOTROPY"), debug.end());
    EXPECT_NE(std::find(debug.begin(), debug.end(), "DEBUG_VIEW_ANISOTROPY"), debug.end());
}

TEST(VariantKey, IridescenceOnlyForFilmedMaterialsInTheLitFrameAndItsOwnView)
{
    // KHR_materials_iridescence: a material without a film pays nothing (no define); with one,
    // the lit frame and DebugView::Iridescence get IRIDESCENCE, other material views and a Doom
    // frame's indices do not.
    const auto make = [](uint32_t features, DebugView d, bool doom = false) {
        return ForwardVariant::make(features, {}, d, IblVariant::None, false, false, doom).defines();
    };
    const auto has = [](const std::vector<std::string>& defines) {
        return std::find(defines.begin(), defines.end(), "IRIDESCENCE") != defines.end();
    };
    EXPECT_FALSE(has(make(0, DebugView::None)));
    EXPECT_FALSE(has(make(0, DebugView::Iridescence)));
    EXPECT_TRUE(has(make(SPECULA_MATERIAL_IRIDESCENCE, DebugView::None)));
    EXPECT_TRUE(has(make(SPECULA_MATERIAL_IRIDESCENCE, DebugView::Iridescence)));
    EXPECT_FALSE(has(make(SPECULA_MATERIAL_IRIDESCENCE, DebugView::BrdfF)));
    EXPECT_FALSE(has(make(SPECULA_MATERIAL_IRIDESCENCE, DebugView::None, true)));
    const std::vector<std::string> view = make(0, DebugView::Iridescence);
    EXPECT_NE(std::find(view.begin(), view.end(), "DEBUG_VIEW_IRIDESCENCE"), view.end());
}

// Every debug view has a name that parses back to it, and a material view its own define; the
// clearcoat's views keep CLEARCOAT on a coated material (they show the layer), the other
// material views drop it.
TEST(VariantKey, EveryDebugViewNamesItselfAndTheClearcoatViewsKeepTheLayer)
{
    std::set<std::string> names;
    for (int k = 0; k <= int(kLastDebugView); ++k) {
        const DebugView view = DebugView(k);
        const std::string name = debugViewName(view);
        EXPECT_TRUE(names.insert(name).second) << name;
        EXPECT_EQ(parseDebugView(name), view) << name;
    }
    EXPECT_FALSE(parseDebugView("clear-coat").has_value());
    const auto make = [](DebugView d) {
        return ForwardVariant::make(SPECULA_MATERIAL_CLEARCOAT, {}, d, IblVariant::None, false, false, false).defines();
    };
    const auto has = [](const std::vector<std::string>& defines, const char* define) {
        return std::find(defines.begin(), defines.end(), define) != defines.end();
    };
    EXPECT_TRUE(has(make(DebugView::None), "CLEARCOAT"));
    EXPECT_TRUE(has(make(DebugView::Clearcoat), "CLEARCOAT"));
    EXPECT_TRUE(has(make(DebugView::Clearcoat), "DEBUG_VIEW_CLEARCOAT"));
    EXPECT_TRUE(has(make(DebugView::ClearcoatNormal), "CLEARCOAT"));
    EXPECT_TRUE(has(make(DebugView::ClearcoatNormal), "DEBUG_VIEW_CLEARCOAT_NORMAL"));
    EXPECT_FALSE(has(make(DebugView::Normal), "CLEARCOAT"));
    EXPECT_FALSE(has(make(DebugView::Sheen), "CLEARCOAT"));
}

// The frame's lights: a kind it has none of is compiled out, and with every light everywhere
// (LIGHTS_ALL) a count up to 16 is a constant of the program; more lights keep the count a
// read, and the clustered lists never have one.
TEST(VariantKey, LightsCompileInOnlyTheKindsAndTheCountOfAFewLights)
{
    const auto with = [](const LightVariant& l) {
        return ForwardVariant::make(0, {}, DebugView::None, IblVariant::None, false, false, false, {}, l).defines();
    };
    using V = std::vector<std::string>;
    EXPECT_TRUE(with({}).empty()) << "every kind, clustered: the default";
    EXPECT_EQ(with({.all = true, .count = 4, .directional = false, .spot = false}),
              (V{"LIGHTS_ALL", "NO_DIRECTIONAL_LIGHTS", "NO_SPOT_LIGHTS", "LIGHT_COUNT 4u"}));
    EXPECT_EQ(with({.all = true, .count = 0, .directional = false, .point = false, .spot = false}),
              (V{"LIGHTS_ALL", "NO_DIRECTIONAL_LIGHTS", "NO_POINT_LIGHTS", "NO_SPOT_LIGHTS", "LIGHT_COUNT 0u"}));
    EXPECT_EQ(with({.all = true, .count = 16}), (V{"LIGHTS_ALL", "LIGHT_COUNT 16u"}));
    EXPECT_EQ(with({.all = true, .count = 17}), (V{"LIGHTS_ALL"})) << "too many to unroll";
    EXPECT_EQ(with({.all = false, .count = 4, .point = false}), (V{"NO_POINT_LIGHTS"})) << "the lists' counts vary per cluster";
    // Each count is its own program.
    EXPECT_NE(ForwardVariant::make(0, {}, DebugView::None, IblVariant::None, false, false, false, {}, {.all = true, .count = 3}).key,
              ForwardVariant::make(0, {}, DebugView::None, IblVariant::None, false, false, false, {}, {.all = true, .count = 4}).key);
}

// The extension textures' bits live above the record's 32 (MaterialBinding::features): the
// SPECULAR_TEXTURES variant for the lit frame and the views that show Fresnel, never for a Doom
// frame's indices or the other views; TRANSMISSION_TEXTURES only with TRANSMISSION.
TEST(VariantKey, ExtensionTexturesAboveTheRecordsBits)
{
    const auto make = [](uint64_t features, DebugView d, bool doom = false) {
        return ForwardVariant::make(features, {}, d, IblVariant::None, false, false, doom).defines();
    };
    const auto has = [](const std::vector<std::string>& defines, const char* define) {
        return std::find(defines.begin(), defines.end(), define) != defines.end();
    };
    const uint64_t specular = SPECULA_MATERIAL_SPECULAR_TEXTURES;
    EXPECT_TRUE(has(make(specular, DebugView::None), "SPECULAR_TEXTURES"));
    EXPECT_TRUE(has(make(specular, DebugView::BrdfF), "SPECULAR_TEXTURES"));
    EXPECT_TRUE(has(make(specular, DebugView::Iridescence), "SPECULAR_TEXTURES"));
    EXPECT_FALSE(has(make(specular, DebugView::BaseColor), "SPECULAR_TEXTURES"));
    EXPECT_FALSE(has(make(specular, DebugView::None, true), "SPECULAR_TEXTURES"));
    EXPECT_FALSE(has(make(0u, DebugView::None), "SPECULAR_TEXTURES"));
    // Above bit 31: the record's flags alone never carry them.
    EXPECT_EQ(uint32_t(specular | SPECULA_MATERIAL_TRANSMISSION_TEXTURES), 0u);
    const uint64_t transmission = SPECULA_MATERIAL_TRANSMISSION | SPECULA_MATERIAL_TRANSMISSION_TEXTURES;
    EXPECT_TRUE(has(make(transmission, DebugView::None), "TRANSMISSION_TEXTURES"));
    EXPECT_FALSE(has(make(SPECULA_MATERIAL_TRANSMISSION_TEXTURES, DebugView::None), "TRANSMISSION_TEXTURES"));
    EXPECT_FALSE(has(make(transmission, DebugView::Normal), "TRANSMISSION_TEXTURES"));
    // KHR_materials_diffuse_transmission: the lobe in the lit frame only, its textures with it.
    const uint64_t diffuse = SPECULA_MATERIAL_DIFFUSE_TRANSMISSION | SPECULA_MATERIAL_DIFFUSE_TRANSMISSION_TEXTURES;
    EXPECT_EQ(uint32_t(diffuse), 0u);
    EXPECT_TRUE(has(make(diffuse, DebugView::None), "DIFFUSE_TRANSMISSION"));
    EXPECT_TRUE(has(make(diffuse, DebugView::None), "DIFFUSE_TRANSMISSION_TEXTURES"));
    EXPECT_FALSE(has(make(SPECULA_MATERIAL_DIFFUSE_TRANSMISSION_TEXTURES, DebugView::None), "DIFFUSE_TRANSMISSION_TEXTURES"));
    EXPECT_FALSE(has(make(diffuse, DebugView::BaseColor), "DIFFUSE_TRANSMISSION"));
    EXPECT_FALSE(has(make(diffuse, DebugView::None, true), "DIFFUSE_TRANSMISSION"));
}
