#pragma once
// Image-based lighting resources: the environment as a mipmapped cube map, its prefiltered
// specular mip chain, its irradiance cube (the diffuse term), its order-2 SH irradiance (the
// BRDF explorer's and the CPU's), and the split-sum DFG table of each BRDF
// variant in use. Bakes run as compute shaders and are cached on disk, keyed by the
// environment's content (or the table's shader source) and the bake parameters.
#include <filesystem>
#include <functional>
#include <memory>

#include "render/BakeSettings.h"
#include "shading/EnvironmentMap.h"
#include "shading/ShadingVariant.h"

namespace specula::gl {
class State;
class Texture;
} // namespace specula::gl

namespace specula::render {

/// The variant whose DFG table a draw shaded with `shading` reads: its D, G and F, the model
/// and diffuse lobe at their defaults (they do not enter the table). F = none reads Schlick's
/// table: with F = f0 both terms scale by f0, E = f0 (scale + bias), and scale + bias is the
/// integral without F, the same for every Fresnel weight.
ResolvedShading dfgVariant(const ResolvedShading& shading);

class ImageBasedLighting {
public:
    ImageBasedLighting();
    ~ImageBasedLighting();
    ImageBasedLighting(ImageBasedLighting&&) noexcept;
    ImageBasedLighting& operator=(ImageBasedLighting&&) noexcept;

    /// Makes the GPU resources for `map`: from the cache when `cacheDirectory` holds them,
    /// else by baking (and then writing the cache, if a directory is given).
    /// BakeMode::Progressive: a preview now and the full bake by advanceBake.
    BakeReport setEnvironment(gl::State& state, const EnvironmentMap& map, const BakeSettings& settings,
                              const std::filesystem::path& cacheDirectory = {}, BakeMode mode = BakeMode::Now);
    /// Runs the pending progressive bake's next steps, waiting for each, until `budgetMs` is
    /// spent (at least one step; all of them with an infinite budget). When the last is done
    /// the full bake replaces the preview (forget cached texture bindings: `finished`) and is
    /// written to the cache.
    BakeProgress advanceBake(gl::State& state, double budgetMs);
    /// A progressive bake's cache file is written by a thread (the frame that finishes the bake
    /// does not wait for the disk): waits until it is (the destructor waits too).
    void waitForCacheWrite();

    bool hasEnvironment() const;
    const Sh9& sh() const;
    /// The cube lighting reads (the importance-sampled specular's source, with box mips).
    const gl::Texture& cube() const;
    /// The cube the sky shows: cube(), or, where the map's sky shows what lighting does not (an
    /// extracted sun, EnvironmentMap::skyOnly), a cube of its own made from skyOf(map).
    const gl::Texture& sky() const;
    /// The blurred sky's chain: prefiltered(), or the sky's own, baked as the map's is.
    const gl::Texture& skyPrefiltered() const;
    const gl::Texture& prefiltered() const;
    /// E(n) in lux, kIrradianceSize² faces (shading/EnvironmentMap: the exact cosine
    /// convolution of the map, not its SH).
    const gl::Texture& irradiance() const;
    /// The environment's brightest parts, taken out of the irradiance cube and summed per pixel
    /// (EnvironmentData::bright*), at most kIrradianceBrightSources.
    const std::vector<IrradianceSource>& brightSources() const;
    /// How many of the bright sources (the first, brightest) the specular lobe takes as lights
    /// too (ibl/bright_sources.glsl): those holding 98 % of the sources' flux
    /// (leadingSourceCount), when they hold at least kSourcesSpecularShare of the map's (a
    /// studio's softboxes, a sun), where box mips or the prefilter would spread them across a
    /// rough lobe's horizon; else 0.
    int specularSourceCount() const;
    bool brightSourcesSpecular() const { return specularSourceCount() > 0; }
    static constexpr float kSourcesSpecularShare = 0.2f;
    /// The environment cube less what the bright sources stand for (their texels black), with
    /// box-filtered mips, and the prefiltered chain's levels kResidualFirstLevel.. made from it
    /// (its level 0 is the chain's kResidualFirstLevel): baked and cached when
    /// brightSourcesSpecular(). Below that level the split sum reads the whole map's chain.
    const gl::Texture& residualCube() const;
    const gl::Texture& residualPrefiltered() const;
    static constexpr int kResidualFirstLevel = 1;
    /// The split-sum DFG table of dfgVariant(shading): baked on first use by
    /// shaders/ibl/dfg.comp compiled with the variant's defines (the forward pass's), and
    /// cached on disk (setLutCacheDirectory) under a name that holds the variant, the table
    /// size and samples, and a hash of the compiled source. Kept until the table parameters
    /// of setEnvironment's settings change.
    const gl::Texture& dfg(gl::State& state, const ResolvedShading& shading);
    /// Whether dfg(shading) is ready.
    bool hasDfg(const ResolvedShading& shading) const;
    /// KHR_materials_sheen's table: the Charlie lobe's directional albedo E(n.v, sheen perceptual
    /// roughness) in R, one for every variant (the lobe has no D, G or F choices). Baked on first
    /// use by shaders/ibl/sheen_albedo.comp at the DFG table's size with kSheenAlbedoSampleFactor x
    /// its samples (the lobe's half vectors near the horizon send most reflections below it), and
    /// cached on disk as the DFG tables are.
    const gl::Texture& sheenAlbedo(gl::State& state);
    static constexpr int kSheenAlbedoSampleFactor = 4;
    void setLutCacheDirectory(const std::filesystem::path& directory);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
