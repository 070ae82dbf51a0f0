#include "render/PostSettings.h"

#include <algorithm>
#include <cmath>

namespace specula::render {

std::optional<DebugView> parseDebugView(std::string_view name)
{
    if (name == "none") return DebugView::None;
    if (name == "ssao") return DebugView::Ssao;
    if (name == "bloom") return DebugView::Bloom;
    for (DebugView view : {DebugView::BaseColor, DebugView::Normal, DebugView::Roughness, DebugView::Metallic, DebugView::Occlusion,
                           DebugView::Emissive, DebugView::BrdfD, DebugView::BrdfG, DebugView::BrdfF})
        if (name == debugViewName(view)) return view;
    return std::nullopt;
}

const char* debugViewName(DebugView view)
{
    switch (view) {
    case DebugView::None: return "none";
    case DebugView::Ssao: return "ssao";
    case DebugView::Bloom: return "bloom";
    case DebugView::BaseColor: return "base-color";
    case DebugView::Normal: return "normal";
    case DebugView::Roughness: return "roughness";
    case DebugView::Metallic: return "metallic";
    case DebugView::Occlusion: return "occlusion";
    case DebugView::Emissive: return "emissive";
    case DebugView::BrdfD: return "brdf-d";
    case DebugView::BrdfG: return "brdf-g";
    case DebugView::BrdfF: return "brdf-f";
    }
    return "none";
}

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
