#pragma once
// glTF animation as plain data (samplers, channels, skins, morph targets) and the evaluation of
// a sampler at a time, as the glTF 2.0 specification defines it (section 3.11 and Appendix C).
// What a pose does to a scene's nodes and vertices is scene/Pose.h.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace specula::scene {

enum class Interpolation { Step, Linear, CubicSpline };
enum class AnimationPath { Translation, Rotation, Scale, Weights, Property };

/// What a KHR_animation_pointer channel animates besides a node's transform and weights: a
/// material's factor, a texture's KHR_texture_transform, a KHR_lights_punctual light's property,
/// a camera's, or a node's KHR_node_visibility (scene/Pose.h applyProperties, posedCamera and
/// nodeVisibility write it into a copy of the material, light or camera, or the pose's nodes).
enum class AnimatedField : uint8_t {
    // Materials (Material's fields of the same names).
    BaseColor, Metallic, Roughness, Emissive, EmissiveStrength, SpecularFactor, SpecularColor, Ior,
    ClearcoatFactor, ClearcoatRoughness, SheenColor, SheenRoughness, AnisotropyStrength, AnisotropyRotation,
    IridescenceFactor, IridescenceIor, IridescenceThicknessMinimum, IridescenceThicknessMaximum,
    DiffuseTransmission, DiffuseTransmissionColor, Dispersion, AlphaCutoff, NormalScale, OcclusionStrength,
    ClearcoatNormalScale, Transmission, Thickness, AttenuationDistance, AttenuationColor,
    // A material's texture (AnimatedProperty::texture) KHR_texture_transform.
    TextureOffset, TextureRotation, TextureScale,
    // Lights.
    LightColor, LightIntensity, LightRange, SpotInnerConeAngle, SpotOuterConeAngle,
    // Cameras (scene/Pose.h posedCamera).
    CameraYfov, CameraZnear, CameraZfar, CameraXmag, CameraYmag,
    // Nodes: KHR_node_visibility's `visible`, a bool (keyframes 0 or not; STEP).
    NodeVisible,
};
/// The floats a field's keyframes hold (4: base colour; 3: colours; 2: texture offset, scale).
int animatedFieldComponents(AnimatedField field);
bool isMaterialField(AnimatedField field); ///< a material's factor or one of its textures' transform
bool isLightField(AnimatedField field);
bool isCameraField(AnimatedField field);
bool isNodeField(AnimatedField field);

struct AnimatedProperty {
    AnimatedField field = AnimatedField::BaseColor;
    int index = 0;    ///< the material's, light's, camera's or node's index in the scene
    int texture = -1; ///< texture transforms: the texture's index in kMaterialTextures (Scene.h)
    bool operator==(const AnimatedProperty&) const = default;
};

/// Keyframes: `times` in seconds, strictly increasing; per keyframe `components` floats of
/// `values` (Step, Linear), or three groups of them for CubicSpline: in-tangent, value,
/// out-tangent. Components: 3 (translation, scale), 4 (rotation, x y z w), or a mesh's number
/// of morph targets (weights).
struct AnimationSampler {
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;
    std::vector<float> values;
    int components = 0;
};

struct AnimationChannel {
    int sampler = 0; ///< index into its Animation::samplers
    int node = 0;    ///< index into Scene::nodes (-1 for AnimationPath::Property)
    AnimationPath path = AnimationPath::Translation;
    AnimatedProperty property; ///< AnimationPath::Property only (KHR_animation_pointer)
};

struct Animation {
    std::string name;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
    /// The last keyframe time of any sampler (seconds); 0 without keyframes.
    float duration() const;
};

/// glTF skin: the nodes that are its joints, and per joint the matrix from the mesh's bind
/// space into the joint's (identity when the file gives none).
struct Skin {
    std::string name;
    std::vector<int> joints;
    std::vector<glm::mat4> inverseBindMatrices;
    int skeleton = -1; ///< the file's skeleton root (informative: joint matrices do not use it)
};

/// One morph target of a primitive: displacements per vertex, each list empty or one per vertex.
struct MorphTarget {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec3> tangents;
};

/// The sampler's value at time `t` (seconds) into `out` (`components` floats). Before the first
/// keyframe the first value holds, after the last the last (the glTF spec's clamping). Linear
/// rotations are spherical (slerp along the shorter arc); rotations of every interpolation come
/// out normalised. `rotation`: the channel animates a rotation (a quaternion, x y z w).
void evaluateSampler(const AnimationSampler& sampler, float t, bool rotation, float* out);

/// Shorter-arc spherical interpolation of unit quaternions, normalised (glTF spec Appendix C).
glm::quat slerpShortest(glm::quat a, glm::quat b, float s);

} // namespace specula::scene
