#pragma once
// A scene as plain data: what a glTF file or a scene file describes, with no GL in sight.
// Units: lengths in metres; point and spot intensities in candela, directional in lux;
// emissive in cd/m² (factor × strength); rendered values are radiance in cd/m².
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/Animation.h"
#include "scene/MaterialModel.h"

namespace specula::scene {

/// 8-bit image, tightly packed, first row at the top (as files store it).
struct Image {
    std::string name;
    int width = 0;
    int height = 0;
    int channels = 4; ///< always 4 after import (RGBA)
    std::vector<uint8_t> pixels;
};

enum class Filter { Nearest, Linear };
enum class Wrap { Repeat, MirroredRepeat, ClampToEdge };

struct Sampler {
    Filter magFilter = Filter::Linear;
    Filter minFilter = Filter::Linear;
    bool mipmaps = true;           ///< min filter uses mipmaps
    bool mipLinear = true;         ///< ..._MIPMAP_LINEAR rather than _NEAREST
    Wrap wrapS = Wrap::Repeat;
    Wrap wrapT = Wrap::Repeat;
};

/// KHR_texture_transform: uv' = T * R * S * uv.
struct UvTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f; ///< radians, counter-clockwise in uv space
    glm::vec2 scale{1.0f};
    bool isIdentity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
    /// The 3x3 matrix of the glTF extension.
    glm::mat3 matrix() const;
};

struct TextureRef {
    int image = -1;   ///< index into Scene::images; -1 = none
    int sampler = -1; ///< index into Scene::samplers; -1 = default sampler
    int texCoord = 0; ///< 0 or 1
    UvTransform transform;
    bool valid() const { return image >= 0; }
};

enum class AlphaMode { Opaque, Mask, Blend };

