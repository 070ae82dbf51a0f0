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

/// How setEnvironment bakes what the cache does not hold.
enum class BakeMode {
    Now,         ///< the whole bake before it returns (render, bench, bake, tests)
    Progressive, ///< a small bake before it returns, the full one a step at a time over the
                 ///< frames (advanceBake), swapped in and cached when done (the viewer)
};

/// What a bake did (Renderer::setEnvironment).
struct BakeReport {
    bool fromCache = false;
    /// BakeMode::Progressive: what is ready is a preview (previewSettings) and the full bake is
    /// pending.
    bool progressive = false;
    double milliseconds = 0.0; ///< until the environment was ready to render (a preview's)
    std::filesystem::path cacheFile; ///< empty when not cached
};

/// Where a progressive bake stands (advanceBake).
struct BakeProgress {
    bool pending = false;  ///< steps are left
    bool finished = false; ///< this call swapped in the full bake
    double fraction = 1.0; ///< of its texture reads done
};

/// A progressive bake's preview of `full` (resolved): a cube of at most kPreviewCubeSize²
/// faces, its chain with at most kPreviewSamples samples; equal to `full` when that is as small.
BakeSettings previewSettings(const BakeSettings& full);
inline constexpr int kPreviewCubeSize = 256;
inline constexpr int kPreviewSamples = 32;

} // namespace specula::render
