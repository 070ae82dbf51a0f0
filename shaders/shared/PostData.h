// Post-processing constants: SSAO and auto-exposure parameters (uniform buffers, std140) and
// the exposure state the auto-exposure pass leaves for the tone mapper (storage buffer).
#ifdef __cplusplus
#pragma once
#endif
#include "Prelude.h"

SPECULA_SHARED_BEGIN

#define SPECULA_SSAO_MAX_SAMPLES 64
#define SPECULA_SSAO_NOISE_SIZE 4
// 256 bins: bin 0 holds the pixels too dark to measure, bins 1..255 split the log2 luminance
// range evenly. Each bin also sums where in the bin its pixels fall, in 1/16ths, so the mean
// is exact to ~1/16 of a bin rather than to a whole bin.
#define SPECULA_HISTOGRAM_BINS 256
#define SPECULA_HISTOGRAM_SUBSTEPS 16

struct SsaoData {
    mat4 projection;
    vec4 params;  // x radius (m), y bias (m), z power, w sample count
    vec4 size;    // xy target size in pixels, zw 1 / size
    vec4 options; // x 1 for an orthographic projection, else 0
    vec4 kernel[SPECULA_SSAO_MAX_SAMPLES]; // xyz hemisphere offsets (tangent space, z up, length <= 1)
};

struct ExposureParams {
    vec4 histogram;  // x min log2 luminance, y max log2 luminance, z low percentile, w high percentile
    vec4 adaptation; // x delta time (s; 0 = converge now), y speed up, z speed down (1/s), w unused
    vec4 clampEv;    // x min EV100, y max EV100
};

struct ExposureState {
    vec4 value; // x EV100 in use, y exposure = 1 / (1.2 * 2^EV100), z average luminance measured
                // in the last frame (cd/m^2), w 1 once measured
};

SPECULA_SHARED_END

#ifdef __cplusplus
static_assert(sizeof(specula::shared::SsaoData) == 64 + 3 * 16 + SPECULA_SSAO_MAX_SAMPLES * 16);
static_assert(sizeof(specula::shared::ExposureParams) == 3 * 16);
static_assert(sizeof(specula::shared::ExposureState) == 16);
#endif
