#pragma once
// Photographic exposure (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", camera
// exposure): GL-free maths shared by the renderer, the frame setup and tests.

namespace specula::render {

/// EV100 of a camera (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", camera exposure):
/// log2(N² / t × 100 / S) for f-number N, shutter time t (seconds) and ISO S.
float ev100FromCamera(float aperture, float shutterSeconds, float iso);
/// The scale a camera at `ev100` applies to radiance: 1 / (1.2 × 2^EV100) (ibid.,
/// saturation-based sensitivity: a luminance of 1.2 × 2^EV100 cd/m² just saturates).
float exposureFromEv100(float ev100);
/// EV100 a reflected-light meter (K = 12.5) picks for an average luminance (cd/m²).
float ev100FromLuminance(float luminance);

} // namespace specula::render
