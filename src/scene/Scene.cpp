#include "scene/Scene.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

namespace specula::scene {

glm::mat3 UvTransform::matrix() const
{
    // KHR_texture_transform: T * R * S with R rotating counter-clockwise in uv space
    // (the extension's matrix, column-major).
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::mat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::mat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    return t * r * sc;
}

Bounds Bounds::transformed(const glm::mat4& m) const
{
    Bounds out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
        out.extend(glm::vec3(m * glm::vec4(corner, 1.0f)));
    }
    return out;
}

glm::mat4 Node::localMatrix() const
{
    if (matrix) return *matrix;
    return glm::translate(glm::mat4(1.0f), translation) * glm::toMat4(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

int Scene::addNode(Node node, int parent)
{
    nodes.push_back(std::move(node));
    const int index = int(nodes.size() - 1);
    if (parent >= 0) {
        nodes[size_t(parent)].children.push_back(index);
    } else {
        roots.push_back(index);
    }
    return index;
}

void Scene::append(Scene other, const glm::mat4& transform)
{
    const int imageBase = int(images.size());
    const int samplerBase = int(samplers.size());
    const int materialBase = int(materials.size());
    const int meshBase = int(meshes.size());
    const int cameraBase = int(cameras.size());
    const int lightBase = int(lights.size());
    const int nodeBase = int(nodes.size());
    const int skinBase = int(skins.size());

    auto shiftTexture = [&](TextureRef& ref) {
        if (ref.image >= 0) ref.image += imageBase;
        if (ref.sampler >= 0) ref.sampler += samplerBase;
    };
    for (auto& material : other.materials) material.forEachTexture(shiftTexture);
    // Variants are matched by name: a variant "red" chooses the red of every model that has one.
    std::vector<int> variantIndex;
    for (const std::string& name : other.variants) {
        const auto found = std::find(variants.begin(), variants.end(), name);
        variantIndex.push_back(int(found - variants.begin()));
        if (found == variants.end()) variants.push_back(name);
    }
    for (auto& mesh : other.meshes)
        for (auto& primitive : mesh.primitives) {
            if (primitive.material >= 0) primitive.material += materialBase;
            for (VariantMapping& mapping : primitive.variants) {
                if (mapping.material >= 0) mapping.material += materialBase;
                mapping.variant = variantIndex[size_t(mapping.variant)];
            }
        }
    for (auto& node : other.nodes) {
        if (node.mesh >= 0) node.mesh += meshBase;
        if (node.camera >= 0) node.camera += cameraBase;
        if (node.light >= 0) node.light += lightBase;
        if (node.skin >= 0) node.skin += skinBase;
        if (node.weightsFrom >= 0) node.weightsFrom += nodeBase;
        for (int& child : node.children) child += nodeBase;
    }
    auto move = [](auto& to, auto& from) {
        to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
    };
    move(images, other.images);
    move(samplers, other.samplers);
    move(materials, other.materials);
    move(meshes, other.meshes);
    move(cameras, other.cameras);
    move(lights, other.lights);
    move(nodes, other.nodes);
    move(warnings, other.warnings);
    for (auto& skin : other.skins) {
        for (int& joint : skin.joints) joint += nodeBase;
        if (skin.skeleton >= 0) skin.skeleton += nodeBase;
    }
    move(skins, other.skins);
    for (auto& animation : other.animations)
        for (auto& channel : animation.channels) {
            if (channel.path != AnimationPath::Property) channel.node += nodeBase;
            // KHR_animation_pointer's material, light, camera or node.
            else channel.property.index += isLightField(channel.property.field)    ? lightBase
                                           : isCameraField(channel.property.field) ? cameraBase
                                           : isNodeField(channel.property.field)   ? nodeBase
                                                                                   : materialBase;
        }
    move(animations, other.animations);
    // Billboards are in world space, not nodes: place them with the transform here. Their size
    // stays as given (a sprite has no orientation for a rotation or scale to act on).
    for (auto& group : other.billboards) {
        if (group.image >= 0) group.image += imageBase;
        for (auto& billboard : group.billboards) {
            billboard.position = glm::vec3(transform * glm::vec4(billboard.position, 1.0f));
            billboard.axis = glm::mat3(transform) * billboard.axis;
        }
    }
    move(billboards, other.billboards);

    Node root;
    root.name = other.name.empty() ? "model" : other.name;
    root.matrix = transform;
    for (int r : other.roots) root.children.push_back(r + nodeBase);
    addNode(std::move(root));
}

namespace {

template <typename Visit>
void walk(const Scene& scene, Visit&& visit)
{
    struct Item {
        int node;
        glm::mat4 parent;
        bool visible; ///< the parent's (KHR_node_visibility)
    };
    std::vector<Item> stack;
    // Depth first, in file order: push in reverse so the first root is visited first.
    for (auto it = scene.roots.rbegin(); it != scene.roots.rend(); ++it) stack.push_back({*it, glm::mat4(1.0f), true});
    // Guards against malformed files whose node graph is not a tree.
    size_t budget = scene.nodes.size() * 4 + 16;
    while (!stack.empty() && budget-- > 0) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.node < 0 || size_t(item.node) >= scene.nodes.size()) continue;
        const Node& node = scene.nodes[size_t(item.node)];
        const glm::mat4 world = item.parent * node.localMatrix();
        const bool visible = item.visible && node.visible;
        visit(item.node, node, world, visible);
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back({*it, world, visible});
    }
}

} // namespace

std::vector<MeshInstance> Scene::meshInstances(HiddenNodes hidden) const
{
    std::vector<MeshInstance> out;
    walk(*this, [&](int index, const Node& node, const glm::mat4& world, bool visible) {
        if (node.mesh >= 0 && size_t(node.mesh) < meshes.size() && (visible || hidden == HiddenNodes::Include))
            out.push_back({node.mesh, index, world, node.castShadows, node.receiveShadows, visible});
    });
    return out;
}

std::vector<CameraInstance> Scene::cameraInstances() const
{
    std::vector<CameraInstance> out;
    walk(*this, [&](int index, const Node& node, const glm::mat4& world, bool) {
        if (node.camera >= 0 && size_t(node.camera) < cameras.size()) out.push_back({node.camera, index, world});
    });
    return out;
}

std::vector<LightInstance> Scene::lightInstances(HiddenNodes hidden) const
{
    std::vector<LightInstance> out;
    walk(*this, [&](int index, const Node& node, const glm::mat4& world, bool visible) {
        if (node.light >= 0 && size_t(node.light) < lights.size() && (visible || hidden == HiddenNodes::Include)) {
            LightInstance instance;
            instance.light = node.light;
            instance.node = index;
            instance.position = glm::vec3(world[3]);
            instance.direction = glm::normalize(glm::vec3(world * glm::vec4(0, 0, -1, 0)));
            instance.visible = visible;
            out.push_back(instance);
        }
    });
    return out;
}

Bounds Scene::worldBounds() const
{
    Bounds bounds;
    for (const auto& instance : meshInstances())
        for (const auto& primitive : meshes[size_t(instance.mesh)].primitives)
            bounds.extend(primitive.bounds.transformed(instance.world));
    return bounds;
}

size_t Scene::triangleCount() const
{
    size_t count = 0;
    for (const auto& instance : meshInstances())
        for (const auto& primitive : meshes[size_t(instance.mesh)].primitives)
            if (primitive.topology == Topology::Triangles)
                count += (primitive.indices.empty() ? primitive.vertices.size() : primitive.indices.size()) / 3;
    return count;
}

} // namespace specula::scene
