#pragma once
// Environments on the CPU: equirectangular radiance (cd/m²), the direction convention, the
// procedural sky, and order-2 spherical harmonics for irradiance. No GL here.
//
// Convention: +Y is up; a world direction d maps to u = 0.5 + atan2(d.x, -d.z) / 2π,
// v = acos(d.y) / π, (0, 0) the top-left pixel. An environment rotated by `rotation`
// degrees about +Y shows at world direction d what the file holds at Ry(-rotation) d.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace specula::render {

/// A sun taken out of a map (shading/SunExtraction.h, --env-sun extract): the directional light
/// that stands for it.
struct ExtractedSun {
    glm::vec3 direction{0.0f, 1.0f, 0.0f}; ///< towards the sun, environment space (unit)
    glm::vec3 illuminance{0.0f};           ///< lux on a surface facing it, RGB
    /// Radians: the disc with the region's second moment of angle about its centre (a uniform
    /// disc of radius ρ has a mean θ² of ρ²/2), so a dim halo around the sun hardly widens it.
    float angularDiameter = 0.0f;
    int texels = 0;                        ///< texels the region covered
};

/// Equirectangular linear radiance, RGB 32-bit float, top row first.
struct EnvironmentMap {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> texels;
    /// Identifies the content for the bake cache (a hash of the file bytes or of the parameters).
    std::string key;
    /// Texels the sky shows brighter than lighting sees them: what a light took out of the map
    /// (the extracted sun, shading/SunExtraction), as (index into `texels`, the radiance the
    /// sky shows there). Empty for a map as loaded. The bake makes the sky's cube from
    /// skyOf(map) and everything that lights from `texels`.
    struct SkyTexel {
        size_t index;
        glm::vec3 radiance;
    };
    std::vector<SkyTexel> skyOnly;
    /// The sun taken out of `texels` (extractSun), in environment space: lighting must add it
    /// back as a directional light (setup::environmentSunLight), turned and scaled with the map.
    std::optional<ExtractedSun> sun;

    glm::vec3 at(int x, int y) const { return texels[size_t(y) * size_t(width) + size_t(x)]; }
    /// Bilinear lookup in direction d (environment space), wrapping in u.
    glm::vec3 sample(const glm::vec3& d) const;
};

/// The irradiance cube's face size and its bake's source resolution (docs/ibl.md: measured).
constexpr int kIrradianceSize = 32;
constexpr int kIrradianceSourceWidth = 256;
constexpr int kIrradianceCubeSourceWidth = 64;
constexpr int kIrradianceBrightSources = 32; // = SPECULA_IBL_BRIGHT_SOURCES

struct SkyParams {
    glm::vec3 sunDirection = glm::normalize(glm::vec3(0.4f, 0.55f, -0.7f)); ///< towards the sun
    float sunIlluminance = 6.0f;                      ///< lux on a surface facing the sun
    float sunAngularRadius = glm::radians(1.5f);      ///< larger than the real 0.27° to be visible at 1k
    glm::vec3 zenith{0.06f, 0.12f, 0.3f};             ///< cd/m²
    glm::vec3 horizon{0.3f, 0.33f, 0.36f};
    glm::vec3 ground{0.08f, 0.075f, 0.07f};
};

glm::vec2 directionToEquirect(const glm::vec3& d);
glm::vec3 equirectToDirection(const glm::vec2& uv);
/// Rotation about +Y by `degrees` (applied to environment-space directions to get world ones).
glm::mat3 environmentRotation(float degrees);

/// Reads .hdr or .exr (negatives clamped to 0, 32-bit float kept); key = hash of the file bytes.
EnvironmentMap loadEnvironmentMap(const std::filesystem::path& path);
EnvironmentMap constantEnvironment(const glm::vec3& radiance);
/// `map` box-filtered down to fit `maxSize` on both sides, keeping its aspect ratio (each output
/// texel the mean radiance of the source texels its footprint covers, at least one); the same
/// map when it fits. Its key names the new size (the bake cache keeps them apart).
EnvironmentMap downscaledToFit(const EnvironmentMap& map, int maxSize);
/// What the sky shows: `map` with its skyOnly texels in place (and none left over).
EnvironmentMap skyOf(const EnvironmentMap& map);
EnvironmentMap proceduralSky(const SkyParams& params = {}, int width = 512);

/// Order-2 (9-coefficient) real spherical harmonics of the radiance, projected with the exact
/// solid angle of each equirectangular texel, (cos θ0 − cos θ1) Δφ.
using Sh9 = std::array<glm::vec3, 9>;
Sh9 projectSh9(const EnvironmentMap& map);
/// Irradiance E(n) = ∫ L(ω) max(0, n·ω) dω (lux) by brute force over every texel of `map`
/// with its exact solid angle: the reference the irradiance cube is tested against.
glm::vec3 bruteForceIrradiance(const EnvironmentMap& map, const glm::vec3& n);

/// Direction of texel centre st ∈ [0, 1]² of cube face 0..5 (+X, −X, +Y, −Y, +Z, −Z, t down
/// the face: OpenGL's convention, as shaders/ibl/cube.glsl).
glm::vec3 cubeDirection(int face, const glm::vec2& st);

