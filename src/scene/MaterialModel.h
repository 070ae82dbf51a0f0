#pragma once
// How a material is shaded: the shading model and, for the physically based model, which
// term of the microfacet BRDF to use. Plain data (no GL): scene files and the command line
// set it, render/ turns it into shader defines (shaders/brdf/brdf.glsl, shaders/forward/).
#include <cstdint>
#include <optional>
#include <string_view>

namespace specula::scene {

/// The history of real-time lighting, oldest idea last-but-one.
enum class ShadingModel : uint8_t {
    Pbr,        ///< Cook-Torrance microfacet BRDF (glTF 2.0 Appendix B by default)
    Unlit,      ///< base colour and emission only
    Flat,       ///< one shade per face (Warnock 1969): Phong lighting with the face normal
    Gouraud,    ///< Phong lighting per vertex, interpolated (Gouraud 1971)
    Phong,      ///< ambient + diffuse + (R·V)^shininess per pixel (Phong 1975)
    BlinnPhong, ///< ambient + diffuse + (N·H)^shininess per pixel (Blinn 1977)
    Doom,       ///< sector light level, light diminishing, 256-colour palette (id Software 1993)
};
constexpr int kShadingModelCount = 7;

/// Microfacet normal distribution D.
enum class BrdfDistribution : uint8_t { GGX, Beckmann, BlinnPhong };
/// Masking-shadowing G (SmithGGX and SchlickGGX keep their historical values).
enum class BrdfGeometry : uint8_t { SmithGGX, SchlickGGX, SmithGGXCorrelated, Neumann, Kelemen, CookTorrance, Implicit };
/// Fresnel F.
enum class BrdfFresnel : uint8_t { Schlick, SchlickSG, None };
/// Diffuse lobe.
enum class BrdfDiffuse : uint8_t { Lambert, OrenNayar, Burley };

/// A material's choices; unset = the frame's (render::FrameSettings), else the default.
struct MaterialShading {
    std::optional<ShadingModel> model;
    std::optional<BrdfDistribution> distribution;
    std::optional<BrdfGeometry> geometry;
    std::optional<BrdfFresnel> fresnel;
    std::optional<BrdfDiffuse> diffuse;
};

/// Command-line and scene-file names ("blinn-phong", "smith-ggx-correlated", "schlick-sg"...).
std::optional<ShadingModel> parseShadingModel(std::string_view name);
std::optional<BrdfDistribution> parseBrdfDistribution(std::string_view name);
std::optional<BrdfGeometry> parseBrdfGeometryName(std::string_view name);
std::optional<BrdfFresnel> parseBrdfFresnel(std::string_view name);
std::optional<BrdfDiffuse> parseBrdfDiffuse(std::string_view name);
const char* shadingModelName(ShadingModel model);
const char* brdfDistributionName(BrdfDistribution d);
const char* brdfGeometryName(BrdfGeometry g);
const char* brdfFresnelName(BrdfFresnel f);
const char* brdfDiffuseName(BrdfDiffuse d);
/// The names accepted, comma-separated, for error messages.
const char* shadingModelNames();
const char* brdfDistributionNames();
const char* brdfGeometryNames();
const char* brdfFresnelNames();
const char* brdfDiffuseNames();

/// F0 at normal incidence of a dielectric of index of refraction `ior` in air (Fresnel
/// equations at 0°): ((ior - 1) / (ior + 1))², 0.04 for ior = 1.5.
float f0FromIor(float ior);

} // namespace specula::scene
