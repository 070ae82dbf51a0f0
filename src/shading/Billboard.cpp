#include "shading/Billboard.h"

#include <algorithm>
#include <cmath>

namespace specula::render {
namespace {

// Two unit vectors closer than sin²θ < 1e-6 (θ < 0.06°) are treated as parallel: below that
// the direction of their cross product is mostly float rounding and would flicker from frame
// to frame, so a fallback is no worse and is at least steady.
constexpr float kParallel = 1e-6f;
// A camera closer than 1 µm to the billboard's position gives no usable direction.
constexpr float kMinLength2 = 1e-12f;

constexpr glm::vec3 kY{0.0f, 1.0f, 0.0f};
constexpr glm::vec3 kZ{0.0f, 0.0f, 1.0f};

glm::vec3 normalizeOr(glm::vec3 v, glm::vec3 fallback)
{
    const float length2 = glm::dot(v, v);
    return length2 > kMinLength2 ? v / std::sqrt(length2) : fallback;
}

/// A unit vector perpendicular to unit `n`, a continuous function of n except across n.z = 0
/// where the sign flips (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1), listing 3).
glm::vec3 perpendicular(glm::vec3 n)
{
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

glm::mat4 toMatrix(glm::vec3 right, glm::vec3 up, glm::vec3 look, glm::vec3 position)
{
    return glm::mat4(glm::vec4(right, 0.0f), glm::vec4(up, 0.0f), glm::vec4(look, 0.0f), glm::vec4(position, 1.0f));
}

/// right = normalize(cross(axis, look)); when look is (anti)parallel to the axis, the camera looks
/// along it (straight down on a tree): face away from the camera's up instead, which is where the
/// look direction came from for a camera tilting over the pole (at (0, h, ε) looking at the
/// origin, up ≈ −Z and look ≈ +Z), so the fallback continues the usual orbit smoothly.
glm::vec3 rightAbout(glm::vec3 axis, glm::vec3 look, glm::vec3 cameraUp)
{
    glm::vec3 right = glm::cross(axis, look);
    if (glm::dot(right, right) >= kParallel) return glm::normalize(right);
    right = glm::cross(axis, -normalizeOr(cameraUp, kZ));
    if (glm::dot(right, right) >= kParallel) return glm::normalize(right);
    // The camera's up is along the axis too (a malformed view): any steady perpendicular.
    return perpendicular(axis);
}

} // namespace

glm::mat4 billboardMatrix(scene::BillboardKind kind, glm::vec3 position, glm::vec3 camera, glm::vec3 cameraUp, glm::vec3 axis)
{
    // Camera on the position: look along +Z, as an unrotated sprite does.
    const glm::vec3 look0 = normalizeOr(camera - position, kZ);
    switch (kind) {
    case scene::BillboardKind::PointSprite: {
        const glm::vec3 up0 = normalizeOr(cameraUp, kY);
        glm::vec3 right = glm::cross(up0, look0);
        // Looking along the camera's up: the sprite is 90° off the view axis, outside any
        // perspective frustum, so any steady right will do.
        right = glm::dot(right, right) >= kParallel ? glm::normalize(right) : perpendicular(look0);
        const glm::vec3 up = glm::cross(look0, right);
        return toMatrix(right, up, look0, position);
    }
    case scene::BillboardKind::AxisAligned: {
        // look flattened onto the ground plane; right = cross(Y, look) is then already unit.
        glm::vec3 flattened(look0.x, 0.0f, look0.z);
        if (glm::dot(flattened, flattened) < kParallel) {
            // Straight above or below: see rightAbout for why −cameraUp.
            const glm::vec3 away = -normalizeOr(cameraUp, kZ);
            flattened = glm::vec3(away.x, 0.0f, away.z);
            if (glm::dot(flattened, flattened) < kParallel) flattened = kZ;
        }
        const glm::vec3 look = glm::normalize(flattened);
        const glm::vec3 right = glm::cross(kY, look);
        return toMatrix(right, kY, look, position);
    }
    case scene::BillboardKind::ArbitraryAxis: {
        const glm::vec3 a = normalizeOr(axis, kY);
        const glm::vec3 right = rightAbout(a, look0, cameraUp);
        const glm::vec3 look = glm::cross(right, a);
        return toMatrix(right, a, look, position);
    }
    }
    return toMatrix({1, 0, 0}, kY, kZ, position);
}

glm::vec3 cameraUpFromView(const glm::mat4& view)
{
    // The view matrix's rotation maps world to camera; its inverse (the transpose) maps the
    // camera's +Y to world, which is the rotation's second row.
    return glm::vec3(view[0][1], view[1][1], view[2][1]);
}

std::array<glm::vec3, 4> billboardCorners(const glm::mat4& basis, glm::vec2 size, glm::vec2 anchor)
{
    const glm::vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::array<glm::vec3, 4> corners;
    for (int i = 0; i < 4; ++i) {
        const glm::vec2 local = (uv[i] - anchor) * size;
        corners[size_t(i)] = glm::vec3(basis * glm::vec4(local, 0.0f, 1.0f));
    }
    return corners;
}

float worldUnitsPerPixel(const glm::mat4& viewProjection, const glm::mat4& projection, glm::vec3 position, int viewportHeight)
{
    // NDC spans 2 over the viewport's height; a world length L at clip w covers L·P[1][1]/w of it.
    const float w = (viewProjection * glm::vec4(position, 1.0f)).w;
    return 2.0f * std::max(w, 0.0f) / (projection[1][1] * float(std::max(viewportHeight, 1)));
}

scene::Image makeBuiltinSprite(scene::BuiltinSprite sprite, int size)
{
    size = std::max(size, 4);
    scene::Image image;
    image.width = size;
    image.height = sprite == scene::BuiltinSprite::Tree ? 2 * size : size;
    image.channels = 4;
    image.pixels.resize(size_t(image.width) * size_t(image.height) * 4);
    auto put = [&](int x, int y, glm::vec3 srgb, float alpha) {
        uint8_t* p = &image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
        p[0] = uint8_t(std::lround(255.0f * std::clamp(srgb.r, 0.0f, 1.0f)));
        p[1] = uint8_t(std::lround(255.0f * std::clamp(srgb.g, 0.0f, 1.0f)));
        p[2] = uint8_t(std::lround(255.0f * std::clamp(srgb.b, 0.0f, 1.0f)));
        p[3] = uint8_t(std::lround(255.0f * std::clamp(alpha, 0.0f, 1.0f)));
    };
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            // u right, v up, both in [0, 1] at texel centres; rows are stored top first.
            const float u = (float(x) + 0.5f) / float(image.width);
            const float v = 1.0f - (float(y) + 0.5f) / float(image.height);
            if (sprite == scene::BuiltinSprite::Bar) {
                // Solid across the middle half, then a smooth fall to 0 a texel short of the
                // sides (as the disc's rim); the same all along the height, so stretching the
                // quad to any length keeps the profile.
                const float r = 2.0f * std::abs(u - 0.5f) * float(size) / float(size - 2);
                const float t = std::clamp((r - 0.5f) / 0.5f, 0.0f, 1.0f);
                put(x, y, glm::vec3(1.0f), 1.0f - t * t * (3.0f - 2.0f * t));
                continue;
            }
            if (sprite == scene::BuiltinSprite::Disc) {
                // Solid out to half the radius, then a smooth fall to 0 at the rim: soft when
                // blended, a clean circle when cut out at alpha 0.5. The rim stops a texel short
                // of the border so the outermost texels, and hence the quad's outline, stay clear.
                const float r = 2.0f * glm::length(glm::vec2(u, v) - 0.5f) * float(size) / float(size - 2);
                const float t = std::clamp((r - 0.5f) / 0.5f, 0.0f, 1.0f);
                put(x, y, glm::vec3(1.0f), 1.0f - t * t * (3.0f - 2.0f * t));
                continue;
            }
            // Tree: a trunk in the bottom fifth and three stacked triangles of canopy. Coverage
            // is the signed distance to the outline in texels (horizontal, which for these
            // steep sides is close to the true distance), antialiasing the edge over one texel.
            const float dx = std::abs(u - 0.5f) * float(image.width);
            const float tiers[3][3] = {{0.12f, 0.52f, 0.46f}, {0.38f, 0.76f, 0.38f}, {0.60f, 0.99f, 0.28f}}; // base v, top v, half width at the base (u)
            float canopy = -1e9f;
            for (const auto& tier : tiers) {
                if (v < tier[0] || v > tier[1]) continue;
                const float halfWidth = tier[2] * (tier[1] - v) / (tier[1] - tier[0]);
                const float fromBase = (v - tier[0]) * float(image.height);
                canopy = std::max(canopy, std::min(halfWidth * float(image.width) - dx, fromBase));
            }
            const float trunk = v <= 0.2f ? 0.06f * float(image.width) - dx : -1e9f;
            const float canopyAlpha = std::clamp(canopy + 0.5f, 0.0f, 1.0f);
            const float trunkAlpha = std::clamp(trunk + 0.5f, 0.0f, 1.0f);
            const glm::vec3 green(0.16f, 0.42f, 0.18f), brown(0.38f, 0.25f, 0.14f);
            if (canopyAlpha > 0.0f) {
                // Lighter on the left, darker on the right, so the flat sprite reads as a volume.
                put(x, y, green * (1.15f - 0.3f * u), std::max(canopyAlpha, trunkAlpha));
            } else if (trunkAlpha > 0.0f) {
                put(x, y, brown, trunkAlpha);
            } else {
                // Transparent: the colour of what is nearby (trunk low down, leaves above).
                put(x, y, v < 0.12f ? brown : green, 0.0f);
            }
        }
    }
    image.name = sprite == scene::BuiltinSprite::Tree  ? "builtin tree sprite"
               : sprite == scene::BuiltinSprite::Bar ? "builtin bar sprite"
                                                     : "builtin disc sprite";
    return image;
}

} // namespace specula::render
