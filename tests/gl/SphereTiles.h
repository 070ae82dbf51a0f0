#pragma once
// Spheres in a row of square tiles, seen by an orthographic camera looking down -Z with
// no lights: the image-based lighting tests' scene (test_ibl.cpp, test_ibl_reference.cpp),
// and the normal and view vector under each pixel centre for their CPU references.
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "ImageProbe.h"
#include "core/ImageIO.h"
#include "render/Renderer.h"
#include "scene/Procedural.h"

namespace specula::test {

struct SphereRender {
    ImageFloat image;
    glm::mat4 viewProjection;
};

constexpr int kSize = 64;         // pixels of one sphere's tile, square
constexpr float kHalfExtent = 1.2f; // half the tile's width in world units

// Sphere i of `count` in a row is centred at x = sphereCentreX(i, count), in tile i (columns
// i kSize to (i + 1) kSize - 1 of the image).
inline float sphereCentreX(int i, int count)
{
    return (2.0f * float(i) - float(count - 1)) * kHalfExtent;
}

// The eye position the shader computes v from: far along +Z, so that v is +Z to within 1e-3
// rad at every pixel of every tile, as for a true orthographic camera.
inline const glm::vec3 kEye(0.0f, 0.0f, 1000.0f);

// Unit spheres in a row, one per material, seen by an orthographic camera looking down -Z,
// no lights.
inline void setSpheres(render::Renderer& renderer, const std::vector<scene::Material>& materials)
{
    scene::Scene s;
    const int count = int(materials.size());
    for (int i = 0; i < count; ++i)
        scene::addShape(s, scene::makeUvSphere(1.0f, 128, 64), materials[size_t(i)],
                        glm::translate(glm::mat4(1.0f), glm::vec3(sphereCentreX(i, count), 0.0f, 0.0f)), "sphere");
    renderer.setScene(s);
}

// The `count` spheres setSpheres put in the renderer's scene, rendered again.
inline SphereRender renderSphereTiles(render::Renderer& renderer, int count, const render::FrameSettings& base = {})
{
    render::View view;
    view.view = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    view.projection = glm::ortho(-kHalfExtent * float(count), kHalfExtent * float(count), -kHalfExtent, kHalfExtent, 0.1f, 20.0f);
    view.position = kEye;
    render::FrameSettings settings = base;
    settings.width = kSize * count;
    settings.height = kSize;
    settings.msaa = 1;
    settings.tonemap = render::Tonemap::None;
    renderer.render(view, settings);
    return {renderer.readRadiance(), view.projection * view.view};
}

inline SphereRender renderSpheres(render::Renderer& renderer, const std::vector<scene::Material>& materials,
                           const render::FrameSettings& base = {})
{
    setSpheres(renderer, materials);
    return renderSphereTiles(renderer, int(materials.size()), base);
}

// One unit sphere at the origin.
inline SphereRender renderSphere(render::Renderer& renderer, float metallic, float roughness, glm::vec3 baseColor,
                          const render::FrameSettings& base = {}, float specularFactor = 1.0f)
{
    scene::Material m;
    m.specularFactor = specularFactor;
    m.baseColorFactor = glm::vec4(baseColor, 1.0f);
    m.metallicFactor = metallic;
    m.roughnessFactor = roughness;
    return renderSpheres(renderer, {m}, base);
}

// The view vector the shader uses at the point of sphere i (of `count`) with normal n.
inline glm::dvec3 viewVector(int i, int count, const glm::dvec3& n)
{
    return glm::normalize(glm::dvec3(kEye) - glm::dvec3(sphereCentreX(i, count), 0.0, 0.0) - n);
}

// Pixel centre of a tile -> the sphere normal under it (orthographic, image row 0 at the top);
// false off the sphere.
inline bool sphereNormal(int x, int y, glm::vec3& n)
{
    const float px = ((x + 0.5f) / kSize * 2.0f - 1.0f) * kHalfExtent;
    const float py = (1.0f - (y + 0.5f) / kSize * 2.0f) * kHalfExtent;
    const float r2 = px * px + py * py;
    if (r2 >= 1.0f) return false;
    n = {px, py, std::sqrt(1.0f - r2)};
    return true;
}

} // namespace specula::test
