// Procedural meshes for the built-in scenes: all with unit normals, uvs and tangents.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ssr::meshgen {

// Axis-aligned rectangle in the XZ plane at y = 0, facing +Y, size x size_z, uv scaled by uv_scale.
Mesh plane(glm::vec2 size, float uv_scale = 1.0f);
// Axis-aligned box centred at the origin with the given full extents, faces pointing outwards.
Mesh box(glm::vec3 extents);
// UV sphere centred at the origin.
Mesh sphere(float radius, int segments = 48, int rings = 24);
// Capped cylinder along +Y from y = 0 to y = height.
Mesh cylinder(float radius, float height, int segments = 32);

// Applies an affine transform to positions, normals and tangents (normals by inverse transpose).
void transform(Mesh& mesh, const glm::mat4& m);

// Fills Vertex::tangent from positions, normals and uvs (used for OBJ files without tangents).
void compute_tangents(Mesh& mesh);

// Any unit vector orthogonal to the unit vector n (a fallback tangent).
glm::vec3 any_orthogonal(glm::vec3 n);

}  // namespace ssr::meshgen
