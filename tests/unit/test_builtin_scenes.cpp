// The built-in scenes: they build and validate, keep their promises (reflector rectangles that
// cover their meshes, named default cameras, the gallery's marker in view with its reflection).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <optional>
#include <set>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/errors.h"
#include "scene/builtin_scenes.h"

namespace {

using ssr::Mesh;
using ssr::Scene;

const Mesh* find_mesh(const Scene& s, const std::string& name) {
  for (const Mesh& m : s.meshes)
    if (m.name == name) return &m;
  return nullptr;
}

void bounds(const Mesh& m, glm::vec3& lo, glm::vec3& hi) {
  lo = glm::vec3(1e30f);
  hi = glm::vec3(-1e30f);
  for (const ssr::Vertex& v : m.vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
}

// World -> NDC through a camera at 16:9, as the renderer builds it (lookAt + perspective).
// Returns nothing for points behind the camera.
std::optional<glm::vec3> to_ndc(const ssr::Camera& c, glm::vec3 p, float aspect = 16.0f / 9.0f) {
  const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
  const glm::mat4 proj =
      glm::perspective(glm::radians(c.fov_y_deg), aspect, c.near_plane, c.far_plane);
  const glm::vec4 clip = proj * view * glm::vec4(p, 1.0f);
  if (clip.w <= 1e-6f) return std::nullopt;
  return glm::vec3(clip) / clip.w;
}

// Does the open segment a -> b cross any triangle of the scene, ignoring meshes named in `skip`?
bool segment_blocked(const Scene& s, glm::vec3 a, glm::vec3 b, const std::set<std::string>& skip) {
  const glm::vec3 d = b - a;
  for (const Mesh& m : s.meshes) {
    if (skip.count(m.name)) continue;
    for (std::size_t i = 0; i < m.indices.size(); i += 3) {
      const glm::vec3 p0 = m.vertices[m.indices[i]].position;
      const glm::vec3 e1 = m.vertices[m.indices[i + 1]].position - p0;
      const glm::vec3 e2 = m.vertices[m.indices[i + 2]].position - p0;
      const glm::vec3 pv = glm::cross(d, e2);
      const float det = glm::dot(e1, pv);
      if (std::abs(det) < 1e-12f) continue;
      const glm::vec3 tv = a - p0;
      const float u = glm::dot(tv, pv) / det;
      if (u < 0.0f || u > 1.0f) continue;
      const glm::vec3 qv = glm::cross(tv, e1);
      const float v = glm::dot(d, qv) / det;
      if (v < 0.0f || u + v > 1.0f) continue;
      const float t = glm::dot(e2, qv) / det;
      if (t > 1e-4f && t < 1.0f - 1e-4f) return true;
    }
  }
  return false;
}

// Checks that every mesh tagged with a reflector id lies in that reflector's rectangle.
void check_reflector_meshes(const Scene& s) {
  for (const Mesh& m : s.meshes) {
    if (m.reflector == 0) continue;
    SCOPED_TRACE(s.name + " mesh " + m.name);
    ASSERT_GE(m.reflector, 1);
    ASSERT_LE(m.reflector, static_cast<int>(s.reflectors.size()));
    const ssr::Reflector& r = s.reflectors[m.reflector - 1];
    const glm::vec3 n = r.normal();
    for (const ssr::Vertex& v : m.vertices) {
      const glm::vec3 d = v.position - r.center;
      EXPECT_NEAR(glm::dot(d, n), 0.0f, 1e-4f);
      EXPECT_LE(std::abs(glm::dot(d, r.tangent)), r.half_extents.x + 1e-3f);
      EXPECT_LE(std::abs(glm::dot(d, r.bitangent)), r.half_extents.y + 1e-3f);
      EXPECT_GT(glm::dot(v.normal, n), 0.9999f);  // the mesh faces the same way as the reflector
    }
  }
}

TEST(BuiltinScenes, ListsTheScenesWithGalleryFirst) {
  const auto& list = ssr::builtin_scenes();
  ASSERT_EQ(list.size(), 4u);
  EXPECT_EQ(list[0].name, "gallery");
  EXPECT_EQ(list[1].name, "cornell");
  EXPECT_EQ(list[2].name, "corridor");
  EXPECT_EQ(list[3].name, "glass");
  for (const auto& info : list) EXPECT_FALSE(info.description.empty()) << info.name;
}

TEST(BuiltinScenes, EachBuildsValidatesAndIsWellFormed) {
  for (const auto& info : ssr::builtin_scenes()) {
    SCOPED_TRACE(info.name);
    const Scene s = ssr::make_builtin_scene(info.name);
    EXPECT_NO_THROW(ssr::validate(s));
    EXPECT_EQ(s.name, info.name);
    EXPECT_LT(s.triangle_count(), 200000u);
    EXPECT_GE(s.lights.size(), 1u);
    EXPECT_LE(s.lights.size(), 8u);
    ASSERT_GE(s.cameras.size(), 2u);
    EXPECT_LE(s.cameras.size(), 4u);
    EXPECT_EQ(s.cameras[0].name, "default");
    EXPECT_EQ(&s.camera("default"), &s.cameras[0]);
    std::set<std::string> cams, meshes, mats;
    for (const auto& c : s.cameras) EXPECT_TRUE(cams.insert(c.name).second) << c.name;
    for (const auto& m : s.meshes) {
      EXPECT_FALSE(m.name.empty());
      EXPECT_TRUE(meshes.insert(m.name).second) << m.name;
    }
    for (const auto& m : s.materials) {
      EXPECT_FALSE(m.name.empty());
      EXPECT_TRUE(mats.insert(m.name).second) << m.name;
    }
    // Lights are inside the scene's geometry bounds; cameras too (or just in front of it).
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Mesh& m : s.meshes) {
      glm::vec3 a, b;
      bounds(m, a, b);
      lo = glm::min(lo, a);
      hi = glm::max(hi, b);
    }
    for (const auto& l : s.lights) {
      EXPECT_TRUE(glm::all(glm::greaterThan(l.position, lo)) && glm::all(glm::lessThan(l.position, hi)));
      EXPECT_GT(l.range, 0.0f);
    }
    check_reflector_meshes(s);
  }
}

TEST(BuiltinScenes, SameNameBuildsTheSameScene) {
  const Scene a = ssr::make_builtin_scene("gallery"), b = ssr::make_builtin_scene("gallery");
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  ASSERT_EQ(a.images.size(), b.images.size());
  for (std::size_t i = 0; i < a.images.size(); ++i) EXPECT_EQ(a.images[i].rgba, b.images[i].rgba);
  for (std::size_t i = 0; i < a.meshes.size(); ++i)
    EXPECT_EQ(a.meshes[i].vertices.size(), b.meshes[i].vertices.size());
}

TEST(BuiltinScenes, UnknownNameThrowsInputErrorListingKnownNames) {
  EXPECT_THROW(ssr::make_builtin_scene("nope"), ssr::InputError);
  EXPECT_THROW(ssr::make_builtin_scene(""), ssr::InputError);
  EXPECT_THROW(ssr::make_builtin_scene("Gallery"), ssr::InputError);
  try {
    ssr::make_builtin_scene("nope");
    FAIL() << "no exception";
  } catch (const ssr::InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'nope'"), std::string::npos) << msg;
    for (const auto& info : ssr::builtin_scenes())
      EXPECT_NE(msg.find(info.name), std::string::npos) << msg;
  }
}

TEST(BuiltinScenes, GalleryFloorIsAPlanarMirrorReflectorFacingUp) {
  const Scene s = ssr::make_builtin_scene("gallery");
  const Mesh* floor = find_mesh(s, "floor");
  ASSERT_NE(floor, nullptr);
  EXPECT_EQ(floor->reflector, 1);
  ASSERT_GE(s.reflectors.size(), 1u);
  const ssr::Reflector& r = s.reflectors[0];
  EXPECT_NEAR(glm::dot(r.normal(), glm::vec3(0, 1, 0)), 1.0f, 1e-6f);
  EXPECT_NEAR(r.center.y, 0.0f, 1e-6f);
  const ssr::Material& m = s.materials.at(floor->material);
  EXPECT_EQ(m.metallic, 1.0f);
  EXPECT_EQ(m.roughness, 0.0f);
  EXPECT_EQ(m.reflectance, 1.0f);
  // The rectangle covers the floor and is no bigger than it.
  glm::vec3 lo, hi;
  bounds(*floor, lo, hi);
  EXPECT_NEAR(hi.x - lo.x, 2.0f * r.half_extents.x, 1e-3f);
  EXPECT_NEAR(hi.z - lo.z, 2.0f * r.half_extents.y, 1e-3f);
  check_reflector_meshes(s);
  // The back wall carries a procedural texture.
  const Mesh* wall = find_mesh(s, "back_wall");
  ASSERT_NE(wall, nullptr);
  const int tex = s.materials.at(wall->material).albedo_texture;
  ASSERT_GE(tex, 0);
  EXPECT_EQ(s.images.at(tex).width, 256);
  EXPECT_EQ(s.images.at(tex).height, 256);
}

TEST(BuiltinScenes, GalleryMarkerAndItsReflectionAreInViewAndUnoccluded) {
  const Scene s = ssr::make_builtin_scene("gallery");
  const Mesh* marker = find_mesh(s, "marker");
  ASSERT_NE(marker, nullptr);
  glm::vec3 lo, hi;
  bounds(*marker, lo, hi);
  const glm::vec3 centre = 0.5f * (lo + hi);
  EXPECT_NEAR(lo.y, 0.0f, 1e-4f);  // standing on the mirror floor
  EXPECT_GT(glm::length(s.materials.at(marker->material).emission), 1.0f);
  const ssr::Reflector& r = s.reflectors.at(0);
  const glm::vec3 n = r.normal();
  auto mirror = [&](glm::vec3 p) { return p - 2.0f * glm::dot(p - r.center, n) * n; };
  const ssr::Camera& cam = s.cameras[0];

  // Every vertex of the marker and of its mirror image projects inside the frame.
  for (const ssr::Vertex& v : marker->vertices) {
    for (const glm::vec3 p : {v.position, mirror(v.position)}) {
      const auto ndc = to_ndc(cam, p);
      ASSERT_TRUE(ndc.has_value());
      EXPECT_LT(std::abs(ndc->x), 0.9f);
      EXPECT_LT(std::abs(ndc->y), 0.9f);
    }
  }
  const glm::vec3 c_ndc = *to_ndc(cam, centre), m_ndc = *to_ndc(cam, mirror(centre));
  std::cout << "gallery marker centre " << centre.x << ", " << centre.y << ", " << centre.z
            << " -> NDC (" << c_ndc.x << ", " << c_ndc.y << "); mirror image -> NDC (" << m_ndc.x
            << ", " << m_ndc.y << ")\n";
  EXPECT_GT(c_ndc.y - m_ndc.y, 0.1f);  // clearly separated on screen

  // Line of sight to the marker, and the reflected path via the floor, are free.
  EXPECT_FALSE(segment_blocked(s, cam.position, centre, {"marker"}));
  const glm::vec3 image = mirror(centre);
  const float t = cam.position.y / (cam.position.y - image.y);
  const glm::vec3 on_floor = cam.position + t * (image - cam.position);
  EXPECT_NEAR(on_floor.y, 0.0f, 1e-4f);
  EXPECT_LE(std::abs(on_floor.x - r.center.x), r.half_extents.x);
  EXPECT_LE(std::abs(on_floor.z - r.center.z), r.half_extents.y);
  EXPECT_FALSE(segment_blocked(s, cam.position, on_floor, {"marker", "floor"}));
  EXPECT_FALSE(segment_blocked(s, on_floor, centre, {"marker", "floor"}));
}

TEST(BuiltinScenes, DefaultCamerasSeeTheReflectiveFloor) {
  // The ray through the lower middle of the frame (NDC (0, -0.6)) hits the floor mesh first.
  for (const auto& info : ssr::builtin_scenes()) {
    SCOPED_TRACE(info.name);
    const Scene s = ssr::make_builtin_scene(info.name);
    const ssr::Camera& cam = s.cameras[0];
    const glm::mat4 inv = glm::inverse(
        glm::perspective(glm::radians(cam.fov_y_deg), 16.0f / 9.0f, cam.near_plane, cam.far_plane) *
        glm::lookAt(cam.position, cam.target, cam.up));
    const glm::vec4 far_h = inv * glm::vec4(0.0f, -0.6f, 1.0f, 1.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3(far_h) / far_h.w - cam.position);
    ASSERT_LT(dir.y, 0.0f);
    const glm::vec3 hit = cam.position + dir * (cam.position.y / -dir.y);
    const Mesh* floor = find_mesh(s, "floor");
    ASSERT_NE(floor, nullptr);
    glm::vec3 lo, hi;
    bounds(*floor, lo, hi);
    EXPECT_TRUE(hit.x > lo.x && hit.x < hi.x && hit.z > lo.z && hit.z < hi.z);
    EXPECT_FALSE(segment_blocked(s, cam.position, hit, {"floor"}));
  }
}

TEST(BuiltinScenes, CornellIsAGlossyBoxWithoutPlanarReflectors) {
  const Scene s = ssr::make_builtin_scene("cornell");
  EXPECT_TRUE(s.reflectors.empty());
  const Mesh* floor = find_mesh(s, "floor");
  ASSERT_NE(floor, nullptr);
  EXPECT_EQ(floor->reflector, 0);
  const ssr::Material& fm = s.materials.at(floor->material);
  EXPECT_FLOAT_EQ(fm.roughness, 0.3f);
  EXPECT_EQ(fm.reflectance, 1.0f);
  const Mesh* left = find_mesh(s, "left_wall");
  const Mesh* right = find_mesh(s, "right_wall");
  ASSERT_TRUE(left && right);
  const glm::vec3 red = s.materials.at(left->material).albedo;
  const glm::vec3 green = s.materials.at(right->material).albedo;
  EXPECT_GT(red.x, 3.0f * std::max(red.y, red.z));
  EXPECT_GT(green.y, 2.0f * std::max(green.x, green.z));
  // Interior faces: the left wall has a +X face at x = -2.5, the right wall a -X face at 2.5.
  auto has_face = [](const Mesh& m, glm::vec3 normal, float x) {
    for (const ssr::Vertex& v : m.vertices)
      if (glm::dot(v.normal, normal) > 0.9999f && std::abs(v.position.x - x) < 1e-4f) return true;
    return false;
  };
  EXPECT_TRUE(has_face(*left, {1, 0, 0}, -2.5f));
  EXPECT_TRUE(has_face(*right, {-1, 0, 0}, 2.5f));
  EXPECT_EQ(s.lights.size(), 1u);
}

TEST(BuiltinScenes, CorridorDimensionsAndMirrorFloor) {
  const Scene s = ssr::make_builtin_scene("corridor");
  const Mesh* floor = find_mesh(s, "floor");
  ASSERT_NE(floor, nullptr);
  EXPECT_EQ(floor->reflector, 1);
  EXPECT_NEAR(glm::dot(s.reflectors.at(0).normal(), glm::vec3(0, 1, 0)), 1.0f, 1e-6f);
  EXPECT_EQ(s.materials.at(floor->material).metallic, 1.0f);
  EXPECT_LE(s.materials.at(floor->material).roughness, 0.05f);
  glm::vec3 lo, hi;
  bounds(*floor, lo, hi);
  EXPECT_NEAR(hi.x - lo.x, 4.0f, 1e-4f);
  EXPECT_NEAR(hi.z - lo.z, 40.0f, 1e-4f);
  const Mesh* ceiling = find_mesh(s, "ceiling");
  ASSERT_NE(ceiling, nullptr);
  bounds(*ceiling, lo, hi);
  EXPECT_NEAR(lo.y, 3.5f, 1e-4f);
  for (const ssr::Vertex& v : ceiling->vertices) EXPECT_NEAR(v.normal.y, -1.0f, 1e-6f);
  // The far end of the corridor is in view of the default camera.
  const auto ndc = to_ndc(s.cameras[0], {0.0f, 1.0f, -39.9f});
  ASSERT_TRUE(ndc.has_value());
  EXPECT_LT(std::abs(ndc->x), 0.5f);
  EXPECT_LT(std::abs(ndc->y), 0.5f);
}

}  // namespace
