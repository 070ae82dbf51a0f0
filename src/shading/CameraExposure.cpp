#include "shading/CameraExposure.h"

#include <algorithm>
#include <cmath>

namespace specula::render {

float ev100FromCamera(float aperture, float shutterSeconds, float iso)
{
    return std::log2(aperture * aperture / shutterSeconds * 100.0f / iso);
}

float exposureFromEv100(float ev100)
{
    return 1.0f / (1.2f * std::exp2(ev100));
}

float ev100FromLuminance(float luminance)
{
    // S = 100, K = 12.5 (the calibration constant of Canon, Nikon and Sekonic meters).
    return std::log2(std::max(luminance, 1e-30f) * 100.0f / 12.5f);
}

} // namespace specula::render