/// How a blended surface (AlphaMode::Blend) combines with what is behind it (docs/transparency.md).
/// Both write premultiplied alpha; they differ in what alpha scales.
enum class BlendMode {
    /// Alpha is coverage: everything the surface sends (diffuse, specular, emission) is scaled by
    /// it, the "over" operator of the glTF specification. glTF's default.
    Fade,
    /// Alpha is the diffuse part's opacity only: specular reflection and emission are added in
    /// full, so a clear glass keeps its highlights (Newell, Newell and Sancha 1972; Filament's
    /// "transparent").
    Transparent,
};

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f; ///< perceptual roughness; α = roughness²
    glm::vec3 emissiveFactor{0.0f};
    float emissiveStrength = 1.0f; ///< KHR_materials_emissive_strength
    /// KHR_materials_specular: the dielectric's F0 = min(F0(ior) x specular colour, 1) x specular
    /// and its F90 = specular, the colour being the factor x specularColorTexture's RGB (sRGB)
    /// and the specular the factor x specularTexture's A; 0 leaves a pure Lambertian dielectric.
    float specularFactor = 1.0f;
    glm::vec3 specularColorFactor{1.0f};
    TextureRef specularTexture;      ///< A
    TextureRef specularColorTexture; ///< sRGB
    float normalScale = 1.0f;
    float occlusionStrength = 1.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    BlendMode blendMode = BlendMode::Fade; ///< AlphaMode::Blend only
    bool doubleSided = false;
    /// KHR_materials_transmission: the fraction of light that passes through the dielectric
    /// part instead of being scattered diffusely (0 = none: an ordinary surface), times
    /// transmissionTexture's R.
    float transmissionFactor = 0.0f;
    TextureRef transmissionTexture; ///< R
    /// KHR_materials_volume: thickness of the volume under the surface in object-space metres
    /// (0 = thin-walled: light passes straight through), times thicknessTexture's G, and its
    /// Beer–Lambert attenuation: light keeps attenuationColor after attenuationDistance metres
    /// (0 = infinite: no loss).
    float thickness = 0.0f;
    TextureRef thicknessTexture; ///< G
    float attenuationDistance = 0.0f;
    glm::vec3 attenuationColor{1.0f};
    /// KHR_materials_dispersion: 20 / the Abbe number V_d (0 = none). A volume's red, green and
    /// blue refract with their own index of refraction (ior ∓ (ior − 1) × 0.025 × dispersion).
    float dispersion = 0.0f;
    /// KHR_materials_diffuse_transmission: that fraction of the dielectric's diffuse light is
    /// a Lambertian BTDF instead (light through a thin leaf or paper, from the other side), of
    /// colour diffuseTransmissionColorFactor x diffuseTransmissionColorTexture's RGB (sRGB); the
    /// fraction is the factor x diffuseTransmissionTexture's A (0 = none: an ordinary surface).
    float diffuseTransmissionFactor = 0.0f;
    glm::vec3 diffuseTransmissionColorFactor{1.0f};
    TextureRef diffuseTransmissionTexture;      ///< A
    TextureRef diffuseTransmissionColorTexture; ///< sRGB
    TextureRef baseColorTexture;         ///< sRGB
    TextureRef metallicRoughnessTexture; ///< G = roughness, B = metallic
    TextureRef normalTexture;
    TextureRef occlusionTexture;         ///< R
    TextureRef emissiveTexture;          ///< sRGB
    /// KHR_materials_clearcoat: a GGX dielectric layer (F0 0.04, ior 1.5) over the material,
    /// with its own roughness and normal (0 = no layer). The layer's strength is the factor x
    /// clearcoatTexture's R, its perceptual roughness the factor x clearcoatRoughnessTexture's G.
    float clearcoatFactor = 0.0f;
    float clearcoatRoughnessFactor = 0.0f;
    float clearcoatNormalScale = 1.0f;
    TextureRef clearcoatTexture;          ///< R
    TextureRef clearcoatRoughnessTexture; ///< G
    TextureRef clearcoatNormalTexture;    ///< tangent space, as normalTexture
    /// KHR_materials_sheen: a Charlie sheen lobe (Estevez & Kulla 2017) over the material, which
    /// is scaled by 1 - max(sheen colour) E(n.v) (black = no sheen). The colour is the factor x
    /// sheenColorTexture's RGB (sRGB), the perceptual roughness the factor x sheenRoughnessTexture's A.
    glm::vec3 sheenColorFactor{0.0f};
    float sheenRoughnessFactor = 0.0f;
    TextureRef sheenColorTexture;     ///< sRGB
    TextureRef sheenRoughnessTexture; ///< A
    /// KHR_materials_anisotropy: the specular lobe's alpha along a direction in the tangent
    /// plane grows to mix(alpha, 1, strength^2) (0 = isotropic). The direction is the mesh's
    /// tangent turned by anisotropyRotation (radians, counter-clockwise), or anisotropyTexture's
    /// RG (x 2 - 1, linear) turned by it; the texture's B scales the strength.
    float anisotropyStrength = 0.0f;
    float anisotropyRotation = 0.0f;
    TextureRef anisotropyTexture; ///< RG direction, B strength (linear)
    /// KHR_materials_iridescence: a thin dielectric film of IOR iridescenceIor over the material
    /// whose interference colours its Fresnel (0 = no film). Strength = the factor x
    /// iridescenceTexture's R; thickness (nm) = mix(minimum, maximum, iridescenceThicknessTexture's
    /// G), the maximum without that texture.
    float iridescenceFactor = 0.0f;
    float iridescenceIor = 1.3f;
    float iridescenceThicknessMinimum = 100.0f;
    float iridescenceThicknessMaximum = 400.0f;
    TextureRef iridescenceTexture;          ///< R
    TextureRef iridescenceThicknessTexture; ///< G
    /// Shading model and BRDF terms (scene files); unset ones come from the frame.
    MaterialShading shading;
    /// Index of refraction of the dielectric part (KHR_materials_ior): F0 = ((ior − 1)/(ior + 1))²
    /// in place of 0.04 (ior 1.5). Unset: 0.04 exactly.
    std::optional<float> ior;
    /// Phong and Blinn-Phong exponent; 0 = from roughness, 2/α² − 2 (Walter et al. 2007, eq. 30).
    float shininess = 0.0f;
    /// Doom model: the sector's light level, 0–255 (scene/DoomLighting.h). The default, 192,
    /// is a lit room's: full bright up close, darker with distance (255 never darkens).
    int sectorLight = 192;

    /// Calls `f(TextureRef&)` for every texture the material samples (kMaterialTextures).
    template <typename F>
    void forEachTexture(F&& f);
};

