#pragma once
// Billboard geometry on the CPU: the basis each kind turns to, the quad it spans, and the
// built-in sprites. shaders/billboard/basis.glsl builds the same bases on the GPU; the
// formulas and fallbacks of the two must stay equal (tests/gl/test_billboard_gpu.cpp checks).
#include <array>

#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace specula::render {

/// The billboard matrix: columns right, up, look (a right-handed orthonormal basis: right ×
/// up = look) and the position; model space is the sprite's plane z = 0, +Y up the sprite,
/// +Z towards the camera. With look₀ = normalize(camera − position):
///   PointSprite:   look = look₀, right = normalize(cross(cameraUp, look)), up = cross(look, right)
///   AxisAligned:   up = +Y, look = normalize(look₀ with y = 0), right = cross(+Y, look)
///   ArbitraryAxis: up = A = normalize(axis), right = normalize(cross(A, look₀)), look = cross(right, A)
/// Degenerate cases (camera at the position; look₀ parallel to cameraUp or to the axis, e.g.
/// the camera straight above an axis-aligned billboard) fall back to finite, deterministic
/// bases; see billboardMatrix in Billboard.cpp. Never NaN for finite inputs.
glm::mat4 billboardMatrix(scene::BillboardKind kind, glm::vec3 position, glm::vec3 camera, glm::vec3 cameraUp,
                          glm::vec3 axis = {0.0f, 1.0f, 0.0f});

/// The camera's up vector in world space: the second row of the view matrix's rotation.
glm::vec3 cameraUpFromView(const glm::mat4& view);

/// World corners of the quad of `basis` (from billboardMatrix): bottom left, bottom right, top
/// right, top left. `size` is width × height in world units, `anchor` the point of the sprite
/// (in [0, 1]², (0, 0) = bottom left) that sits at the position.
std::array<glm::vec3, 4> billboardCorners(const glm::mat4& basis, glm::vec2 size, glm::vec2 anchor);

/// World units per pixel of a billboard at `position` for a sprite sized in pixels: a pixel
/// spans 2w / (P[1][1] · viewportHeight) at clip w (exact at the centre of the view, for both
/// perspective and orthographic projections). 0 behind the camera.
float worldUnitsPerPixel(const glm::mat4& viewProjection, const glm::mat4& projection, glm::vec3 position,
                         int viewportHeight);

/// A built-in sprite as an 8-bit sRGB RGBA image, top row first, `size` pixels wide (the tree
/// is twice as tall as wide). Transparent texels carry their neighbours' colour so filtering
/// at the edges does not darken them.
scene::Image makeBuiltinSprite(scene::BuiltinSprite sprite, int size = 64);

} // namespace specula::render
