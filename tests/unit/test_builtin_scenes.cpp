// The built-in scenes: they build and validate, keep their promises (reflector rectangles that
// cover their meshes, named default cameras, the gallery's marker in view with its reflection).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/errors.h"
#include "input_error.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_io.h"

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
  ASSERT_EQ(list.size(), 13u);
  EXPECT_EQ(list[0].name, "gallery");
  EXPECT_EQ(list[1].name, "cornell");
  EXPECT_EQ(list[2].name, "corridor");
  EXPECT_EQ(list[3].name, "glass");
  EXPECT_EQ(list[4].name, "ramp");
  EXPECT_EQ(list[5].name, "hard-grazing");
  EXPECT_EQ(list[6].name, "hard-mirror-box");
  EXPECT_EQ(list[7].name, "hard-thin");
  EXPECT_EQ(list[8].name, "hard-depth-range");
  EXPECT_EQ(list[9].name, "hard-far-origin");
  EXPECT_EQ(list[10].name, "hard-degenerate");
  EXPECT_EQ(list[11].name, "hard-roughness");
  EXPECT_EQ(list[12].name, "hard-reflectors");
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
  // The ray through the lower middle of the frame (NDC (0, -0.6)) hits the floor mesh first
  // (the ramp's floor is its bands, "band_0.0" .. "band_1.0", all at y = 0).
  for (const auto& info : ssr::builtin_scenes()) {
    SCOPED_TRACE(info.name);
    const Scene s = ssr::make_builtin_scene(info.name);
    const ssr::Camera& cam = s.cameras[0];
    // In double: hard-depth-range's far / near = 1e8 leaves a float inverse without precision.
    const glm::dmat4 inv = glm::inverse(
        glm::perspective(glm::radians(double(cam.fov_y_deg)), 16.0 / 9.0, double(cam.near_plane),
                         double(cam.far_plane)) *
        glm::lookAt(glm::dvec3(cam.position), glm::dvec3(cam.target), glm::dvec3(cam.up)));
    const glm::dvec4 far_h = inv * glm::dvec4(0.0, -0.6, 1.0, 1.0);
    const glm::vec3 dir = glm::normalize(glm::vec3(glm::dvec3(far_h) / far_h.w - glm::dvec3(cam.position)));
    ASSERT_LT(dir.y, 0.0f);
    const glm::vec3 hit = cam.position + dir * (cam.position.y / -dir.y);
    std::set<std::string> floor_names;
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Mesh& m : s.meshes) {
      if (m.name != "floor" && m.name.rfind("band_", 0) != 0) continue;
      floor_names.insert(m.name);
      glm::vec3 a, b;
      bounds(m, a, b);
      lo = glm::min(lo, a);
      hi = glm::max(hi, b);
    }
    ASSERT_FALSE(floor_names.empty());
    EXPECT_TRUE(hit.x > lo.x && hit.x < hi.x && hit.z > lo.z && hit.z < hi.z);
    EXPECT_FALSE(segment_blocked(s, cam.position, hit, floor_names));
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

// ---- built-in scene options: gallery:reflectors=N, gallery:normal_map=... ------------------------

namespace {

// Is some point of reflector k's rectangle (a 9 x 9 grid, a little inside the edges) in the
// default view at 16:9 and unoccluded by anything but the meshes of reflector k?
bool reflector_in_view(const Scene& s, int k) {
  const ssr::Reflector& r = s.reflectors.at(static_cast<std::size_t>(k - 1));
  const ssr::Camera& cam = s.cameras[0];
  std::set<std::string> own;
  for (const Mesh& m : s.meshes)
    if (m.reflector == k) own.insert(m.name);
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      const float a = -0.95f + 1.9f * static_cast<float>(i) / 8.0f;
      const float b = -0.95f + 1.9f * static_cast<float>(j) / 8.0f;
      const glm::vec3 p =
          r.center + a * r.half_extents.x * r.tangent + b * r.half_extents.y * r.bitangent;
      if (glm::dot(cam.position - p, r.normal()) <= 0.0f) continue;  // seen from behind
      const auto ndc = to_ndc(cam, p);
      if (!ndc || std::abs(ndc->x) > 0.98f || std::abs(ndc->y) > 0.98f) continue;
      if (!segment_blocked(s, cam.position, p, own)) return true;
    }
  return false;
}

}  // namespace

