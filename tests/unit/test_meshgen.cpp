// Procedural meshes: unit normals, tangent frames that follow the uvs, counter-clockwise winding
// that agrees with the normals, exact shapes, no degenerate triangles, correct transforms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/meshgen.h"

namespace {

using ssr::Mesh;
using ssr::Vertex;
namespace mg = ssr::meshgen;

constexpr float kPi = std::numbers::pi_v<float>;

bool finite3(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Every invariant a generated (or transformed) mesh must hold. `flat_faces`: each triangle's
// geometric normal equals its vertex normals (boxes, planes).
void check_mesh(const Mesh& m, const std::string& what, bool flat_faces = false) {
  SCOPED_TRACE(what);
  ASSERT_FALSE(m.indices.empty());
  ASSERT_EQ(m.indices.size() % 3, 0u);
  std::vector<bool> used(m.vertices.size(), false);
  for (std::uint32_t i : m.indices) {
    ASSERT_LT(i, m.vertices.size());
    used[i] = true;
  }
  for (std::size_t i = 0; i < used.size(); ++i) EXPECT_TRUE(used[i]) << "unused vertex " << i;
  for (const Vertex& v : m.vertices) {
    ASSERT_TRUE(finite3(v.position));
    ASSERT_TRUE(std::isfinite(v.uv.x) && std::isfinite(v.uv.y));
    ASSERT_TRUE(finite3(glm::vec3(v.tangent)) && std::isfinite(v.tangent.w));
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-5f);
    EXPECT_EQ(std::abs(v.tangent.w), 1.0f);
  }
  for (std::size_t i = 0; i < m.indices.size(); i += 3) {
    const Vertex* t[3] = {&m.vertices[m.indices[i]], &m.vertices[m.indices[i + 1]],
                          &m.vertices[m.indices[i + 2]]};
    const glm::vec3 e1 = t[1]->position - t[0]->position, e2 = t[2]->position - t[0]->position;
    const glm::vec3 face = glm::cross(e1, e2);
    const float scale = std::max(glm::dot(e1, e1), glm::dot(e2, e2));
    // No degenerate (zero-area or needle) triangles.
    ASSERT_GT(glm::length(face), 1e-6f * scale) << "degenerate triangle " << i / 3;
    const glm::vec3 fn = glm::normalize(face);
    for (const Vertex* v : t) {
      // Counter-clockwise seen from the side the normals point to.
      EXPECT_GT(glm::dot(fn, v->normal), flat_faces ? 0.9999f : 0.0f) << "triangle " << i / 3;
    }
    // The tangent frame follows the uvs: tangent along dP/du, cross(n, t) * w along dP/dv.
    const glm::vec2 d1 = t[1]->uv - t[0]->uv, d2 = t[2]->uv - t[0]->uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) > 1e-12f) {
      const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det;
      const glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) / det;
      for (const Vertex* v : t) {
        const glm::vec3 tv(v->tangent);
        EXPECT_GT(glm::dot(tv, glm::normalize(dpdu)), 0.0f) << "triangle " << i / 3;
        EXPECT_GT(glm::dot(glm::cross(v->normal, tv) * v->tangent.w, dpdv), 0.0f)
            << "triangle " << i / 3;
      }
    }
  }
}

