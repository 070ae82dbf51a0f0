#pragma once
// The forward pass: the scene's surfaces lit by the punctual lights and the environment into
// the frame's HDR target (or, in a Doom frame, palette indices and levels). In order
// (render/passes/BillboardPass.h gives the reasons):
//   1. opaque and masked surfaces (the frame's opaque draw list)
//   2. cutout and opaque billboards
//   3. the skybox (render/passes/SkyboxPass)
//   4. transmissive surfaces, refracting the frame so far (docs/transparency.md)
//   5. blended surfaces: back to front (the blended draw list), or with --transparency oit
//      into weighted blended OIT's targets, then composited over the frame
//   6. blended billboards, then the light gizmos
// When the frame has transmissive surfaces or OIT, 1–3 are the pass "forward" and 4–6 the
// pass "transparent", and "forward" ends by copying its frame into "opaque frame" (resolved,
// with a mip chain, for rough refraction), which "transparent" reads. Otherwise all of it is
// the one pass "forward", as before either existed.
// It keeps the programs of every variant it has met (keyed by shading/VariantKey), and resolves
// each material's program and DFG table once a frame (prepareMaterials) so that no compile or
// bake lands inside the pass or a draw.
#include <map>
#include <memory>
#include <vector>

#include "render/DrawList.h"
#include "shading/VariantKey.h"
#include "render/graph/FrameGraph.h"
#include "render/passes/SkyboxPass.h"

namespace specula::render {

class BillboardPass;
class DoomPass;
class LightCullPass;
class ShadowPass;
struct FrameContext;

/// The frame's draw lists of its one view, built once and read by every pass that draws it.
struct FrameDrawLists {
    DrawList opaque;       ///< opaque and masked surfaces
    DrawList transmissive; ///< surfaces with transmission, back to front
    DrawList blended;      ///< blended surfaces, back to front
};

class ForwardPass {
public:
    ForwardPass();
    ~ForwardPass();
    ForwardPass(const ForwardPass&) = delete;
    ForwardPass& operator=(const ForwardPass&) = delete;

    /// Each material's program for this frame (compiled on first use), and the DFG table it
    /// reads, baked on first use. `shadows`: what the frame's shadow maps ask (SHADOWS variants);
    /// `lights`: the frame's kinds of light, and every light at every point (LIGHTS_ALL) with
    /// their count, or the cluster lists.
    const std::vector<DrawProgram>& prepareMaterials(const FrameContext& frame, const ShadowVariant& shadows = {},
                                                     const LightVariant& lights = {});
    /// The draw lists of the frame's view, sorted with prepareMaterials' programs.
    FrameDrawLists drawLists(const FrameContext& frame) const;

    struct Targets {
        GraphTexture color; ///< RGBA16F radiance, or a Doom frame's RG8UI indices
        GraphTexture depth;
        GraphTexture occlusion; ///< SSAO's, when the frame has it
        GraphTexture shadows;   ///< the shadow atlas, when some light has a map
        GraphBuffer clusters;   ///< the cluster light lists, when the frame culled lights
    };
    /// Adds "forward": clears the targets (to the background radiance, or in a Doom frame its
    /// nearest palette index) and draws into them. `doom` is needed when a material (or the
    /// frame) uses the Doom model: its tables are bound. `shadows` binds the shadow maps when
    /// targets.shadows is set, `culling` the cluster lists when targets.clusters is.
    void addTo(FrameGraph& graph, const FrameContext& frame, const FrameDrawLists& lists, const Targets& targets,
               BillboardPass& billboards, DoomPass* doom, const ShadowPass* shadows = nullptr,
               const LightCullPass* culling = nullptr);

    /// Whether any material is shaded with the Doom model under these settings.
    static bool anyDoomMaterial(const FrameContext& frame);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