TEST(BuiltinSceneOptions, GalleryReflectorsSplitsTheMirrorIntoNReflectors) {
  for (const int n : {1, 2, 3, 4, 5, 8, 16}) {
    const std::string name = "gallery:reflectors=" + std::to_string(n);
    SCOPED_TRACE(name);
    const Scene s = ssr::make_builtin_scene(name);
    EXPECT_NO_THROW(ssr::validate(s));
    EXPECT_EQ(s.name, name);
    ASSERT_EQ(s.reflectors.size(), static_cast<std::size_t>(n));
    // Every id 1..N is used by at least one mesh, and every such mesh lies in its rectangle
    // (vertices within the half extents, on the plane within 1e-4, facing the reflecting side).
    std::set<int> used;
    for (const Mesh& m : s.meshes)
      if (m.reflector) used.insert(m.reflector);
    for (int k = 1; k <= n; ++k) EXPECT_TRUE(used.count(k)) << "reflector " << k << " has no mesh";
    check_reflector_meshes(s);
    for (std::size_t k = 0; k < s.reflectors.size(); ++k) {
      const ssr::Reflector& r = s.reflectors[k];
      EXPECT_NEAR(glm::length(r.tangent), 1.0f, 1e-6f);
      EXPECT_NEAR(glm::length(r.bitangent), 1.0f, 1e-6f);
      EXPECT_NEAR(glm::dot(r.tangent, r.bitangent), 0.0f, 1e-6f);
      EXPECT_GT(r.half_extents.x, 0.0f);
      EXPECT_GT(r.half_extents.y, 0.0f);
      // Each reflector is seen by the default camera, from its reflecting side.
      EXPECT_TRUE(reflector_in_view(s, static_cast<int>(k) + 1)) << "reflector " << k + 1;
    }
    // The rest of the gallery is still there.
    for (const char* keep : {"marker", "back_wall", "sphere_gold", "column_1"})
      EXPECT_NE(find_mesh(s, keep), nullptr) << keep;
    // The floor reflectors (facing +Y at y = 0) cover the same 32 x 17 m as the plain floor,
    // less the gaps between tiles.
    float floor_area = 0.0f;
    int vertical = 0;
    for (const ssr::Reflector& r : s.reflectors) {
      if (glm::dot(r.normal(), glm::vec3(0, 1, 0)) > 0.9999f) {
        EXPECT_NEAR(r.center.y, 0.0f, 1e-6f);
        floor_area += 4.0f * r.half_extents.x * r.half_extents.y;
      } else {
        EXPECT_NEAR(r.normal().y, 0.0f, 1e-6f);  // the others are vertical wall mirrors
        ++vertical;
      }
    }
    EXPECT_LE(floor_area, 32.0f * 17.0f + 1e-2f);
    EXPECT_GT(floor_area, 0.97f * 32.0f * 17.0f);
    EXPECT_EQ(vertical, n >= 4 ? 2 : (n >= 2 ? 1 : 0));
  }
  // reflectors=1 is the plain gallery.
  const Scene plain = ssr::make_builtin_scene("gallery");
  const Scene one = ssr::make_builtin_scene("gallery:reflectors=1");
  ASSERT_EQ(one.meshes.size(), plain.meshes.size());
  ASSERT_EQ(one.reflectors.size(), 1u);
  EXPECT_EQ(one.reflectors[0].center, plain.reflectors[0].center);
  EXPECT_EQ(one.reflectors[0].half_extents, plain.reflectors[0].half_extents);
  for (std::size_t i = 0; i < one.meshes.size(); ++i) EXPECT_EQ(one.meshes[i].name, plain.meshes[i].name);
}

