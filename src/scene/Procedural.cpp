#include "scene/Procedural.h"

#include <glm/gtc/constants.hpp>

namespace specula::scene {

Primitive makeUvSphere(float radius, int segments, int rings)
{
    Primitive p;
    const float pi = glm::pi<float>();
    for (int y = 0; y <= rings; ++y) {
        const float v = float(y) / float(rings);
        const float theta = v * pi; // from +Y down
        for (int x = 0; x <= segments; ++x) {
            const float u = float(x) / float(segments);
            const float phi = u * 2.0f * pi;
            Vertex vertex;
            // z = -sin(theta) sin(phi) so that the texture is not mirrored seen from outside.
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            vertex.position = n * radius;
            vertex.normal = n;
            // dP/du normalised (well defined at the poles too). glTF's bitangent cross(n, t) * w
            // points up the image (towards -v); here cross(n, t) already does, so w = +1.
            vertex.tangent = glm::vec4(-std::sin(phi), 0.0f, -std::cos(phi), 1.0f);
            vertex.uv0 = vertex.uv1 = glm::vec2(u, v);
            p.vertices.push_back(vertex);
        }
    }
    const int stride = segments + 1;
    for (int y = 0; y < rings; ++y) {
        for (int x = 0; x < segments; ++x) {
            const uint32_t i0 = uint32_t(y * stride + x), i1 = i0 + 1;
            const uint32_t i2 = uint32_t((y + 1) * stride + x), i3 = i2 + 1;
            // Counter-clockwise seen from outside. Skip the degenerate pole triangles.
            if (y != 0) p.indices.insert(p.indices.end(), {i0, i2, i1});
            if (y != rings - 1) p.indices.insert(p.indices.end(), {i1, i2, i3});
        }
    }
    p.hasTangents = true;
    p.bounds.extend(glm::vec3(-radius));
    p.bounds.extend(glm::vec3(radius));
    return p;
}

Primitive makeCube(float h)
{
    Primitive p;
    struct Face {
        glm::vec3 n, t, b;
    };
    const Face faces[6] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    for (const Face& f : faces) {
        const uint32_t base = uint32_t(p.vertices.size());
        const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (const glm::vec2& c : corners) {
            Vertex v;
            v.position = h * (f.n + (c.x * 2 - 1) * f.t + (c.y * 2 - 1) * f.b);
            v.normal = f.n;
            v.tangent = glm::vec4(f.t, 1.0f);
            // uv v grows downwards in glTF convention.
            v.uv0 = v.uv1 = glm::vec2(c.x, 1.0f - c.y);
            p.vertices.push_back(v);
        }
        p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    // cross(n, t) = b points up the image (v decreases along b), so w = +1 on every face.
    p.hasTangents = true;
    p.bounds.extend(glm::vec3(-h));
    p.bounds.extend(glm::vec3(h));
    return p;
}

Primitive makePlane(float size, float uvRepeat)
{
    Primitive p;
    const float h = size * 0.5f;
    const glm::vec3 corners[4] = {{-h, 0, h}, {h, 0, h}, {h, 0, -h}, {-h, 0, -h}};
    const glm::vec2 uvs[4] = {{0, uvRepeat}, {uvRepeat, uvRepeat}, {uvRepeat, 0}, {0, 0}};
    for (int i = 0; i < 4; ++i) {
        Vertex v;
        v.position = corners[i];
        v.normal = {0, 1, 0};
        v.tangent = {1, 0, 0, 1};
        v.uv0 = v.uv1 = uvs[i];
        p.vertices.push_back(v);
    }
    p.indices = {0, 1, 2, 0, 2, 3};
    p.hasTangents = true;
    p.bounds.extend(glm::vec3(-h, 0, -h));
    p.bounds.extend(glm::vec3(h, 0, h));
    return p;
}

int addShape(Scene& scene, Primitive primitive, const Material& material, const glm::mat4& transform,
             const std::string& name)
{
    scene.materials.push_back(material);
    primitive.material = int(scene.materials.size() - 1);
    Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(std::move(primitive));
    scene.meshes.push_back(std::move(mesh));
    Node node;
    node.name = name;
    node.mesh = int(scene.meshes.size() - 1);
    node.matrix = transform;
    return scene.addNode(std::move(node));
}

} // namespace specula::scene
