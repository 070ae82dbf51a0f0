#pragma once
// A scene's meshes, textures and materials uploaded to the GPU, and its draw list.
#include <array>
#include <memory>
#include <string>
#include <optional>
#include <vector>

#include "gl/Buffer.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "scene/MeshLod.h"
#include "scene/Scene.h"
#include "shaders/shared/MaterialData.h"

namespace specula::render {

/// A primitive's vertex and index buffers and their vertex array. Primitives whose vertices and
/// indices are the same, byte for byte, share one (a scene's repeated shapes, each with its own
/// material: the LearnOpenGL grid's 49 spheres are one upload); a deformed draw has its own.
struct GpuGeometry {
    gl::Buffer vertices;
    gl::Buffer indices;
    gl::VertexArray vertexArray;
};

struct GpuPrimitive {
    std::shared_ptr<GpuGeometry> geometry;
    uint32_t count = 0;   ///< indices, or vertices when not indexed (level 0)
    bool indexed = false;
    scene::Topology topology = scene::Topology::Triangles; ///< lines and points: no shadows, no levels of detail
    /// Levels of detail (scene/MeshLod.h) in the geometry's `indices`, once
    /// GpuScene::buildLevelsOfDetail has made them: level 0 is the primitive itself; empty: only that one.
    std::vector<scene::LodLevel> lods;
    std::string name; ///< the mesh's, for labels
    int material = 0;     ///< index into GpuScene::materials (the default material is last)
    scene::Bounds bounds; ///< object space
    /// KHR_materials_variants: `material` when no variant is chosen, and the record under each
    /// variant that maps the primitive (VariantMapping::material is a GpuScene::materials index).
    int baseMaterial = 0;
    std::vector<scene::VariantMapping> variants;
};

enum class TextureSlot {
    BaseColor, MetallicRoughness, Normal, Occlusion, Emissive,
    Clearcoat, ClearcoatRoughness, ClearcoatNormal, ///< KHR_materials_clearcoat (CLEARCOAT variant only)
    SheenColor, SheenRoughness,                     ///< KHR_materials_sheen (SHEEN variant only)
    Anisotropy,                                     ///< KHR_materials_anisotropy (ANISOTROPY variant only)
    Iridescence, IridescenceThickness,              ///< KHR_materials_iridescence (IRIDESCENCE variant only)
    Specular, SpecularColor,                        ///< KHR_materials_specular (SPECULAR_TEXTURES variant only)
    Transmission, Thickness,                        ///< KHR_materials_transmission, _volume (TRANSMISSION_TEXTURES only)
    DiffuseTransmission, DiffuseTransmissionColor,  ///< KHR_materials_diffuse_transmission (DIFFUSE_TRANSMISSION_TEXTURES only)
    Count
};
/// The texture unit of each slot (shaders/shared/Bindings.h): the first five are units 0-4.
int textureUnit(TextureSlot slot);

struct MaterialBinding {
    std::array<const gl::Texture*, size_t(TextureSlot::Count)> textures{};
    std::array<const gl::Sampler*, size_t(TextureSlot::Count)> samplers{};
    /// The alpha mode the material is drawn with: the file's (`declaredAlphaMode`), except that
    /// a blended material whose alpha is 1 wherever it is drawn is drawn as opaque
    /// (GpuScene::updateCoverage): blending it gives the surface itself, the frontmost layer
    /// wins as it does with every triangle sorted. It still casts no shadow (castsShadow reads
    /// the declared mode: files mark lamps and decals BLEND so). Drawn blended, without
    /// depth writes and in index order, a mesh that overlaps itself (a closed model, the back
    /// faces of a double-sided one) shows far triangles over near ones.
    scene::AlphaMode alphaMode = scene::AlphaMode::Opaque;
    scene::AlphaMode declaredAlphaMode = scene::AlphaMode::Opaque;
    /// Nothing but the factor lowers the alpha: the base colour texture's alpha and the vertex
    /// colours' (of every primitive drawn with this record) are 1 everywhere, or there are none.
    bool opaqueTexels = true;
    bool doubleSided = false;
    float transmission = 0.0f; ///< KHR_materials_transmission factor
    /// A copy for lines and points without normals (scene::Primitive::unlit): stays unlit
    /// whatever its material's shading is set to (setShading).
    bool unlitCopy = false;
    /// SPECULA_MATERIAL_* bits (the record's 32, the shading choice's, and the extension
    /// textures' above them): selects the shader variant, and which extension texture units the
    /// draw binds (DrawList: clearcoat 19-21, sheen 22-23, anisotropy 24, iridescence 25-26,
    /// specular 30-31, transmission and thickness 32-33)
    uint64_t features = 0;
};

/// The shadow rule for surfaces light passes through (docs/transparency.md): a surface casts
/// into the depth map where it stops at least half of the light. Blended surfaces cast none
/// there (their alpha varies per texel and a depth map holds no fraction; nor do those drawn
/// opaque for an alpha of 1: MaterialBinding::declaredAlphaMode); transmissive ones cast like
/// opaque ones below a transmission of 0.5 and none from 0.5 up, texel by texel where a
/// transmission texture scales the factor (transmissionCutout). What the others let through
/// tints the light beyond them (tintsShadow).
constexpr float kTransmissionShadowLimit = float(SPECULA_TRANSMISSION_SHADOW_LIMIT);
bool castsShadow(const MaterialBinding& material);
/// A caster whose transmission texture decides where it casts: its factor reaches the limit,
/// so the shadow pass cuts out the texels where factor × texture (R) does too. (Below the
/// limit the product is below it everywhere: the surface casts whole.)
bool transmissionCutout(const MaterialBinding& material);
/// A surface that lets light through, coloured or in part, into the shadow pass's tint map
/// (lights/shadow.glsl): blended ones (a coverage of alpha) and those whose transmission
/// reaches the limit somewhere (the transmitted light tinted by the base colour and the
/// volume's attenuation). Shadow maps hold no fraction; the tint map holds what such surfaces
/// let through and the nearest one's depth.
bool tintsShadow(const MaterialBinding& material);

struct DrawItem {
    int primitive = 0;
    glm::mat4 world{1.0f};
    glm::mat3 normalMatrix{1.0f};
    bool mirrored = false; ///< negative determinant: front faces wind clockwise
    bool castShadows = true;
    bool receiveShadows = true;
    bool visible = true; ///< KHR_node_visibility: false, not drawn (an animation may show it)
};

class GpuScene {
public:
    explicit GpuScene(const scene::Scene& scene);

