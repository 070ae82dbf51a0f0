#pragma once
// The GL tests' lit sphere: a unit sphere at the origin seen from (0, 0, 4) through a 40° square
// view, rendered, and its pixels handed to a CPU evaluation of the same BRDF one by one.
#include <vector>

#include <glm/glm.hpp>

#include "ImageProbe.h"
#include "render/Renderer.h"
#include "scene/Scene.h"

namespace specula::test {

inline const glm::vec3 kSphereEye(0.0f, 0.0f, 4.0f);

inline render::View sphereView()
{
    return render::lookAtView(kSphereEye, {0, 0, 0}, {0, 1, 0}, glm::radians(40.0f), 1.0f, 0.1f, 20.0f);
}

/// `scene` rendered from kSphereEye with `settings`: the radiance (readRadiance).
inline ImageFloat renderSphere(const scene::Scene& scene, const render::FrameSettings& settings)
{
    render::Renderer renderer;
    renderer.setScene(scene);
    renderer.render(sphereView(), settings);
    return renderer.readRadiance();
}

/// A point light of `intensity` candela, slightly warm by default (so that colour mistakes show).
inline scene::Light pointLight(float intensity, const glm::vec3& color = {1.0f, 0.9f, 0.8f})
{
    scene::Light light;
    light.type = scene::Light::Type::Point;
    light.intensity = intensity;
    light.color = color;
    return light;
}

/// A pixel whose centre ray meets the sphere: where (p), its unit normal n and the unit
/// direction v to the eye, and the rendered radiance.
struct SpherePixel {
    int x = 0, y = 0;
    glm::dvec3 p{0.0}, n{0.0}, v{0.0};
    glm::dvec3 got{0.0};
};

/// The pixels of `image` (from renderSphere) that see the sphere with n·v ≥ minNoV: nearer the
/// silhouette a pixel straddles the tessellated sphere's facets and the background.
inline std::vector<SpherePixel> spherePixels(const ImageFloat& image, double minNoV = 0.25)
{
    const glm::dmat4 inverse = inverseViewProjection(sphereView());
    std::vector<SpherePixel> out;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            SpherePixel px;
            if (!hitUnitSphere(pixelRay(inverse, x, y, image.width, image.height), px.p)) continue;
            px.x = x;
            px.y = y;
            px.n = glm::normalize(px.p);
            px.v = glm::normalize(glm::dvec3(kSphereEye) - px.p);
            if (glm::dot(px.n, px.v) < minNoV) continue;
            px.got = glm::dvec3(pixel(image, x, y));
            out.push_back(px);
        }
    return out;
}

/// A point light (no range) at `position` seen from p: the unit direction to it and its
/// illuminance on a surface facing it, colour × intensity / d² (lux, per channel).
struct PointLightAt {
    glm::dvec3 l{0.0}, E{0.0};
};
inline PointLightAt pointLightAt(const scene::Light& light, const glm::vec3& position, const glm::dvec3& p)
{
    const glm::dvec3 toLight = glm::dvec3(position) - p;
    const double distance = glm::length(toLight);
    return {toLight / distance, glm::dvec3(light.color) * (double(light.intensity) / (distance * distance))};
}

} // namespace specula::test
