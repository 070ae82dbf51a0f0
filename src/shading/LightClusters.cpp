#include "shading/LightClusters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "shading/ContactSheet.h"

namespace specula::render {
namespace {

int divideUp(int a, int b)
{
    return (a + b - 1) / b;
}

glm::vec3 unproject(const glm::mat4& inverseProjection, glm::vec3 ndc)
{
    const glm::vec4 p = inverseProjection * glm::vec4(ndc, 1.0f);
    return glm::vec3(p) / p.w;
}

} // namespace

ClusterGrid ClusterGrid::make(int width, int height, const glm::mat4& projection)
{
    ClusterGrid g;
    g.width = std::max(width, 1);
    g.height = std::max(height, 1);
    g.tileWidth = divideUp(g.width, SPECULA_CLUSTER_TILES_X);
    g.tileHeight = divideUp(g.height, SPECULA_CLUSTER_TILES_Y);
    g.tilesX = divideUp(g.width, g.tileWidth);
    g.tilesY = divideUp(g.height, g.tileHeight);
    g.slices = SPECULA_CLUSTER_SLICES;
    const glm::mat4 inverse = glm::inverse(projection);
    g.near = -unproject(inverse, {0.0f, 0.0f, -1.0f}).z;
    // The far plane, through w: an infinite projection puts it at w = 0.
    const glm::vec4 farPoint = inverse * glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
    const float farDepth = farPoint.w != 0.0f ? -farPoint.z / farPoint.w : std::numeric_limits<float>::infinity();
    const float kMaxRatio = 1e6f; // an infinite (or absurd) far plane: slices stop here
    const float kFirstSlice = 5.0f; // metres
    const float far = std::isfinite(farDepth) && farDepth > 0.0f ? farDepth : kFirstSlice * kMaxRatio;
    g.first = std::max({std::min(kFirstSlice, 0.1f * far), g.near, 1e-4f});
    g.far = std::clamp(far, g.first * 1.001f, g.first * kMaxRatio);
    return g;
}

float ClusterGrid::sliceScale() const
{
    return float(slices - 1) / std::log(far / first);
}

float ClusterGrid::sliceBias() const
{
    return 1.0f - std::log(first) * sliceScale();
}

float ClusterGrid::sliceDepth(int k) const
{
    if (k <= 0) return near;
    if (k >= slices) return far;
    return first * std::pow(far / first, float(k - 1) / float(slices - 1));
}

int ClusterGrid::clusterAt(glm::vec2 window, float depth) const
{
    // As the shaders: a multiply by the inverse tile size (the boxes' padding covers its rounding).
    const int x = std::clamp(int(std::max(window.x, 0.0f) * (1.0f / float(tileWidth))), 0, tilesX - 1);
    const int y = std::clamp(int(std::max(window.y, 0.0f) * (1.0f / float(tileHeight))), 0, tilesY - 1);
    const float s = std::floor(std::log(std::max(depth, 1e-6f)) * sliceScale() + sliceBias());
    const int slice = std::clamp(int(std::clamp(s, -1.0f, float(slices))), 0, slices - 1);
    return index(x, y, slice);
}

std::vector<shared::ClusterBounds> clusterBounds(const ClusterGrid& grid, const glm::mat4& projection)
{
    const glm::mat4 inverse = glm::inverse(projection);
    std::vector<shared::ClusterBounds> out(size_t(grid.count()));
    for (int slice = 0; slice < grid.slices; ++slice) {
        const float d0 = grid.sliceDepth(slice), d1 = grid.sliceDepth(slice + 1);
        const float pad = 1e-4f * std::abs(d1);
        for (int ty = 0; ty < grid.tilesY; ++ty) {
            for (int tx = 0; tx < grid.tilesX; ++tx) {
                const float x0 = float(tx * grid.tileWidth), x1 = float(std::min((tx + 1) * grid.tileWidth, grid.width));
                const float y0 = float(ty * grid.tileHeight), y1 = float(std::min((ty + 1) * grid.tileHeight, grid.height));
                glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
                for (const float px : {x0, x1}) {
                    for (const float py : {y0, y1}) {
                        const glm::vec2 ndc(2.0f * px / float(grid.width) - 1.0f, 2.0f * py / float(grid.height) - 1.0f);
                        // The ray through the pixel corner: its points on the near plane and at
                        // NDC depth 0 (finite even for an infinite projection).
                        const glm::vec3 a = unproject(inverse, {ndc, -1.0f}), b = unproject(inverse, {ndc, 0.0f});
                        for (const float d : {d0, d1}) {
                            const float t = (-d - a.z) / (b.z - a.z);
                            const glm::vec3 p = a + t * (b - a);
                            lo = glm::min(lo, p);
                            hi = glm::max(hi, p);
                        }
                    }
                }
                out[size_t(grid.index(tx, ty, slice))] = {glm::vec4(lo - pad, 0.0f), glm::vec4(hi + pad, 0.0f)};
            }
        }
    }
    return out;
}

std::array<glm::vec4, 6> viewFrustumPlanes(const glm::mat4& p)
{
    const auto row = [&](int i) { return glm::vec4(p[0][i], p[1][i], p[2][i], p[3][i]); };
    std::array<glm::vec4, 6> planes = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
                                       row(3) - row(1), row(3) + row(2), row(3) - row(2)};
    for (glm::vec4& plane : planes) {
        const float length = glm::length(glm::vec3(plane));
        plane = length > 0.0f ? plane / length : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f); // an infinite far plane: no plane
    }
    return planes;
}

