#pragma once
#include "scene/Scene.h"

namespace specula::scene {

/// Replaces normals by face normals (vertices are un-shared so each face is flat). Both
/// functions carry a primitive's skin and morph target data along with the vertices they copy.
void generateFlatNormals(Primitive& primitive);

/// Generates per-vertex tangents the MikkTSpace way: per-triangle tangent and bitangent
/// from uv derivatives, weighted by the corner angle, orthogonalised against the vertex
/// normal (Gram-Schmidt), with handedness w = sign(dot(cross(n, t), b)) so that
/// bitangent = cross(normal, tangent.xyz) * w as glTF defines it. t = dP/du and
/// b = -dP/dv: glTF's v runs down the image while a normal map's green runs up, so this is
/// MikkTSpace run on (u, 1 - v). Vertices whose mapping is mirrored relative to their
/// neighbours are split. Sets hasTangents.
void generateTangents(Primitive& primitive, int uvSet = 0);

} // namespace specula::scene
