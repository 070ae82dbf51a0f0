#pragma once
// One draw list per view and filter, and the one path that submits it (Filament's
// RenderPass::appendCommands and its sort key): the depth/normal pre-pass, the forward pass and,
// next, every shadow view draw the scene through here.
//
// A list holds the frustum-visible draws of the scene that pass a filter, each with a 64-bit
// sort key. Opaque and masked draws sort by program, then material (fewer state changes), then
// front to back (early depth rejection); blended and transmissive draws back to front by the
// view depth of their bounds' centre, ties in scene order.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/MeshLod.h"

namespace specula::gl {
class Program;
class State;
class Texture;
} // namespace specula::gl

namespace specula::render {

class GpuScene;
struct DrawItem;
struct GpuPrimitive;

enum class DrawFilter : uint8_t {
    Opaque,        ///< opaque and alpha-masked surfaces without transmission
    Blended,       ///< alpha-blended surfaces without transmission
    Transmissive,  ///< surfaces with transmission (KHR_materials_transmission), blended or not
    ShadowCasters, ///< surfaces that cast shadows (render::castsShadow: not blended, transmission below 0.5 somewhere)
    ShadowTinters, ///< surfaces that let light through, coloured or in part (render::tintsShadow)
};

struct DrawCommand {
    uint64_t key = 0;
    const DrawItem* item = nullptr;
    int material = 0;
    int lod = 0; ///< level of detail of the item's primitive (GpuPrimitive::lods)
};

/// What one material draws with in a pass: its program (and the program's uniform locations)
/// and, when the program samples one, its DFG table.
struct DrawProgram {
    const gl::Program* program = nullptr;
    int model = -1;
    int normalMatrix = -1;
    const gl::Texture* dfg = nullptr;
    int receiveShadows = -1; ///< uReceiveShadows, set per draw from its DrawItem when present
    const gl::Texture* sheenAlbedo = nullptr; ///< the SHEEN variant's E table (ImageBasedLighting::sheenAlbedo)
};

/// How a pass's draws bind their material.
enum class MaterialTextures : uint8_t {
    All,    ///< every texture slot (flat defaults where a material has none)
    Cutouts ///< only what a depth pass's cutouts read: a masked material's base colour, a
            ///< transmission cutout's transmission texture (render::transmissionCutout)
};

/// How a list's blended draws combine with the target.
enum class BlendOutput : uint8_t {
    Premultiplied, ///< premultiplied alpha over the target (pbr.frag premultiplies), no depth writes
    WeightedOit,   ///< weighted blended OIT's accumulation and revealage targets (McGuire & Bavoil 2013)
};

struct SubmitOptions {
    MaterialTextures textures = MaterialTextures::All;
    /// Blended draws blend and do not write depth; false: drawn like cutouts (a Doom frame's
    /// indices cannot blend).
    bool blend = true;
    BlendOutput blendOutput = BlendOutput::Premultiplied;
    /// Textures bound where a material has none, for MaterialTextures::All.
    const gl::Texture* white = nullptr;
    const gl::Texture* flatNormal = nullptr;
    /// A shadow pass: every face drawn (so that open and double-sided meshes cast from either
    /// side), with this slope-scaled and constant depth bias.
    bool shadowCasters = false;
    /// With shadowCasters: the tint map's draws (ShadowPass), blended by gl::BlendMode::ShadowTint
    /// with no depth test or write.
    bool shadowTint = false;
    float depthBiasSlope = 0.0f;
    float depthBiasConstant = 0.0f;
};

class DrawList {
public:
    /// Whether a draw of the scene belongs to `filter`'s lists (shown, and of its kind).
    static bool passes(const GpuScene& scene, const DrawItem& item, DrawFilter filter);
    /// The scene's draws visible in `viewProjection` that pass `filter`, sorted.
    /// `programs[material]` orders opaque draws by program. Each draw takes the level of
    /// detail `lod` chooses for it (scene::selectLod); the default LodView: full detail.
    static DrawList build(const GpuScene& scene, const glm::mat4& view, const glm::mat4& viewProjection, DrawFilter filter,
                          const std::vector<DrawProgram>& programs, const scene::LodView& lod = {});

    /// Draws the list with `programs[material]` into the bound target. Returns triangles.
    size_t submit(gl::State& state, const GpuScene& scene, const std::vector<DrawProgram>& programs,
                  const SubmitOptions& options) const;

    const std::vector<DrawCommand>& commands() const { return mCommands; }
    bool empty() const { return mCommands.empty(); }

    /// An order-preserving map of a float onto unsigned integers (for keys): a < b ⇔ f(a) < f(b).
    static uint32_t orderedBits(float value);

private:
    DrawFilter mFilter = DrawFilter::Opaque;
    std::vector<DrawCommand> mCommands;
};

} // namespace specula::render
