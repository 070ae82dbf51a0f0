// glTF import: skins (JOINTS_n, WEIGHTS_n, inverse bind matrices), morph targets and animations.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <optional>
#include <string_view>

#include "scene/GltfInternal.h"

namespace specula::scene::gltf_detail {

namespace {

const char* pathName(AnimationPath path)
{
    switch (path) {
    case AnimationPath::Translation: return "translation";
    case AnimationPath::Rotation: return "rotation";
    case AnimationPath::Scale: return "scale";
    case AnimationPath::Weights: return "weights";
    case AnimationPath::Property: return "pointer";
    }
    return "?";
}

// KHR_animation_pointer: the material properties Specula animates, by their path below
// /materials/{i}/.
struct MaterialPointer {
    std::string_view path;
    AnimatedField field;
};
constexpr MaterialPointer kMaterialPointers[] = {
    {"pbrMetallicRoughness/baseColorFactor", AnimatedField::BaseColor},
    {"pbrMetallicRoughness/metallicFactor", AnimatedField::Metallic},
    {"pbrMetallicRoughness/roughnessFactor", AnimatedField::Roughness},
    {"emissiveFactor", AnimatedField::Emissive},
    {"extensions/KHR_materials_emissive_strength/emissiveStrength", AnimatedField::EmissiveStrength},
    {"extensions/KHR_materials_specular/specularFactor", AnimatedField::SpecularFactor},
    {"extensions/KHR_materials_specular/specularColorFactor", AnimatedField::SpecularColor},
    {"extensions/KHR_materials_ior/ior", AnimatedField::Ior},
    {"extensions/KHR_materials_clearcoat/clearcoatFactor", AnimatedField::ClearcoatFactor},
    {"extensions/KHR_materials_clearcoat/clearcoatRoughnessFactor", AnimatedField::ClearcoatRoughness},
    {"extensions/KHR_materials_sheen/sheenColorFactor", AnimatedField::SheenColor},
    {"extensions/KHR_materials_sheen/sheenRoughnessFactor", AnimatedField::SheenRoughness},
    {"extensions/KHR_materials_anisotropy/anisotropyStrength", AnimatedField::AnisotropyStrength},
    {"extensions/KHR_materials_anisotropy/anisotropyRotation", AnimatedField::AnisotropyRotation},
    {"extensions/KHR_materials_iridescence/iridescenceFactor", AnimatedField::IridescenceFactor},
    {"extensions/KHR_materials_iridescence/iridescenceIor", AnimatedField::IridescenceIor},
    {"extensions/KHR_materials_iridescence/iridescenceThicknessMinimum", AnimatedField::IridescenceThicknessMinimum},
    {"extensions/KHR_materials_iridescence/iridescenceThicknessMaximum", AnimatedField::IridescenceThicknessMaximum},
    {"extensions/KHR_materials_diffuse_transmission/diffuseTransmissionFactor", AnimatedField::DiffuseTransmission},
    {"extensions/KHR_materials_diffuse_transmission/diffuseTransmissionColorFactor", AnimatedField::DiffuseTransmissionColor},
    {"extensions/KHR_materials_dispersion/dispersion", AnimatedField::Dispersion},
    {"alphaCutoff", AnimatedField::AlphaCutoff},
    {"normalTexture/scale", AnimatedField::NormalScale},
    {"occlusionTexture/strength", AnimatedField::OcclusionStrength},
    {"extensions/KHR_materials_clearcoat/clearcoatNormalTexture/scale", AnimatedField::ClearcoatNormalScale},
    {"extensions/KHR_materials_transmission/transmissionFactor", AnimatedField::Transmission},
    {"extensions/KHR_materials_volume/thicknessFactor", AnimatedField::Thickness},
    {"extensions/KHR_materials_volume/attenuationDistance", AnimatedField::AttenuationDistance},
    {"extensions/KHR_materials_volume/attenuationColor", AnimatedField::AttenuationColor},
};
// Each texture's textureInfo below /materials/{i}/, in the order of kMaterialTextures (Scene.h).
constexpr std::string_view kTexturePointers[] = {
    "pbrMetallicRoughness/baseColorTexture",
    "pbrMetallicRoughness/metallicRoughnessTexture",
    "normalTexture",
    "occlusionTexture",
    "emissiveTexture",
    "extensions/KHR_materials_clearcoat/clearcoatTexture",
    "extensions/KHR_materials_clearcoat/clearcoatRoughnessTexture",
    "extensions/KHR_materials_clearcoat/clearcoatNormalTexture",
    "extensions/KHR_materials_sheen/sheenColorTexture",
    "extensions/KHR_materials_sheen/sheenRoughnessTexture",
    "extensions/KHR_materials_anisotropy/anisotropyTexture",
    "extensions/KHR_materials_iridescence/iridescenceTexture",
    "extensions/KHR_materials_iridescence/iridescenceThicknessTexture",
    "extensions/KHR_materials_specular/specularTexture",
    "extensions/KHR_materials_specular/specularColorTexture",
    "extensions/KHR_materials_transmission/transmissionTexture",
    "extensions/KHR_materials_volume/thicknessTexture",
    "extensions/KHR_materials_diffuse_transmission/diffuseTransmissionTexture",
    "extensions/KHR_materials_diffuse_transmission/diffuseTransmissionColorTexture",
};
static_assert(std::size(kTexturePointers) == kMaterialTextures.size(), "a pointer path for every texture of scene::Material");

/// A non-negative decimal index (JSON pointer tokens have no sign or leading zeros to honour here).
std::optional<int> pointerIndex(std::string_view token)
{
    if (token.empty() || token.size() > 9) return std::nullopt;
    int value = 0;
    for (char c : token) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + (c - '0');
    }
    return value;
}

/// KHR_animation_pointer's target as a channel, or nothing where Specula does not animate it.
/// Indices are checked by the caller.
std::optional<AnimationChannel> pointerChannel(std::string_view pointer)
{
    std::vector<std::string_view> tokens;
    if (!pointer.starts_with('/')) return std::nullopt;
    for (size_t start = 1; start <= pointer.size();) {
        const size_t end = std::min(pointer.find('/', start), pointer.size());
        tokens.push_back(pointer.substr(start, end - start));
        start = end + 1;
    }
    AnimationChannel out;
    out.node = -1;
    if (tokens.size() == 3 && tokens[0] == "nodes") {
        const auto node = pointerIndex(tokens[1]);
        if (!node) return std::nullopt;
        out.node = *node;
        if (tokens[2] == "translation") out.path = AnimationPath::Translation;
        else if (tokens[2] == "rotation") out.path = AnimationPath::Rotation;
        else if (tokens[2] == "scale") out.path = AnimationPath::Scale;
        else if (tokens[2] == "weights") out.path = AnimationPath::Weights;
        else return std::nullopt;
        return out;
    }
    out.path = AnimationPath::Property;
    if (tokens.size() == 5 && tokens[0] == "nodes" && tokens[2] == "extensions" && tokens[3] == "KHR_node_visibility" &&
        tokens[4] == "visible") {
        const auto node = pointerIndex(tokens[1]);
        if (!node) return std::nullopt;
        out.property.index = *node;
        out.property.field = AnimatedField::NodeVisible;
        return out;
    }
    if (tokens.size() >= 3 && tokens[0] == "materials") {
        const auto material = pointerIndex(tokens[1]);
        if (!material) return std::nullopt;
        out.property.index = *material;
        const std::string_view rest = pointer.substr(pointer.find('/', 1 + tokens[0].size() + 1) + 1);
        for (const MaterialPointer& p : kMaterialPointers)
            if (rest == p.path) {
                out.property.field = p.field;
                return out;
            }
        constexpr std::string_view kTransform = "/extensions/KHR_texture_transform/";
        for (size_t t = 0; t < std::size(kTexturePointers); ++t) {
            if (!rest.starts_with(kTexturePointers[t]) || rest.substr(kTexturePointers[t].size()).find(kTransform) != 0) continue;
            const std::string_view name = rest.substr(kTexturePointers[t].size() + kTransform.size());
            out.property.texture = int(t);
            if (name == "offset") out.property.field = AnimatedField::TextureOffset;
            else if (name == "rotation") out.property.field = AnimatedField::TextureRotation;
            else if (name == "scale") out.property.field = AnimatedField::TextureScale;
            else return std::nullopt;
            return out;
        }
        return std::nullopt;
    }
    if (tokens.size() == 4 && tokens[0] == "cameras") {
        const auto camera = pointerIndex(tokens[1]);
        if (!camera) return std::nullopt;
        out.property.index = *camera;
        const std::string_view type = tokens[2], name = tokens[3];
        if (type == "perspective" && name == "yfov") out.property.field = AnimatedField::CameraYfov;
        else if ((type == "perspective" || type == "orthographic") && name == "znear") out.property.field = AnimatedField::CameraZnear;
        else if ((type == "perspective" || type == "orthographic") && name == "zfar") out.property.field = AnimatedField::CameraZfar;
        else if (type == "orthographic" && name == "xmag") out.property.field = AnimatedField::CameraXmag;
        else if (type == "orthographic" && name == "ymag") out.property.field = AnimatedField::CameraYmag;
        else return std::nullopt; // aspectRatio: the viewport's is used
        return out;
    }
    if ((tokens.size() == 5 || tokens.size() == 6) && tokens[0] == "extensions" && tokens[1] == "KHR_lights_punctual" &&
        tokens[2] == "lights") {
        const auto light = pointerIndex(tokens[3]);
        if (!light) return std::nullopt;
        out.property.index = *light;
        if (tokens.size() == 5 && tokens[4] == "color") out.property.field = AnimatedField::LightColor;
        else if (tokens.size() == 5 && tokens[4] == "intensity") out.property.field = AnimatedField::LightIntensity;
        else if (tokens.size() == 5 && tokens[4] == "range") out.property.field = AnimatedField::LightRange;
        else if (tokens.size() == 6 && tokens[4] == "spot" && tokens[5] == "innerConeAngle")
            out.property.field = AnimatedField::SpotInnerConeAngle;
        else if (tokens.size() == 6 && tokens[4] == "spot" && tokens[5] == "outerConeAngle")
            out.property.field = AnimatedField::SpotOuterConeAngle;
        else return std::nullopt;
        return out;
    }
    return std::nullopt;
}

} // namespace

