#pragma once
// Which buffer a frame shows instead of itself (--debug-view, the viewer's combo). Plain data
// held by render::FrameSettings, named here so that the apps parse it without the renderer.
#include <optional>
#include <string_view>

namespace specula {

/// Shows one buffer instead of the frame.
enum class DebugView {
    None,
    Ssao,  ///< the blurred ambient occlusion, 1 = unoccluded, as grey (turns SSAO on)
    Bloom, ///< only the glow bloom adds, exposed and tone mapped like the frame (turns bloom on)
    // Material inputs and BRDF terms, from the forward pass with exposure and tone mapping off
    // (shaders/forward/debug_views.glsl): colours as authored, scalars as value × 255.
    BaseColor, ///< base colour × texture × vertex colour
    Normal,    ///< world-space shading normal (after normal mapping), n × 0.5 + 0.5
    Roughness, ///< perceptual roughness
    Metallic,
    Occlusion, ///< the material's occlusion (× SSAO when on)
    Emissive,  ///< emissive radiance, cd/m²
    BrdfD,     ///< D / D(n·h = 1) for the first light
    BrdfG,     ///< G for the first light
    BrdfF,     ///< F (rgb) for the first light
    Cascades,  ///< the first shadowed directional light's cascade (red, green, blue, yellow) × its shadow
    /// The shadow atlas, fitted into the frame: grey = 1 − (1 − window depth)^¼ (white: empty or
    /// far; the curve keeps perspective depths near 1 apart), turns shadows on.
    ShadowAtlas,
    /// Lights per pixel: the length of each shading point's light list (its cluster's, with
    /// the directional lights), as a heat map with its legend (docs/clustered-shading.md).
    LightCount,
    /// KHR_materials_sheen: what the sheen lobe reflects of light from all around, sheen colour ×
    /// E(n·v, sheen roughness) (rgb; black without sheen), the share the base below gives up.
    Sheen,
    /// KHR_materials_anisotropy: the direction in the tangent frame, rotated, as RG = xy × 0.5 +
    /// 0.5 (the texture's own encoding), and the strength as B; (0.5, 0.5, 0) without anisotropy.
    Anisotropy,
    /// The specular lobe's Fresnel at n·v (rgb): with KHR_materials_iridescence mix(F, the
    /// film's thin-film Fresnel, factor), else F alone (shaders/forward/iridescence.glsl).
    Iridescence,
    /// KHR_materials_clearcoat: the layer's factor (R) and perceptual roughness (G), each × its
    /// texture (B 0); black without a clearcoat.
    Clearcoat,
    /// KHR_materials_clearcoat: the layer's normal (its own normal map's, else the geometric
    /// normal), n × 0.5 + 0.5 as `Normal`; black without a clearcoat.
    ClearcoatNormal,
};

/// The last of DebugView's values (they run from 0 to it).
constexpr DebugView kLastDebugView = DebugView::ClearcoatNormal;

std::optional<DebugView> parseDebugView(std::string_view name);
const char* debugViewName(DebugView view);

} // namespace specula
