// Procedural meshes. Conventions shared by every generator here:
//
// - Front faces are counter-clockwise seen from outside (OpenGL's default), and for every
//   triangle cross(p1 - p0, p2 - p0) points the same way as its vertex normals.
// - uv follows the OpenGL / OBJ convention: u grows to the right and v grows *upwards* in the
//   image as seen from the front of the face, so v = 0 is the bottom row of an Image (whose row
//   0 is the top row): an uploader that keeps PNG row order samples with (u, 1 - v) or flips
//   rows. Textures are never mirrored on a generated face.
// - Vertex::tangent.xyz is dP/du (unit, orthogonal to the normal); w = +1 when
//   cross(normal, tangent) points along dP/dv, else -1 (the generators always give +1; a
//   mirroring transform flips it). A shader gets the bitangent as cross(n, t) * w.
// - No degenerate triangles: sphere poles use one triangle per segment, with a pole vertex per
//   segment whose tangent is the analytic (finite) one.
#include "scene/meshgen.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace ssr::meshgen {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Appends a flat rectangle origin + s*U + t*V, s,t in [0,1], facing normalize(cross(U, V)).
// uv = (s, t) * uv_size; tangent = U direction (w = +1 since U and V are orthogonal).
void add_quad(Mesh& m, glm::vec3 origin, glm::vec3 U, glm::vec3 V, glm::vec2 uv_size) {
  const glm::vec3 n = glm::normalize(glm::cross(U, V));
  const glm::vec4 t(glm::normalize(U), 1.0f);
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  const glm::vec2 st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const glm::vec2& c : st)
    m.vertices.push_back(Vertex{origin + c.x * U + c.y * V, n, c * uv_size, t});
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

float sign_or_one(float v) { return v < 0.0f ? -1.0f : 1.0f; }

bool finite3(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

glm::vec3 any_orthogonal(glm::vec3 n) {
  const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(a, n));
}

Mesh plane(glm::vec2 size, float uv_scale) {
  // Seen from above (+Y), u runs along +X and v along -Z (image up = away from a viewer at +Z).
  Mesh m;
  m.name = "plane";
  const float hx = 0.5f * size.x, hz = 0.5f * size.y;
  add_quad(m, {-hx, 0.0f, hz}, {size.x, 0, 0}, {0, 0, -size.y}, glm::vec2(uv_scale));
  return m;
}

Mesh box(glm::vec3 e) {
  Mesh m;
  m.name = "box";
  const glm::vec3 h = 0.5f * e;
  // Each face: origin at its bottom-left seen from outside, U to the right, V up.
  add_quad(m, {h.x, -h.y, h.z}, {0, 0, -e.z}, {0, e.y, 0}, glm::vec2(1));     // +X
  add_quad(m, {-h.x, -h.y, -h.z}, {0, 0, e.z}, {0, e.y, 0}, glm::vec2(1));    // -X
  add_quad(m, {-h.x, h.y, h.z}, {e.x, 0, 0}, {0, 0, -e.z}, glm::vec2(1));     // +Y
  add_quad(m, {-h.x, -h.y, -h.z}, {e.x, 0, 0}, {0, 0, e.z}, glm::vec2(1));    // -Y
  add_quad(m, {-h.x, -h.y, h.z}, {e.x, 0, 0}, {0, e.y, 0}, glm::vec2(1));     // +Z
  add_quad(m, {h.x, -h.y, -h.z}, {-e.x, 0, 0}, {0, e.y, 0}, glm::vec2(1));    // -Z
  return m;
}