TEST(BuiltinSceneOptions, SomeReflectorsOverlapOnScreen) {
  // With wall mirrors, a floor tile's rectangle runs on behind a wall mirror: their projected
  // rectangles overlap in the default view (the case a PPR loop over reflectors must handle).
  const Scene s = ssr::make_builtin_scene("gallery:reflectors=5");
  const ssr::Camera& cam = s.cameras[0];
  auto screen_box = [&](const ssr::Reflector& r, glm::vec2& lo, glm::vec2& hi) {
    lo = glm::vec2(1e30f);
    hi = glm::vec2(-1e30f);
    for (int i = 0; i <= 16; ++i)
      for (int j = 0; j <= 16; ++j) {
        const float a = -1.0f + 2.0f * static_cast<float>(i) / 16.0f;
        const float b = -1.0f + 2.0f * static_cast<float>(j) / 16.0f;
        const auto ndc = to_ndc(cam, r.center + a * r.half_extents.x * r.tangent +
                                         b * r.half_extents.y * r.bitangent);
        if (!ndc) continue;
        const glm::vec2 p = glm::clamp(glm::vec2(*ndc), glm::vec2(-1.0f), glm::vec2(1.0f));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
  };
  int overlaps = 0;
  for (std::size_t a = 0; a < s.reflectors.size(); ++a)
    for (std::size_t b = a + 1; b < s.reflectors.size(); ++b) {
      if (std::abs(glm::dot(s.reflectors[a].normal(), s.reflectors[b].normal())) > 0.5f) continue;
      glm::vec2 alo, ahi, blo, bhi;
      screen_box(s.reflectors[a], alo, ahi);
      screen_box(s.reflectors[b], blo, bhi);
      const glm::vec2 lo = glm::max(alo, blo), hi = glm::min(ahi, bhi);
      if (hi.x - lo.x > 0.05f && hi.y - lo.y > 0.05f) ++overlaps;
    }
  EXPECT_GE(overlaps, 1);
}

TEST(BuiltinSceneOptions, GalleryNormalMapsAreTangentSpaceAndReadRight) {
  const Scene plain = ssr::make_builtin_scene("gallery");
  for (const char* kind : {"ripples", "tiles"}) {
    const std::string name = std::string("gallery:normal_map=") + kind;
    SCOPED_TRACE(name);
    const Scene s = ssr::make_builtin_scene(name);
    EXPECT_NO_THROW(ssr::validate(s));
    const Mesh* floor = find_mesh(s, "floor");
    ASSERT_NE(floor, nullptr);
    EXPECT_EQ(floor->reflector, 1);
    ASSERT_EQ(s.reflectors.size(), 1u);
    EXPECT_EQ(s.reflectors[0].center, plain.reflectors[0].center);  // rectangle unchanged
    EXPECT_EQ(s.reflectors[0].half_extents, plain.reflectors[0].half_extents);
    check_reflector_meshes(s);
    const ssr::Material& m = s.materials.at(floor->material);
    EXPECT_EQ(m.metallic, 1.0f);
    EXPECT_EQ(m.roughness, 0.0f);
    EXPECT_NEAR(m.normal_strength, 1.0f, 0.5f);
    ASSERT_GE(m.normal_texture, 0);
    const ssr::Image& im = s.images.at(m.normal_texture);
    ASSERT_EQ(im.width, 256);
    ASSERT_EQ(im.height, 256);
    ASSERT_EQ(im.rgba.size(), 256u * 256u * 4u);
    // Every texel is a unit normal pointing out of the surface; some are tilted.
    auto texel = [&](int x, int y) {
      const std::uint8_t* p = &im.rgba[(static_cast<std::size_t>(y) * 256 + x) * 4];
      return glm::vec3(p[0], p[1], p[2]) / 255.0f * 2.0f - 1.0f;
    };
    int tilted = 0;
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x) {
        const glm::vec3 n = texel(x, y);
        EXPECT_NEAR(glm::length(n), 1.0f, 0.02f);
        EXPECT_GT(n.z, 0.5f);
        if (glm::length(glm::vec2(n)) > 0.03f) ++tilted;  // more than ~1.7 deg
        if (HasFailure()) return;
      }
    EXPECT_GT(tilted, 256 * 256 / 10);
    // The floor's tangent frame: tangent +X (w = +1), so the bitangent cross(n, t) * w is -Z,
    // the direction v grows in; uvs repeat the map (not one copy over the whole floor).
    glm::vec2 uv_lo(1e30f), uv_hi(-1e30f);
    for (const ssr::Vertex& v : floor->vertices) {
      EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), glm::vec3(1, 0, 0)), 1.0f, 1e-6f);
      EXPECT_EQ(v.tangent.w, 1.0f);
      uv_lo = glm::min(uv_lo, v.uv);
      uv_hi = glm::max(uv_hi, v.uv);
    }
    for (const ssr::Vertex& v : floor->vertices)
      for (const ssr::Vertex& w : floor->vertices) {
        if (v.position.x < w.position.x - 1.0f) EXPECT_LT(v.uv.x, w.uv.x);  // u along +X
        if (v.position.z < w.position.z - 1.0f) EXPECT_GT(v.uv.y, w.uv.y);  // v along -Z
      }
    EXPECT_GE(uv_hi.x - uv_lo.x, 4.0f);
  }
  // Tiles: a tile's bevels tilt away from its centre. The top-left tile of the map spans
  // pixels 0..63; its left bevel (column 4) tilts left (-X), its top bevel (row 4) tilts up
  // the image (+Y), its right and bottom bevels the other ways; its middle is flat.
  const Scene t = ssr::make_builtin_scene("gallery:normal_map=tiles");
  const ssr::Image& im =
      t.images.at(t.materials.at(find_mesh(t, "floor")->material).normal_texture);
  auto px = [&](int x, int y, int c) {
    return static_cast<int>(im.rgba[(static_cast<std::size_t>(y) * 256 + x) * 4 + c]);
  };
  EXPECT_LT(px(4, 32, 0), 100);   // left bevel: x < 0
  EXPECT_GT(px(59, 32, 0), 156);  // right bevel: x > 0
  EXPECT_GT(px(32, 4, 1), 156);   // top bevel: y > 0 (image up)
  EXPECT_LT(px(32, 59, 1), 100);  // bottom bevel: y < 0
  EXPECT_EQ(px(32, 32, 0), 128);
  EXPECT_EQ(px(32, 32, 1), 128);
  EXPECT_EQ(px(32, 32, 2), 255);
  // none is the plain floor; options combine.
  const Scene none = ssr::make_builtin_scene("gallery:normal_map=none");
  EXPECT_EQ(none.materials.at(find_mesh(none, "floor")->material).normal_texture, -1);
  const Scene both = ssr::make_builtin_scene("gallery:reflectors=3,normal_map=tiles");
  EXPECT_EQ(both.reflectors.size(), 3u);
  check_reflector_meshes(both);
  for (const Mesh& m : both.meshes)
    if (m.name.rfind("floor_tile_", 0) == 0)
      EXPECT_GE(both.materials.at(m.material).normal_texture, 0) << m.name;
}