void Importer::readDeformation(const tinygltf::Primitive& source, size_t vertexCount, Primitive& primitive,
                               const std::string& where, DracoPrimitive* draco)
{
    auto readAttribute = [&](const std::string& name, int index) {
        if (draco) {
            const auto it = draco->attributes.find(name);
            if (it != draco->attributes.end()) return std::move(it->second);
        }
        return read<float>(index, where + " " + name);
    };
    auto attribute = [&](const std::string& name) {
        const auto it = source.attributes.find(name);
        return it == source.attributes.end() ? -1 : it->second;
    };
    // JOINTS_0/WEIGHTS_0, then JOINTS_1/WEIGHTS_1: four influences per set (glTF 2.0 spec 3.7.3.3).
    int sets = 0;
    while (attribute(fmt::format("JOINTS_{}", sets)) >= 0) ++sets;
    if (sets == 0) {
        if (attribute("WEIGHTS_0") >= 0) warn("{} has WEIGHTS_0 but no JOINTS_0; it is not skinned", where);
    } else {
        // Two sets cover what people ship (the spec allows more; they would cost every vertex).
        if (sets > 2) {
            warn("{} has {} sets of JOINTS/WEIGHTS; only the first 2 (8 influences) are used", where, sets);
            sets = 2;
        }
        primitive.influences = 4 * sets;
        primitive.joints.assign(vertexCount * size_t(primitive.influences), 0);
        primitive.weights.assign(vertexCount * size_t(primitive.influences), 0.0f);
        for (int set = 0; set < sets; ++set) {
            const std::string jointsName = fmt::format("JOINTS_{}", set), weightsName = fmt::format("WEIGHTS_{}", set);
            const int jointsIndex = attribute(jointsName), weightsIndex = attribute(weightsName);
            if (weightsIndex < 0) fail("{} has {} but no {}", where, jointsName, weightsName);
            const auto& jointsAccessor = at(mModel.accessors, jointsIndex, "accessor", where + " " + jointsName);
            const auto& weightsAccessor = at(mModel.accessors, weightsIndex, "accessor", where + " " + weightsName);
            if (jointsAccessor.type != TINYGLTF_TYPE_VEC4 || jointsAccessor.normalized ||
                (jointsAccessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                 jointsAccessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT))
                fail("{} {}: accessor {} must hold VEC4 of unsigned bytes or shorts", where, jointsName, jointsIndex);
            const bool weightsOk =
                weightsAccessor.type == TINYGLTF_TYPE_VEC4 &&
                (weightsAccessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                 (weightsAccessor.normalized && (weightsAccessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                 weightsAccessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)));
            if (!weightsOk)
                fail("{} {}: accessor {} must hold VEC4 of floats or normalized unsigned bytes or shorts", where,
                     weightsName, weightsIndex);
            const auto joints = readAttribute(jointsName, jointsIndex);
            const auto weights = readAttribute(weightsName, weightsIndex);
            if (joints.count != vertexCount || weights.count != vertexCount)
                fail("{} {} / {} have {} / {} elements but POSITION has {}", where, jointsName, weightsName,
                     joints.count, weights.count, vertexCount);
            for (size_t i = 0; i < vertexCount; ++i) {
                for (int k = 0; k < 4; ++k) {
                    const size_t slot = i * size_t(primitive.influences) + size_t(set * 4 + k);
                    const float w = weights.at(i, k);
                    if (!std::isfinite(w) || w < 0.0f) fail("{} {} has the weight {} (weights are >= 0)", where, weightsName, w);
                    primitive.joints[slot] = uint16_t(joints.at(i, k));
                    primitive.weights[slot] = w;
                }
            }
        }
    }

    for (size_t t = 0; t < source.targets.size(); ++t) {
        MorphTarget target;
        for (const auto& [name, index] : source.targets[t]) {
            std::vector<glm::vec3>* list = name == "POSITION" ? &target.positions
                                           : name == "NORMAL" ? &target.normals
                                           : name == "TANGENT" ? &target.tangents
                                                               : nullptr;
            if (!list) continue; // TEXCOORD_n and COLOR_n targets are allowed but not animated here
            const std::string targetWhere = fmt::format("{} target {} {}", where, t, name);
            const auto data = read<float>(index, targetWhere);
            if (data.components != 3) fail("{} must be VEC3", targetWhere);
            if (data.count != vertexCount) fail("{} has {} elements but POSITION has {}", targetWhere, data.count, vertexCount);
            list->resize(vertexCount);
            for (size_t i = 0; i < vertexCount; ++i) {
                (*list)[i] = {data.at(i, 0), data.at(i, 1), data.at(i, 2)};
                if (!std::isfinite((*list)[i].x + (*list)[i].y + (*list)[i].z)) fail("{} holds a non-finite number", targetWhere);
            }
        }
        primitive.targets.push_back(std::move(target));
    }
}

