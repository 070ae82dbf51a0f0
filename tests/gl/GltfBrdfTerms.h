#pragma once
// The glTF 2.0 BRDF's terms (Appendix B) in double precision, ported from the specification
// (not from the shaders), for the material extensions' tests: GGX's D, the separable Smith-GGX
// visibility, Schlick's Fresnel, and the sRGB transfer function textures are decoded with.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace specula::test::gltf {

inline constexpr double kPi = 3.14159265358979323846;

inline double D_GGX(double NoH, double alpha)
{
    const double a2 = alpha * alpha;
    const double f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * f * f);
}

/// Appendix B.3.2: V = G / (4 |n.l| |n.v|) with the separable Smith-GGX G.
inline double V_GGX(double NoL, double NoV, double alpha)
{
    const double a2 = alpha * alpha;
    return 1.0 / ((NoL + std::sqrt(a2 + (1.0 - a2) * NoL * NoL)) * (NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV)));
}

inline glm::dvec3 schlick(const glm::dvec3& f0, double f90, double c)
{
    return f0 + (f90 - f0) * std::pow(1.0 - std::clamp(c, 0.0, 1.0), 5.0);
}

/// The sRGB transfer function's inverse (8-bit sRGB texels to linear).
inline double srgbToLinear(double c)
{
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

} // namespace specula::test::gltf
