#include "shading/Brdf.h"

#include <algorithm>
#include <cmath>

namespace specula::render::brdf {

double D_GGX(double NoH, double alpha)
{
    const double a2 = alpha * alpha;
    const double f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * f * f);
}

double D_Beckmann(double NoH, double alpha)
{
    const double a2 = alpha * alpha;
    const double NoH2 = std::max(NoH * NoH, 1e-8);
    return std::exp((NoH2 - 1.0) / (a2 * NoH2)) / (kPi * a2 * NoH2 * NoH2);
}

double D_BlinnPhong(double NoH, double alpha)
{
    const double n = 2.0 / (alpha * alpha) - 2.0;
    return (n + 2.0) / (2.0 * kPi) * std::pow(NoH, n);
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

double V_SchlickGGXImageBased(double NoV, double NoL, double alpha)
{
    const double k = alpha / 2.0;
    const double gl = NoL / (NoL * (1.0 - k) + k);
    const double gv = NoV / (NoV * (1.0 - k) + k);
    return gl * gv / std::max(4.0 * NoL * NoV, 1e-7);
}

double V_SmithGGXCorrelated(double NoV, double NoL, double alpha)
{
    const double a2 = alpha * alpha;
    const double lambdaV = NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2);
    const double lambdaL = NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / std::max(lambdaV + lambdaL, 1e-7);
}

double V_Neumann(double NoV, double NoL)
{
    return 0.25 / std::max(std::max(NoL, NoV), 1e-7);
}

double V_Kelemen(double VoH)
{
    return 0.25 / std::max(VoH * VoH, 1e-7);
}

double V_CookTorrance(double NoV, double NoL, double NoH, double VoH)
{
    const double G = std::min(1.0, 2.0 * NoH * std::min(NoV, NoL) / std::max(VoH, 1e-7));
    return G / std::max(4.0 * NoL * NoV, 1e-7);
}

double V_Implicit()
{
    return 0.25;
}

dvec3 F_Schlick(const dvec3& f0, double VoH)
{
    return F_Schlick(f0, 1.0, VoH);
}

dvec3 F_Schlick(const dvec3& f0, double f90, double VoH)
{
    const double x = 1.0 - VoH;
    const double x5 = x * x * x * x * x;
    return f0 + (dvec3(f90) - f0) * x5;
}

dvec3 F_SchlickSG(const dvec3& f0, double f90, double VoH)
{
    return f0 + (dvec3(f90) - f0) * std::exp2((-5.55473 * VoH - 6.98316) * VoH);
}

double Fd_Burley(double r, double NoV, double NoL, double LoH)
{
    const double f90 = 0.5 + 2.0 * r * LoH * LoH;
    const double lightScatter = 1.0 + (f90 - 1.0) * std::pow(1.0 - NoL, 5.0);
    const double viewScatter = 1.0 + (f90 - 1.0) * std::pow(1.0 - NoV, 5.0);
    return lightScatter * viewScatter / kPi;
}

double Fd_OrenNayar(double r, double NoV, double NoL, double VoL)
{
    const double s2 = r * r;
    const double A = 1.0 - 0.5 * s2 / (s2 + 0.33);
    const double B = 0.45 * s2 / (s2 + 0.09);
    const double s = VoL - NoV * NoL;
    return (A + B * std::max(s, 0.0) / std::max(std::max(NoL, NoV), 1e-7)) / kPi;
}

double distribution(Distribution d, double NoH, double alpha)
{
    switch (d) {
    case Distribution::GGX: return D_GGX(NoH, alpha);
    case Distribution::Beckmann: return D_Beckmann(NoH, alpha);
    case Distribution::BlinnPhong: return D_BlinnPhong(NoH, alpha);
    }
    return 0.0;
}

double visibility(Geometry g, double NoV, double NoL, double NoH, double VoH, double r)
{
    const double alpha = r * r;
    switch (g) {
    case Geometry::SmithGGX: return V_SmithGGX(NoV, NoL, alpha);
    case Geometry::SchlickGGX: return V_SchlickGGX(NoV, NoL, r);
    case Geometry::SmithGGXCorrelated: return V_SmithGGXCorrelated(NoV, NoL, alpha);
    case Geometry::Neumann: return V_Neumann(NoV, NoL);
    case Geometry::Kelemen: return V_Kelemen(VoH);
    case Geometry::CookTorrance: return V_CookTorrance(NoV, NoL, NoH, VoH);
    case Geometry::Implicit: return V_Implicit();
    }
    return 0.0;
}

double visibilityImageBased(Geometry g, double NoV, double NoL, double NoH, double VoH, double r)
{
    if (g == Geometry::SchlickGGX) return V_SchlickGGXImageBased(NoV, NoL, r * r);
    return visibility(g, NoV, NoL, NoH, VoH, r);
}