/// Every texture a material samples, in the order of render::TextureSlot (render/GpuScene.h
/// checks the count): one list, so that nothing that walks a material's textures misses one.
inline constexpr std::array kMaterialTextures{
    &Material::baseColorTexture,  &Material::metallicRoughnessTexture,  &Material::normalTexture,
    &Material::occlusionTexture,  &Material::emissiveTexture,           &Material::clearcoatTexture,
    &Material::clearcoatRoughnessTexture, &Material::clearcoatNormalTexture, &Material::sheenColorTexture,
    &Material::sheenRoughnessTexture, &Material::anisotropyTexture,     &Material::iridescenceTexture,
    &Material::iridescenceThicknessTexture, &Material::specularTexture, &Material::specularColorTexture,
    &Material::transmissionTexture, &Material::thicknessTexture,   &Material::diffuseTransmissionTexture,
    &Material::diffuseTransmissionColorTexture,
};

template <typename F>
void Material::forEachTexture(F&& f)
{
    for (TextureRef Material::*member : kMaterialTextures) f(this->*member);
}

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f}; ///< xyz tangent, w = bitangent sign
    glm::vec2 uv0{0.0f};
    glm::vec2 uv1{0.0f};
    glm::vec4 color{1.0f};
};

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    bool empty() const { return min.x > max.x; }
    void extend(const glm::vec3& p)
    {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Bounds& b)
    {
        if (!b.empty()) {
            extend(b.min);
            extend(b.max);
        }
    }
    Bounds transformed(const glm::mat4& m) const;
    glm::vec3 center() const { return 0.5f * (min + max); }
    float radius() const { return empty() ? 0.0f : 0.5f * glm::length(max - min); }
};

/// KHR_materials_variants: primitive draws with `material` (-1: the default material) when
/// variant `variant` (an index into Scene::variants) is chosen.
struct VariantMapping {
    int variant = 0;
    int material = -1;
};

/// One draw: triangles with one material.
/// What a primitive draws (glTF's modes: strips, fans and loops are made lists at import).
enum class Topology : uint8_t { Triangles, Lines, Points };

struct Primitive {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices; ///< empty = non-indexed (the vertices are a list of `topology`)
    Topology topology = Topology::Triangles;
    /// Lines and points without normals: nothing to light them by, so they are drawn with the
    /// unlit model (their colour is the base colour term), whatever their material's.
    bool unlit = false;
    int material = -1;             ///< -1 = the default material
    /// KHR_materials_variants: the primitive's material under each variant that maps it
    /// (`material` under the others and when none is chosen).
    std::vector<VariantMapping> variants;
    bool hasTangents = false;      ///< tangents came from the file or were generated
    bool hasColors = false;
    Bounds bounds;
    /// Skinning (glTF JOINTS_0/WEIGHTS_0, and JOINTS_1/WEIGHTS_1): `influences` (0, 4 or 8)
    /// joint indices into the node's skin and their weights per vertex, vertex after vertex.
    int influences = 0;
    std::vector<uint16_t> joints;
    std::vector<float> weights;
    /// Morph targets: displacements of POSITION, NORMAL and TANGENT (scene/Animation.h).
    std::vector<MorphTarget> targets;
    /// The normals were made per face (the file had none): a deformed copy makes them again.
    bool flatNormals = false;
    /// Deformed by a skin or by morph targets (render/GpuScene keeps a vertex buffer per draw).
    bool deformable() const { return influences > 0 || !targets.empty(); }
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
    /// Default morph target weights (glTF mesh.weights); empty = all 0.
    std::vector<float> weights;
};

