#pragma once
// Command-line options of the post-processing passes, shared by `render` and `bench`, and how
// they combine with a scene file's "post" object and camera exposure.
#include <optional>
#include <string>

#include "render/Renderer.h"
#include "scene/SceneFile.h"

namespace CLI {
class App;
}

namespace specula::cli {

/// Unset options come from the scene file, then from the defaults (render/PostSettings.h).
struct PostOptions {
    std::optional<std::string> bloom, ssao, fxaa, autoExposure; ///< on | off
    std::optional<float> bloomIntensity, bloomRadius, bloomThreshold, bloomKnee;
    std::optional<int> bloomLevels;
    std::optional<std::string> bloomFireflyFilter; ///< on | off
    std::optional<float> ssaoRadius, ssaoBias, ssaoPower;
    std::optional<int> ssaoSamples;
    std::optional<float> ev100;
};

void addPostOptions(CLI::App* command, PostOptions& options);

/// Fills the post-processing part of `settings` (passes, their parameters, camera EV100):
/// command line over scene file over defaults. Throws Error on bad values. (--debug-view,
/// shared with the material views, is parsed with the other frame options.)
void resolvePostSettings(const scene::SceneDocument& document, const PostOptions& options, render::FrameSettings& settings);

} // namespace specula::cli
