#include "PostOptions.h"

#include <CLI/CLI.hpp>

#include <cmath>

#include "core/Error.h"

namespace specula::cli {
namespace {

/// "on" / "off" of `flag` (already restricted to those by CLI11), else the file's, else `fallback`.
bool onOff(const std::optional<std::string>& option, std::optional<bool> file, bool fallback)
{
    if (option) return *option == "on";
    return file.value_or(fallback);
}

template <typename T>
T pick(const std::optional<T>& option, const std::optional<T>& file, T fallback)
{
    return option ? *option : file.value_or(fallback);
}

void check(bool ok, const char* flag, const char* requirement, double value)
{
    if (!ok) throw Error("{} {} (got {})", flag, requirement, value);
}

} // namespace

void addPostOptions(CLI::App* command, PostOptions& o)
{
    const auto onOffCheck = CLI::IsMember({"on", "off"});
    command->add_option("--bloom", o.bloom, "bloom (compute shaders): on or off (default)")->check(onOffCheck);
    command->add_option("--bloom-intensity", o.bloomIntensity, "fraction of the frame's energy added as glow (default 0.04)");
    command->add_option("--bloom-levels", o.bloomLevels, "down-sampled levels, 1 to 8 (default 6): each doubles the reach");
    command->add_option("--bloom-radius", o.bloomRadius, "up-sampling tent spread in texels (default 1)");
    command->add_option("--bloom-threshold", o.bloomThreshold,
                        "only what exceeds this exposed pixel value blooms, soft knee (default 0: all light blooms)");
    command->add_option("--bloom-knee", o.bloomKnee, "soft-knee half-width as a fraction of the threshold, 0 to 1 (default 0.5)");
    command->add_option("--bloom-firefly-filter", o.bloomFireflyFilter,
                        "Karis average on the first level, on (default) or off (then bloom conserves energy exactly)")
        ->check(onOffCheck);
    command->add_option("--ssao", o.ssao, "screen-space ambient occlusion: on or off (default)")->check(onOffCheck);
    command->add_option("--ssao-radius", o.ssaoRadius, "hemisphere radius in metres (default 0.5)");
    command->add_option("--ssao-bias", o.ssaoBias, "depth bias in metres (default 0.025)");
    command->add_option("--ssao-power", o.ssaoPower, "occlusion exponent (default 1.5)");
    command->add_option("--ssao-samples", o.ssaoSamples, "samples per pixel, 1 to 64 (default 16)");
    command->add_option("--fxaa", o.fxaa, "FXAA 3.11 on the tone-mapped image: on or off (default)")->check(onOffCheck);
    command->add_option("--auto-exposure", o.autoExposure,
                        "exposure from a luminance histogram: on or off (default); --exposure then compensates")
        ->check(onOffCheck);
    command->add_option("--ev100", o.ev100, "physical camera exposure 1 / (1.2 x 2^EV100), times 2^--exposure");
}

void resolvePostSettings(const scene::SceneDocument& document, const PostOptions& o, render::FrameSettings& s)
{
    const scene::PostFileSettings& file = document.post;

    render::BloomSettings& bloom = s.bloom;
    bloom.enabled = onOff(o.bloom, file.bloom.enabled, bloom.enabled);
    bloom.intensity = pick(o.bloomIntensity, file.bloom.intensity, bloom.intensity);
    bloom.levels = pick(o.bloomLevels, file.bloom.levels, bloom.levels);
    bloom.radius = pick(o.bloomRadius, file.bloom.radius, bloom.radius);
    bloom.threshold = pick(o.bloomThreshold, file.bloom.threshold, bloom.threshold);
    bloom.knee = pick(o.bloomKnee, file.bloom.knee, bloom.knee);
    bloom.fireflyFilter = onOff(o.bloomFireflyFilter, file.bloom.fireflyFilter, bloom.fireflyFilter);
    check(bloom.intensity >= 0.0f, "--bloom-intensity", "must not be negative", bloom.intensity);
    check(bloom.levels >= 1 && bloom.levels <= 8, "--bloom-levels", "must be between 1 and 8", bloom.levels);
    check(bloom.radius > 0.0f, "--bloom-radius", "must be positive", bloom.radius);
    check(bloom.threshold >= 0.0f, "--bloom-threshold", "must not be negative", bloom.threshold);
    check(bloom.knee >= 0.0f && bloom.knee <= 1.0f, "--bloom-knee", "must be between 0 and 1", bloom.knee);

    render::SsaoSettings& ssao = s.ssao;
    ssao.enabled = onOff(o.ssao, file.ssao.enabled, ssao.enabled);
    ssao.radius = pick(o.ssaoRadius, file.ssao.radius, ssao.radius);
    ssao.bias = pick(o.ssaoBias, file.ssao.bias, ssao.bias);
    ssao.power = pick(o.ssaoPower, file.ssao.power, ssao.power);
    ssao.samples = pick(o.ssaoSamples, file.ssao.samples, ssao.samples);
    check(ssao.radius > 0.0f, "--ssao-radius", "must be positive", ssao.radius);
    check(ssao.bias >= 0.0f, "--ssao-bias", "must not be negative", ssao.bias);
    check(ssao.power > 0.0f, "--ssao-power", "must be positive", ssao.power);
    check(ssao.samples >= 1 && ssao.samples <= 64, "--ssao-samples", "must be between 1 and 64", ssao.samples);

    render::AutoExposureSettings& automatic = s.autoExposure;
    const auto& fileAuto = file.autoExposure;
    automatic.enabled = onOff(o.autoExposure, fileAuto.enabled, automatic.enabled);
    automatic.minEv100 = fileAuto.minEv100.value_or(automatic.minEv100);
    automatic.maxEv100 = fileAuto.maxEv100.value_or(automatic.maxEv100);
    automatic.lowPercentile = fileAuto.lowPercentile.value_or(automatic.lowPercentile);
    automatic.highPercentile = fileAuto.highPercentile.value_or(automatic.highPercentile);
    automatic.speedUp = fileAuto.speedUp.value_or(automatic.speedUp);
    automatic.speedDown = fileAuto.speedDown.value_or(automatic.speedDown);

    s.fxaa.enabled = onOff(o.fxaa, file.fxaa, s.fxaa.enabled);

    // The camera: --ev100, else the file's render.ev100 or camera aperture/shutter/ISO.
    if (o.ev100) {
        s.ev100 = *o.ev100;
    } else if (document.render.ev100) {
        s.ev100 = *document.render.ev100;
    } else if (const auto& camera = document.render.cameraExposure) {
        s.ev100 = render::ev100FromCamera(camera->aperture, camera->shutter, camera->iso);
    }
    if (s.ev100) check(std::isfinite(*s.ev100), "--ev100", "must be a finite number", *s.ev100);
}

} // namespace specula::cli