void Importer::convertSkins()
{
    for (size_t s = 0; s < mModel.skins.size(); ++s) {
        const tinygltf::Skin& source = mModel.skins[s];
        const auto where = fmt::format("skin {}", s);
        Skin skin;
        skin.name = source.name;
        if (source.joints.empty()) fail("{} has no joints", where);
        for (int joint : source.joints) {
            at(mModel.nodes, joint, "node", where + " joints");
            skin.joints.push_back(joint);
        }
        if (source.skeleton >= 0) {
            at(mModel.nodes, source.skeleton, "node", where + " skeleton");
            skin.skeleton = source.skeleton;
        }
        skin.inverseBindMatrices.assign(skin.joints.size(), glm::mat4(1.0f));
        if (source.inverseBindMatrices >= 0) {
            const auto ibmWhere = where + " inverseBindMatrices";
            const auto& accessor = at(mModel.accessors, source.inverseBindMatrices, "accessor", ibmWhere);
            if (accessor.type != TINYGLTF_TYPE_MAT4 || accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT ||
                accessor.bufferView < 0 || accessor.sparse.isSparse)
                fail("{}: accessor {} must hold MAT4 floats in a bufferView (not sparse)", ibmWhere,
                     source.inverseBindMatrices);
            if (accessor.count < skin.joints.size())
                fail("{} has {} matrices for {} joints", ibmWhere, accessor.count, skin.joints.size());
            const auto& view = at(mModel.bufferViews, accessor.bufferView, "bufferView", ibmWhere);
            const size_t stride = view.byteStride != 0 ? view.byteStride : 64;
            if (stride < 64) fail("{}: bufferView {} has a byteStride of {}, less than a matrix", ibmWhere, accessor.bufferView, stride);
            const unsigned char* data = elements(accessor.bufferView, accessor.byteOffset, skin.joints.size(), 64, stride, ibmWhere);
            for (size_t j = 0; j < skin.joints.size(); ++j) {
                float m[16];
                std::memcpy(m, data + j * stride, sizeof m);
                for (float v : m)
                    if (!std::isfinite(v)) fail("{} holds a non-finite number", ibmWhere);
                skin.inverseBindMatrices[j] = glm::mat4(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9], m[10],
                                                        m[11], m[12], m[13], m[14], m[15]); // column major
            }
        }
        mScene.skins.push_back(std::move(skin));
    }
    // Every joint index of a skinned mesh must name a joint of the skin that skins it.
    for (size_t n = 0; n < mScene.nodes.size(); ++n) {
        const Node& node = mScene.nodes[n];
        if (node.skin < 0 || node.mesh < 0) continue;
        const size_t joints = mScene.skins[size_t(node.skin)].joints.size();
        for (size_t p = 0; p < mScene.meshes[size_t(node.mesh)].primitives.size(); ++p) {
            const Primitive& primitive = mScene.meshes[size_t(node.mesh)].primitives[p];
            for (size_t i = 0; i < primitive.joints.size(); ++i)
                if (primitive.joints[i] >= joints && primitive.weights[i] > 0.0f)
                    fail("node {} draws mesh {} with skin {}, but a vertex of primitive {} uses joint {} (the skin has {})",
                         n, node.mesh, node.skin, p, primitive.joints[i], joints);
        }
    }
}

