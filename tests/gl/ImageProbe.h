#pragma once
// Reading rendered images back in the GL tests: a world point's pixel, and a pixel's value.
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

} // namespace specula::test