Mesh sphere(float radius, int segments, int rings) {
  segments = std::max(segments, 3);
  rings = std::max(rings, 2);
  Mesh m;
  m.name = "sphere";
  // theta: 0 at +Y (top) .. pi at -Y; phi: longitude, growing to the right seen from outside.
  // p = r (sin t cos f, cos t, -sin t sin f); dP/dphi ~ (-sin f, 0, -cos f); v = 1 - theta/pi.
  // Rows in between have segments + 1 vertices (the seam column is duplicated for the uv
  // wrap); each pole row has one vertex per segment.
  const int cols = segments + 1;
  for (int i = 0; i <= rings; ++i) {
    const bool pole = i == 0 || i == rings;
    const float theta = kPi * static_cast<float>(i) / static_cast<float>(rings);
    for (int j = 0; j < (pole ? segments : cols); ++j) {
      // A pole vertex belongs to one segment's triangle: give it that segment's middle u.
      const float s = (static_cast<float>(j) + (pole ? 0.5f : 0.0f)) / static_cast<float>(segments);
      const float phi = 2.0f * kPi * s;
      glm::vec3 n;
      if (i == 0)
        n = {0, 1, 0};
      else if (i == rings)
        n = {0, -1, 0};
      else
        n = {std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)};
      n = glm::normalize(n);
      const glm::vec4 t(-std::sin(phi), 0.0f, -std::cos(phi), 1.0f);
      const float v = 1.0f - static_cast<float>(i) / static_cast<float>(rings);
      m.vertices.push_back(Vertex{radius * n, n, {s, v}, t});
    }
  }
  auto id = [cols, segments](int i, int j) {
    return static_cast<std::uint32_t>(i == 0 ? j : segments + (i - 1) * cols + j);
  };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      // a (i,j) top-left, d (i,j+1) top-right, b (i+1,j) bottom-left, c (i+1,j+1) bottom-right.
      const std::uint32_t a = id(i, j), d = id(i, j + 1), b = id(i + 1, j), c = id(i + 1, j + 1);
      if (i == 0) {  // top cap: a is the pole
        m.indices.insert(m.indices.end(), {b, c, a});
      } else if (i == rings - 1) {  // bottom cap: b is the pole
        m.indices.insert(m.indices.end(), {b, d, a});
      } else {
        m.indices.insert(m.indices.end(), {b, c, d, b, d, a});
      }
    }
  }
  return m;
}

Mesh cylinder(float radius, float height, int segments) {
  segments = std::max(segments, 3);
  Mesh m;
  m.name = "cylinder";
  // Side: p = (r cos f, y, -r sin f), u = phi / 2pi growing to the right, v = y / height.
  for (int k = 0; k <= 1; ++k) {
    const float y = k ? height : 0.0f;
    for (int j = 0; j <= segments; ++j) {
      const float s = static_cast<float>(j) / static_cast<float>(segments);
      const float phi = 2.0f * kPi * s;
      const glm::vec3 n(std::cos(phi), 0.0f, -std::sin(phi));
      const glm::vec4 t(-std::sin(phi), 0.0f, -std::cos(phi), 1.0f);
      m.vertices.push_back(Vertex{{radius * n.x, y, radius * n.z}, n, {s, static_cast<float>(k)}, t});
    }
  }
  for (int j = 0; j < segments; ++j) {
    const auto bl = static_cast<std::uint32_t>(j), br = bl + 1;
    const auto tl = static_cast<std::uint32_t>(segments + 1 + j), tr = tl + 1;
    m.indices.insert(m.indices.end(), {bl, br, tr, bl, tr, tl});
  }
  // Caps: planar uv; top seen from above has image up = -Z (as plane()), bottom seen from
  // below has image up = +Z. Tangent +X in both, w = +1.
  for (int k = 0; k <= 1; ++k) {
    const bool top = k == 1;
    const float y = top ? height : 0.0f;
    const glm::vec3 n(0.0f, top ? 1.0f : -1.0f, 0.0f);
    const glm::vec4 t(1, 0, 0, 1);
    auto uv_of = [&](float x, float z) {
      return glm::vec2(0.5f + 0.5f * x / radius, 0.5f + (top ? -0.5f : 0.5f) * z / radius);
    };
    const auto center = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back(Vertex{{0, y, 0}, n, {0.5f, 0.5f}, t});
    for (int j = 0; j < segments; ++j) {
      const float phi = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(segments);
      const float x = radius * std::cos(phi), z = -radius * std::sin(phi);
      m.vertices.push_back(Vertex{{x, y, z}, n, uv_of(x, z), t});
    }
    for (int j = 0; j < segments; ++j) {
      const std::uint32_t r0 = center + 1 + static_cast<std::uint32_t>(j);
      const std::uint32_t r1 = center + 1 + static_cast<std::uint32_t>((j + 1) % segments);
      if (top)
        m.indices.insert(m.indices.end(), {center, r0, r1});
      else
        m.indices.insert(m.indices.end(), {center, r1, r0});
    }
  }
  return m;
}