    const std::vector<GpuPrimitive>& primitives() const { return mPrimitives; }
    const std::vector<MaterialBinding>& materials() const { return mMaterials; }
    const std::vector<DrawItem>& draws() const { return mDraws; }
    const gl::Buffer& materialBuffer() const { return mMaterialBuffer; }
    /// Byte offset of material `index`'s record (records are aligned for uniform block ranges).
    size_t materialOffset(int index) const { return size_t(index) * mMaterialStride; }
    size_t triangleCount() const { return mTriangles; }
    /// World bounds of every draw, and of those that cast shadows.
    const scene::Bounds& bounds() const { return mBounds; }
    const scene::Bounds& casterBounds() const { return mCasterBounds; }

    /// Scene materials plus the default one (last); records beyond them are per-primitive
    /// copies (vertex colours) that follow their material.
    int materialCount() const { return mMaterialCount; }
    /// Material `material`'s record as uploaded (its first record).
    const shared::GpuMaterial& record(int material) const { return mRecords[size_t(material)]; }
    /// Replaces the shading bits of `material`'s (and its copies') variant key.
    void setShading(int material, const scene::MaterialShading& shading);
    /// Sets or clears SPECULA_MATERIAL_BLEND_TRANSPARENT of a blended material (and its copies).
    void setBlendMode(int material, scene::BlendMode mode);
    /// KHR_animation_pointer: rewrites the animated `fields` of `material` from `m`, its posed
    /// copy (the floats that changed, in every record it has, through writeMaterial's path; the
    /// other fields keep what they hold, a viewer's edits included).
    void setAnimatedFields(int material, const scene::Material& m, const std::vector<scene::AnimatedProperty>& fields);
    /// Writes `size` bytes at `offset` within `material`'s record (and its copies'), in the
    /// CPU copy and in the buffer: no other byte of the buffer is written but the record's
    /// flags when a layer's factor crosses 0 (a clearcoat, sheen, anisotropy, film,
    /// transmission, dispersion or diffuse transmission of factor 0 is no layer: its variant
    /// goes, and its textures; bits above 31 are the binding's only, MaterialData.h), and the
    /// shadow rule follows the transmission.
    void writeMaterial(int material, size_t offset, size_t size, const void* data);
    size_t textureBytes() const { return mTextureBytes; }
    /// Makes every large primitive's levels of detail (scene/MeshLod.h), once: a frame that asks
    /// for them (FrameSettings::lodPixels > 0) pays the simplification, a scene that never does
    /// pays nothing at load.
    void buildLevelsOfDetail();
    bool hasLevelsOfDetail() const { return mLevelsOfDetail; }