dvec3 fresnel(Fresnel f, const dvec3& f0, double f90, double VoH)
{
    switch (f) {
    case Fresnel::Schlick: return F_Schlick(f0, f90, VoH);
    case Fresnel::SchlickSG: return F_SchlickSG(f0, f90, VoH);
    case Fresnel::None: return f0;
    }
    return f0;
}

double diffuseLobe(Diffuse d, double r, double NoV, double NoL, double LoH, double VoL)
{
    switch (d) {
    case Diffuse::Lambert: return 1.0 / kPi;
    case Diffuse::OrenNayar: return Fd_OrenNayar(r, NoV, NoL, VoL);
    case Diffuse::Burley: return Fd_Burley(r, NoV, NoL, LoH);
    }
    return 0.0;
}

double D_GGX_Anisotropic(double NoH, double ToH, double BoH, double at, double ab)
{
    const double a2 = at * ab;
    const dvec3 f(ab * ToH, at * BoH, a2 * NoH);
    const double w2 = a2 / glm::dot(f, f);
    return a2 * w2 * w2 / kPi;
}

double V_SmithGGXCorrelatedAnisotropic(double NoV, double NoL, double ToV, double BoV, double ToL, double BoL, double at, double ab)
{
    const double lambdaV = NoL * glm::length(dvec3(at * ToV, ab * BoV, NoV));
    const double lambdaL = NoV * glm::length(dvec3(at * ToL, ab * BoL, NoL));
    return std::min(0.5 / std::max(lambdaV + lambdaL, 1e-7), 1.0); // the extension's clamp
}

dvec3 evaluate(const Surface& s, const dvec3& n, const dvec3& v, const dvec3& l)
{
    dvec3 diffuse, specular;
    evaluateLobes(s, n, v, l, diffuse, specular);
    return diffuse + specular;
}

void evaluateLobes(const Surface& s, const dvec3& n, const dvec3& v, const dvec3& l, dvec3& diffuse, dvec3& specular)
{
    diffuse = specular = dvec3(0.0);
    const double NoL = std::clamp(glm::dot(n, l), 0.0, 1.0);
    if (NoL <= 0.0) return;
    const double r = std::clamp(s.perceptualRoughness, kMinPerceptualRoughness, 1.0);
    const double alpha = r * r;
    const dvec3 h = glm::normalize(v + l);
    const double NoV = std::abs(glm::dot(n, v));
    const double NoH = std::clamp(glm::dot(n, h), 0.0, 1.0);
    const double VoH = std::clamp(glm::dot(v, h), 0.0, 1.0);
    const dvec3 f0Dielectric = glm::min(s.f0Dielectric * s.specularColor, dvec3(1.0)) * s.specularFactor;
    const dvec3 f0 = glm::mix(f0Dielectric, s.baseColor, s.metallic);
    const double f90 = s.specularFactor + (1.0 - s.specularFactor) * s.metallic;
    const dvec3 diffuseColor = s.baseColor * (1.0 - s.metallic);
    const dvec3 F = fresnel(s.fresnel, f0, f90, VoH);
    const double D = distribution(s.distribution, NoH, alpha);
    const double V = s.imageBased ? visibilityImageBased(s.geometry, NoV, NoL, NoH, VoH, r)
                                  : visibility(s.geometry, NoV, NoL, NoH, VoH, r);
    const double Fd = diffuseLobe(s.diffuse, r, NoV, NoL, VoH, glm::dot(v, l));
    // The specular lobe's D V: KHR_materials_anisotropy's along its direction (GGX only).
    double DV = D * V;
    if (s.anisotropy > 0.0 && s.distribution == Distribution::GGX) {
        const dvec3 t = glm::normalize(s.anisotropyDirection - n * glm::dot(n, s.anisotropyDirection));
        const dvec3 b = glm::cross(n, t);
        const double at = glm::mix(alpha, 1.0, s.anisotropy * s.anisotropy);
        DV = D_GGX_Anisotropic(NoH, glm::dot(t, h), glm::dot(b, h), at, alpha) *
             V_SmithGGXCorrelatedAnisotropic(NoV, NoL, glm::dot(t, v), glm::dot(b, v), glm::dot(t, l), glm::dot(b, l), at, alpha);
    }
    // Its Fresnel and the diffuse lobe's weight: KHR_materials_iridescence's film mixed in.
    dvec3 specularF = F, diffuseWeight = dvec3(1.0) - F;
    if (s.iridescence.factor > 0.0) {
        const dvec3 film = filmFresnel(s.iridescence, f0Dielectric, s.baseColor, s.metallic, VoH);
        const double filmMax = std::max({film.r, film.g, film.b});
        diffuseWeight = glm::mix(diffuseWeight, dvec3(std::max(1.0 - filmMax, 0.0)), s.iridescence.factor);
        specularF = glm::mix(F, film, s.iridescence.factor);
    }
    diffuse = diffuseWeight * diffuseColor * Fd;
    specular = specularF * DV;
    if (glm::any(glm::greaterThan(s.sheenColor, dvec3(0.0)))) {
        // The base gives up what the sheen reflects; a clearcoat (below) then lies over both.
        const double rs = std::clamp(s.sheenRoughness, kMinPerceptualRoughness, 1.0);
        const double scaling = 1.0 - std::max(std::max(s.sheenColor.x, s.sheenColor.y), s.sheenColor.z) * s.sheenAlbedo;
        diffuse *= scaling;
        specular = specular * scaling + s.sheenColor * (D_Charlie(NoH, rs * rs) * V_Charlie(std::max(NoV, 1e-4), NoL, rs * rs));
    }
    if (s.clearcoat > 0.0) {
        const double rc = std::clamp(s.clearcoatRoughness, kMinPerceptualRoughness, 1.0);
        const double Vc = s.imageBased ? visibilityImageBased(s.geometry, NoV, NoL, NoH, VoH, rc)
                                       : visibility(s.geometry, NoV, NoL, NoH, VoH, rc);
        const dvec3 attenuation = dvec3(1.0) - s.clearcoat * fresnel(s.fresnel, dvec3(0.04), 1.0, NoV);
        diffuse *= attenuation;
        specular = specular * attenuation + s.clearcoat * fresnel(s.fresnel, dvec3(0.04), 1.0, VoH) * (distribution(s.distribution, NoH, rc * rc) * Vc);
    }
}

