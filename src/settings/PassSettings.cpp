#include "settings/PassSettings.h"

namespace specula {

namespace {

using Range = SettingRange;

// Each pass's fields in the struct's order, which is the order of the command line's help, the
// scene file's checks and the viewer's widgets. A slider is given where the range is open.

constexpr SettingField<BloomSettings> kBloom[] = {
    {.name = "enabled", .member = &BloomSettings::enabled, .help = "bloom (compute shaders)"},
    {.name = "intensity", .member = &BloomSettings::intensity, .help = "fraction of the frame's energy added as glow",
     .range = Range::nonNegative(), .slider = Range::between(0, 1)},
    {.name = "levels", .member = &BloomSettings::levels, .help = "down-sampled levels, each doubling the glow's reach",
     .range = Range::between(1, 8)},
    {.name = "radius", .member = &BloomSettings::radius, .help = "up-sampling tent spread in texels", .range = Range::positive(),
     .slider = Range::between(0.1, 4)},
    {.name = "threshold", .member = &BloomSettings::threshold,
     .help = "0: all light blooms; above 0 only what exceeds this exposed pixel value, with a soft knee",
     .range = Range::nonNegative(), .slider = Range::between(0, 100)},
    {.name = "knee", .member = &BloomSettings::knee, .help = "soft-knee half-width as a fraction of the threshold",
     .range = Range::between(0, 1)},
    {.name = "fireflyFilter", .member = &BloomSettings::fireflyFilter,
     .help = "Karis average on the first level (off: bloom conserves energy exactly)"},
};

constexpr SettingField<SsaoSettings> kSsao[] = {
    {.name = "enabled", .member = &SsaoSettings::enabled, .help = "screen-space ambient occlusion"},
    {.name = "radius", .member = &SsaoSettings::radius, .help = "hemisphere radius in metres", .range = Range::positive(),
     .slider = Range::between(0.01, 5), .label = "radius (m)"},
    {.name = "bias", .member = &SsaoSettings::bias, .help = "depth bias in metres", .range = Range::nonNegative(),
     .slider = Range::between(0, 0.2), .label = "bias (m)"},
    {.name = "power", .member = &SsaoSettings::power, .help = "occlusion exponent", .range = Range::positive(),
     .slider = Range::between(0.1, 4)},
    {.name = "samples", .member = &SsaoSettings::samples, .help = "samples per pixel", .range = Range::between(1, 64)},
};

// Only the switch is a flag; the rest is the scene file's and the viewer's.
constexpr SettingField<AutoExposureSettings> kAutoExposure[] = {
    {.name = "enabled", .member = &AutoExposureSettings::enabled,
     .help = "exposure from a luminance histogram (--exposure then compensates)"},
    {.name = "minEv100", .member = &AutoExposureSettings::minEv100, .help = "the lowest EV100 it picks",
     .slider = Range::between(-10, 20), .label = "min EV100", .commandLine = false},
    {.name = "maxEv100", .member = &AutoExposureSettings::maxEv100, .help = "the highest EV100 it picks",
     .slider = Range::between(-10, 20), .label = "max EV100", .commandLine = false},
    {.name = "lowPercentile", .member = &AutoExposureSettings::lowPercentile,
     .help = "fraction of the pixels ignored at the dark end", .range = Range::between(0, 1), .slider = Range::between(0, 0.5),
     .commandLine = false},
    {.name = "highPercentile", .member = &AutoExposureSettings::highPercentile,
     .help = "fraction of the pixels below the bright end ignored", .range = Range::between(0, 1),
     .slider = Range::between(0.5, 1), .commandLine = false},
    {.name = "speedUp", .member = &AutoExposureSettings::speedUp, .help = "adaptation rate towards a brighter scene, 1/s",
     .range = Range::nonNegative(), .slider = Range::between(0, 20), .label = "speed up (1/s)", .commandLine = false},
    {.name = "speedDown", .member = &AutoExposureSettings::speedDown, .help = "adaptation rate towards a darker scene, 1/s",
     .range = Range::nonNegative(), .slider = Range::between(0, 20), .label = "speed down (1/s)", .commandLine = false},
};

constexpr SettingOrder<AutoExposureSettings> kAutoExposureOrders[] = {
    {&AutoExposureSettings::minEv100, &AutoExposureSettings::maxEv100},
    {&AutoExposureSettings::lowPercentile, &AutoExposureSettings::highPercentile},
};

constexpr SettingField<FxaaSettings> kFxaa[] = {
    {.name = "enabled", .member = &FxaaSettings::enabled, .help = "FXAA 3.11 on the tone-mapped image"},
};

constexpr SettingField<ShadowSettings> kShadows[] = {
    {.name = "enabled", .member = &ShadowSettings::enabled, .help = "shadow maps for every light that casts"},
    {.name = "cascades", .member = &ShadowSettings::cascades, .help = "cascades of a directional light",
     .range = Range::between(1, 4)},
    {.name = "cascadeSplit", .member = &ShadowSettings::cascadeSplit,
     .help = "lambda of the practical split scheme (0 uniform, 1 logarithmic)", .range = Range::between(0, 1)},
    {.name = "distance", .member = &ShadowSettings::distance,
     .help = "metres the cascades reach (0: the far plane or the scene's far side)", .range = Range::nonNegative(),
     .slider = Range::between(0, 500), .label = "distance (m)"},
    {.name = "cascadeBlend", .member = &ShadowSettings::cascadeBlend, .help = "fraction of a cascade blended into the next",
     .range = Range::between(0, 0.5)},
    {.name = "normalBias", .member = &ShadowSettings::normalBias, .help = "normal-offset bias in texels",
     .range = Range::nonNegative(), .slider = Range::between(0, 5)},
    {.name = "slopeBias", .member = &ShadowSettings::slopeBias, .help = "slope-scaled depth bias of the shadow pass",
     .range = Range::nonNegative(), .slider = Range::between(0, 8)},
    {.name = "constantBias", .member = &ShadowSettings::constantBias, .help = "constant depth bias of the shadow pass",
     .range = Range::nonNegative(), .slider = Range::between(0, 16)},
    {.name = "maxLights", .member = &ShadowSettings::maxLights, .help = "spot and point lights given a map, by importance",
     .range = Range::between(0, 1024), .slider = Range::between(0, 256)},
    {.name = "maxDirectional", .member = &ShadowSettings::maxDirectional, .help = "directional lights given cascades",
     .range = Range::between(0, 4)},
    {.name = "lightSize", .member = &ShadowSettings::lightSize, .help = "scale of every light's size (PCSS penumbrae)",
     .range = Range::nonNegative(), .slider = Range::between(0, 10)},
    {.name = "cache", .member = &ShadowSettings::cache, .help = "keep maps whose lights and casters did not change"},
    {.name = "tint", .member = &ShadowSettings::tint,
     .help = "coloured and partial shadows from glass and blended surfaces (the tint map)"},
};

} // namespace

const char* shadowQualityName(ShadowQuality quality)
{
    switch (quality) {
    case ShadowQuality::Low: return "low";
    case ShadowQuality::Medium: return "medium";
    case ShadowQuality::High: return "high";
    }
    return "medium";
}

const char* shadowFilterName(ShadowFilter filter)
{
    switch (filter) {
    case ShadowFilter::Hard: return "hard";
    case ShadowFilter::Pcf: return "pcf";
    case ShadowFilter::Pcss: return "pcss";
    }
    return "pcf";
}

template <>
const SettingsTable<ShadowSettings>& settingsTable<ShadowSettings>()
{
    static const SettingsTable<ShadowSettings> table{"shadows", "shadows", kShadows};
    return table;
}

template <>
const SettingsTable<BloomSettings>& settingsTable<BloomSettings>()
{
    static const SettingsTable<BloomSettings> table{"bloom", "bloom", kBloom};
    return table;
}

template <>
const SettingsTable<SsaoSettings>& settingsTable<SsaoSettings>()
{
    static const SettingsTable<SsaoSettings> table{"ssao", "SSAO", kSsao};
    return table;
}

template <>
const SettingsTable<AutoExposureSettings>& settingsTable<AutoExposureSettings>()
{
    static const SettingsTable<AutoExposureSettings> table{"autoExposure", "auto exposure", kAutoExposure, kAutoExposureOrders};
    return table;
}

template <>
const SettingsTable<FxaaSettings>& settingsTable<FxaaSettings>()
{
    static const SettingsTable<FxaaSettings> table{"fxaa", "FXAA", kFxaa};
    return table;
}

} // namespace specula