TEST(BuiltinSceneOptions, BadOptionsThrowInputErrorNamingTheKeyAndAllowedValues) {
  struct Case {
    const char* scene;
    std::vector<std::string> words;  // each must appear in the message
  };
  const Case cases[] = {
      {"gallery:reflectors=0", {"reflectors", "1..16", "'0'"}},
      {"gallery:reflectors=17", {"reflectors", "1..16", "'17'"}},
      {"gallery:reflectors=abc", {"reflectors", "1..16", "'abc'"}},
      {"gallery:reflectors=-2", {"reflectors", "1..16"}},
      {"gallery:reflectors=2x", {"reflectors", "1..16"}},
      {"gallery:reflectors= 2", {"reflectors", "1..16"}},
      {"gallery:reflectors=", {"reflectors", "1..16"}},
      {"gallery:normal_map=waves", {"normal_map", "ripples|tiles|none", "'waves'"}},
      {"gallery:normal_map=Ripples", {"normal_map", "ripples|tiles|none"}},
      {"gallery:foo=1", {"'foo'", "reflectors=1..16", "normal_map=ripples|tiles|none"}},
      // Every scene takes path=NAME (its camera paths); other keys are the gallery's.
      {"cornell:reflectors=2", {"'cornell'", "no option 'reflectors'", "path=dolly"}},
      {"corridor:normal_map=tiles", {"'corridor'", "no option 'normal_map'", "path=dolly|pan"}},
      {"corridor:path=nope", {"'path'", "'corridor'", "dolly|pan", "'nope'"}},
      {"gallery:path=", {"'path'", "dolly|orbit|pan|slide|enter|cut"}},
      {"gallery:", {"gallery", "reflectors=1..16", "normal_map"}},
      {"gallery:reflectors", {"'reflectors'", "1..16", "no value"}},
      {"gallery:reflectors=2,", {"empty", "reflectors=1..16"}},
      {"gallery:reflectors=2,reflectors=3", {"'reflectors'", "twice"}},
      {"gallery:=2", {"reflectors=1..16"}},
      {"nope:reflectors=2", {"'nope'", "gallery", "cornell"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.scene);
    try {
      ssr::make_builtin_scene(c.scene);
      ADD_FAILURE() << "no exception";
    } catch (const ssr::InputError& e) {
      const std::string msg = e.what();
      for (const std::string& w : c.words) EXPECT_NE(msg.find(w), std::string::npos) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  }
}

TEST(BuiltinSceneOptions, LoadSceneRoutesOptionsToTheBuiltinScenes) {
  const Scene s = ssr::load_scene("gallery:reflectors=3,normal_map=ripples");
  EXPECT_EQ(s.reflectors.size(), 3u);
  EXPECT_EQ(s.name, "gallery:reflectors=3,normal_map=ripples");
  EXPECT_THROW(ssr::load_scene("gallery:reflectors=17"), ssr::InputError);
  EXPECT_THROW(ssr::load_scene("cornell:reflectors=2"), ssr::InputError);
  EXPECT_THROW(ssr::load_scene("gallery:"), ssr::InputError);
  // builtin_scenes() still lists plain names; the gallery's description names its options.
  for (const auto& info : ssr::builtin_scenes()) EXPECT_EQ(info.name.find(':'), std::string::npos);
  const std::string& desc = ssr::builtin_scenes().front().description;
  EXPECT_NE(desc.find("reflectors="), std::string::npos) << desc;
  EXPECT_NE(desc.find("normal_map="), std::string::npos) << desc;
}

// The hard cases (issue 7): each validates and keeps the promise its description makes.
TEST(BuiltinHardScenes, EveryHardSceneValidatesAndKeepsItsPromise) {
  int n = 0;
  for (const auto& info : ssr::builtin_scenes()) {
    if (info.name.rfind("hard-", 0) != 0) continue;
    ++n;
    SCOPED_TRACE(info.name);
    const Scene s = ssr::make_builtin_scene(info.name);
    EXPECT_NO_THROW(ssr::validate(s));
    EXPECT_EQ(s.cameras.at(0).name, "default");
    check_reflector_meshes(s);
  }
  EXPECT_EQ(n, 8);

  {
    const Scene s = ssr::make_builtin_scene("hard-grazing");
    EXPECT_NEAR(s.cameras[0].position.y, 0.05f, 1e-6f);
    EXPECT_NEAR(s.cameras[0].target.y, 0.05f, 1e-6f);  // looking along the floor
    ASSERT_NE(find_mesh(s, "floor"), nullptr);
    EXPECT_GE(s.reflectors.at(0).half_extents.x, 100.0f);
  }
  {
    // The camera is inside a box closed on all six sides by mirror reflectors.
    const Scene s = ssr::make_builtin_scene("hard-mirror-box");
    EXPECT_EQ(s.reflectors.size(), 6u);
    const glm::vec3 eye = s.cameras[0].position;
    for (const ssr::Reflector& r : s.reflectors) EXPECT_GT(glm::dot(eye - r.center, r.normal()), 0.0f);
    for (const glm::vec3 dir : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                                glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)})
      EXPECT_TRUE(segment_blocked(s, eye, eye + 10.0f * dir, {})) << dir.x << dir.y << dir.z;
  }
  {
    const Scene s = ssr::make_builtin_scene("hard-thin");
    glm::vec3 lo, hi;
    ASSERT_NE(find_mesh(s, "pole"), nullptr);
    bounds(*find_mesh(s, "pole"), lo, hi);
    EXPECT_NEAR(hi.x - lo.x, 0.02f, 1e-4f);
    ASSERT_NE(find_mesh(s, "fin_0"), nullptr);
    bounds(*find_mesh(s, "fin_0"), lo, hi);
    EXPECT_NEAR(hi.z - lo.z, 0.01f, 1e-4f);
  }
  {
    const Scene s = ssr::make_builtin_scene("hard-depth-range");
    EXPECT_FLOAT_EQ(s.cameras[0].near_plane, 0.001f);
    EXPECT_FLOAT_EQ(s.cameras[0].far_plane, 1.0e5f);
    // Something 1 cm from the eye and something 5e4 m away, both in the default view.
    float nearest = 1e30f, farthest = 0.0f;
    for (const Mesh& m : s.meshes) {
      if (m.name == "floor") continue;
      glm::vec3 lo, hi;
      bounds(m, lo, hi);
      const glm::vec3 c = 0.5f * (lo + hi);
      const auto ndc = to_ndc(s.cameras[0], c);
      ASSERT_TRUE(ndc.has_value()) << m.name;
      EXPECT_LT(std::abs(ndc->x), 1.0f) << m.name;
      EXPECT_LT(std::abs(ndc->y), 1.0f) << m.name;
      const float d = glm::distance(c, s.cameras[0].position);
      nearest = std::min(nearest, d);
      farthest = std::max(farthest, d);
    }
    EXPECT_LT(nearest, 0.02f);
    EXPECT_GT(farthest, 4.9e4f);
  }
  {
    const Scene far = ssr::make_builtin_scene("hard-far-origin");
    const Scene near = ssr::make_builtin_scene("gallery");
    ASSERT_EQ(far.meshes.size(), near.meshes.size());
    EXPECT_GE(glm::length(far.cameras[0].position), 1.0e4f);
    const glm::vec3 off = far.cameras[0].position - near.cameras[0].position;
    EXPECT_GE(glm::length(off), 1.0e4f);
    EXPECT_NEAR(glm::length(far.reflectors[0].center - near.reflectors[0].center - off), 0.0f, 1e-2f);
  }
  {
    // Unit normals that disagree with their faces; a zero-area triangle.
    const Scene s = ssr::make_builtin_scene("hard-degenerate");
    for (const char* name : {"normals_in_face", "normals_flipped", "normals_cancel", "zero_area"}) {
      const Mesh* m = find_mesh(s, name);
      ASSERT_NE(m, nullptr) << name;
      const glm::vec3 face = glm::cross(m->vertices[m->indices[1]].position - m->vertices[m->indices[0]].position,
                                        m->vertices[m->indices[2]].position - m->vertices[m->indices[0]].position);
      if (std::string(name) == "zero_area") {
        EXPECT_EQ(glm::length(face), 0.0f);
        continue;
      }
      bool disagrees = false;
      for (const ssr::Vertex& v : m->vertices)
        disagrees |= glm::dot(v.normal, glm::normalize(face)) < 0.5f;
      EXPECT_TRUE(disagrees) << name;
    }
  }
  {
    const Scene s = ssr::make_builtin_scene("hard-roughness");
    std::set<float> r;
    for (const Mesh& m : s.meshes)
      if (m.reflector > 0) {
        r.insert(s.materials[m.material].roughness);
        EXPECT_EQ(s.materials[m.material].metallic, 1.0f);
      }
    EXPECT_EQ(r, (std::set<float>{0.0f, 1.0f}));
  }
  {
    // Two reflectors contain the default eye (edge-on) and one is behind it.
    const Scene s = ssr::make_builtin_scene("hard-reflectors");
    const ssr::Camera& c = s.cameras[0];
    const glm::vec3 fwd = glm::normalize(c.target - c.position);
    int edge_on = 0, behind = 0;
    for (const ssr::Reflector& r : s.reflectors) {
      edge_on += std::abs(glm::dot(c.position - r.center, r.normal())) < 1e-5f;
      behind += glm::dot(r.center - c.position, fwd) < 0.0f;
    }
    EXPECT_EQ(edge_on, 2);
    EXPECT_EQ(behind, 1);
  }
}