double D_Charlie(double NoH, double alpha)
{
    const double sin2h = std::max(1.0 - NoH * NoH, 0.0);
    return (2.0 + 1.0 / alpha) * std::pow(sin2h, 0.5 / alpha) / (2.0 * kPi);
}

namespace {

// Estevez & Kulla 2017's fit of ln Λ, interpolated by (1 − α)² between its α = 0 and α = 1 fits.
double charlieL(double x, double alpha)
{
    const double t = (1.0 - alpha) * (1.0 - alpha);
    const auto mix = [t](double a, double b) { return a + (b - a) * t; };
    return mix(21.5473, 25.3245) / (1.0 + mix(3.82987, 3.32435) * std::pow(x, mix(0.19823, 0.16801))) +
           mix(-1.97760, -1.27393) * x + mix(-4.32054, -4.85967);
}

double charlieLambda(double cosTheta, double alpha)
{
    return cosTheta < 0.5 ? std::exp(charlieL(cosTheta, alpha)) : std::exp(2.0 * charlieL(0.5, alpha) - charlieL(1.0 - cosTheta, alpha));
}

} // namespace

double V_Charlie(double NoV, double NoL, double alpha)
{
    return 1.0 / ((1.0 + charlieLambda(NoV, alpha) + charlieLambda(NoL, alpha)) * (4.0 * NoV * NoL));
}

double sheenDirectionalAlbedo(double NoV, double perceptualRoughness, int steps)
{
    const double r = std::clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0), alpha = r * r;
    NoV = std::clamp(NoV, 1e-4, 1.0);
    const dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double cosT = (i + 0.5) / steps, sinT = std::sqrt(1.0 - cosT * cosT);
        for (int j = 0; j < steps; ++j) { // phi over half the circle: the lobe is symmetric in it
            const double phi = kPi * (j + 0.5) / steps;
            const dvec3 l(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
            sum += D_Charlie(glm::normalize(v + l).z, alpha) * V_Charlie(NoV, cosT, alpha) * cosT;
        }
    }
    return sum * (1.0 / steps) * (2.0 * kPi / steps);
}

dvec3 evaluateClassic(const dvec3& kd, const dvec3& ks, double shininess, bool blinn, const dvec3& n, const dvec3& v,
                      const dvec3& l)
{
    const double NoL = glm::dot(n, l);
    if (NoL <= 0.0) return dvec3(0.0);
    const double lobe = blinn ? std::clamp(glm::dot(n, glm::normalize(l + v)), 0.0, 1.0)
                              : std::clamp(glm::dot(glm::reflect(-l, n), v), 0.0, 1.0);
    return (kd * NoL + ks * std::pow(lobe, shininess)) / kPi;
}

double classicShininess(double perceptualRoughness)
{
    const double alpha = perceptualRoughness * perceptualRoughness;
    return std::clamp(2.0 / (alpha * alpha) - 2.0, 1.0, 8192.0);
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
