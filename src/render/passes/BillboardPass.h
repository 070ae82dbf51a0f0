#pragma once
// The billboard pass: a scene's billboard groups and the light gizmos, drawn instanced (one
// draw call per group) into the forward pass's HDR target. The basis is built in the vertex
// shader (shaders/billboard/basis.glsl) with the formulas of shading/Billboard.h.
//
// Order within the forward pass (Renderer::Impl::drawScene):
//   1. opaque glTF surfaces
//   2. drawOpaque(): groups with AlphaMode::Mask (cutout) or Opaque; depth-tested and written
//   3. blended glTF surfaces, sorted back to front
//   4. drawBlended(): billboards of AlphaMode::Blend groups, all groups sorted together back to
//      front by view depth (consecutive billboards of one group share a draw), depth-tested,
//      not written; then the light gizmos on top of everything: rods, then discs.
// Blended billboards and blended glTF surfaces are sorted apart, so a blended sprite behind a
// blended glTF surface is drawn over it; scenes mixing the two should keep them apart.
//
// In a Doom frame (render/DoomPass) both draws write a palette index and a colour-map level
// instead of radiance: texel × tint through the palette's nearest-index table, one level per
// sprite from its group's sector light and its distance, texels unfiltered; blended sprites
// and gizmos are cut out at half coverage.
#include <memory>
#include <vector>

#include "render/PlacedLight.h"
#include "render/View.h"
#include "scene/Scene.h"

namespace specula::gl {
class State;
}

namespace specula::render {

class LightBuffer;

/// Light gizmos: a disc of this many pixels across, emitting the light's colour × this radiance
/// (cd/m²; bright enough to read as a light and to bloom, whatever the light's intensity).
constexpr float kGizmoSizePixels = 24.0f;
constexpr float kGizmoRadiance = 6.0f;
/// Rods (direction, cone edges): lines this many pixels wide, emitting the light's colour × this
/// radiance: dimmer than the discs, so that tone mapping keeps their hue and they bloom less.
constexpr float kGizmoRodPixels = 2.0f;
constexpr float kGizmoRodRadiance = 2.0f;
/// Rods along a spot light's outer cone, and (dimmer, kGizmoInnerConeTint) its inner cone.
constexpr int kGizmoOuterConeRods = 8;
constexpr int kGizmoInnerConeRods = 4;
constexpr float kGizmoInnerConeTint = 0.12f;
/// The selected light's disc and rods are drawn this much larger and wider.
constexpr float kGizmoSelectedScale = 1.6f;
/// At most this many gizmo billboards per light (a spot light's disc and rods).
constexpr int kGizmoBillboardsPerLight = 2 + kGizmoOuterConeRods + kGizmoInnerConeRods;

/// The light gizmos as two blended billboard groups, tinted with each light's colour.
/// - discs: a point sprite per light, kGizmoSizePixels across, × kGizmoRadiance. Point and spot lights sit at
///   their position; a directional light has none, so its disc sits where its light comes
///   from, on the bounding sphere of `sceneBounds` (centre − direction × radius; radius 1
///   around the origin for empty bounds).
/// - rods: arbitrary-axis billboards spanning their axis (BillboardGroup::spanAxis),
///   kGizmoRodPixels wide, × kGizmoRodRadiance. A directional light's runs from its disc along its direction to
///   the centre (length = radius). A spot light has one along its direction and
///   kGizmoOuterConeRods along the edges of its outer cone, kGizmoInnerConeRods (dimmer) along
///   its inner cone, all from its position, as long as its range, or without one as far as
///   the centre of the bounds (at least the radius). Point lights have none.
/// The light at index `selected` (if any) gets a disc kGizmoSelectedScale times larger and
/// rods as much wider.
struct LightGizmos {
    scene::BillboardGroup discs;
    scene::BillboardGroup rods;
};
LightGizmos makeLightGizmos(const std::vector<PlacedLight>& lights, const scene::Bounds& sceneBounds, int selected = -1);

class BillboardPass {
public:
    BillboardPass();
    ~BillboardPass();
    BillboardPass(const BillboardPass&) = delete;
    BillboardPass& operator=(const BillboardPass&) = delete;

    /// Uploads the scene's billboard groups, their sprites, and remembers its bounds (gizmos).
    void setScene(const scene::Scene& scene);
    /// Compiles the program (of a Doom frame's output, with `doomIndexed`) now rather than on first use.
    void prepare(bool doomIndexed = false);

    /// Draws the cutout and opaque groups into the bound target; returns triangles submitted.
    /// `doomIndexed`: the target is a Doom frame's index and level (DoomPass::target).
    size_t drawOpaque(gl::State& state, int viewportHeight, bool doomIndexed = false);
    /// Draws the blended billboards back to front, then the gizmos of `gizmoLights` (if not
    /// null) on top, light `selectedLight` highlighted; returns triangles submitted.
    size_t drawBlended(gl::State& state, const View& view, int viewportHeight, const LightBuffer* gizmoLights,
                       int selectedLight = -1, bool doomIndexed = false);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