/// The map reduced for the irradiance bake: blocks of texels, each the sum of its texels'
/// radiance × solid angle (flux per unit area, lux at normal incidence), seen from the
/// radiance-weighted centroid of their directions (so a sun keeps its direction). At most
/// `sourceWidth` × sourceWidth/2 of them.
struct IrradianceSource {
    glm::vec3 direction;
    glm::vec3 flux;
    /// How far its light spreads about `direction`: the half-width s (radians) of a band of
    /// uniform light with the same second moment of angle, s² = 1.5 ⟨θ²⟩ (a block of uniform
    /// texels: half its width; a sun: 0.87 × its angular radius). 0: a point (the cube's
    /// sources of splitIrradiance).
    float spread = 0.0f;
};
/// What a surface of normal n receives from a source of spread s, per unit of its flux, as a
/// function of c = n·direction: c where the whole band is above the horizon (c ≥ s), nothing
/// where it is all below (c ≤ −s), and (c + s)² / 4s in between — the cosine integrated over the
/// band, which rounds the kink a point has at the terminator (shaders/ibl/source_cosine.glsl).
float sourceCosine(float cosine, float spread);
std::vector<IrradianceSource> irradianceSources(const EnvironmentMap& map, int sourceWidth = kIrradianceSourceWidth);

/// E(n) = Σ flux · sourceCosine(n·direction, spread) over `sources`.
glm::vec3 irradianceAt(const std::vector<IrradianceSource>& sources, const glm::vec3& n);

/// The diffuse term's two parts: the `brightCount` sources of most flux (luminance) of the map
/// reduced to `brightWidth` × brightWidth/2, which shading sums per pixel, and the rest reduced
/// further, to `cubeWidth` × cubeWidth/2, which the irradiance cube is baked from.
struct IrradianceSplit {
    std::vector<IrradianceSource> bright;
    std::vector<IrradianceSource> cube;
    /// The map's texels that the bright sources stand for: block k of `bright` covers texels
    /// [brightBlocks[k].x, + blockSize) × [brightBlocks[k].y, + blockSize) (clipped to the map).
    std::vector<glm::ivec2> brightBlocks;
    int blockSize = 1;
};
IrradianceSplit splitIrradiance(const EnvironmentMap& map, int brightCount = kIrradianceBrightSources,
                                int brightWidth = kIrradianceSourceWidth, int cubeWidth = kIrradianceCubeSourceWidth);

/// Folds the bright sources that the irradiance cube can hold into it: moves them into
/// `split.cube` one at a time from the faintest up (never the first keepAtLeast) for as long as
/// the cube's bilinear filter, in the middle of four of its `cubeSize`² texel centres (every
/// other cell of each face), reads the folded sources' irradiance within `tolerance` of E(n)
/// per channel (or of 5 % of the mean irradiance, where E is less); the first k stay exact. A map whose few bright texels are a small share of its light (an
/// interior, an overcast sky) then needs no per-pixel sum; a sun or a softbox, whose kink at
/// the terminator a bilinear filter rounds, stays exact. Returns k.
constexpr float kIrradianceFoldTolerance = 0.0025f;
size_t foldSmoothSources(IrradianceSplit& split, size_t keepAtLeast = 0, int cubeSize = kIrradianceSize,
                         float tolerance = kIrradianceFoldTolerance);

/// `map` less what `split`'s bright sources stand for (their texels black): the environment the
/// specular lobe reads from the cube where shading adds the bright sources as lights
/// (ibl/bright_sources.glsl), so that no energy is lost or counted twice.
/// Only the first `count` sources (all: -1) are taken out.
EnvironmentMap withoutBrightSources(const EnvironmentMap& map, const IrradianceSplit& split, int count = -1);

/// The share of the map's flux (luminance × solid angle over the sphere) in the first `count`
/// of `split`'s bright sources (all: -1): the bright and the cube sources hold all of it.
float brightFluxShare(const IrradianceSplit& split, int count = -1);

/// How many of `bright` (brightest first, as splitIrradiance orders them) hold `fraction` of
/// their luminance flux: the specular lobe's lights (a sun is a few blocks of 32; the rest,
/// sky beside it, would cost a BRDF evaluation each for little).
int leadingSourceCount(const std::vector<IrradianceSource>& bright, float fraction = 0.98f);

/// The irradiance cube (shaders/ibl/irradiance.comp bakes it on the GPU; this is its CPU
/// twin): irradianceAt the centre of each texel of six `size`² faces. Face after face, rows
/// in t order, RGB.
std::vector<glm::vec3> irradianceCube(const std::vector<IrradianceSource>& sources, int size);

/// Irradiance E(n) (lux) from the SH radiance, convolved with the clamped cosine
/// (Ramamoorthi & Hanrahan 2001, eq. 8: Â0 = π, Â1 = 2π/3, Â2 = π/4).
glm::vec3 shIrradiance(const Sh9& sh, const glm::vec3& n);

} // namespace specula::render
