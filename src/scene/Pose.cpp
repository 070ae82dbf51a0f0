#include "scene/Pose.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

namespace specula::scene {

glm::mat4 NodeTransform::local() const
{
    if (matrix) return *matrix;
    return glm::translate(glm::mat4(1.0f), translation) * glm::toMat4(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

Pose restPose(const Scene& scene)
{
    Pose pose;
    pose.nodes.reserve(scene.nodes.size());
    for (const Node& node : scene.nodes)
        pose.nodes.push_back({node.translation, node.rotation, node.scale, node.matrix});
    pose.weights.resize(scene.nodes.size());
    return pose;
}

void applyAnimation(const Scene& scene, int animation, float t, Pose& pose)
{
    if (animation < 0 || size_t(animation) >= scene.animations.size()) return;
    const Animation& a = scene.animations[size_t(animation)];
    std::vector<float> value;
    for (const AnimationChannel& channel : a.channels) {
        if (channel.sampler < 0 || size_t(channel.sampler) >= a.samplers.size()) continue;
        const AnimationSampler& sampler = a.samplers[size_t(channel.sampler)];
        if (channel.path == AnimationPath::Property) {
            const int n = animatedFieldComponents(channel.property.field);
            if (sampler.components != n) continue; // the importer refuses these
            PropertyValue v{channel.property, glm::vec4(0.0f)};
            evaluateSampler(sampler, t, false, &v.value.x);
            // Two channels on one property: the later one wins, as for a node's.
            const auto same = std::find_if(pose.properties.begin(), pose.properties.end(),
                                           [&](const PropertyValue& p) { return p.property == channel.property; });
            if (same != pose.properties.end()) *same = v;
            else pose.properties.push_back(v);
            continue;
        }
        if (channel.node < 0 || size_t(channel.node) >= pose.nodes.size())
            continue; // the importer refuses these; a hand-made Scene may still hold them
        value.assign(size_t(std::max(sampler.components, 0)), 0.0f);
        evaluateSampler(sampler, t, channel.path == AnimationPath::Rotation, value.data());
        NodeTransform& node = pose.nodes[size_t(channel.node)];
        switch (channel.path) {
        case AnimationPath::Translation:
            if (value.size() == 3) node.translation = {value[0], value[1], value[2]};
            break;
        case AnimationPath::Scale:
            if (value.size() == 3) node.scale = {value[0], value[1], value[2]};
            break;
        case AnimationPath::Rotation:
            if (value.size() == 4) node.rotation = glm::quat(value[3], value[0], value[1], value[2]);
            break;
        case AnimationPath::Weights: pose.weights[size_t(channel.node)] = value; break;
        case AnimationPath::Property: break; // above
        }
    }
}

Pose poseAt(const Scene& scene, int animation, float t)
{
    Pose pose = restPose(scene);
    applyAnimation(scene, animation, t, pose);
    return pose;
}

void applyProperties(const Pose& pose, std::vector<Material>& materials, std::vector<Light>& lights)
{
    const auto unit = [](float x) { return std::clamp(x, 0.0f, 1.0f); };
    const auto positive = [](float x) { return std::max(x, 0.0f); };
    for (const PropertyValue& p : pose.properties) {
        const glm::vec4 v = p.value;
        const AnimatedField field = p.property.field;
        if (isCameraField(field) || isNodeField(field)) continue; // posedCamera, nodeVisibility
        if (isLightField(field)) {
            if (p.property.index < 0 || size_t(p.property.index) >= lights.size()) continue;
            Light& light = lights[size_t(p.property.index)];
            switch (field) {
            case AnimatedField::LightColor: light.color = glm::max(glm::vec3(v), glm::vec3(0.0f)); break;
            case AnimatedField::LightIntensity: light.intensity = positive(v.x); break;
            case AnimatedField::LightRange: light.range = positive(v.x); break;
            case AnimatedField::SpotInnerConeAngle: light.innerConeAngle = std::clamp(v.x, 0.0f, glm::half_pi<float>()); break;
            case AnimatedField::SpotOuterConeAngle: light.outerConeAngle = std::clamp(v.x, 0.0f, glm::half_pi<float>()); break;
            default: break;
            }
            continue;
        }
        if (p.property.index < 0 || size_t(p.property.index) >= materials.size()) continue;
        Material& m = materials[size_t(p.property.index)];
        if (field == AnimatedField::TextureOffset || field == AnimatedField::TextureRotation || field == AnimatedField::TextureScale) {
            if (p.property.texture < 0 || size_t(p.property.texture) >= kMaterialTextures.size()) continue;
            UvTransform& transform = (m.*kMaterialTextures[size_t(p.property.texture)]).transform;
            if (field == AnimatedField::TextureOffset) transform.offset = glm::vec2(v);
            else if (field == AnimatedField::TextureRotation) transform.rotation = v.x;
            else transform.scale = glm::vec2(v);
            continue;
        }
        switch (field) {
        case AnimatedField::BaseColor: m.baseColorFactor = glm::clamp(v, 0.0f, 1.0f); break;
        case AnimatedField::Metallic: m.metallicFactor = unit(v.x); break;
        case AnimatedField::Roughness: m.roughnessFactor = unit(v.x); break;
        case AnimatedField::Emissive: m.emissiveFactor = glm::clamp(glm::vec3(v), 0.0f, 1.0f); break;
        case AnimatedField::EmissiveStrength: m.emissiveStrength = positive(v.x); break;
        case AnimatedField::SpecularFactor: m.specularFactor = unit(v.x); break;
        case AnimatedField::SpecularColor: m.specularColorFactor = glm::max(glm::vec3(v), glm::vec3(0.0f)); break;
        case AnimatedField::Ior:
            if (v.x >= 1.0f) m.ior = v.x; // below 1 (0: "no interface") has no F0 here, as at import
            break;
        case AnimatedField::ClearcoatFactor: m.clearcoatFactor = unit(v.x); break;
        case AnimatedField::ClearcoatRoughness: m.clearcoatRoughnessFactor = unit(v.x); break;
        case AnimatedField::SheenColor: m.sheenColorFactor = glm::clamp(glm::vec3(v), 0.0f, 1.0f); break;
        case AnimatedField::SheenRoughness: m.sheenRoughnessFactor = unit(v.x); break;
        case AnimatedField::AnisotropyStrength: m.anisotropyStrength = unit(v.x); break;
        case AnimatedField::AnisotropyRotation: m.anisotropyRotation = v.x; break;
        case AnimatedField::IridescenceFactor: m.iridescenceFactor = unit(v.x); break;
        case AnimatedField::IridescenceIor: m.iridescenceIor = std::max(v.x, 1.0f); break;
        case AnimatedField::IridescenceThicknessMinimum: m.iridescenceThicknessMinimum = positive(v.x); break;
        case AnimatedField::IridescenceThicknessMaximum: m.iridescenceThicknessMaximum = positive(v.x); break;
        case AnimatedField::DiffuseTransmission: m.diffuseTransmissionFactor = unit(v.x); break;
        case AnimatedField::DiffuseTransmissionColor: m.diffuseTransmissionColorFactor = glm::clamp(glm::vec3(v), 0.0f, 1.0f); break;
        case AnimatedField::Dispersion: m.dispersion = positive(v.x); break;
        case AnimatedField::AlphaCutoff: m.alphaCutoff = positive(v.x); break;
        case AnimatedField::NormalScale: m.normalScale = v.x; break;
        case AnimatedField::OcclusionStrength: m.occlusionStrength = unit(v.x); break;
        case AnimatedField::ClearcoatNormalScale: m.clearcoatNormalScale = v.x; break;
        case AnimatedField::Transmission: m.transmissionFactor = unit(v.x); break;
        case AnimatedField::Thickness: m.thickness = positive(v.x); break;
        case AnimatedField::AttenuationDistance:
            m.attenuationDistance = std::isfinite(v.x) && v.x > 0.0f ? v.x : 0.0f; // 0: no attenuation, as at import
            break;
        case AnimatedField::AttenuationColor: m.attenuationColor = glm::clamp(glm::vec3(v), 0.0f, 1.0f); break;
        default: break;
        }
    }
}

Camera posedCamera(const Scene& scene, const Pose& pose, int index)
{
    Camera camera = scene.cameras.at(size_t(index));
    for (const PropertyValue& p : pose.properties) {
        if (!isCameraField(p.property.field) || p.property.index != index) continue;
        const float v = p.value.x;
        switch (p.property.field) {
        case AnimatedField::CameraYfov: camera.yfov = std::clamp(v, 1e-4f, glm::pi<float>() - 1e-4f); break;
        case AnimatedField::CameraZnear: camera.znear = std::max(v, 0.0f); break;
        case AnimatedField::CameraZfar: camera.zfar = std::max(v, 0.0f); break;
        case AnimatedField::CameraXmag: camera.xmag = v; break;
        case AnimatedField::CameraYmag: camera.ymag = v; break;
        default: break;
        }
    }
    return camera;
}

std::vector<AnimatedProperty> animatedProperties(const Scene& scene)
{
    std::vector<AnimatedProperty> all;
    for (const Animation& a : scene.animations)
        for (const AnimationChannel& c : a.channels)
            if (c.path == AnimationPath::Property && std::find(all.begin(), all.end(), c.property) == all.end())
                all.push_back(c.property);
    return all;
}

std::vector<glm::mat4> worldMatrices(const Scene& scene, const Pose& pose)
{
    std::vector<glm::mat4> world(scene.nodes.size(), glm::mat4(1.0f));
    std::vector<bool> done(scene.nodes.size(), false);
    struct Item {
        int node;
        glm::mat4 parent;
    };
    std::vector<Item> stack;
    for (int root : scene.roots) stack.push_back({root, glm::mat4(1.0f)});
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.node < 0 || size_t(item.node) >= scene.nodes.size() || done[size_t(item.node)]) continue;
        done[size_t(item.node)] = true; // a malformed graph (not a tree) cannot loop here
        const glm::mat4 m = item.parent * pose.nodes[size_t(item.node)].local();
        world[size_t(item.node)] = m;
        for (int child : scene.nodes[size_t(item.node)].children) stack.push_back({child, m});
    }
    return world;
}

std::vector<bool> nodeVisibility(const Scene& scene, const Pose& pose)
{
    std::vector<bool> own(scene.nodes.size());
    for (size_t n = 0; n < scene.nodes.size(); ++n) own[n] = scene.nodes[n].visible;
    for (const PropertyValue& p : pose.properties)
        if (p.property.field == AnimatedField::NodeVisible && p.property.index >= 0 && size_t(p.property.index) < own.size())
            own[size_t(p.property.index)] = p.value.x != 0.0f;
    std::vector<bool> visible(scene.nodes.size(), true), done(scene.nodes.size(), false);
    struct Item {
        int node;
        bool parent;
    };
    std::vector<Item> stack;
    for (int root : scene.roots) stack.push_back({root, true});
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.node < 0 || size_t(item.node) >= scene.nodes.size() || done[size_t(item.node)]) continue;
        done[size_t(item.node)] = true;
        const bool v = item.parent && own[size_t(item.node)];
        visible[size_t(item.node)] = v;
        for (int child : scene.nodes[size_t(item.node)].children) stack.push_back({child, v});
    }
    return visible;
}

