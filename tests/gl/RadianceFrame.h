#pragma once
// The frame the GL tests compare with a CPU expectation: one sample at each pixel centre and no
// tone curve, so that Renderer::readRadiance() is the forward pass's radiance, pixel by pixel.
#include "render/Renderer.h"

namespace specula::test {

/// Default: the renderer's BRDF (with its multiple-scattering energy compensation). Exact: the
/// glTF BRDF as the file gives it, single scattering, as shading/Brdf.cpp evaluates it.
enum class Brdf { Default, Exact };

inline render::FrameSettings radianceFrame(int width, int height, Brdf brdf = Brdf::Default)
{
    render::FrameSettings settings;
    settings.width = width;
    settings.height = height;
    settings.msaa = 1;
    settings.tonemap = render::Tonemap::None;
    if (brdf == Brdf::Exact) settings.energyCompensation = false;
    return settings;
}

} // namespace specula::test