    /// The scene moves: it has animations, or skinned or morphed meshes (whose vertices are
    /// deformed on the CPU into a vertex buffer of each such draw, so that every pass, the
    /// shadow and pre-passes too, draws the same deformed positions). A static scene keeps no
    /// copy of anything and setPose does nothing.
    bool animated() const { return mRig.has_value(); }
    /// Poses the scene: animation `animation` (an index into the scene's animations; -1: none,
    /// the rest pose) at `seconds`. Moves the draws, re-deforms skinned and morphed primitives
    /// and updates the bounds. Returns the bytes of vertices it uploaded.
    size_t setPose(int animation, float seconds);
    /// KHR_materials_variants: draws every primitive with its material under variant `variant`
    /// (an index into the scene's variants; -1: none, the materials the primitives name).
    /// Returns whether any draw's material changed.
    bool setVariant(int variant);

    /// Every node's world matrix at the last setPose (empty before one, and for a static scene).
    const std::vector<glm::mat4>& nodeWorlds() const { return mNodeWorlds; }
    /// Every node's KHR_node_visibility at the last setPose (scene::nodeVisibility; empty before one).
    const std::vector<bool>& nodeVisible() const { return mNodeVisible; }
    /// The scene's lights at the last setPose, KHR_animation_pointer's properties applied (empty
    /// before one, and for a static scene).
    const std::vector<scene::Light>& posedLights() const { return mPosedLights; }

private:
    const gl::Texture* texture(const scene::Scene& scene, int image, bool srgb);
    const gl::Sampler* sampler(const scene::Scene& scene, int index);
    void updateBounds();
    /// Draws record `record` opaque or blended (MaterialBinding::alphaMode) from its declared
    /// mode, its texels and its factor's alpha as the record holds it; its variant key follows.
    void updateCoverage(size_t record);
    /// One record's bytes, in the CPU copy and in the buffer (and its coverage when the alpha
    /// changes, its layers' variants and shadow rule when their factors do: writeMaterial).
    void writeRecord(size_t record, size_t offset, size_t size, const void* data);

    /// What posing needs of the scene: its nodes, meshes, skins and animations (no images).
    std::optional<scene::Scene> mRig;
    std::vector<int> mDrawNode; ///< per draw: the node that draws it (animated scenes)
    /// A draw whose primitive is deformed: its own GpuPrimitive, refilled by setPose.
    struct DeformedDraw {
        size_t draw = 0;
        int mesh = 0;
        int primitive = 0; ///< index within the mesh
        bool skinned = false;
    };
    std::vector<DeformedDraw> mDeformed;
    std::vector<scene::Vertex> mScratch;
    std::vector<glm::mat4> mNodeWorlds;
    std::vector<bool> mNodeVisible;
    /// The materials KHR_animation_pointer animates, and what of each.
    struct AnimatedMaterial {
        int material = 0;
        std::vector<scene::AnimatedProperty> fields;
    };
    std::vector<AnimatedMaterial> mAnimatedMaterials;
    std::vector<scene::Light> mPosedLights;

    std::vector<GpuPrimitive> mPrimitives;
    std::vector<MaterialBinding> mMaterials;
    std::vector<DrawItem> mDraws;
    gl::Buffer mMaterialBuffer;
    size_t mMaterialStride = 0;
    std::vector<shared::GpuMaterial> mRecords; ///< what the buffer holds, record by record
    std::vector<int> mRecordMaterial;          ///< the scene material each record belongs to
    int mMaterialCount = 0;
    // One texture per (image, colour space); images used as both get two.
    std::vector<std::array<gl::Texture, 2>> mTextures;
    std::vector<gl::Sampler> mSamplers;
    gl::Sampler mDefaultSampler;
    size_t mTriangles = 0;
    scene::Bounds mBounds, mCasterBounds;
    size_t mTextureBytes = 0;
    bool mLevelsOfDetail = false;
};

} // namespace specula::render