std::vector<glm::mat4> jointMatrices(const Skin& skin, const std::vector<glm::mat4>& world)
{
    std::vector<glm::mat4> out(skin.joints.size(), glm::mat4(1.0f));
    for (size_t j = 0; j < skin.joints.size(); ++j) {
        const int node = skin.joints[j];
        const glm::mat4 global = node >= 0 && size_t(node) < world.size() ? world[size_t(node)] : glm::mat4(1.0f);
        out[j] = global * (j < skin.inverseBindMatrices.size() ? skin.inverseBindMatrices[j] : glm::mat4(1.0f));
    }
    return out;
}

std::vector<float> morphWeights(const Scene& scene, const Pose& pose, int node, size_t targets)
{
    std::vector<float> out;
    if (node >= 0 && size_t(node) < scene.nodes.size()) {
        const Node& n = scene.nodes[size_t(node)];
        const size_t animated = size_t(n.weightsFrom >= 0 ? n.weightsFrom : node); // an instance: its node's animation
        if (animated < pose.weights.size() && !pose.weights[animated].empty()) out = pose.weights[animated];
        else if (!n.weights.empty()) out = n.weights;
        else if (n.mesh >= 0 && size_t(n.mesh) < scene.meshes.size()) out = scene.meshes[size_t(n.mesh)].weights;
    }
    out.resize(targets, 0.0f);
    return out;
}

