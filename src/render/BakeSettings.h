#pragma once
/// \file
/// How an environment is baked for image-based lighting, and what a bake reports (no GL: for
/// Renderer.h and the apps; the bake itself is render/ImageBasedLighting, private).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace specula::render {

/// The sizes and sample counts of an environment's bake (Renderer::setEnvironment).
struct BakeSettings {
    std::string name = "default";
    int cubeSize = 256;       ///< base cube map face size
    int prefilterSize = 128;  ///< prefiltered level 0 face size
    int prefilterLevels = 6;  ///< roughness = level / (levels - 1)
    int prefilterSamples = 256;
    int lutSize = 128;        ///< DFG table size (n.v × perceptual roughness)
    int lutSamples = 512;     ///< DFG samples per texel
    /// Cache file name part for these parameters.
    std::string key() const;
};

/// "default", or "reference": the LearnOpenGL tutorial's parameters (512² cube, 128² prefilter
/// with 5 mips and 1024 samples, 512² LUT with 1024 samples) for side-by-side measurements.
std::optional<BakeSettings> bakePreset(std::string_view name);

/// $SPECULA_CACHE_DIR, else $XDG_CACHE_HOME/specula, else ~/.cache/specula.
std::filesystem::path defaultCacheDirectory();

/// What a bake did (Renderer::setEnvironment).
struct BakeReport {
    bool fromCache = false;
    double milliseconds = 0.0;
    std::filesystem::path cacheFile; ///< empty when not cached
};

} // namespace specula::render
