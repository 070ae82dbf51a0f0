#pragma once
// Procedural meshes with normals, tangents and uvs.
#include "scene/Scene.h"

namespace specula::scene {

/// UV sphere centred at the origin; `segments` around, `rings` from pole to pole.
Primitive makeUvSphere(float radius = 1.0f, int segments = 64, int rings = 64);
/// Axis-aligned cube of half extent `halfExtent`, 24 vertices (flat faces).
Primitive makeCube(float halfExtent = 1.0f);
/// Square in the XZ plane facing +Y, side `size`, uv repeated `uvRepeat` times.
Primitive makePlane(float size = 1.0f, float uvRepeat = 1.0f);

/// Adds a mesh with one primitive and one material, and a node placing it; returns the node.
int addShape(Scene& scene, Primitive primitive, const Material& material, const glm::mat4& transform,
             const std::string& name = {});

} // namespace specula::scene
