#pragma once
// CPU port of shaders/forward/iridescence.glsl: KHR_materials_iridescence's thin-film Fresnel
// (Belcour & Barla 2017, "A Practical Extension to Microfacet Theory for the Modeling of Varying
// Iridescence", in the approximate form the extension's "Iridescence Fresnel" section writes:
// Schlick reflectances at both interfaces, phase shifts 0 or π, the spectral integral done in
// Fourier space against Gaussian fits of the XYZ sensitivities, XYZ to Rec. 709). Double
// precision, for the BRDF explorer and the GPU-against-CPU tests. Keep it in step with the shader.
#include <glm/glm.hpp>

namespace specula::render::brdf {

/// The film: iridescenceFactor × texture R, its IOR, its thickness in nanometres (mix of the
/// minimum and maximum by the thickness texture's G, the maximum without one).
struct ThinFilm {
    double factor = 0.0;
    double ior = 1.3;
    double thickness = 400.0;
};

/// The analytic spectral sensitivity of the extension, evalSensitivity(OPD, shift): the XYZ
/// Gaussians' Fourier transforms at optical path difference `opdNm`, phase-shifted by `shift`,
/// in Rec. 709.
glm::dvec3 iridescenceSensitivity(double opdNm, const glm::dvec3& shift);

/// F_iridescence: the film's reflectance (Rec. 709) at cos θ1 = `cosTheta1` between a medium of
/// `outsideIor` and a base whose normal-incidence reflectance is `baseF0`. A thickness of 0 takes
/// the film's IOR to the outside's, as the Khronos sample renderer does (smoothstep over
/// 0–0.03 nm): there is no film.
glm::dvec3 iridescentFresnel(double outsideIor, double filmIor, double cosTheta1, double thicknessNm, const glm::dvec3& baseF0);

/// The film over a metal-rough material: mix(F_iridescence(f0 dielectric), F_iridescence(base
/// colour), metallic), each base's reflectance from its F0 (iridescent_dielectric_layer and
/// iridescent_conductor_layer of the extension), outside IOR 1 (a clearcoat's interface is
/// ignored, as the extension says).
glm::dvec3 filmFresnel(const ThinFilm& film, const glm::dvec3& f0Dielectric, const glm::dvec3& baseColor, double metallic,
                       double cosTheta);

} // namespace specula::render::brdf
