#version 450 core
// Auto exposure, step 1: a histogram of log2 luminance of the HDR frame. Each work group
// counts into shared memory, then adds its non-empty bins to the global histogram, so the
// global atomics are one per bin and group, not one per pixel.
#include "../shared/Bindings.h"
#include "../shared/PostData.h"
#include "../common/color.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(std140, binding = SPECULA_BINDING_EXPOSURE_PARAMS) uniform ExposureParamsBlock { ExposureParams params; };
layout(std430, binding = SPECULA_BINDING_HISTOGRAM) buffer HistogramBlock {
    uint counts[SPECULA_HISTOGRAM_BINS];
    uint positions[SPECULA_HISTOGRAM_BINS]; // sum over the bin's pixels of where in the bin, in 1/16ths
};
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uHdr;

uniform ivec2 uSize;

// 10^-6 cd/m²: far below anything an eye or a camera meters (starlight is ~10^-3), above
// rounding noise of a black pixel.
const float kBlack = 1e-6;

shared uint sCounts[SPECULA_HISTOGRAM_BINS];
shared uint sPositions[SPECULA_HISTOGRAM_BINS];

void main()
{
    uint index = gl_LocalInvocationIndex; // 256 invocations: one per bin
    sCounts[index] = 0u;
    sPositions[index] = 0u;
    barrier();

    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(p, uSize))) {
        float lum = luminance(texelFetch(uHdr, p, 0).rgb);
        float minLog = params.histogram.x, maxLog = params.histogram.y;
        // Black (nothing drawn, or unlit and not emitting) goes to bin 0, which the average
        // skips: a small object against black is exposed for itself. Anything else outside
        // the range is clamped into the first or last bin.
        if (lum > kBlack) {
            const float bins = float(SPECULA_HISTOGRAM_BINS - 1);
            // Just below the top, so the brightest pixels land in the last bin, not past it.
            float x = clamp((log2(lum) - minLog) / (maxLog - minLog), 0.0, 1.0) * bins;
            x = min(x, bins - 1.0 / 64.0);
            uint bin = 1u + uint(x);
            atomicAdd(sCounts[bin], 1u);
            atomicAdd(sPositions[bin], uint(fract(x) * float(SPECULA_HISTOGRAM_SUBSTEPS)));
        } else {
            atomicAdd(sCounts[0], 1u);
        }
    }
    barrier();
    if (sCounts[index] > 0u) {
        atomicAdd(counts[index], sCounts[index]);
        atomicAdd(positions[index], sPositions[index]);
    }
}