bool sphereInFrustum(const std::array<glm::vec4, 6>& planes, glm::vec4 sphere)
{
    if (sphere.w < 0.0f) return true;
    bool inside = true;
    for (const glm::vec4& plane : planes)
        inside = inside && plane.x * sphere.x + plane.y * sphere.y + plane.z * sphere.z + plane.w >= -sphere.w;
    return inside;
}

shared::CullLight cullLight(const shared::GpuLight& light, const glm::mat4& view, uint32_t index)
{
    shared::CullLight c{};
    const glm::vec4 p = view * glm::vec4(glm::vec3(light.positionRange), 1.0f);
    c.sphere = glm::vec4(glm::vec3(p), light.positionRange.w > 0.0f ? light.positionRange.w : -1.0f);
    c.cone = glm::vec4(0.0f, 0.0f, 0.0f, -2.0f);
    const bool spot = uint32_t(light.directionType.w + 0.5f) == SPECULA_LIGHT_SPOT;
    // A cone of up to 90° can be tested (Wronski's test needs cos ≥ 0); wider: its sphere only.
    if (spot && light.spot.w >= 0.0f)
        c.cone = glm::vec4(glm::normalize(glm::mat3(view) * glm::vec3(light.directionType)), light.spot.w);
    c.info = glm::uvec4(index, 0u, 0u, 0u);
    return c;
}

float effectiveRange(float range, float cutoff)
{
    if (range > 0.0f) return range;
    if (cutoff > 0.0f) return 1.0f / std::sqrt(cutoff);
    return 0.0f;
}

size_t ClusterLists::entries() const
{
    size_t n = 0;
    for (const auto& list : clusters) n += list.size();
    return n;
}

size_t ClusterLists::longest() const
{
    size_t n = 0;
    for (const auto& list : clusters) n = std::max(n, list.size());
    return n;
}

ClusterLists cullLights(const ClusterGrid& grid, const std::vector<shared::ClusterBounds>& bounds, const glm::mat4& view,
                        const glm::mat4& projection, const std::vector<shared::GpuLight>& lights)
{
    ClusterLists out;
    out.clusters.resize(size_t(grid.count()));
    const std::array<glm::vec4, 6> planes = viewFrustumPlanes(projection);
    std::vector<shared::CullLight> visible;
    for (size_t i = 0; i < lights.size(); ++i) {
        if (uint32_t(lights[i].directionType.w + 0.5f) == SPECULA_LIGHT_DIRECTIONAL) {
            out.directional.push_back(uint32_t(i));
            continue;
        }
        if (shared::lightIsDark(lights[i].colorIntensity)) continue;
        const shared::CullLight c = cullLight(lights[i], view, uint32_t(i));
        if (sphereInFrustum(planes, c.sphere)) visible.push_back(c);
    }
    out.visible = uint32_t(visible.size());
    for (size_t k = 0; k < bounds.size(); ++k)
        for (const shared::CullLight& c : visible)
            if (shared::lightTouchesCluster(c, bounds[k])) out.clusters[k].push_back(c.info.x);
    return out;
}

ImageRGBA8 makeLightCountLegend()
{
    constexpr int kBox = 30, kPad = 4, kBoxHeight = 12, kText = 9;
    ImageRGBA8 image;
    image.width = SPECULA_LIGHT_COUNT_BINS * kBox + 2 * kPad;
    image.height = kBoxHeight + kText + 3 * kPad;
    image.pixels.assign(size_t(image.width) * size_t(image.height) * 4, 0);
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        image.pixels[i] = image.pixels[i + 1] = image.pixels[i + 2] = 24;
        image.pixels[i + 3] = 255;
    }
    const uint8_t white[4] = {235, 235, 235, 255};
    for (int bin = 0; bin < SPECULA_LIGHT_COUNT_BINS; ++bin) {
        const glm::vec4 c = shared::lightCountColor(uint32_t(bin));
        const uint8_t rgba[4] = {uint8_t(std::lround(c.r * 255.0f)), uint8_t(std::lround(c.g * 255.0f)), uint8_t(std::lround(c.b * 255.0f)), 255};
        const int x0 = kPad + bin * kBox;
        for (int y = kPad; y < kPad + kBoxHeight; ++y)
            for (int x = x0 + 1; x < x0 + kBox - 1; ++x) std::copy_n(rgba, 4, &image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4]);
        // Each bin from its lower bound: 0, 1, 2, 4, ... (bin b holds 2^(b-1) to 2^b - 1).
        const int lower = bin == 0 ? 0 : 1 << (bin - 1);
        const std::string label = std::to_string(lower) + (bin == SPECULA_LIGHT_COUNT_BINS - 1 ? "+" : "");
        drawText(image, x0 + 2, kPad * 2 + kBoxHeight, label, 1, white);
    }
    return image;
}

} // namespace specula::render
