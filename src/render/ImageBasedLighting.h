#pragma once
// Image-based lighting resources: the environment as a mipmapped cube map, its prefiltered
// specular mip chain, its order-2 SH irradiance, and the split-sum DFG tables. Bakes run as
// compute shaders and are cached on disk, keyed by the environment's content and the bake
// parameters.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "render/EnvironmentMap.h"

namespace specula::gl {
class Texture;
}

namespace specula::render {

struct BakeSettings {
    std::string name = "default";
    int cubeSize = 256;       ///< base cube map face size
    int prefilterSize = 128;  ///< prefiltered level 0 face size
    int prefilterLevels = 6;  ///< roughness = level / (levels - 1)
    int prefilterSamples = 256;
    int lutSize = 128;
    int lutSamples = 512;
    /// Cache file name part for these parameters.
    std::string key() const;
};

/// "default", or "reference": the LearnOpenGL tutorial's parameters (512² cube, 128² prefilter
/// with 5 mips and 1024 samples, 512² LUT with 1024 samples) for side-by-side measurements.
std::optional<BakeSettings> bakePreset(std::string_view name);

/// $SPECULA_CACHE_DIR, else $XDG_CACHE_HOME/specula, else ~/.cache/specula.
std::filesystem::path defaultCacheDirectory();

struct BakeReport {
    bool fromCache = false;
    double milliseconds = 0.0;
    std::filesystem::path cacheFile; ///< empty when not cached
};

class ImageBasedLighting {
public:
    ImageBasedLighting();
    ~ImageBasedLighting();
    ImageBasedLighting(ImageBasedLighting&&) noexcept;
    ImageBasedLighting& operator=(ImageBasedLighting&&) noexcept;

    /// Makes the GPU resources for `map`: from the cache when `cacheDirectory` holds them,
    /// else by baking (and then writing the cache, if a directory is given).
    BakeReport setEnvironment(const EnvironmentMap& map, const BakeSettings& settings,
                              const std::filesystem::path& cacheDirectory = {});

    bool hasEnvironment() const;
    const Sh9& sh() const;
    const gl::Texture& cube() const;
    const gl::Texture& prefiltered() const;
    /// The DFG table for the separable Smith term (schlick = false) or Schlick-GGX with
    /// k = r²/2; computed on first use (and cached on disk with the same directory rules).
    const gl::Texture& dfg(bool schlickGgx);
    void setLutCacheDirectory(const std::filesystem::path& directory);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