// ---- the roughness ramp (issue 14) ----------------------------------------------------------------

namespace {

// The band names, left to right, as the header comment and assets/scenes/README.md document them.
const std::vector<std::string> kRampBands = {"band_0.0", "band_0.1", "band_0.2", "band_0.3",
                                             "band_0.4", "band_0.5", "band_0.6", "band_0.7",
                                             "band_0.8", "band_0.9", "band_1.0"};
const float kRampRoughness[] = {0.0f, 0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f, 1.0f};

// The first triangle the ray origin + t dir (0 < t < t_max) hits: its mesh index, or -1.
int closest_hit(const Scene& s, glm::vec3 origin, glm::vec3 dir, float t_max, float& t_hit) {
  int best = -1;
  t_hit = t_max;
  for (std::size_t k = 0; k < s.meshes.size(); ++k) {
    const Mesh& m = s.meshes[k];
    for (std::size_t i = 0; i < m.indices.size(); i += 3) {
      const glm::vec3 p0 = m.vertices[m.indices[i]].position;
      const glm::vec3 e1 = m.vertices[m.indices[i + 1]].position - p0;
      const glm::vec3 e2 = m.vertices[m.indices[i + 2]].position - p0;
      const glm::vec3 pv = glm::cross(dir, e2);
      const float det = glm::dot(e1, pv);
      if (std::abs(det) < 1e-12f) continue;
      const glm::vec3 tv = origin - p0;
      const float u = glm::dot(tv, pv) / det;
      if (u < 0.0f || u > 1.0f) continue;
      const glm::vec3 qv = glm::cross(tv, e1);
      const float v = glm::dot(dir, qv) / det;
      if (v < 0.0f || u + v > 1.0f) continue;
      const float t = glm::dot(e2, qv) / det;
      if (t > 1e-4f && t < t_hit) {
        t_hit = t;
        best = static_cast<int>(k);
      }
    }
  }
  return best;
}

// What the default camera sees of each band on a `w` x `h` grid of pixel centres at 16:9:
// pixels whose first hit is the band, and of those, pixels whose mirror ray (the view ray
// reflected about +Y) first hits something that is itself in the frame and seen by the camera
// there (a reflection a screen-space method can find), and the meshes those rays hit.
struct BandView {
  int pixels = 0, traceable = 0;
  std::set<std::string> reflected;
};
std::vector<BandView> ramp_band_views(const Scene& s, int w, int h) {
  const ssr::Camera& cam = s.cameras[0];
  const glm::mat4 inv = glm::inverse(
      glm::perspective(glm::radians(cam.fov_y_deg), 16.0f / 9.0f, cam.near_plane, cam.far_plane) *
      glm::lookAt(cam.position, cam.target, cam.up));
  std::vector<BandView> views(kRampBands.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec2 ndc(-1.0f + 2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(w),
                          -1.0f + 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
      const glm::vec4 far_h = inv * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 dir = glm::normalize(glm::vec3(far_h) / far_h.w - cam.position);
      float t = 0.0f;
      const int m = closest_hit(s, cam.position, dir, 1000.0f, t);
      if (m < 0) continue;
      const auto band = std::find(kRampBands.begin(), kRampBands.end(), s.meshes[static_cast<std::size_t>(m)].name);
      if (band == kRampBands.end()) continue;
      BandView& v = views[static_cast<std::size_t>(band - kRampBands.begin())];
      ++v.pixels;
      const glm::vec3 p = cam.position + t * dir;
      const glm::vec3 r(dir.x, -dir.y, dir.z);
      float tr = 0.0f;
      const int hit = closest_hit(s, p, r, 1000.0f, tr);
      if (hit < 0) continue;  // the sky
      const glm::vec3 q = p + tr * r;
      const auto q_ndc = to_ndc(cam, q);
      if (!q_ndc || std::abs(q_ndc->x) >= 1.0f || std::abs(q_ndc->y) >= 1.0f) continue;  // off screen
      float tq = 0.0f;
      const glm::vec3 to_q = q - cam.position;
      if (closest_hit(s, cam.position, glm::normalize(to_q), 1000.0f, tq) != hit ||
          std::abs(tq - glm::length(to_q)) > 0.02f)
        continue;  // hidden from the camera
      ++v.traceable;
      v.reflected.insert(s.meshes[static_cast<std::size_t>(hit)].name);
    }
  return views;
}

}  // namespace

TEST(BuiltinRamp, ElevenBandsOfRoughnessZeroToOneLeftToRightWithReflectorIds1To11) {
  const Scene s = ssr::make_builtin_scene("ramp");
  EXPECT_NO_THROW(ssr::validate(s));
  ASSERT_EQ(s.reflectors.size(), 11u);
  check_reflector_meshes(s);
  float prev_hi_x = -1e30f;
  for (std::size_t k = 0; k < kRampBands.size(); ++k) {
    SCOPED_TRACE(kRampBands[k]);
    const Mesh* band = find_mesh(s, kRampBands[k]);
    ASSERT_NE(band, nullptr);
    EXPECT_EQ(band->reflector, static_cast<int>(k) + 1);  // reflector:N is band N - 1
    const ssr::Material& m = s.materials.at(static_cast<std::size_t>(band->material));
    EXPECT_EQ(m.roughness, kRampRoughness[k]);  // exactly, as the literal
    EXPECT_EQ(m.metallic, 1.0f);
    EXPECT_GE(std::min({m.albedo.x, m.albedo.y, m.albedo.z}), 0.8f);  // light grey metal
    EXPECT_LT(glm::length(m.emission), 1e-6f);
    EXPECT_EQ(m.normal_texture, -1);
    // Flat at y = 0, facing up; the reflector rectangle is exactly the band.
    const ssr::Reflector& r = s.reflectors[k];
    EXPECT_NEAR(glm::dot(r.normal(), glm::vec3(0, 1, 0)), 1.0f, 1e-6f);
    EXPECT_NEAR(r.center.y, 0.0f, 1e-6f);
    glm::vec3 lo, hi;
    bounds(*band, lo, hi);
    EXPECT_NEAR(lo.y, 0.0f, 1e-6f);
    EXPECT_NEAR(hi.y, 0.0f, 1e-6f);
    EXPECT_NEAR(hi.x - lo.x, 2.0f * r.half_extents.x, 1e-4f);
    EXPECT_NEAR(hi.z - lo.z, 2.0f * r.half_extents.y, 1e-4f);
    // Side by side along x, left to right in roughness order, touching, running along the view
    // (much longer in z than wide).
    if (k > 0) EXPECT_NEAR(lo.x, prev_hi_x, 1e-4f);
    prev_hi_x = hi.x;
    EXPECT_GT(hi.z - lo.z, 10.0f * (hi.x - lo.x));
  }
  // The bands are the only reflective surfaces: every other mesh is non-metallic, not a
  // reflector, F0 = 0.16 r^2 well below the G-buffer's 0.1 threshold.
  for (const Mesh& m : s.meshes) {
    if (std::find(kRampBands.begin(), kRampBands.end(), m.name) != kRampBands.end()) continue;
    SCOPED_TRACE(m.name);
    EXPECT_EQ(m.reflector, 0);
    const ssr::Material& mat = s.materials.at(static_cast<std::size_t>(m.material));
    EXPECT_EQ(mat.metallic, 0.0f);
    EXPECT_LT(0.16f * mat.reflectance * mat.reflectance, 0.05f);
    EXPECT_FALSE(mat.transparent);
  }
}

TEST(BuiltinRamp, RoughnessGrowsWithTheBandsXAndTheirReflectorIds) {
  // Sorting the bands by their x (left to right on screen) or by reflector id gives roughness
  // 0.0, 0.1, ..., 1.0 in that order: a swapped pair anywhere fails here.
  const Scene s = ssr::make_builtin_scene("ramp");
  std::vector<std::pair<float, float>> by_x;   // (centre x, roughness)
  std::vector<std::pair<int, float>> by_id;    // (reflector id, roughness)
  std::vector<std::pair<std::string, float>> by_name;
  for (const Mesh& m : s.meshes) {
    if (m.reflector == 0) continue;
    glm::vec3 lo, hi;
    bounds(m, lo, hi);
    const float r = s.materials.at(static_cast<std::size_t>(m.material)).roughness;
    by_x.emplace_back(0.5f * (lo.x + hi.x), r);
    by_id.emplace_back(m.reflector, r);
    by_name.emplace_back(m.name, r);
  }
  ASSERT_EQ(by_x.size(), 11u);
  std::sort(by_x.begin(), by_x.end());
  std::sort(by_id.begin(), by_id.end());
  for (std::size_t k = 0; k < 11; ++k) {
    EXPECT_EQ(by_x[k].second, kRampRoughness[k]) << "band " << k << " from the left";
    EXPECT_EQ(by_id[k].first, static_cast<int>(k) + 1);
    EXPECT_EQ(by_id[k].second, kRampRoughness[k]) << "reflector " << k + 1;
  }
  // The name says the roughness: "band_0.3" has roughness 0.3.
  for (const auto& [name, r] : by_name) EXPECT_EQ(std::stof(name.substr(5)), r) << name;
  // The material names say it too, and every band has its own material.
  std::set<int> materials;
  for (const Mesh& m : s.meshes)
    if (m.reflector) EXPECT_TRUE(materials.insert(m.material).second) << m.name;
}

TEST(BuiltinRamp, EveryBandCoversAShareOfTheDefaultViewAndReflectsSomething) {
  const Scene s = ssr::make_builtin_scene("ramp");
  constexpr int w = 192, h = 108;
  const std::vector<BandView> views = ramp_band_views(s, w, h);
  int total = 0;
  for (std::size_t k = 0; k < views.size(); ++k) {
    const BandView& v = views[k];
    total += v.pixels;
    const double share = 100.0 * v.pixels / (w * h);
    const double traceable = v.pixels ? 100.0 * v.traceable / v.pixels : 0.0;
    std::string what;
    for (const std::string& n : v.reflected) what += (what.empty() ? "" : " ") + n;
    std::printf("%s: %.1f%% of the frame, %.0f%% of it reflects something on screen: %s\n",
                kRampBands[k].c_str(), share, traceable, what.c_str());
    SCOPED_TRACE(kRampBands[k]);
    EXPECT_GT(share, 1.5);
    EXPECT_GT(traceable, 40.0);
    // The wall and at least two objects standing on the floor are reflected in every band.
    EXPECT_TRUE(v.reflected.count("back_wall"));
    EXPECT_GE(v.reflected.size(), 3u);
  }
  EXPECT_GT(100.0 * total / (w * h), 35.0);  // the bands fill over a third of the frame
  // The glowing strip on the wall is reflected in every band (the same bright line, blurred
  // more and more from left to right).
  for (std::size_t k = 0; k < views.size(); ++k)
    EXPECT_TRUE(views[k].reflected.count("light_strip")) << kRampBands[k];
}

TEST(BuiltinRamp, PathsAndOptions) {
  const Scene s = ssr::make_builtin_scene("ramp");
  std::set<std::string> names;
  for (const ssr::CameraPath& p : s.animation.paths) names.insert(p.name);
  EXPECT_EQ(names, (std::set<std::string>{"dolly", "orbit", "pan"}));
  EXPECT_EQ(s.animation.default_path, -1);
  EXPECT_TRUE(s.animation.objects.empty());  // a still scene: only the camera moves
  const Scene dolly = ssr::make_builtin_scene("ramp:path=dolly");
  ASSERT_GE(dolly.animation.default_path, 0);
  EXPECT_EQ(dolly.animation.paths[static_cast<std::size_t>(dolly.animation.default_path)].name, "dolly");
  // At time 0 every path is at the default camera; the dolly ends closer to its target.
  const ssr::Camera& cam = s.cameras[0];
  for (const ssr::CameraPath& p : s.animation.paths) {
    const ssr::Camera c0 = ssr::camera_at(p, 0.0f, cam);
    EXPECT_EQ(c0.position, cam.position) << p.name;
    EXPECT_EQ(c0.target, cam.target) << p.name;
  }
  const ssr::Camera end = ssr::camera_at(ssr::find_path(s, "dolly"), 4.0f, cam);
  EXPECT_NEAR(glm::distance(end.position, cam.position), 4.0f, 0.1f);
  // The ramp takes no option but path=.
  EXPECT_THROW(ssr::make_builtin_scene("ramp:floor_roughness=0.5"), ssr::InputError);
  EXPECT_THROW(ssr::make_builtin_scene("ramp:reflectors=2"), ssr::InputError);
  EXPECT_NO_THROW(ssr::load_scene("ramp"));
}

// ---- gallery:floor_roughness=R (the PPR thesis's charts 5 and 6: roughness 0.2, 0.5, 1.0) ----------

TEST(BuiltinSceneOptions, GalleryFloorRoughnessSetsTheMirrorFloorsRoughness) {
  struct Case {
    const char* value;
    float roughness;
  };
  for (const Case c : {Case{"0", 0.0f}, Case{"0.2", 0.2f}, Case{"0.5", 0.5f}, Case{"1", 1.0f},
                       Case{"1.0", 1.0f}, Case{"0.25", 0.25f}, Case{".5", 0.5f}, Case{"-0", 0.0f},
                       Case{"5e-1", 0.5f}}) {
    const std::string name = std::string("gallery:floor_roughness=") + c.value;
    SCOPED_TRACE(name);
    const Scene s = ssr::make_builtin_scene(name);
    EXPECT_EQ(s.name, name);
    const Mesh* floor = find_mesh(s, "floor");
    ASSERT_NE(floor, nullptr);
    EXPECT_EQ(floor->reflector, 1);
    const ssr::Material& m = s.materials.at(static_cast<std::size_t>(floor->material));
    EXPECT_EQ(m.roughness, c.roughness);
    EXPECT_FALSE(std::signbit(m.roughness));
    EXPECT_EQ(m.metallic, 1.0f);
  }
  // The default is today's mirror; other materials are untouched.
  const Scene plain = ssr::make_builtin_scene("gallery");
  const Scene rough = ssr::make_builtin_scene("gallery:floor_roughness=0.5");
  EXPECT_EQ(plain.materials.at(static_cast<std::size_t>(find_mesh(plain, "floor")->material)).roughness, 0.0f);
  ASSERT_EQ(plain.materials.size(), rough.materials.size());
  for (std::size_t i = 0; i < plain.materials.size(); ++i)
    if (plain.materials[i].name != "mirror_floor")
      EXPECT_EQ(plain.materials[i].roughness, rough.materials[i].roughness) << plain.materials[i].name;
  // With tiles and wall mirrors: every floor tile gets it, the wall mirrors stay mirrors; it
  // combines with the normal map.
  const Scene tiles = ssr::make_builtin_scene("gallery:reflectors=5,floor_roughness=1,normal_map=tiles");
  int n_tiles = 0;
  for (const Mesh& m : tiles.meshes) {
    const ssr::Material& mat = tiles.materials.at(static_cast<std::size_t>(m.material));
    if (m.name.rfind("floor_tile_", 0) == 0) {
      ++n_tiles;
      EXPECT_EQ(mat.roughness, 1.0f) << m.name;
      EXPECT_GE(mat.normal_texture, 0) << m.name;
    } else if (m.name.rfind("mirror_", 0) == 0 && m.reflector) {
      EXPECT_EQ(mat.roughness, 0.0f) << m.name;
    }
  }
  EXPECT_EQ(n_tiles, 3);
  // hard-far-origin (the gallery moved) keeps the mirror floor.
  const Scene far = ssr::make_builtin_scene("hard-far-origin");
  EXPECT_EQ(far.materials.at(static_cast<std::size_t>(find_mesh(far, "floor")->material)).roughness, 0.0f);
}

TEST(BuiltinSceneOptions, GalleryFloorRoughnessRejectsWhatIsNotANumberInZeroToOne) {
  for (const char* bad : {"1.5", "-0.1", "2", "abc", "", "0.5x", " 0.5", "0.5 ", "+0.5", "nan",
                          "inf", "-inf", "1e3", "0,5", "0x1p-1", "1.0000001"}) {
    const std::string name = std::string("gallery:floor_roughness=") + bad;
    SCOPED_TRACE(name);
    try {
      ssr::make_builtin_scene(name);
      ADD_FAILURE() << "no exception";
    } catch (const ssr::InputError& e) {
      const std::string msg = e.what();
      // "0,5" is split at the comma: "5" is then an option without a key.
      if (std::string(bad) == "0,5") continue;
      for (const std::string w : {std::string("'floor_roughness'"), std::string("a number in [0, 1]"),
                                  "'" + std::string(bad) + "'"})
        EXPECT_NE(msg.find(w), std::string::npos) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  }
  EXPECT_THROW(ssr::load_scene("gallery:floor_roughness=1.5"), ssr::InputError);
  EXPECT_THROW(ssr::make_builtin_scene("gallery:floor_roughness=0.2,floor_roughness=0.5"), ssr::InputError);
  // The help lists it, with its range.
  const std::string msg = ssr::test::input_error([] { ssr::make_builtin_scene("gallery:foo=1"); });
  EXPECT_NE(msg.find("floor_roughness=0.0..1.0"), std::string::npos) << msg;
  EXPECT_NE(ssr::builtin_scenes().front().description.find("floor_roughness="), std::string::npos);
}
