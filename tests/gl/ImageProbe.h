#pragma once
// Reading rendered images back in the GL tests: a world point's pixel, a pixel's value, and the
// ray through a pixel's centre (for CPU references that trace the scene).
#include <cmath>

#include <glm/glm.hpp>

#include "core/ImageIO.h"
#include "render/View.h"

namespace specula::test {

/// Pixel (x, y), image row 0 at the top, of world point p in a width × height image of `view`.
inline glm::ivec2 projectToPixel(const render::View& view, const glm::vec3& p, int width, int height)
{
    const glm::vec4 clip = view.projection * view.view * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {int(std::floor((ndc.x * 0.5f + 0.5f) * float(width))), int(std::floor((0.5f - ndc.y * 0.5f) * float(height)))};
}

/// RGB of pixel (x, y), row 0 at the top.
inline glm::vec3 pixel(const ImageFloat& image, int x, int y)
{
    const float* v = &image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
    return {v[0], v[1], v[2]};
}
inline glm::vec3 pixel(const ImageFloat& image, glm::ivec2 p)
{
    return pixel(image, p.x, p.y);
}

/// The world-space ray through pixel (x, y)'s centre (row 0 at the top) of a width × height
/// image seen through `inverse`, the inverse of the view-projection matrix.
struct Ray {
    glm::dvec3 origin, direction;
};
inline glm::dmat4 inverseViewProjection(const render::View& view)
{
    return glm::inverse(glm::dmat4(view.projection * view.view));
}
inline Ray pixelRay(const glm::dmat4& inverse, int x, int y, int width, int height)
{
    const double ndcX = (x + 0.5) / width * 2.0 - 1.0;
    const double ndcY = 1.0 - (y + 0.5) / height * 2.0;
    const glm::dvec4 nearPoint = inverse * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
    const glm::dvec4 farPoint = inverse * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
    const glm::dvec3 origin = glm::dvec3(nearPoint) / nearPoint.w;
    return {origin, glm::normalize(glm::dvec3(farPoint) / farPoint.w - origin)};
}
inline Ray pixelRay(const render::View& view, int x, int y, int width, int height)
{
    return pixelRay(inverseViewProjection(view), x, y, width, height);
}

/// Where `ray` first meets the unit sphere at the origin, if it does.
inline bool hitUnitSphere(const Ray& ray, glm::dvec3& point)
{
    const double b = glm::dot(ray.origin, ray.direction);
    const double disc = b * b - (glm::dot(ray.origin, ray.origin) - 1.0);
    if (disc <= 0.0) return false;
    point = ray.origin + ray.direction * (-b - std::sqrt(disc));
    return true;
}

} // namespace specula::test
