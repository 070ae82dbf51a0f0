#pragma once
// CPU port of shaders/brdf/ and shaders/lights/punctual.glsl: the same equations, in double
// precision, for unit tests and GPU-against-CPU comparisons. Keep the two in step.
#include <glm/glm.hpp>

namespace specula::render::brdf {

constexpr double kPi = 3.14159265358979323846;
/// Same clamp as the shader (Filament's MIN_PERCEPTUAL_ROUGHNESS).
constexpr double kMinPerceptualRoughness = 0.045;

enum class Geometry { SmithGGX, SchlickGGX };

using dvec3 = glm::dvec3;

double D_GGX(double NoH, double alpha);
double V_SmithGGX(double NoV, double NoL, double alpha);
double V_SchlickGGX(double NoV, double NoL, double perceptualRoughness);
dvec3 F_Schlick(const dvec3& f0, double VoH);

struct Surface {
    dvec3 baseColor{1.0};
    double metallic = 0.0;
    double perceptualRoughness = 0.5; ///< clamped to kMinPerceptualRoughness like the shader
    Geometry geometry = Geometry::SmithGGX;
    double specularFactor = 1.0; ///< KHR_materials_specular (dielectric F0 and F90)
};

/// f(l, v) (1/sr) for unit n, v, l, not multiplied by NoL. Zero when NoL <= 0.
dvec3 evaluate(const Surface& surface, const dvec3& n, const dvec3& v, const dvec3& l);

/// KHR_lights_punctual falloffs.
double rangeAttenuation(double range, double distance);
double spotAttenuation(const dvec3& lightDirection, const dvec3& toLight, double innerCone, double outerCone);

} // namespace specula::render::brdf
