#pragma once
// Shadow maps for every kind of light, in one depth atlas (shading/ShadowMaps.h decides the
// views, lights/shadow.glsl reads them):
//   - directional lights: 1–4 cascades, each fitted to its frustum slice's bounding sphere
//     and snapped to whole texels;
//   - spot lights: one perspective view of the cone;
//   - point lights: six 90° cube-face views.
// Spot and point lights get tiles sized by their screen importance, within a budget
// (ShadowSettings::maxLights, chosen by importance); what is left out is counted in
// FrameStats::shadows, never dropped silently.
//
// A view's tile is rendered again only when what it shows may have changed: its matrix (the
// light moved or was edited; a cascade follows the camera), its tile, the bias, or the
// casters (a new scene, an edited material). A still scene renders no shadow map after its
// first frame.
//
// Casters: opaque and alpha-masked surfaces (masked ones cut out with their cutoff and base
// colour texture), every face of them (double-sided and open meshes cast from either side),
// except models and shapes with castShadows off. Blended surfaces and those that let half the
// light or more through cast none into the atlas; what they let through goes into the tint map
// (the atlas's resolution up to 4096², made when a scene has such a surface: render::tintsShadow),
// which colours or dims the light beyond them. Billboards cast none. The Doom frame has no
// shadows.
#include <memory>

#include "render/graph/FrameGraph.h"
#include "shading/VariantKey.h"

namespace specula::gl {
class State;
class Texture;
} // namespace specula::gl

namespace specula::render {

struct FrameContext;

class ShadowPass {
public:
    ShadowPass();
    ~ShadowPass();
    ShadowPass(const ShadowPass&) = delete;
    ShadowPass& operator=(const ShadowPass&) = delete;

    /// Decides this frame's shadowed lights, views and tiles, uploads the shadow records and
    /// each light's slot (render::LightBuffer), and adds the passes that render the views
    /// that changed ("shadows: cascades", "shadows: spot", "shadows: point"). Returns the atlas
    /// for the forward pass to sample, or no texture when no light has a map this frame.
    GraphTexture addTo(FrameGraph& graph, const FrameContext& frame);

    /// What the last addTo's maps ask of the forward pass's program (its SHADOWS variant:
    /// no kind when no light has a map).
    const ShadowVariant& variant() const;
    /// Binds the atlas (compared and raw) and the records for shading (lights/shadow.glsl).
    void bind(gl::State& state) const;
    /// The atlas (the shadow-atlas debug view), when made.
    const gl::Texture* atlas() const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
