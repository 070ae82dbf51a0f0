#include "shading/ShadowMaps.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/Frustum.h"

namespace specula::render {

std::vector<float> cascadeSplits(float near, float far, int count, float lambda)
{
    std::vector<float> splits;
    count = std::max(count, 1);
    near = std::max(near, 1e-4f);
    far = std::max(far, near * 1.001f);
    for (int i = 1; i <= count; ++i) {
        const float t = float(i) / float(count);
        const float logarithmic = near * std::pow(far / near, t);
        const float uniform = near + (far - near) * t;
        splits.push_back(lambda * logarithmic + (1.0f - lambda) * uniform);
    }
    splits.back() = far; // exactly, not by rounding
    return splits;
}

glm::mat4 clipToAtlas(const AtlasTile& tile, int atlasSize)
{
    const float s = 0.5f * float(tile.size) / float(atlasSize);
    glm::mat4 m(1.0f);
    m[0][0] = s;
    m[1][1] = s;
    m[2][2] = 0.5f;
    m[3] = glm::vec4((float(tile.x) + 0.5f * float(tile.size)) / float(atlasSize),
                     (float(tile.y) + 0.5f * float(tile.size)) / float(atlasSize), 0.5f, 1.0f);
    return m;
}

ShadowView cascadeView(const glm::mat4& cameraView, const glm::mat4& cameraProjection, float sliceNear, float sliceFar,
                       const glm::vec3& lightDirection, const scene::Bounds& casters, int tileSize)
{
    // The slice's corners in world space (a symmetric or off-centre perspective alike).
    const glm::mat4 toWorld = glm::inverse(cameraView);
    const float tx = 1.0f / cameraProjection[0][0], ty = 1.0f / cameraProjection[1][1];
    const float ox = cameraProjection[2][0] / cameraProjection[0][0], oy = cameraProjection[2][1] / cameraProjection[1][1];
    std::array<glm::vec3, 8> corners;
    glm::vec3 center(0.0f);
    int k = 0;
    for (const float z : {sliceNear, sliceFar})
        for (const float sx : {-1.0f, 1.0f})
            for (const float sy : {-1.0f, 1.0f}) {
                // An orthographic camera's slice is a box: its x and y do not grow with depth.
                const bool orthographic = cameraProjection[2][3] == 0.0f;
                const glm::vec3 p = orthographic ? glm::vec3((sx - cameraProjection[3][0]) * tx, (sy - cameraProjection[3][1]) * ty, -z)
                                                 : glm::vec3((sx * tx + ox) * z, (sy * ty + oy) * z, -z);
                corners[size_t(k)] = glm::vec3(toWorld * glm::vec4(p, 1.0f));
                center += corners[size_t(k++)];
            }
    center /= 8.0f;
    float radius = 0.0f;
    for (const glm::vec3& c : corners) radius = std::max(radius, glm::length(c - center));
    // The radius depends only on the slice's shape; rounded up so that float noise cannot
    // change the texel size from frame to frame.
    radius = std::ceil(radius * 16.0f) / 16.0f;

    // A basis that depends on the light alone: the texel grid is fixed in the world.
    const glm::vec3 f = glm::normalize(lightDirection);
    const glm::vec3 helper = std::abs(f.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 right = glm::normalize(glm::cross(f, helper));
    const glm::vec3 up = glm::cross(right, f);
    const float texel = 2.0f * radius / float(tileSize);
    const float cr = std::floor(glm::dot(center, right) / texel) * texel;
    const float cu = std::floor(glm::dot(center, up) / texel) * texel;
    const float cf = glm::dot(center, f);

    // Depth along the light: from the nearest caster (or the sphere) to the sphere's far side.
    float dNear = cf - radius, dFar = cf + radius;
    if (!casters.empty()) {
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 p((i & 1) ? casters.max.x : casters.min.x, (i & 2) ? casters.max.y : casters.min.y,
                              (i & 4) ? casters.max.z : casters.min.z);
            dNear = std::min(dNear, glm::dot(p, f));
        }
    }
    const float margin = 0.01f * (dFar - dNear) + 0.05f;
    dNear -= margin;
    dFar += margin;

    glm::mat4 view(1.0f); // rows: right, up, −f (the camera looks along f)
    for (int c = 0; c < 3; ++c) {
        view[c][0] = right[c];
        view[c][1] = up[c];
        view[c][2] = -f[c];
    }
    view[3] = glm::vec4(-cr, -cu, 0.0f, 1.0f);
    ShadowView v;
    v.viewProjection = glm::ortho(-radius, radius, -radius, radius, dNear, dFar) * view;
    v.orthographic = true;
    v.near = dNear;
    v.far = dFar;
    v.texelWorld = texel;
    return v;
}

namespace {

glm::vec3 anyUp(const glm::vec3& direction)
{
    return std::abs(direction.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

float nearFor(float far)
{
    return std::clamp(far * 1e-3f, 1e-3f, 0.05f);
}

// Texels at each edge of a point light's face past its 90°, so that a filter kernel at the
// face's border still reads this face's depths.
constexpr float kFaceMarginTexels = 4.0f;

} // namespace

ShadowView spotView(const glm::vec3& position, const glm::vec3& direction, float outerConeAngle, float far, int tileSize)
{
    const glm::vec3 d = glm::normalize(direction);
    const float halfAngle = std::min(outerConeAngle, glm::radians(85.0f));
    // The cone's tangent at the tile's edge less the margin.
    const float tanHalf = std::tan(halfAngle) / (1.0f - 2.0f * kFaceMarginTexels / float(tileSize));
    ShadowView v;
    v.near = nearFor(far);
    v.far = far;
    v.viewProjection = glm::perspective(2.0f * std::atan(tanHalf), 1.0f, v.near, v.far) * glm::lookAt(position, position + d, anyUp(d));
    v.texelWorld = 2.0f * tanHalf / float(tileSize);
    return v;
}

std::vector<ShadowView> pointViews(const glm::vec3& position, float far, int tileSize)
{
    static const glm::vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::vec3 kUps[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    const float tanHalf = 1.0f / (1.0f - 2.0f * kFaceMarginTexels / float(tileSize));
    std::vector<ShadowView> views;
    for (int face = 0; face < 6; ++face) {
        ShadowView v;
        v.near = nearFor(far);
        v.far = far;
        v.viewProjection = glm::perspective(2.0f * std::atan(tanHalf), 1.0f, v.near, v.far) *
                           glm::lookAt(position, position + kAxes[face], kUps[face]);
        v.texelWorld = 2.0f * tanHalf / float(tileSize);
        views.push_back(v);
    }
    return views;
}

int shadowFace(const glm::vec3& d)
{
    const glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
    return d.z >= 0.0f ? 4 : 5;
}

ShadowAtlas::ShadowAtlas(int size, int minTile) : mSize(size), mMinTile(std::min(minTile, size))
{
    clear();
}

void ShadowAtlas::clear()
{
    int levels = 1;
    while ((mSize >> levels) >= mMinTile) ++levels;
    mFree.assign(size_t(levels), {});
    mFree[0].push_back({0, 0, mSize});
}

std::optional<AtlasTile> ShadowAtlas::allocate(int tileSize)
{
    int level = 0;
    while ((mSize >> level) > tileSize) ++level;
    if ((mSize >> level) != tileSize || level >= int(mFree.size())) return std::nullopt;
    // The smallest free tile that holds it, split down to its size (its first quarter kept
    // free lists in reading order, so that the same requests give the same tiles).
    int from = level;
    while (from >= 0 && mFree[size_t(from)].empty()) --from;
    if (from < 0) return std::nullopt;
    for (; from < level; ++from) {
        const AtlasTile t = mFree[size_t(from)].front();
        mFree[size_t(from)].erase(mFree[size_t(from)].begin());
        const int h = t.size / 2;
        auto& next = mFree[size_t(from) + 1];
        next.insert(next.begin(), {{t.x, t.y, h}, {t.x + h, t.y, h}, {t.x, t.y + h, h}, {t.x + h, t.y + h, h}});
    }
    const AtlasTile tile = mFree[size_t(level)].front();
    mFree[size_t(level)].erase(mFree[size_t(level)].begin());
    return tile;
}

float screenImportance(const glm::vec3& center, float radius, const glm::mat4& view, const glm::mat4& projection)
{
    const glm::vec3 c = glm::vec3(view * glm::vec4(center, 1.0f));
    if (glm::length(c) <= radius) return 1.0f;
    const Frustum frustum(projection);
    for (const glm::vec4& p : frustum.planes)
        if (glm::dot(glm::vec3(p), c) + p.w < -radius * glm::length(glm::vec3(p))) return 0.0f;
    const float depth = std::max(-c.z, radius);
    return std::clamp(radius * projection[1][1] / depth, 0.0f, 1.0f);
}

int tileSizeFor(float importance, int maxTile, int minTile)
{
    int size = maxTile;
    while (size > minTile && importance * float(maxTile) <= float(size) / 2.0f) size /= 2;
    return size;
}

std::vector<ShadowCandidate> chooseShadowed(std::vector<ShadowCandidate> candidates, int budget, int maxDirectional,
                                            std::vector<int>* dropped)
{
    std::stable_sort(candidates.begin(), candidates.end(), [](const ShadowCandidate& a, const ShadowCandidate& b) {
        return a.importance != b.importance ? a.importance > b.importance : a.light < b.light;
    });
    std::vector<ShadowCandidate> chosen;
    int local = 0, directional = 0;
    for (const ShadowCandidate& c : candidates) {
        const bool isDirectional = c.type == scene::Light::Type::Directional;
        int& used = isDirectional ? directional : local;
        if (used < (isDirectional ? maxDirectional : budget)) {
            ++used;
            chosen.push_back(c);
        } else if (dropped) {
            dropped->push_back(c.light);
        }
    }
    return chosen;
}

} // namespace specula::render