// Signed volume enclosed by a closed mesh (divergence theorem): positive when it faces outwards.
float signed_volume(const Mesh& m) {
  double v = 0.0;
  for (std::size_t i = 0; i < m.indices.size(); i += 3) {
    const glm::dvec3 a(m.vertices[m.indices[i]].position), b(m.vertices[m.indices[i + 1]].position),
        c(m.vertices[m.indices[i + 2]].position);
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return static_cast<float>(v);
}

void bounds(const Mesh& m, glm::vec3& lo, glm::vec3& hi) {
  lo = glm::vec3(1e30f);
  hi = glm::vec3(-1e30f);
  for (const Vertex& v : m.vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
}

TEST(Meshgen, PlaneFacesUpWithSizeAndUvScale) {
  const Mesh m = mg::plane({4.0f, 2.0f}, 3.0f);
  check_mesh(m, "plane", true);
  EXPECT_EQ(m.indices.size(), 6u);
  glm::vec3 lo, hi;
  bounds(m, lo, hi);
  EXPECT_EQ(lo, glm::vec3(-2.0f, 0.0f, -1.0f));
  EXPECT_EQ(hi, glm::vec3(2.0f, 0.0f, 1.0f));
  for (const Vertex& v : m.vertices) {
    EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(glm::vec3(v.tangent), glm::vec3(1, 0, 0));
    // u along +X, v along -Z (image up points away from a viewer standing at +Z), range [0, 3].
    EXPECT_NEAR(v.uv.x, 3.0f * (v.position.x + 2.0f) / 4.0f, 1e-6f);
    EXPECT_NEAR(v.uv.y, 3.0f * (1.0f - v.position.z) / 2.0f, 1e-6f);
  }
}

TEST(Meshgen, BoxBoundsEqualExtentsAndFacesPointOutwards) {
  const glm::vec3 e(1.0f, 2.0f, 3.0f);
  const Mesh m = mg::box(e);
  check_mesh(m, "box", true);
  EXPECT_EQ(m.indices.size(), 36u);
  glm::vec3 lo, hi;
  bounds(m, lo, hi);
  EXPECT_EQ(lo, -0.5f * e);
  EXPECT_EQ(hi, 0.5f * e);
  EXPECT_NEAR(signed_volume(m), 6.0f, 1e-5f);
  int per_axis[6] = {};
  for (const Vertex& v : m.vertices) {
    // The normal is an axis, and the vertex lies on the box face of that axis.
    int axis = -1;
    for (int a = 0; a < 3; ++a)
      if (std::abs(v.normal[a]) == 1.0f) axis = a;
    ASSERT_GE(axis, 0);
    EXPECT_FLOAT_EQ(v.position[axis], v.normal[axis] * 0.5f * e[axis]);
    ++per_axis[2 * axis + (v.normal[axis] > 0 ? 0 : 1)];
  }
  for (int n : per_axis) EXPECT_EQ(n, 4);
}

TEST(Meshgen, SphereVerticesLieAtRadiusWithRadialNormals) {
  const int configs[][2] = {{48, 24}, {3, 2}, {4, 3}, {8, 5}, {5, 7}, {1, 1}};
  for (const auto& c : configs) {
    const std::string what = "sphere " + std::to_string(c[0]) + "x" + std::to_string(c[1]);
    const float r = 1.7f;
    const Mesh m = mg::sphere(r, c[0], c[1]);
    check_mesh(m, what);
    for (const Vertex& v : m.vertices) {
      EXPECT_NEAR(glm::length(v.position), r, 1e-5f) << what;
      EXPECT_GT(glm::dot(v.normal, v.position / r), 0.99999f) << what;
    }
    EXPECT_GT(signed_volume(m), 0.0f) << what;
  }
  const Mesh fine = mg::sphere(1.0f, 48, 24);
  EXPECT_NEAR(signed_volume(fine), 4.0f / 3.0f * kPi, 0.02f * 4.0f / 3.0f * kPi);
}

TEST(Meshgen, SpherePolesHaveFiniteTangentsAndOneTrianglePerSegment) {
  const int segments = 12, rings = 6;
  const Mesh m = mg::sphere(1.0f, segments, rings);
  // 2 caps of `segments` triangles + 2 triangles per quad in between.
  EXPECT_EQ(m.indices.size() / 3, static_cast<std::size_t>(2 * segments + 2 * segments * (rings - 2)));
  int poles = 0;
  for (const Vertex& v : m.vertices) {
    if (std::abs(v.position.y) > 0.99999f) {
      ++poles;
      EXPECT_NEAR(std::abs(v.normal.y), 1.0f, 1e-6f);
      EXPECT_NEAR(v.tangent.y, 0.0f, 1e-6f);
      EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-6f);
    }
  }
  EXPECT_GE(poles, 2 * segments);
}

TEST(Meshgen, CylinderShape) {
  const float r = 0.6f, h = 2.5f;
  const int segments = 20;
  const Mesh m = mg::cylinder(r, h, segments);
  check_mesh(m, "cylinder");
  glm::vec3 lo, hi;
  bounds(m, lo, hi);
  EXPECT_NEAR(lo.y, 0.0f, 1e-6f);
  EXPECT_NEAR(hi.y, h, 1e-6f);
  for (const Vertex& v : m.vertices) {
    EXPECT_TRUE(v.position.y == 0.0f || v.position.y == h);
    const float radial = glm::length(glm::vec2(v.position.x, v.position.z));
    if (std::abs(v.normal.y) < 0.5f) {  // side
      EXPECT_NEAR(radial, r, 1e-5f);
      EXPECT_NEAR(v.normal.y, 0.0f, 1e-6f);
      EXPECT_GT(glm::dot(glm::vec2(v.normal.x, v.normal.z), glm::vec2(v.position.x, v.position.z)), 0.0f);
    } else {  // caps
      EXPECT_LE(radial, r + 1e-5f);
      EXPECT_EQ(v.normal.y, v.position.y == 0.0f ? -1.0f : 1.0f);
    }
  }
  // A closed prism over a regular polygon.
  const float expected = 0.5f * segments * r * r * std::sin(2.0f * kPi / segments) * h;
  EXPECT_NEAR(signed_volume(m), expected, 1e-4f * expected);
  check_mesh(mg::cylinder(1.0f, 0.1f, 3), "cylinder 3");
}

TEST(Meshgen, TransformNonUniformScaleKeepsNormalsUnitAndCorrect) {
  const glm::vec3 c(1.0f, -2.0f, 3.0f), s(2.0f, 0.5f, 1.5f);
  const glm::mat4 R = glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 0.5f)));
  const glm::mat4 M = glm::translate(glm::mat4(1.0f), c) * R * glm::scale(glm::mat4(1.0f), s);
  Mesh m = mg::sphere(1.0f, 24, 12);
  mg::transform(m, M);
  check_mesh(m, "ellipsoid");
  // Exact normal of the ellipsoid |S^-1 R^T (q - c)| = 1 is R S^-2 R^T (q - c).
  const glm::mat3 r3(R);
  for (const Vertex& v : m.vertices) {
    const glm::vec3 local = glm::transpose(r3) * (v.position - c);
    EXPECT_NEAR(glm::length(local / s), 1.0f, 1e-5f);
    const glm::vec3 expected = glm::normalize(r3 * (local / (s * s)));
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(v.normal, expected), 0.99999f);
  }
  EXPECT_NEAR(signed_volume(m), signed_volume(mg::sphere(1.0f, 24, 12)) * s.x * s.y * s.z, 1e-3f);

  // Scale between two rotations: a real shear; faces stay flat.
  const glm::mat4 R2 = glm::rotate(glm::mat4(1.0f), -1.1f, glm::normalize(glm::vec3(0.3f, -1, 2)));
  Mesh b = mg::box({1, 1, 1});
  mg::transform(b, M * R2);
  check_mesh(b, "sheared box", true);
  EXPECT_NEAR(signed_volume(b), s.x * s.y * s.z, 1e-4f);
}

