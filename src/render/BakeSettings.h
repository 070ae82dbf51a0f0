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
    /// Base cube map face size; 0: half the map's width (a 1k equirect → 512² faces, 2k →
    /// 1024²), a power of two in 64–1024. A quarter (the map's own texel density at a face's
    /// centre) blurs a mirror by resampling twice: 3.7–4.4 % mean error against the map, 1.6–1.9 %
    /// at half (GlTest.MirrorReflectsTheMapAtItsOwnResolution).
    int cubeSize = 0;
    /// Prefiltered level 0 face size (level 0 is the mirror: roughness 0); 0: the cube's, so
    /// that a mirror reflects the map at its own resolution.
    int prefilterSize = 0;
    /// Roughness = level / (levels − 1); 0: down to 4² faces.
    int prefilterLevels = 0;
    int prefilterSamples = 256;
    int lutSize = 128;        ///< DFG table size (n.v × perceptual roughness)
    int lutSamples = 512;     ///< DFG samples per texel
    /// Cache file name part for these parameters (resolved ones: resolvedFor).
    std::string key() const;
    /// These settings with the sizes left at 0 chosen for a map `mapWidth` texels wide.
    BakeSettings resolvedFor(int mapWidth) const;
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