void deformPrimitive(const Primitive& rest, const std::vector<glm::mat4>& joints, const std::vector<float>& weights,
                     std::vector<Vertex>& out, Bounds& bounds)
{
    out = rest.vertices;
    const size_t count = out.size();
    // Morph targets: p = p0 + sum_i w_i dp_i, likewise normals and tangents (glTF spec 3.7.2.2).
    for (size_t t = 0; t < rest.targets.size() && t < weights.size(); ++t) {
        const float w = weights[t];
        if (w == 0.0f) continue;
        const MorphTarget& target = rest.targets[t];
        if (target.positions.size() == count)
            for (size_t i = 0; i < count; ++i) out[i].position += w * target.positions[i];
        if (target.normals.size() == count)
            for (size_t i = 0; i < count; ++i) out[i].normal += w * target.normals[i];
        if (target.tangents.size() == count)
            for (size_t i = 0; i < count; ++i) out[i].tangent += glm::vec4(w * target.tangents[i], 0.0f);
    }
    const int influences = rest.influences;
    const bool skinned = influences > 0 && !joints.empty() && rest.joints.size() == count * size_t(influences) &&
                         rest.weights.size() == rest.joints.size();
    for (size_t i = 0; i < count; ++i) {
        Vertex& v = out[i];
        if (skinned) {
            glm::mat4 m(0.0f);
            for (int k = 0; k < influences; ++k) {
                const size_t slot = i * size_t(influences) + size_t(k);
                const float w = rest.weights[slot];
                if (w == 0.0f || rest.joints[slot] >= joints.size()) continue;
                m += w * joints[rest.joints[slot]];
            }
            v.position = glm::vec3(m * glm::vec4(v.position, 1.0f));
            const glm::mat3 m3(m);
            // Normals transform by the inverse transpose (a non-uniform scale in a joint).
            const float det = glm::determinant(m3);
            const glm::mat3 normalMatrix = std::abs(det) > 1e-12f ? glm::transpose(glm::inverse(m3)) : m3;
            v.normal = normalMatrix * v.normal;
            v.tangent = glm::vec4(m3 * glm::vec3(v.tangent), v.tangent.w);
        }
        const float nl = glm::length(v.normal);
        if (nl > 0.0f) v.normal /= nl;
        const float tl = glm::length(glm::vec3(v.tangent));
        if (tl > 0.0f) v.tangent = glm::vec4(glm::vec3(v.tangent) / tl, v.tangent.w);
    }
    if (rest.flatNormals && rest.indices.empty()) {
        for (size_t i = 0; i + 2 < count; i += 3) {
            const glm::vec3 face = glm::cross(out[i + 1].position - out[i].position, out[i + 2].position - out[i].position);
            const float l = glm::length(face);
            if (l > 0.0f)
                for (size_t k = 0; k < 3; ++k) out[i + k].normal = face / l;
        }
    }
    bounds = Bounds{};
    for (const Vertex& v : out) bounds.extend(v.position);
}

} // namespace specula::scene