struct Camera {
    enum class Type { Perspective, Orthographic };
    std::string name;
    Type type = Type::Perspective;
    float yfov = glm::radians(45.0f); ///< radians
    float aspectRatio = 0.0f;         ///< 0 = from the viewport
    float znear = 0.1f;
    float zfar = 1000.0f;             ///< 0 = infinite (glTF)
    float xmag = 1.0f, ymag = 1.0f;   ///< orthographic half extents
};

struct Light {
    enum class Type : uint32_t { Directional = 0, Point = 1, Spot = 2 };
    std::string name;
    Type type = Type::Point;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;      ///< cd (point, spot) or lux (directional)
    float range = 0.0f;          ///< 0 = infinite
    float innerConeAngle = 0.0f; ///< radians
    float outerConeAngle = glm::radians(45.0f);
    /// Shadows (render/passes/ShadowPass). A light's size sets the width of its soft shadows
    /// (PCSS): the radius of a point or spot light's sphere, the angular diameter of a
    /// directional light's disc. glTF lights have no size: 5 cm and the sun's 0.53° by default.
    bool castShadows = true;
    float radius = 0.05f;                          ///< metres (point, spot)
    float angularDiameter = glm::radians(0.53f);   ///< radians (directional)
};

struct Node {
    std::string name;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    std::optional<glm::mat4> matrix; ///< when the file gives a matrix instead of TRS
    int mesh = -1;
    int camera = -1;
    int light = -1;
    int skin = -1; ///< index into Scene::skins: its mesh is skinned by it
    /// Morph target weights of its mesh (glTF node.weights); empty = the mesh's.
    std::vector<float> weights;
    /// EXT_mesh_gpu_instancing: an instance's morph weights follow this node's animation (the
    /// instanced node's, which an animation's weights channel targets); -1 = its own.
    int weightsFrom = -1;
    std::vector<int> children;
    /// Its mesh casts shadows, and receives them (the scene file's castShadows and
    /// receiveShadows of a model or shape, set on each of its nodes).
    bool castShadows = true;
    bool receiveShadows = true;
    /// KHR_node_visibility: false hides its mesh and light and every descendant's, whatever
    /// theirs say (cameras stay); an animation may set it (scene/Pose.h nodeVisibility).
    bool visible = true;
    glm::mat4 localMatrix() const;
};

/// Whether the instances of nodes that KHR_node_visibility hides are listed (with visible
/// false): the renderer keeps them, for an animation that shows them.
enum class HiddenNodes : uint8_t { Skip, Include };

/// World-space results of walking the node tree.
struct MeshInstance {
    int mesh = -1;
    int node = -1;
    glm::mat4 world{1.0f};
    bool castShadows = true;
    bool receiveShadows = true;
    bool visible = true; ///< the node and its ancestors visible (KHR_node_visibility)
};
struct CameraInstance {
    int camera = -1;
    int node = -1;
    glm::mat4 world{1.0f}; ///< camera looks down its local -Z, +Y up
};
struct LightInstance {
    int light = -1;
    int node = -1;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; ///< where the light points (local -Z)
    bool visible = true; ///< the node and its ancestors visible (KHR_node_visibility)
};

/// How a billboard turns to face the camera (the basis formulas are in shading/Billboard.h).
enum class BillboardKind : uint32_t {
    PointSprite = 0,   ///< turns about its centre to face the camera, keeping the camera's up
    AxisAligned = 1,   ///< turns about world +Y only (trees, grass)
    ArbitraryAxis = 2, ///< turns about its Billboard::axis only (beams, tracers)
};

/// The procedural sprite used when a billboard group has no image (no file needed).
enum class BuiltinSprite : uint32_t {
    Disc = 0, ///< soft round disc, white, alpha falling off towards the rim
    Tree = 1, ///< a conifer shape: brown trunk, green canopy, hard alpha edges for cutout
    Bar = 2,  ///< white, opaque along its height, fading out across its width: rods, lines
};