TEST(Meshgen, MirroringTransformKeepsWindingAndFlipsHandedness) {
  Mesh b = mg::box({1.0f, 2.0f, 3.0f});
  mg::transform(b, glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)));
  check_mesh(b, "mirrored box", true);
  EXPECT_NEAR(signed_volume(b), 6.0f, 1e-5f);
  for (const Vertex& v : b.vertices) EXPECT_EQ(v.tangent.w, -1.0f);

  Mesh s = mg::sphere(1.0f, 16, 8);
  mg::transform(s, glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -2.0f, 1.0f)));
  check_mesh(s, "mirrored sphere");
  EXPECT_GT(signed_volume(s), 0.0f);
}

TEST(Meshgen, ComputeTangentsReproducesGeneratedFrames) {
  const Mesh meshes[] = {mg::plane({3, 5}, 2.0f), mg::box({1, 2, 3}), mg::sphere(1.0f, 32, 16),
                         mg::cylinder(0.5f, 2.0f, 24)};
  for (const Mesh& original : meshes) {
    Mesh m = original;
    for (Vertex& v : m.vertices) v.tangent = glm::vec4(0.0f);
    mg::compute_tangents(m);
    check_mesh(m, "recomputed " + original.name, original.name == "plane" || original.name == "box");
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      EXPECT_GT(glm::dot(glm::vec3(m.vertices[i].tangent), glm::vec3(original.vertices[i].tangent)),
                0.95f)
          << original.name << " vertex " << i;
      EXPECT_EQ(m.vertices[i].tangent.w, original.vertices[i].tangent.w);
    }
  }
}

TEST(Meshgen, ComputeTangentsMirroredUvsGiveNegativeHandedness) {
  Mesh m = mg::plane({2, 2});
  for (Vertex& v : m.vertices) v.uv.x = 1.0f - v.uv.x;
  mg::compute_tangents(m);
  check_mesh(m, "u-mirrored plane", true);
  for (const Vertex& v : m.vertices) {
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), glm::vec3(-1, 0, 0)), 1.0f, 1e-5f);
    EXPECT_EQ(v.tangent.w, -1.0f);
  }
}

TEST(Meshgen, ComputeTangentsSurvivesDegenerateInput) {
  Mesh m;
  const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 1));
  // Collapsed uvs on a real triangle, then a zero-area triangle, then an unused vertex.
  m.vertices = {Vertex{{0, 0, 0}, n, {0.5f, 0.5f}, {}}, Vertex{{1, -1, 0}, n, {0.5f, 0.5f}, {}},
                Vertex{{1, 0, -1}, n, {0.5f, 0.5f}, {}}, Vertex{{0, 0, 0}, n, {0, 0}, {}},
                Vertex{{0, 0, 0}, n, {1, 0}, {}},       Vertex{{0, 0, 0}, n, {0, 1}, {}},
                Vertex{{5, 5, 5}, glm::vec3(0, 0, 1), {0, 0}, {}}};
  m.indices = {0, 1, 2, 3, 4, 5};
  mg::compute_tangents(m);
  for (const Vertex& v : m.vertices) {
    const glm::vec3 t(v.tangent);
    ASSERT_TRUE(finite3(t));
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(t, v.normal), 0.0f, 1e-5f);
    EXPECT_EQ(std::abs(v.tangent.w), 1.0f);
  }
}

}  // namespace
