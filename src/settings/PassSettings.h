#pragma once
// Parameters of the post-processing passes (bloom, SSAO, exposure, FXAA): plain data held by
// render::FrameSettings, each declared once with its table (settingsTable<T>(), the .cpp), which
// the command line, the scene file's "post" object and the viewer all read. Every pass is off by
// default, and a pass that is off costs nothing: no target is allocated, no program compiled,
// no dispatch issued.
//
// A new field is one member here and one row in its table.
#include "settings/SettingField.h"

namespace specula {

/// Physically based bloom (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
/// Advanced Warfare"): the frame plus `intensity` × an energy-preserving wide blur of itself.
struct BloomSettings {
    bool enabled = false;
    /// Fraction of the frame's energy added back as glow: Σ(out − in) = intensity × Σ in.
    float intensity = 0.04f;
    /// Down-sampled levels (1–8); each doubles the glow's reach.
    int levels = 6;
    /// Spread of the 3×3 tent filter of each up-sampling step, in texels of the level read.
    float radius = 1.0f;
    /// 0 = every pixel blooms (the physically based default). Above 0, only what exceeds
    /// `threshold` (pixel value after the frame's manual exposure) blooms, with a quadratic
    /// soft knee of half-width `knee` × threshold, for stylised looks.
    float threshold = 0.0f;
    float knee = 0.5f;
    /// Karis's luma-weighted average on the first down-sample, so that a single very bright
    /// pixel cannot dominate (and flicker) the glow. It deliberately takes energy from
    /// isolated highlights; with it off bloom conserves energy exactly.
    bool fireflyFilter = true;
};

/// Screen-space ambient occlusion (Crytek 2007; the normal-oriented hemisphere of
/// LearnOpenGL's "SSAO"). Darkens ambient (image-based) light only, never direct light.
struct SsaoSettings {
    bool enabled = false;
    float radius = 0.5f;   ///< hemisphere radius, metres (view space)
    float bias = 0.025f;   ///< metres a sample must lie behind the surface to occlude
    float power = 1.5f;    ///< ao = (1 − occluded fraction)^power
    int samples = 16;      ///< hemisphere samples per pixel, 1–64
};

/// Automatic exposure from a luminance histogram (compute shader). The measured average
/// luminance L sets EV100 = log2(L × 100 / 12.5) (reflected-light meter, K = 12.5), clamped
/// to [minEv100, maxEv100]; exposure = 1 / (1.2 × 2^EV100) (Lagarde & de Rousiers 2014).
struct AutoExposureSettings {
    bool enabled = false;
    float minEv100 = -6.0f;
    float maxEv100 = 18.0f;
    /// Fractions of the (non-black) pixels ignored at the dark and the bright end of the
    /// histogram, so that a few very dark or bright pixels do not swing the exposure.
    float lowPercentile = 0.10f;
    float highPercentile = 0.95f;
    /// Exponential adaptation rates (1/s) towards a brighter and a darker scene.
    float speedUp = 3.0f;
    float speedDown = 1.0f;
    /// Seconds since the previous frame. 0 = converge within this frame (still renders).
    /// The frame's clock, not a setting: the viewer sets it each frame; it has no table row.
    float deltaTime = 0.0f;
};

/// FXAA 3.11 (Lottes 2011) on the tone-mapped image, instead of or on top of MSAA.
struct FxaaSettings {
    bool enabled = false;
};

/// Shadow maps (render/passes/ShadowPass): on by default, unlike the post passes. Resolution
/// and kernel come from `quality`, the filter from `filter` (their own flags, --shadow-quality
/// and --shadow-filter: names, not numbers, so not table rows).
enum class ShadowQuality { Low, Medium, High };
enum class ShadowFilter { Hard, Pcf, Pcss };

struct ShadowSettings {
    bool enabled = true;
    /// Cascades of each directional light's map (1–4), split by the practical scheme with λ
    /// `cascadeSplit` (0 uniform, 1 logarithmic).
    int cascades = 4;
    float cascadeSplit = 0.8f;
    /// Metres from the camera the cascades reach; 0 = the view's far plane, or the scene's
    /// farthest point if that is nearer.
    float distance = 0.0f;
    /// Fraction of each cascade's depth range over which it blends into the next.
    float cascadeBlend = 0.1f;
    /// Normal-offset bias in texels of the map (scaled by sin θ of the light's incidence).
    float normalBias = 1.5f;
    /// Slope-scaled and constant depth bias of the shadow pass (glPolygonOffset).
    float slopeBias = 3.0f;
    float constantBias = 2.0f;
    /// Spot and point lights given a map, by screen importance; more are left out and counted.
    int maxLights = 64;
    /// Directional lights given cascades.
    int maxDirectional = 4;
    /// Scales every light's size (its soft shadows' penumbra, PCSS).
    float lightSize = 1.0f;
    /// Keep a map while nothing in it changed; off: every map is drawn every frame (to measure).
    bool cache = true;
    /// Coloured and partial shadows from surfaces that let light through (the tint map:
    /// render::tintsShadow); off: they cast none, and frames skip its lookup (on llvmpipe about
    /// a third of the demo's frame, docs/shadows.md).
    bool tint = true;
    ShadowQuality quality = ShadowQuality::Medium;
    ShadowFilter filter = ShadowFilter::Pcf;
};

const char* shadowQualityName(ShadowQuality quality);
const char* shadowFilterName(ShadowFilter filter);

/// Each pass's table; defined for the structs above.
template <typename T>
const SettingsTable<T>& settingsTable();
template <>
const SettingsTable<BloomSettings>& settingsTable<BloomSettings>();
template <>
const SettingsTable<SsaoSettings>& settingsTable<SsaoSettings>();
template <>
const SettingsTable<AutoExposureSettings>& settingsTable<AutoExposureSettings>();
template <>
const SettingsTable<FxaaSettings>& settingsTable<FxaaSettings>();
template <>
const SettingsTable<ShadowSettings>& settingsTable<ShadowSettings>();

/// What one source (the scene file's "post", the command line) sets of each pass.
struct PostOverrides {
    SettingsOverride<BloomSettings> bloom;
    SettingsOverride<SsaoSettings> ssao;
    SettingsOverride<FxaaSettings> fxaa;
    SettingsOverride<AutoExposureSettings> autoExposure;
    SettingsOverride<ShadowSettings> shadows;
};

/// Calls f(s.shadows...), f(s.bloom...), f(s.ssao...), f(s.fxaa...), f(s.autoExposure...): the
/// same pass of each of `s` (structs with those members: render::FrameSettings, PostOverrides),
/// passes in the order the command line's help lists them.
template <typename F, typename... S>
void forEachPass(F&& f, S&... s)
{
    f(s.shadows...);
    f(s.bloom...);
    f(s.ssao...);
    f(s.fxaa...);
    f(s.autoExposure...);
}

} // namespace specula