/// One billboard of a group.
struct Billboard {
    glm::vec3 position{0.0f}; ///< world space, metres; where the group's anchor goes
    float scale = 1.0f;       ///< multiplies the group's size
    glm::vec3 tint{1.0f};     ///< multiplies the group's tint
    glm::vec3 axis{0.0f, 1.0f, 0.0f}; ///< ArbitraryAxis: the axis it turns about (world); need not be unit
};

/// Billboards sharing one sprite, kind, size and alpha mode: drawn with one instanced draw.
/// Billboards are unlit: a texel of colour c (sRGB decoded) and alpha a emits radiance
/// c × tint × Billboard::tint cd/m², so tints above 1 make bright (HDR) sprites that bloom.
struct BillboardGroup {
    std::string name;
    BillboardKind kind = BillboardKind::PointSprite;
    glm::vec2 size{1.0f};             ///< width, height: metres, or pixels when sizeInPixels
    bool sizeInPixels = false;        ///< constant size on screen whatever the distance
    glm::vec2 anchor{0.5f};           ///< point of the sprite at the position, (0, 0) = bottom left
    glm::vec3 tint{1.0f};             ///< linear RGB radiance multiplier, cd/m²; HDR allowed
    AlphaMode alphaMode = AlphaMode::Mask; ///< Mask = cutout (opaque phase), Blend = sorted back to front
    float alphaCutoff = 0.5f;         ///< Mask: texels with alpha below it are discarded
    int image = -1;                   ///< index into Scene::images; -1 = the built-in `sprite`
    BuiltinSprite sprite = BuiltinSprite::Disc;
    /// Doom model frames: the light level, 0–255, of the sector the sprites stand in (they are
    /// lit by it, as Doom's things were; scene/DoomLighting.h). The default, 255 (full bright),
    /// suits what billboards are otherwise: emitters.
    int sectorLight = 255;
    /// ArbitraryAxis only: each quad's height is its billboard's axis vector, |axis| metres from
    /// the anchor along it (size.y is unused), so a rod runs between given end points; size.x ×
    /// scale stays the width, in pixels with sizeInPixels (a line of constant width on screen).
    bool spanAxis = false;
    std::vector<Billboard> billboards;
};

struct Scene {
    std::string name;
    std::vector<Image> images;
    std::vector<Sampler> samplers;
    std::vector<Material> materials;
    std::vector<Mesh> meshes;
    std::vector<Camera> cameras;
    std::vector<Light> lights;
    std::vector<Node> nodes;
    std::vector<int> roots;
    /// Camera-facing sprites, in world space (not nodes: they have no transform of their own).
    std::vector<BillboardGroup> billboards;
    std::vector<Skin> skins;
    std::vector<Animation> animations;
    /// KHR_materials_variants: the names of the material variants, in file order (appended
    /// scenes share a variant of the same name).
    std::vector<std::string> variants;
    /// Warnings met while loading (missing textures...), already logged.
    std::vector<std::string> warnings;

    int addNode(Node node, int parent = -1);
    /// Appends `other` (its indices shifted) under a new root node with `transform`.
    void append(Scene other, const glm::mat4& transform = glm::mat4(1.0f));

    /// The drawn meshes and the lights, in file order; hidden ones (KHR_node_visibility) only
    /// with HiddenNodes::Include. Every camera is listed, hidden or not.
    std::vector<MeshInstance> meshInstances(HiddenNodes hidden = HiddenNodes::Skip) const;
    std::vector<CameraInstance> cameraInstances() const;
    std::vector<LightInstance> lightInstances(HiddenNodes hidden = HiddenNodes::Skip) const;
    /// What a renderer keeps of hidden nodes: Include where an animation may show them (the
    /// scene has animations), else Skip.
    HiddenNodes hiddenNodesToKeep() const { return animations.empty() ? HiddenNodes::Skip : HiddenNodes::Include; }
    Bounds worldBounds() const;
    size_t triangleCount() const;
};

} // namespace specula::scene
