#include "settings/DebugView.h"

namespace specula {

std::optional<DebugView> parseDebugView(std::string_view name)
{
    if (name == "none") return DebugView::None;
    if (name == "ssao") return DebugView::Ssao;
    if (name == "bloom") return DebugView::Bloom;
    for (DebugView view : {DebugView::BaseColor, DebugView::Normal, DebugView::Roughness, DebugView::Metallic, DebugView::Occlusion,
                           DebugView::Emissive, DebugView::BrdfD, DebugView::BrdfG, DebugView::BrdfF, DebugView::Cascades,
                           DebugView::ShadowAtlas, DebugView::LightCount, DebugView::Sheen,
                           DebugView::Anisotropy, DebugView::Iridescence, DebugView::Clearcoat, DebugView::ClearcoatNormal})
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
    case DebugView::Cascades: return "cascades";
    case DebugView::ShadowAtlas: return "shadow-atlas";
    case DebugView::LightCount: return "light-count";
    case DebugView::Sheen: return "sheen";
    case DebugView::Anisotropy: return "anisotropy";
    case DebugView::Iridescence: return "iridescence";
    case DebugView::Clearcoat: return "clearcoat";
    case DebugView::ClearcoatNormal: return "clearcoat-normal";
    }
    return "none";
}

} // namespace specula
