#version 450 core
// Auto exposure, step 2 (one work group): the average log2 luminance of the histogram between
// the low and high percentiles, turned into EV100 the way a reflected-light meter does
// (EV100 = log2(L * S / K), S = 100, K = 12.5), clamped, and approached exponentially from
// the previous frame's value (Pattanaik et al. 2000's time-dependent adaptation, in EV):
//     EV += (target - EV) * (1 - exp(-dt * speed))
// dt = 0 converges at once (still renders). The exposure is 1 / (1.2 * 2^EV100) (Lagarde &
// de Rousiers 2014, saturation-based sensitivity). Clears the histogram for the next frame.
#include "../shared/Bindings.h"
#include "../shared/PostData.h"

layout(local_size_x = SPECULA_HISTOGRAM_BINS) in;

layout(std140, binding = SPECULA_BINDING_EXPOSURE_PARAMS) uniform ExposureParamsBlock { ExposureParams params; };
layout(std430, binding = SPECULA_BINDING_HISTOGRAM) buffer HistogramBlock {
    uint counts[SPECULA_HISTOGRAM_BINS];
    uint positions[SPECULA_HISTOGRAM_BINS];
};
layout(std430, binding = SPECULA_BINDING_EXPOSURE) buffer ExposureBlock { ExposureState state; };

shared uint sCounts[SPECULA_HISTOGRAM_BINS];
shared uint sPositions[SPECULA_HISTOGRAM_BINS];

void main()
{
    uint index = gl_LocalInvocationIndex;
    sCounts[index] = counts[index];
    sPositions[index] = positions[index];
    counts[index] = 0u;
    positions[index] = 0u;
    barrier();
    if (index != 0u) return;

    // 256 bins: a serial walk is cheaper than a parallel prefix sum's barriers.
    float total = 0.0;
    for (uint b = 1u; b < uint(SPECULA_HISTOGRAM_BINS); ++b) total += float(sCounts[b]);
    float low = total * params.histogram.z, high = total * params.histogram.w;
    float below = 0.0, weightSum = 0.0, logSum = 0.0;
    const float bins = float(SPECULA_HISTOGRAM_BINS - 1);
    for (uint b = 1u; b < uint(SPECULA_HISTOGRAM_BINS); ++b) {
        float count = float(sCounts[b]);
        if (count == 0.0) continue;
        // The part of this bin's pixels that lies between the percentiles.
        float w = max(min(below + count, high) - max(below, low), 0.0);
        below += count;
        if (w <= 0.0) continue;
        // Mean position in the bin; +0.5 undoes the truncation to 1/16ths.
        float inBin = (float(sPositions[b]) / count + 0.5) / float(SPECULA_HISTOGRAM_SUBSTEPS);
        float x = (float(b - 1u) + inBin) / bins;
        logSum += w * mix(params.histogram.x, params.histogram.y, x);
        weightSum += w;
    }

    bool measured = state.value.w > 0.0;
    float ev = measured ? state.value.x : params.clampEv.x;
    float averageLuminance = 0.0;
    if (weightSum > 0.0) {
        float averageLog = logSum / weightSum;
        averageLuminance = exp2(averageLog);
        float target = clamp(averageLog + log2(100.0 / 12.5), params.clampEv.x, params.clampEv.y);
        float dt = params.adaptation.x;
        if (!measured || dt <= 0.0) {
            ev = target;
        } else {
            // A higher EV100 is a brighter scene: adapting to it uses the "up" speed.
            float speed = target > ev ? params.adaptation.y : params.adaptation.z;
            ev += (target - ev) * (1.0 - exp(-dt * speed));
        }
        measured = true;
    }
    state.value = vec4(ev, 1.0 / (1.2 * exp2(ev)), averageLuminance, measured ? 1.0 : 0.0);
}