void transform(Mesh& mesh, const glm::mat4& mat) {
  const glm::mat3 linear(mat);
  const glm::mat3 normal_mat = glm::transpose(glm::inverse(linear));
  const float det = glm::determinant(linear);
  const float flip = sign_or_one(det);
  for (Vertex& v : mesh.vertices) {
    v.position = glm::vec3(mat * glm::vec4(v.position, 1.0f));
    glm::vec3 n = normal_mat * v.normal;
    const float nl = glm::length(n);
    n = (nl > 0.0f && std::isfinite(nl)) ? n / nl : glm::vec3(0, 1, 0);
    // Tangents are surface directions: they transform with the matrix itself and stay
    // orthogonal to the inverse-transpose normal. Re-orthogonalise against rounding anyway.
    glm::vec3 t = linear * glm::vec3(v.tangent);
    t -= n * glm::dot(n, t);
    const float tl = glm::length(t);
    t = (tl > 1e-12f && std::isfinite(tl)) ? t / tl : any_orthogonal(n);
    v.normal = n;
    v.tangent = glm::vec4(t, sign_or_one(v.tangent.w) * flip);
  }
  // A mirroring transform turns counter-clockwise triangles clockwise: restore the winding.
  if (det < 0.0f)
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
      std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
}

void compute_tangents(Mesh& mesh) {
  const std::size_t nv = mesh.vertices.size();
  std::vector<glm::vec3> tan(nv, glm::vec3(0.0f)), bit(nv, glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const std::uint32_t ia = mesh.indices[i], ib = mesh.indices[i + 1], ic = mesh.indices[i + 2];
    if (ia >= nv || ib >= nv || ic >= nv) continue;
    const Vertex &a = mesh.vertices[ia], &b = mesh.vertices[ib], &c = mesh.vertices[ic];
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    const float area = 0.5f * glm::length(glm::cross(e1, e2));
    if (!(std::abs(det) > 1e-20f) || !(area > 0.0f)) continue;  // degenerate uv or triangle
    glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det;
    glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) / det;
    const float lu = glm::length(dpdu), lv = glm::length(dpdv);
    if (!(lu > 0.0f) || !(lv > 0.0f) || !std::isfinite(lu) || !std::isfinite(lv)) continue;
    dpdu *= area / lu;  // area-weighted unit directions
    dpdv *= area / lv;
    for (std::uint32_t k : {ia, ib, ic}) {
      tan[k] += dpdu;
      bit[k] += dpdv;
    }
  }
  for (std::size_t k = 0; k < nv; ++k) {
    Vertex& v = mesh.vertices[k];
    glm::vec3 n = v.normal;
    const float nl = glm::length(n);
    n = (nl > 0.0f && std::isfinite(nl)) ? n / nl : glm::vec3(0, 1, 0);
    glm::vec3 t = tan[k] - n * glm::dot(n, tan[k]);
    const float tl = glm::length(t);
    if (tl > 1e-12f && finite3(t))
      t /= tl;
    else if (glm::length(bit[k]) > 0.0f && finite3(bit[k]) &&
             glm::length(glm::cross(bit[k], n)) > 1e-12f)
      t = glm::normalize(glm::cross(bit[k], n));  // only dP/dv is known: T = B x N
    else
      t = any_orthogonal(n);
    const float w = glm::dot(glm::cross(n, t), bit[k]) < 0.0f ? -1.0f : 1.0f;
    v.tangent = glm::vec4(t, w);
  }
}

}  // namespace ssr::meshgen
