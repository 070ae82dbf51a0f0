#pragma once
// A scene posed by an animation: the nodes' local transforms and morph weights at a time, the
// world matrices and joint matrices they give, and the vertices of skinned and morphed
// primitives deformed by them (glTF 2.0 spec 3.7.3 skins, 3.7.2.2 morph targets, 3.11
// animations). GL-free: the renderer uploads what deformPrimitive writes (render/GpuScene).
#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/Scene.h"

namespace specula::scene {

struct NodeTransform {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    std::optional<glm::mat4> matrix; ///< a node given by a matrix (never animated)
    glm::mat4 local() const;
};

/// A KHR_animation_pointer property's value at the pose's time (animatedFieldComponents floats).
struct PropertyValue {
    AnimatedProperty property;
    glm::vec4 value{0.0f};
};

/// Per node: its local transform and its morph weights (empty: its mesh's defaults); and the
/// materials', lights', cameras' and nodes' properties the animation sets (KHR_animation_pointer).
struct Pose {
    std::vector<NodeTransform> nodes;
    std::vector<std::vector<float>> weights;
    std::vector<PropertyValue> properties;
};

/// The nodes as the file gives them.
Pose restPose(const Scene& scene);
/// Writes animation `animation`'s channels at time `t` (seconds) over `pose`; what it does not
/// animate keeps its value. `animation` out of range (-1): nothing changes.
void applyAnimation(const Scene& scene, int animation, float t, Pose& pose);
/// restPose, then applyAnimation.
Pose poseAt(const Scene& scene, int animation, float t);

/// Writes the pose's property values into `materials` and `lights` (copies of the scene's):
/// factors clamped to their ranges as the importer clamps them, a base colour's alpha too.
void applyProperties(const Pose& pose, std::vector<Material>& materials, std::vector<Light>& lights);
/// Camera `camera` of the scene with the pose's property values (yfov, znear, zfar, xmag, ymag).
Camera posedCamera(const Scene& scene, const Pose& pose, int camera);
/// Every property any of the scene's animations sets, once each.
std::vector<AnimatedProperty> animatedProperties(const Scene& scene);

/// KHR_node_visibility under `pose`: a node is visible when its own `visible` (the pose's where
/// an animation sets it, else the file's) and every ancestor's are (true for nodes no root reaches).
std::vector<bool> nodeVisibility(const Scene& scene, const Pose& pose);
/// Each node's world matrix under `pose` (identity for nodes no root reaches).
std::vector<glm::mat4> worldMatrices(const Scene& scene, const Pose& pose);
/// glTF skins: joint matrix j = world(joints[j]) × inverseBindMatrices[j]. A skinned vertex
/// goes to world space by the weighted sum of its joints' matrices (the mesh node's own
/// transform is not applied).
std::vector<glm::mat4> jointMatrices(const Skin& skin, const std::vector<glm::mat4>& world);
/// The morph weights node `node`'s mesh is drawn with: the pose's (for an EXT_mesh_gpu_instancing
/// instance, its instanced node's: Node::weightsFrom), else the node's, else the mesh's, padded
/// with zeros (or cut) to `targets` entries.
std::vector<float> morphWeights(const Scene& scene, const Pose& pose, int node, size_t targets);

/// `rest`'s vertices morphed by `weights` (one per target; missing ones 0) and then, when
/// `joints` is not empty and the primitive has influences, skinned by those joint matrices
/// (into world space). Normals go by the inverse transpose of the blended matrix, tangents by
/// the matrix; both are normalised; per-face normals are made again from the new positions.
/// Joint indices past `joints` are ignored (the importer refuses such files). `bounds` gets
/// the new positions' bounds.
void deformPrimitive(const Primitive& rest, const std::vector<glm::mat4>& joints, const std::vector<float>& weights,
                     std::vector<Vertex>& out, Bounds& bounds);

} // namespace specula::scene