void Importer::convertAnimations()
{
    for (size_t a = 0; a < mModel.animations.size(); ++a) {
        const tinygltf::Animation& source = mModel.animations[a];
        Animation animation;
        animation.name = source.name;
        for (size_t s = 0; s < source.samplers.size(); ++s) {
            const tinygltf::AnimationSampler& sampler = source.samplers[s];
            const auto where = fmt::format("animation {} sampler {}", a, s);
            AnimationSampler out;
            if (sampler.interpolation == "LINEAR") out.interpolation = Interpolation::Linear;
            else if (sampler.interpolation == "STEP") out.interpolation = Interpolation::Step;
            else if (sampler.interpolation == "CUBICSPLINE") out.interpolation = Interpolation::CubicSpline;
            else fail("{} has the unknown interpolation '{}'", where, sampler.interpolation);
            const auto& input = at(mModel.accessors, sampler.input, "accessor", where + " input");
            if (input.type != TINYGLTF_TYPE_SCALAR || input.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
                fail("{} input: accessor {} must hold float scalars", where, sampler.input);
            const auto times = read<float>(sampler.input, where + " input");
            if (times.count == 0) fail("{} has no keyframes", where);
            for (size_t k = 0; k < times.count; ++k) {
                const float t = times.values[k];
                if (!std::isfinite(t) || t < 0.0f) fail("{} has the keyframe time {} (times are finite and >= 0)", where, t);
                if (k > 0 && !(t > times.values[k - 1]))
                    fail("{} has keyframe times that do not increase ({} after {})", where, t, times.values[k - 1]);
            }
            if (out.interpolation == Interpolation::CubicSpline && times.count < 2)
                fail("{} is CUBICSPLINE with fewer than 2 keyframes", where);
            out.times = times.values;
            const auto values = read<float>(sampler.output, where + " output");
            for (float v : values.values)
                if (!std::isfinite(v)) fail("{} output holds a non-finite number", where);
            out.values = values.values;
            out.components = 0; // set by the channels that use it, which know their path
            animation.samplers.push_back(std::move(out));
        }
        for (size_t c = 0; c < source.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = source.channels[c];
            const auto where = fmt::format("animation {} channel {}", a, c);
            AnimationChannel out;
            if (channel.target_path == "pointer") {
                // KHR_animation_pointer: the target is a JSON pointer into the document.
                const auto extension = channel.target_extensions.find("KHR_animation_pointer");
                const tinygltf::Value* pointer =
                    extension == channel.target_extensions.end() ? nullptr : member(extension->second, "pointer");
                if (!pointer || !pointer->IsString()) fail("{} has the path 'pointer' but no KHR_animation_pointer pointer", where);
                const std::optional<AnimationChannel> target = pointerChannel(pointer->Get<std::string>());
                if (!target) {
                    warn("{} animates '{}', which is not supported; it is ignored", where, pointer->Get<std::string>());
                    continue;
                }
                out = *target;
                if (out.path == AnimationPath::Property) {
                    const AnimatedField field = out.property.field;
                    const bool light = isLightField(field), camera = isCameraField(field), node = isNodeField(field);
                    const size_t count = light    ? mScene.lights.size()
                                         : camera ? mScene.cameras.size()
                                         : node   ? mModel.nodes.size()
                                                  : mScene.materials.size();
                    if (out.property.index >= int(count))
                        fail("{} animates '{}', but there are {} {}", where, pointer->Get<std::string>(), count,
                             light ? "lights" : camera ? "cameras" : node ? "nodes" : "materials");
                    if (field == AnimatedField::NodeVisible) {
                        // A bool (the extension's Object Model types): unsigned bytes, STEP.
                        const auto& sampler = at(source.samplers, channel.sampler, "sampler", where);
                        const auto& output = at(mModel.accessors, sampler.output, "accessor", where + " output");
                        if (output.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || output.normalized)
                            fail("{} animates '{}', a bool: its output must be unsigned bytes (0 false, else true)", where,
                                 pointer->Get<std::string>());
                        if (sampler.interpolation != "STEP")
                            fail("{} animates '{}', a bool: its sampler must use STEP interpolation, not {}", where,
                                 pointer->Get<std::string>(), sampler.interpolation);
                    }
                }
            } else {
                if (channel.target_node < 0) {
                    warn("{} has no target node (an extension's target?); it is ignored", where);
                    continue;
                }
                out.node = channel.target_node;
                if (channel.target_path == "translation") out.path = AnimationPath::Translation;
                else if (channel.target_path == "rotation") out.path = AnimationPath::Rotation;
                else if (channel.target_path == "scale") out.path = AnimationPath::Scale;
                else if (channel.target_path == "weights") out.path = AnimationPath::Weights;
                else {
                    warn("{} animates '{}', which is not supported; it is ignored", where, channel.target_path);
                    continue;
                }
            }
            at(source.samplers, channel.sampler, "sampler", where);
            out.sampler = channel.sampler;
            int components = animatedFieldComponents(out.property.field);
            if (out.path != AnimationPath::Property) {
                at(mModel.nodes, out.node, "node", where);
                const Node& node = mScene.nodes[size_t(out.node)];
                if (out.path != AnimationPath::Weights && node.matrix) {
                    // glTF 2.0 spec (Animations): a node with a matrix is not a valid TRS target.
                    warn("{} animates the {} of node {}, which has a matrix; it is ignored", where, pathName(out.path), out.node);
                    continue;
                }
                components = out.path == AnimationPath::Rotation ? 4 : 3;
                if (out.path == AnimationPath::Weights) {
                    // An instanced node's mesh is its instances' (EXT_mesh_gpu_instancing; Node::weightsFrom).
                    int mesh = node.mesh;
                    for (size_t k = 0; mesh < 0 && k < node.children.size(); ++k)
                        if (mScene.nodes[size_t(node.children[k])].weightsFrom == out.node) mesh = mScene.nodes[size_t(node.children[k])].mesh;
                    const size_t targets = mesh >= 0 && !mScene.meshes[size_t(mesh)].primitives.empty()
                                               ? mScene.meshes[size_t(mesh)].primitives[0].targets.size()
                                               : 0;
                    if (targets == 0) fail("{} animates the weights of node {}, whose mesh has no morph targets", where, out.node);
                    components = int(targets);
                }
            }
            AnimationSampler& sampler = animation.samplers[size_t(out.sampler)];
            if (sampler.components != 0 && sampler.components != components)
                fail("{} uses sampler {} for {} values per key, but another channel uses it for {}", where, out.sampler,
                     components, sampler.components);
            const size_t perKey = size_t(components) * (sampler.interpolation == Interpolation::CubicSpline ? 3 : 1);
            if (sampler.values.size() != sampler.times.size() * perKey)
                fail("{}: sampler {} has {} output numbers for {} keyframes of {} {} ({} expected)", where, out.sampler,
                     sampler.values.size(), sampler.times.size(), components,
                     out.path == AnimationPath::Property ? "values" : pathName(out.path), sampler.times.size() * perKey);
            sampler.components = components;
            animation.channels.push_back(out);
        }
        mScene.animations.push_back(std::move(animation));
    }
}

} // namespace specula::scene::gltf_detail
