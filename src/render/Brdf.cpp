#include "render/Brdf.h"

#include <algorithm>
#include <cmath>

namespace specula::render::brdf {

double D_GGX(double NoH, double alpha)
{
    const double a2 = alpha * alpha;
    const double f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * f * f);
}

double V_SmithGGX(double NoV, double NoL, double alpha)
{
    const double a2 = alpha * alpha;
    const double gl = NoL + std::sqrt(a2 + (1.0 - a2) * NoL * NoL);
    const double gv = NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV);
    return 1.0 / (gl * gv);
}

double V_SchlickGGX(double NoV, double NoL, double r)
{
    const double k = (r + 1.0) * (r + 1.0) / 8.0;
    const double gl = NoL / (NoL * (1.0 - k) + k);
    const double gv = NoV / (NoV * (1.0 - k) + k);
    return gl * gv / std::max(4.0 * NoL * NoV, 1e-7);
}

dvec3 F_Schlick(const dvec3& f0, double VoH)
{
    const double x = 1.0 - VoH;
    const double x5 = x * x * x * x * x;
    return f0 + (dvec3(1.0) - f0) * x5;
}

dvec3 evaluate(const Surface& s, const dvec3& n, const dvec3& v, const dvec3& l)
{
    const double NoL = std::clamp(glm::dot(n, l), 0.0, 1.0);
    if (NoL <= 0.0) return dvec3(0.0);
    const double r = std::clamp(s.perceptualRoughness, kMinPerceptualRoughness, 1.0);
    const double alpha = r * r;
    const dvec3 h = glm::normalize(v + l);
    const double NoV = std::abs(glm::dot(n, v));
    const double NoH = std::clamp(glm::dot(n, h), 0.0, 1.0);
    const double VoH = std::clamp(glm::dot(v, h), 0.0, 1.0);
    const dvec3 f0 = glm::mix(dvec3(0.04 * s.specularFactor), s.baseColor, s.metallic);
    const double f90 = s.specularFactor + (1.0 - s.specularFactor) * s.metallic;
    const dvec3 diffuseColor = s.baseColor * (1.0 - s.metallic);
    const double fc = std::pow(1.0 - VoH, 5.0);
    const dvec3 F = f0 + (dvec3(f90) - f0) * fc;
    const double D = D_GGX(NoH, alpha);
    const double V = s.geometry == Geometry::SchlickGGX ? V_SchlickGGX(NoV, NoL, r) : V_SmithGGX(NoV, NoL, alpha);
    return (dvec3(1.0) - F) * diffuseColor / kPi + F * (D * V);
}

double rangeAttenuation(double range, double distance)
{
    const double inverseSquare = 1.0 / std::max(distance * distance, 1e-8);
    if (range <= 0.0) return inverseSquare;
    const double ratio = distance / range;
    return std::clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0) * inverseSquare;
}

double spotAttenuation(const dvec3& lightDirection, const dvec3& toLight, double innerCone, double outerCone)
{
    // KHR_lights_punctual: 1e-3 keeps inner == outer from dividing by zero (a hard edge).
    const double scale = 1.0 / std::max(std::cos(innerCone) - std::cos(outerCone), 1e-3);
    const double offset = -std::cos(outerCone) * scale;
    const double cd = glm::dot(lightDirection, -toLight);
    const double a = std::clamp(cd * scale + offset, 0.0, 1.0);
    return a * a;
}

} // namespace specula::render::brdf
