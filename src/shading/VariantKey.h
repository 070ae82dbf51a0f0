#pragma once
// The forward pass's variant key: every compile-time choice of its program as bits and small
// fields of one integer, and the one table that maps them to the defines of shaders/forward/
// and shaders/brdf/brdf.glsl. The renderer keys its program cache with it; the glslangValidator
// test (tests/unit/test_glslang.cpp) walks the same table, so no list of defines is kept by hand.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "settings/DebugView.h"
#include "shading/ShadingVariant.h"

namespace specula::render {

/// One row of the table: the define is set when (key & mask) == value.
struct VariantDefine {
    uint64_t mask;
    uint64_t value;
    const char* define;
    /// The row's group: flags combine freely; rows of one field exclude each other.
    enum class Kind : uint8_t { MaterialFeature, FrameFeature, DebugView, ShadingModel, Brdf, Shadow } kind;
};

/// What this frame's shadow maps ask of the forward program (lights/shadow.glsl): which kinds
/// of shadowed light there are, the filter and its size. Compiled in, so that the program holds
/// only the paths the frame uses — a CPU rasteriser (llvmpipe) runs every side of a branch.
/// No kind: no SHADOWS variant at all.
struct ShadowVariant {
    bool directional = false, spot = false, point = false;
    int filter = 1; ///< SPECULA_SHADOW_FILTER_* (shaders/shared/ShadowData.h): 0 hard, 1 PCF, 2 PCSS
    int taps = 16;  ///< PCSS's disc taps: 16 or 32
    int tent = 3;   ///< PCF's tent, texels across: 3 or 5
    bool tint = false; ///< SHADOW_TINT: the tint map of surfaces that let light through (render::tintsShadow)
    bool active() const { return directional || spot || point; }
    bool operator==(const ShadowVariant&) const = default;
};

/// What the frame's lights ask of the forward program (lights/punctual.glsl, light_list.glsl):
/// the kinds it has — a kind no light has is compiled out (NO_DIRECTIONAL_LIGHTS,
/// NO_POINT_LIGHTS, NO_SPOT_LIGHTS) — and whether every light is evaluated at every shading
/// point (LIGHTS_ALL, the brute-force frame), then, when they are few, how many (LIGHT_COUNT: a
/// constant trip count, so the loop is unrolled). Compiled in for ShadowVariant's reason: on
/// llvmpipe the learnopengl forward pass took 40 ms, 35 without the kinds' branches, 28 with
/// the constant count too (docs/performance.md). The price: adding or removing a light, or
/// changing its kind, makes the forward programs again; editing one does not.
struct LightVariant {
    bool all = false; ///< LIGHTS_ALL
    int count = -1;   ///< with `all`: the frame's light count when at most kMaxConstantCount, else -1
    /// With a count of at least one: the lights themselves are constants of the program
    /// (LIGHT_CONSTANTS, their values in LIGHT_VALUES, written by render/passes/ForwardPass
    /// while the lights stay still), not texels read per pixel.
    bool constants = false;
    bool directional = true, point = true, spot = true;
    static constexpr int kMaxConstantCount = 16;
    bool operator==(const LightVariant&) const = default;
};

/// Image-based light in the forward program: none, the split sum (IBL), or the split sum's
/// diffuse with the specular lobe importance-sampled per pixel (IBL + IBL_IMPORTANCE).
enum class IblVariant : uint8_t { None, SplitSum, Importance };

/// Every row, in the order the defines are emitted.
std::span<const VariantDefine> forwardVariantTable();

struct IrradianceSource; // shading/EnvironmentMap.h

/// The forward programs' IBL_SOURCE_COUNT, IBL_SOURCE_DIRECTIONS, IBL_SOURCE_FLUXES and
/// IBL_SOURCE_SPREADS: an
/// environment's bright sources as constants of the code (ibl/ibl.glsl), each float exactly.
std::vector<std::string> irradianceSourceDefines(std::span<const IrradianceSource> sources);

struct ForwardVariant {
    uint64_t key = 0;

    /// The program reads its lights from LIGHT_VALUES (LightVariant::constants).
    bool lightConstants() const;

    /// `features`: SPECULA_MATERIAL_* bits (the shading bits above them are ignored: pass the
    /// resolved shading). A model other than the physically based one has no BRDF choices, so
    /// its key holds none and variants that differ only there share one program. `shadows`:
    /// the frame's shadow maps (SHADOWS and SHADOW_*: lights/shadow.glsl samples them).
    /// `lights`: the frame's kinds of light, LIGHTS_ALL and LIGHT_COUNT. `oit`: blended draws write weighted blended OIT's targets (OIT).
    static ForwardVariant make(uint64_t features, const ResolvedShading& shading, DebugView debugView, IblVariant ibl,
                               bool energyCompensation, bool ssao, bool doomIndexed, const ShadowVariant& shadows = {},
                               const LightVariant& lights = {}, bool oit = false);

    ResolvedShading shading() const;
    /// The material or BRDF debug view the key selects, if any.
    bool debugView() const;
    /// Whether the key has KHR_materials_sheen's lobe (SHEEN): its program samples the sheen albedo table.
    bool sheen() const;
    /// The table's defines, then LIGHT_COUNT (a field with a value, outside the table).
    std::vector<std::string> defines() const;
    /// The defines joined by ';' (program labels).
    std::string name() const;
    bool operator==(const ForwardVariant&) const = default;
};

/// Whether `view` replaces shading in the forward pass (a material or BRDF view; the SSAO,
/// bloom and shadow-atlas views are passes of their own).
bool isMaterialDebugView(DebugView view);

} // namespace specula::render
