// Scene animation (scene/animation.h): camera paths, object motions, posing, validation, the
// JSON "animation" key and the built-in scenes' paths.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "input_error.h"
#include "core/errors.h"
#include "scene/animation.h"
#include "scene/builtin_scenes.h"
#include "scene/scene.h"
#include "scene/scene_io.h"

namespace {

using ssr::Camera;
using ssr::CameraKey;
using ssr::CameraPath;
using ssr::InputError;
using ssr::ObjectMotion;
using ssr::Scene;

const std::string kPedestal = std::string(SSRLAB_TEST_DATA) + "/../../assets/scenes/pedestal.json";

using ssr::test::expect_message;
using ssr::test::input_error;

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

float max_abs_diff(const glm::mat4& a, const glm::mat4& b) {
  float d = 0.0f;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  return d;
}

// The upper 3x3 is a rotation: orthonormal columns, determinant +1.
void expect_rotation(const glm::mat4& m) {
  const glm::mat3 r(m);
  const glm::mat3 rtr = glm::transpose(r) * r;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(rtr[c][k], c == k ? 1.0f : 0.0f, 1e-5f);
  EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-5f);
}

bool same_bits(const ssr::Mesh& a, const ssr::Mesh& b) {
  return a.vertices.size() == b.vertices.size() && a.indices == b.indices &&
         std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(ssr::Vertex)) == 0;
}

glm::vec3 centre(const ssr::Mesh& m) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const ssr::Vertex& v : m.vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  return 0.5f * (lo + hi);
}

int mesh_index(const Scene& s, const std::string& name) {
  for (std::size_t i = 0; i < s.meshes.size(); ++i)
    if (s.meshes[i].name == name) return static_cast<int>(i);
  ADD_FAILURE() << "no mesh " << name;
  return 0;
}

// World -> NDC at 16:9 (lookAt + perspective, as the renderer); nothing behind the camera.
std::optional<glm::vec3> to_ndc(const Camera& c, glm::vec3 p) {
  const glm::mat4 vp = glm::perspective(glm::radians(c.fov_y_deg), 16.0f / 9.0f, c.near_plane,
                                        c.far_plane) *
                       glm::lookAt(c.position, c.target, c.up);
  const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
  if (clip.w <= 1e-6f) return std::nullopt;
  return glm::vec3(clip) / clip.w;
}

// A path with a cut at t = 3: keys 0, 1, 2.5 | cut 3, 4.
CameraPath test_path() {
  CameraPath p;
  p.name = "test";
  p.keys = {CameraKey{0.0f, {0, 1, 5}, {0, 1, 0}, 60.0f, false},
            CameraKey{1.0f, {2, 1.5f, 4}, {0, 0.5f, 0}, 50.0f, false},
            CameraKey{2.5f, {3, 1, 1}, {0, 1, -1}, 70.0f, false},
            CameraKey{3.0f, {-6, 3, 0}, {0, 0, 0}, 40.0f, true},
            CameraKey{4.0f, {-5, 2, 1}, {0, 0, 1}, 45.0f, false}};
  return p;
}

Camera base_camera() {
  Camera c;
  c.name = "base";
  c.up = {0, 1, 0};
  c.near_plane = 0.1f;
  c.far_plane = 50.0f;
  return c;
}

// A scene of three small triangles: "still", "spun" (spinning about +Y through (1, 0, 0)) and
// "orbiting" (about +Y through the origin), and a reflector quad "mirror".
Scene motion_scene() {
  Scene s;
  s.name = "motion";
  s.materials.push_back(ssr::Material{});
  auto tri = [&](const std::string& name, glm::vec3 o) {
    ssr::Mesh m;
    m.name = name;
    const glm::vec3 n = glm::normalize(glm::vec3(0.2f, 0.3f, 1.0f));
    const glm::vec4 t(glm::normalize(glm::cross(glm::vec3(0, 1, 0), n)), -1.0f);
    m.vertices = {{o, n, {0, 0}, t}, {o + glm::vec3(0.5f, 0, 0), n, {1, 0}, t},
                  {o + glm::vec3(0, 0.5f, 0), n, {0, 1}, t}};
    m.indices = {0, 1, 2};
    s.meshes.push_back(m);
  };
  tri("still", {-2, 0, 0});
  tri("spun", {1, 0.5f, 0.3f});
  tri("orbiting", {3, 1, 0});
  tri("mirror", {0, 0, -2});
  s.reflectors.push_back(ssr::Reflector{});
  s.meshes[3].reflector = 1;
  s.cameras.push_back(base_camera());
  ObjectMotion spin;
  spin.kind = ObjectMotion::Kind::Spin;
  spin.meshes = {1};
  spin.pivot = {1, 0, 0};
  spin.period = 2.0f;
  ObjectMotion orbit;
  orbit.kind = ObjectMotion::Kind::Orbit;
  orbit.meshes = {2};
  orbit.period = -3.0f;  // clockwise seen from above
  s.animation.objects = {spin, orbit};
  s.animation.duration = 6.0f;
  return s;
}

// ---- camera paths ----------------------------------------------------------------------------

TEST(CameraPath, HitsEveryKeyExactlyAtItsTime) {
  const CameraPath p = test_path();
  const Camera base = base_camera();
  for (const CameraKey& k : p.keys) {
    SCOPED_TRACE(k.time);
    const Camera c = ssr::camera_at(p, k.time, base);
    EXPECT_EQ(c.position, k.position);
    EXPECT_EQ(c.target, k.target);
    EXPECT_EQ(c.fov_y_deg, k.fov_y_deg);
    EXPECT_EQ(c.up, base.up);
    EXPECT_EQ(c.near_plane, base.near_plane);
    EXPECT_EQ(c.far_plane, base.far_plane);
    EXPECT_EQ(c.name, base.name);
  }
  // Clamped at the ends.
  EXPECT_EQ(ssr::camera_at(p, -5.0f, base).position, p.keys.front().position);
  EXPECT_EQ(ssr::camera_at(p, 99.0f, base).position, p.keys.back().position);
  // A one-key path is that key at every time.
  CameraPath one;
  one.keys = {p.keys[1]};
  EXPECT_EQ(ssr::camera_at(one, 0.0f, base).target, p.keys[1].target);
  EXPECT_EQ(ssr::camera_at(one, 7.0f, base).fov_y_deg, p.keys[1].fov_y_deg);
}

TEST(CameraPath, ContinuousExceptAcrossACut) {
  const CameraPath p = test_path();
  const Camera base = base_camera();
  constexpr float dt = 1e-3f;
  int jumps = 0;
  for (float t = -0.5f; t < 4.5f; t += dt) {
    const Camera a = ssr::camera_at(p, t, base), b = ssr::camera_at(p, t + dt, base);
    const float moved = glm::distance(a.position, b.position) + glm::distance(a.target, b.target);
    if (ssr::cut_between(p, t, t + dt)) {
      EXPECT_GT(moved, 1.0f) << t;
      ++jumps;
    } else {
      EXPECT_LT(moved, 0.05f) << t;  // a few m/s at most
      EXPECT_LT(std::abs(a.fov_y_deg - b.fov_y_deg), 0.1f) << t;
    }
    EXPECT_TRUE(std::isfinite(a.position.x + a.position.y + a.position.z + a.fov_y_deg));
  }
  EXPECT_EQ(jumps, 1);
  // Before the cut the camera holds the previous key; from the cut key's time on it is there.
  EXPECT_EQ(ssr::camera_at(p, 2.99f, base).position, p.keys[2].position);
  EXPECT_EQ(ssr::camera_at(p, 3.0f, base).position, p.keys[3].position);
  // Between keys of a run it moves on a curve through them, and fov stays between the keys'.
  const Camera mid = ssr::camera_at(p, 0.5f, base);
  EXPECT_NE(mid.position, p.keys[0].position);
  EXPECT_NE(mid.position, p.keys[1].position);
  EXPECT_GT(mid.fov_y_deg, 50.0f);
  EXPECT_LT(mid.fov_y_deg, 60.0f);
}

// Two valid keys on either side of the target, both looking down at it: half-way the spline looks
// straight down the up vector, where a look-at view has no roll. The camera must still form a
// view there (an up vector across its direction, pointing where the keys head), and keep the
// scene's up wherever the view is not along it.
TEST(CameraPath, PassingOverTheTargetStillFormsAView) {
  CameraPath p;
  p.keys = {{0.0f, {0, 2, 1}, {0, 0, 0}, 60.0f, false}, {1.0f, {0, 2, -1}, {0, 0, 0}, 60.0f, false}};
  const Camera base = base_camera();
  int along = 0;
  for (int i = 0; i <= 100; ++i) {
    const float t = static_cast<float>(i) / 100.0f;
    SCOPED_TRACE(t);
    const Camera c = ssr::camera_at(p, t, base);
    const glm::vec3 d = c.target - c.position;
    const bool down = ssr::up_along_view(d, base.up);
    along += down;
    EXPECT_FALSE(ssr::up_along_view(d, c.up));  // what scene validation asks of a camera
    if (!down) EXPECT_EQ(c.up, base.up);
  }
  EXPECT_EQ(along, 1);  // t = 0.5, exactly above the target
  const Camera mid = ssr::camera_at(p, 0.5f, base);
  EXPECT_GT(glm::dot(mid.up, glm::vec3(0, 0, -1)), 0.99f * glm::length(mid.up));  // key a heads to -z
}

TEST(CameraPath, CutBetweenIsHalfOpen) {
  const CameraPath p = test_path();
  EXPECT_TRUE(ssr::cut_between(p, 2.9f, 3.0f));
  EXPECT_TRUE(ssr::cut_between(p, 0.0f, 4.0f));
  EXPECT_FALSE(ssr::cut_between(p, 3.0f, 3.1f));  // the cut is at t0: already done
  EXPECT_FALSE(ssr::cut_between(p, 0.0f, 2.99f));
  EXPECT_FALSE(ssr::cut_between(p, 3.5f, 2.0f));  // backwards: empty
  EXPECT_FALSE(ssr::cut_between(CameraPath{}, 0.0f, 10.0f));
}

TEST(CameraPath, FindPathListsTheNames) {
  Scene s = motion_scene();
  expect_message(input_error([&] { ssr::find_path(s, "dolly"); }), {"'motion'", "no camera paths"});
  s.animation.paths = {test_path(), test_path()};
  s.animation.paths[1].name = "other";
  EXPECT_EQ(&ssr::find_path(s, "other"), &s.animation.paths[1]);
  expect_message(input_error([&] { ssr::find_path(s, "dolly"); }),
                 {"'motion'", "'dolly'", "test, other"});
}

// ---- object motions --------------------------------------------------------------------------

TEST(ObjectMotion, SpinIsARotationAboutThePivotAndReturnsAfterAPeriod) {
  const Scene s = motion_scene();
  EXPECT_EQ(ssr::mesh_transform(s, 1, 0.0f), glm::mat4(1.0f));
  EXPECT_EQ(ssr::mesh_transform(s, 1, 2.0f), glm::mat4(1.0f));  // one period: exactly
  EXPECT_EQ(ssr::mesh_transform(s, 1, -4.0f), glm::mat4(1.0f));
  EXPECT_LT(max_abs_diff(ssr::mesh_transform(s, 1, 2.0001f), glm::mat4(1.0f)), 1e-3f);
  for (float t : {0.1f, 0.5f, 1.0f, 1.7f, 123.4f}) {
    SCOPED_TRACE(t);
    const glm::mat4 m = ssr::mesh_transform(s, 1, t);
    expect_rotation(m);
    const glm::vec3 pivot = glm::vec3(m * glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(glm::distance(pivot, glm::vec3(1, 0, 0)), 0.0f, 1e-5f);
    // About +Y: heights stay; 360 * t / period degrees.
    const glm::vec3 p = glm::vec3(m * glm::vec4(2, 0.7f, 0, 1));
    EXPECT_NEAR(p.y, 0.7f, 1e-5f);
    const float deg = glm::degrees(std::atan2(-(p.z - 0.0f), p.x - 1.0f));
    const float want = std::fmod(360.0f * t / 2.0f + 180.0f, 360.0f) - 180.0f;
    EXPECT_NEAR(std::remainder(deg - want, 360.0f), 0.0f, 0.05f);
  }
  // A quarter turn of +Y maps +X to -Z.
  const glm::vec3 q = glm::vec3(ssr::mesh_transform(s, 1, 0.5f) * glm::vec4(2, 0, 0, 1));
  EXPECT_NEAR(glm::distance(q, glm::vec3(1, 0, -1)), 0.0f, 1e-5f);
}

TEST(ObjectMotion, OrbitKeepsOrientationAndDistanceToThePivot) {
  const Scene s = motion_scene();
  const glm::vec3 c0 = centre(s.meshes[2]);
  EXPECT_EQ(ssr::mesh_transform(s, 2, 0.0f), glm::mat4(1.0f));
  EXPECT_EQ(ssr::mesh_transform(s, 2, 3.0f), glm::mat4(1.0f));
  for (float t : {0.3f, 0.75f, 1.5f, 2.9f}) {
    SCOPED_TRACE(t);
    const glm::mat4 m = ssr::mesh_transform(s, 2, t);
    EXPECT_EQ(glm::mat3(m), glm::mat3(1.0f));  // a translation only
    const glm::vec3 c = glm::vec3(m * glm::vec4(c0, 1.0f));
    EXPECT_NEAR(c.y, c0.y, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec2(c.x, c.z)), glm::length(glm::vec2(c0.x, c0.z)), 1e-5f);
  }
  // period -3: a quarter turn clockwise from above takes +X to +Z.
  const glm::vec3 c = glm::vec3(ssr::mesh_transform(s, 2, 0.75f) * glm::vec4(c0, 1.0f));
  EXPECT_NEAR(c.x, 0.0f, 1e-5f);
  EXPECT_GT(c.z, 3.0f);
}

TEST(ObjectMotion, KeyframesInterpolateAndClamp) {
  Scene s = motion_scene();
  ObjectMotion k;
  k.meshes = {0};
  k.pivot = {-2, 0, 0};
  k.keys = {ssr::TransformKey{1.0f, {}, {}, glm::vec3(1.0f)},
            ssr::TransformKey{3.0f, {2, 0, 0}, {0, 90, 0}, glm::vec3(2.0f)}};
  s.animation.objects = {k};
  EXPECT_EQ(ssr::mesh_transform(s, 0, 0.0f), glm::mat4(1.0f));  // before the first (rest) key
  EXPECT_EQ(ssr::mesh_transform(s, 0, 1.0f), glm::mat4(1.0f));
  // Halfway: translate 1, 45 degrees about +Y, scale 1.5, about the pivot.
  const glm::mat4 half = ssr::mesh_transform(s, 0, 2.0f);
  const glm::mat4 want = glm::translate(glm::mat4(1.0f), glm::vec3(-1, 0, 0)) *
                         glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 1, 0)) *
                         glm::scale(glm::mat4(1.0f), glm::vec3(1.5f)) *
                         glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0));
  EXPECT_LT(max_abs_diff(half, want), 1e-5f);
  // Clamped after the last key.
  EXPECT_EQ(ssr::mesh_transform(s, 0, 3.0f), ssr::mesh_transform(s, 0, 50.0f));
  const glm::vec3 end = glm::vec3(ssr::mesh_transform(s, 0, 9.0f) * glm::vec4(-1, 0, 0, 1));
  EXPECT_NEAR(glm::distance(end, glm::vec3(0, 0, -2)), 0.0f, 1e-5f);  // +X -> -Z, x2, +2 in x
}

TEST(ObjectMotion, MotionsComposeInListOrderAndAgreeWithMeshTransforms) {
  Scene s = motion_scene();
  s.animation.objects[1].meshes = {1, 2};  // the spun mesh orbits too
  for (float t : {0.0f, 0.4f, 1.3f, 2.0f, 5.5f}) {
    const std::vector<glm::mat4> all = ssr::mesh_transforms(s, t);
    ASSERT_EQ(all.size(), s.meshes.size());
    for (int i = 0; i < static_cast<int>(s.meshes.size()); ++i)
      EXPECT_EQ(all[static_cast<std::size_t>(i)], ssr::mesh_transform(s, i, t)) << i << " " << t;
    // Spin first, then the orbit's translation on the left.
    Scene only_spin = s, only_orbit = s;
    only_spin.animation.objects.pop_back();
    only_orbit.animation.objects.erase(only_orbit.animation.objects.begin());
    EXPECT_EQ(all[1], ssr::mesh_transform(only_orbit, 1, t) * ssr::mesh_transform(only_spin, 1, t));
  }
}

TEST(ObjectMotion, FiniteAndDeterministicForAnyTime) {
  Scene s = motion_scene();
  s.animation.paths = {test_path()};
  s.animation.objects[1].period = 1e-30f;
  for (float t : {-1e30f, -3.0f, 0.0f, 1e-40f, 7.77f, 1e9f, 3e38f, std::nanf(""),
                  std::numeric_limits<float>::infinity()}) {
    SCOPED_TRACE(t);
    for (int i = 0; i < 4; ++i) {
      EXPECT_TRUE(finite(ssr::mesh_transform(s, i, t)));
      EXPECT_EQ(ssr::mesh_transform(s, i, t), ssr::mesh_transform(s, i, t));
    }
    const Camera c = ssr::camera_at(s.animation.paths[0], t, base_camera());
    EXPECT_TRUE(std::isfinite(c.position.x + c.position.y + c.position.z + c.target.x +
                              c.target.y + c.target.z + c.fov_y_deg));
  }
}

TEST(PosedScene, StaticMeshesBitIdenticalMovedNormalsUnit) {
  const Scene s = motion_scene();
  const Scene p = ssr::posed_scene(s, 0.8f);
  ASSERT_EQ(p.meshes.size(), s.meshes.size());
  EXPECT_TRUE(same_bits(p.meshes[0], s.meshes[0]));
  EXPECT_TRUE(same_bits(p.meshes[3], s.meshes[3]));
  for (int i : {1, 2}) {
    EXPECT_FALSE(same_bits(p.meshes[static_cast<std::size_t>(i)], s.meshes[static_cast<std::size_t>(i)]));
    const glm::mat4 m = ssr::mesh_transform(s, i, 0.8f);
    for (std::size_t v = 0; v < s.meshes[static_cast<std::size_t>(i)].vertices.size(); ++v) {
      const ssr::Vertex& a = s.meshes[static_cast<std::size_t>(i)].vertices[v];
      const ssr::Vertex& b = p.meshes[static_cast<std::size_t>(i)].vertices[v];
      EXPECT_LT(glm::distance(glm::vec3(m * glm::vec4(a.position, 1.0f)), b.position), 1e-6f);
      EXPECT_NEAR(glm::length(b.normal), 1.0f, 1e-6f);
      EXPECT_NEAR(glm::length(glm::vec3(b.tangent)), 1.0f, 1e-6f);
      EXPECT_NEAR(glm::dot(b.normal, glm::mat3(m) * a.normal), 1.0f, 1e-5f);  // rigid: turned
      EXPECT_EQ(b.tangent.w, a.tangent.w);
      EXPECT_EQ(b.uv, a.uv);
    }
  }
  EXPECT_NO_THROW(ssr::validate(p));
  // At time 0 and after whole turns of both (6 s) nothing moves, bit for bit.
  for (float t : {0.0f, 6.0f}) {
    const Scene rest = ssr::posed_scene(s, t);
    for (std::size_t i = 0; i < s.meshes.size(); ++i) EXPECT_TRUE(same_bits(rest.meshes[i], s.meshes[i]));
  }
}

// ---- validate() ------------------------------------------------------------------------------

TEST(AnimationValidate, RejectsBrokenAnimations) {
  EXPECT_NO_THROW(ssr::validate(motion_scene()));
  auto expect_invalid = [](const Scene& s, const std::string& fragment) {
    expect_message(input_error([&] { ssr::validate(s); }), {"'motion'", fragment});
  };
  {
    Scene s = motion_scene();
    s.animation.objects[0].meshes = {3};
    expect_invalid(s, "'mirror', a planar reflector");
  }
  {
    Scene s = motion_scene();
    s.animation.objects[0].meshes = {4};
    expect_invalid(s, "out of range");
  }
  {
    Scene s = motion_scene();
    s.animation.objects[0].period = 0.0f;
    expect_invalid(s, "period");
  }
  {
    Scene s = motion_scene();
    s.animation.objects[1].axis = glm::vec3(0.0f);
    expect_invalid(s, "axis");
  }
  {
    Scene s = motion_scene();
    s.animation.duration = std::nanf("");
    expect_invalid(s, "duration");
  }
  {
    Scene s = motion_scene();
    s.animation.objects.resize(1);
    ObjectMotion& k = s.animation.objects[0];
    k = ObjectMotion{};
    k.meshes = {0};
    expect_invalid(s, "at least one key");
    k.keys = {ssr::TransformKey{1.0f}, ssr::TransformKey{1.0f}};
    expect_invalid(s, "strictly increase");
    k.keys = {ssr::TransformKey{1.0f, {}, {}, glm::vec3(1, 0, 1)}};
    expect_invalid(s, "scale");
  }
  {
    Scene s = motion_scene();
    s.animation.paths = {test_path()};
    EXPECT_NO_THROW(ssr::validate(s));
    s.animation.paths[0].keys[2].time = 1.0f;
    expect_invalid(s, "strictly increase");
    s = motion_scene();
    s.animation.paths = {test_path(), test_path()};
    expect_invalid(s, "'test' is defined twice");
    s.animation.paths = {test_path()};
    s.animation.paths[0].keys[1].target = s.animation.paths[0].keys[1].position;
    expect_invalid(s, "target equals its position");
    s.animation.paths = {test_path()};
    s.animation.paths[0].keys[0].cut = true;
    expect_invalid(s, "first key");
    s.animation.paths = {test_path()};
    s.animation.paths[0].keys[4].fov_y_deg = 180.0f;
    expect_invalid(s, "fov");
    s.animation.paths = {test_path()};
    s.animation.paths[0].name = "a,b";
    expect_invalid(s, "letters, digits");
    s.animation.paths = {test_path()};
    s.animation.paths[0].keys.clear();
    expect_invalid(s, "no keys");
    s.animation.paths = {test_path()};
    s.animation.default_path = 1;
    expect_invalid(s, "default path");
  }
}

// ---- built-in scenes and the pedestal file ---------------------------------------------------

TEST(BuiltinAnimation, TimeZeroIsTheStaticScene) {
  std::vector<std::string> names;
  for (const auto& info : ssr::builtin_scenes()) names.push_back(info.name);
  names.push_back(kPedestal);
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const Scene s = ssr::load_scene(name);
    EXPECT_FALSE(s.animation.empty());
    EXPECT_GE(s.animation.duration, 2.0f);
    EXPECT_LE(s.animation.duration, 6.0f);
    for (int i = 0; i < static_cast<int>(s.meshes.size()); ++i)
      EXPECT_EQ(ssr::mesh_transform(s, i, 0.0f), glm::mat4(1.0f)) << s.meshes[static_cast<std::size_t>(i)].name;
    const Scene rest = ssr::posed_scene(s, 0.0f);
    for (std::size_t i = 0; i < s.meshes.size(); ++i) EXPECT_TRUE(same_bits(rest.meshes[i], s.meshes[i]));
    // Every path starts at the default camera's position and target; fov may differ (a zoom).
    const Camera& cam = s.cameras[0];
    for (const CameraPath& p : s.animation.paths) {
      EXPECT_EQ(p.keys.front().time, 0.0f) << p.name;
      EXPECT_EQ(p.keys.front().position, cam.position) << p.name;
      EXPECT_EQ(p.keys.front().target, cam.target) << p.name;
      EXPECT_FALSE(p.description.empty()) << p.name;
      EXPECT_LE(p.keys.back().time, s.animation.duration) << p.name;
    }
    // Moving, the poses stay valid scenes (unit normals, finite) and the reflectors stay put.
    for (float t : {0.7f, 1.9f, 3.3f}) {
      const Scene posed = ssr::posed_scene(s, t);
      EXPECT_NO_THROW(ssr::validate(posed)) << t;
      for (std::size_t i = 0; i < s.meshes.size(); ++i)
        if (s.meshes[i].reflector) EXPECT_TRUE(same_bits(posed.meshes[i], s.meshes[i]));
    }
  }
}

TEST(BuiltinAnimation, EveryScenesHasPathsCoveringTheSixKinds) {
  std::set<std::string> names;
  bool cut = false;
  for (const auto& info : ssr::builtin_scenes()) {
    SCOPED_TRACE(info.name);
    const Scene s = ssr::make_builtin_scene(info.name);
    ASSERT_GE(s.animation.paths.size(), 1u);
    EXPECT_EQ(s.animation.default_path, -1);
    std::string list;
    for (const CameraPath& p : s.animation.paths) {
      names.insert(p.name);
      list += (list.empty() ? "" : "|") + p.name;
      for (const CameraKey& k : p.keys) cut |= k.cut;
      // path=NAME picks it (the option's choices are the scene's path names).
      const Scene chosen = ssr::make_builtin_scene(info.name + ":path=" + p.name);
      ASSERT_GE(chosen.animation.default_path, 0);
      EXPECT_EQ(chosen.animation.paths[static_cast<std::size_t>(chosen.animation.default_path)].name, p.name);
    }
    EXPECT_NE(info.description.find(list), std::string::npos) << info.description;
    const std::string msg = input_error([&] { ssr::make_builtin_scene(info.name + ":path=nope"); });
    for (const std::string& w : {std::string("'path'"), std::string("'nope'"), list})
      EXPECT_NE(msg.find(w), std::string::npos) << msg;
  }
  for (const char* kind : {"dolly", "orbit", "pan", "slide", "enter", "cut"})
    EXPECT_TRUE(names.count(kind)) << kind;
  EXPECT_TRUE(cut);
}

TEST(BuiltinAnimation, GalleryPathsDoWhatTheySay) {
  const Scene s = ssr::make_builtin_scene("gallery");
  auto path = [&](const char* name) { return ssr::find_path(s, name); };
  const Camera& cam = s.cameras[0];
  // slide: a mesh over the mirror floor moves more than 3 m while the camera holds.
  {
    const int green = mesh_index(s, "sphere_green");
    const ssr::Reflector& floor = s.reflectors.at(0);
    float travel = 0.0f;
    for (float t = 0.0f; t <= 4.0f; t += 0.25f) {
      EXPECT_EQ(ssr::camera_at(path("slide"), t, cam).position, cam.position);
      const glm::vec3 c = glm::vec3(ssr::mesh_transform(s, green, t) * glm::vec4(centre(s.meshes[static_cast<std::size_t>(green)]), 1.0f));
      EXPECT_LT(std::abs(c.x - floor.center.x), floor.half_extents.x);
      EXPECT_LT(std::abs(c.z - floor.center.z), floor.half_extents.y);
      travel = std::max(travel, glm::distance(c, centre(s.meshes[static_cast<std::size_t>(green)])));
    }
    EXPECT_GT(travel, 3.0f);
  }
  // enter: sphere_green is out of view at time 0 and in view later; in "slide" the teal pedestal
  // leaves the view and comes back.
  auto in_view = [&](const char* p, const char* mesh, float t) {
    const int i = mesh_index(s, mesh);
    const glm::vec3 c = glm::vec3(ssr::mesh_transform(s, i, t) * glm::vec4(centre(s.meshes[static_cast<std::size_t>(i)]), 1.0f));
    const auto ndc = ssr::camera_at(path(p), t, cam);
    const auto n = to_ndc(ndc, c);
    return n && std::abs(n->x) < 1.0f && std::abs(n->y) < 1.0f;
  };
  EXPECT_FALSE(in_view("enter", "sphere_green", 0.0f));
  EXPECT_TRUE(in_view("enter", "sphere_green", 2.0f));
  EXPECT_FALSE(in_view("enter", "sphere_green", 4.0f));
  EXPECT_TRUE(in_view("slide", "sphere_white", 0.0f));
  EXPECT_FALSE(in_view("slide", "sphere_white", 2.0f));
  EXPECT_TRUE(in_view("slide", "sphere_white", 4.0f));
  // pan: the camera stays and turns faster than 90 deg/s somewhere.
  {
    float fastest = 0.0f;
    for (float t = 0.0f; t < 2.0f; t += 0.02f) {
      const Camera a = ssr::camera_at(path("pan"), t, cam), b = ssr::camera_at(path("pan"), t + 0.02f, cam);
      EXPECT_EQ(a.position, cam.position);
      const float cosang = glm::dot(glm::normalize(a.target - a.position), glm::normalize(b.target - b.position));
      fastest = std::max(fastest, glm::degrees(std::acos(std::min(1.0f, cosang))) / 0.02f);
    }
    EXPECT_GT(fastest, 90.0f);
  }
  // orbit: the camera keeps its distance from the vertical axis and swings > 40 deg each way.
  {
    float lo = 0.0f, hi = 0.0f;
    for (float t = 0.0f; t <= 6.0f; t += 0.1f) {
      const Camera c = ssr::camera_at(path("orbit"), t, cam);
      EXPECT_NEAR(glm::length(glm::vec2(c.position.x, c.position.z)), 7.0f, 0.05f) << t;
      const float a = glm::degrees(std::atan2(c.position.x, c.position.z));
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
    EXPECT_LT(lo, -40.0f);
    EXPECT_GT(hi, 40.0f);
  }
  // dolly: the camera closes in on its target; cut: one cut, at 2 s.
  EXPECT_LT(glm::distance(ssr::camera_at(path("dolly"), 4.0f, cam).position, cam.target),
            0.6f * glm::distance(cam.position, cam.target));
  EXPECT_TRUE(ssr::cut_between(path("cut"), 1.9f, 2.0f));
  EXPECT_FALSE(ssr::cut_between(path("cut"), 2.0f, 6.0f));
}

TEST(BuiltinAnimation, PedestalFileAnimation) {
  const Scene s = ssr::load_scene(kPedestal);
  EXPECT_FLOAT_EQ(s.animation.duration, 6.0f);
  ASSERT_EQ(s.animation.paths.size(), 2u);
  EXPECT_EQ(s.animation.paths[0].name, "orbit");
  EXPECT_EQ(s.animation.paths[0].keys[1].fov_y_deg, s.cameras[0].fov_y_deg);  // the default's
  const float radius = glm::length(glm::vec2(s.cameras[0].position.x, s.cameras[0].position.z));
  for (float t = 0.0f; t <= 6.0f; t += 0.05f) {  // around the pedestal's axis
    const Camera c = ssr::camera_at(ssr::find_path(s, "orbit"), t, s.cameras[0]);
    EXPECT_NEAR(glm::length(glm::vec2(c.position.x, c.position.z)), radius, 0.03f) << t;
  }
  ASSERT_EQ(s.animation.objects.size(), 1u);
  const int ball = mesh_index(s, "ball");
  EXPECT_EQ(s.animation.objects[0].meshes, std::vector<int>{ball});
  const glm::vec3 c0 = centre(s.meshes[static_cast<std::size_t>(ball)]);
  for (float t : {1.0f, 2.5f, 4.0f}) {
    const glm::vec3 c = glm::vec3(ssr::mesh_transform(s, ball, t) * glm::vec4(c0, 1.0f));
    EXPECT_NEAR(glm::length(glm::vec2(c.x, c.z)), glm::length(glm::vec2(c0.x, c0.z)), 1e-4f);
    EXPECT_GT(glm::distance(c, c0), 0.5f);
  }
}

// ---- JSON ------------------------------------------------------------------------------------

std::filesystem::path scene_file(const std::string& name, const std::string& animation) {
  const auto dir = std::filesystem::path(testing::TempDir()) / "ssrlab_animation";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << R"({"primitives": [
      {"type": "plane", "name": "floor", "size": [4, 4], "reflector": true},
      {"type": "sphere", "name": "ball", "translate": [0, 0.5, 0]},
      {"type": "box", "name": "ball", "translate": [1, 0.5, 0]},
      {"type": "box", "name": "crate", "translate": [-1, 0.5, 0]}],
    "cameras": [{"position": [0, 1, 4], "target": [0, 0, 0], "fov_y": 50}],
    "animation": )" << animation
                            << "}";
  return dir / name;
}

TEST(AnimationJson, ReadsPathsMotionsAndDefaults) {
  const Scene s = ssr::load_scene_json(scene_file("good.json", R"({
      "paths": [{"name": "p", "keys": [
                   {"time": 0, "position": [0, 1, 4], "target": [0, 0, 0]},
                   {"time": 2.5, "position": [1, 1, 4], "target": [0, 0, 0], "fov_y": 40, "cut": true}]}],
      "objects": [{"meshes": ["ball"], "keys": [{"time": 0}, {"time": 3, "translate": [1, 0, 0],
                                                 "rotate_deg": [0, 90, 0], "scale": 2}]},
                  {"meshes": ["crate"], "spin": {"axis": [0, 2, 0], "period": -2}},
                  {"meshes": ["crate"], "orbit": {"period": 4, "center": [0, 0, 0]}}]})"));
  const ssr::Animation& a = s.animation;
  EXPECT_FLOAT_EQ(a.duration, 3.0f);  // the last key time
  ASSERT_EQ(a.paths.size(), 1u);
  EXPECT_EQ(a.paths[0].keys[0].fov_y_deg, 50.0f);  // the default camera's
  EXPECT_EQ(a.paths[0].keys[1].fov_y_deg, 40.0f);
  EXPECT_TRUE(a.paths[0].keys[1].cut);
  ASSERT_EQ(a.objects.size(), 3u);
  EXPECT_EQ(a.objects[0].meshes, (std::vector<int>{1, 2}));  // both meshes named "ball"
  EXPECT_EQ(a.objects[0].keys[1].scale, glm::vec3(2.0f));
  EXPECT_EQ(a.objects[1].kind, ObjectMotion::Kind::Spin);
  EXPECT_EQ(a.objects[1].axis, glm::vec3(0, 1, 0));  // normalised
  EXPECT_EQ(a.objects[1].pivot, centre(s.meshes[3]));  // default: the meshes' centre
  EXPECT_EQ(a.objects[2].kind, ObjectMotion::Kind::Orbit);
  EXPECT_EQ(a.objects[2].pivot, glm::vec3(0.0f));

  const Scene spin = ssr::load_scene_json(scene_file("spin.json",
      R"({"objects": [{"meshes": ["crate"], "spin": {"period": 1}}]})"));
  EXPECT_FLOAT_EQ(spin.animation.duration, 4.0f);  // spins alone: 4 s
  const Scene explicit_duration = ssr::load_scene_json(scene_file("duration.json",
      R"({"duration": 2, "objects": [{"meshes": ["crate"], "spin": {"period": 1}}]})"));
  EXPECT_FLOAT_EQ(explicit_duration.animation.duration, 2.0f);
}

TEST(AnimationJson, MalformedAnimationsThrowInputErrorNamingTheKey) {
  struct Case {
    const char* file;
    std::string animation;
    std::vector<std::string> fragments;
  };
  const std::string key0 = R"({"time": 0, "position": [0, 1, 4], "target": [0, 0, 0]})";
  const Case cases[] = {
      {"unknown_key.json", R"({"paths": [], "length": 3})", {"unknown key", "'animation.length'"}},
      {"unknown_key_deep.json",
       R"({"paths": [{"name": "p", "keys": [{"time": 0, "position": [0, 1, 4], "target": [0, 0, 0], "fov": 40}]}]})",
       {"unknown key", "'animation.paths[0].keys[0].fov'"}},
      {"non_monotonic.json",
       R"({"paths": [{"name": "p", "keys": [{"time": 1, "position": [0, 1, 4], "target": [0, 0, 0]},
                                           {"time": 1, "position": [1, 1, 4], "target": [0, 0, 0]}]}]})",
       {"'animation.paths[0].keys[1].time'", "greater than"}},
      {"non_monotonic_object.json",
       R"({"objects": [{"meshes": ["crate"], "keys": [{"time": 2}, {"time": 0.5}]}]})",
       {"'animation.objects[0].keys[1].time'", "greater than"}},
      {"huge_time.json",
       R"({"objects": [{"meshes": ["crate"], "keys": [{"time": 1e39}]}]})",
       {"'animation.objects[0].keys[0].time'", "finite"}},
      {"string_period.json",
       R"({"objects": [{"meshes": ["crate"], "spin": {"period": "NaN"}}]})",
       {"'animation.objects[0].spin.period'", "must be a number"}},
      {"zero_period.json", R"({"objects": [{"meshes": ["crate"], "orbit": {"period": 0, "center": [0, 0, 0]}}]})",
       {"'animation.objects[0].orbit.period'", "not be 0"}},
      {"zero_axis.json", R"({"objects": [{"meshes": ["crate"], "spin": {"axis": [0, 0, 0], "period": 1}}]})",
       {"'animation.objects[0].spin.axis'", "non-zero"}},
      {"reflector.json", R"({"objects": [{"meshes": ["crate", "floor"], "spin": {"period": 1}}]})",
       {"'animation.objects[0].meshes[1]'", "'floor'", "planar reflector"}},
      {"unknown_mesh.json", R"({"objects": [{"meshes": ["nope"], "spin": {"period": 1}}]})",
       {"'animation.objects[0].meshes[0]'", "unknown mesh 'nope'"}},
      {"keys_and_spin.json",
       R"({"objects": [{"meshes": ["crate"], "keys": [{"time": 0}], "spin": {"period": 1}}]})",
       {"'animation.objects[0]'", "'keys'", "'spin'"}},
      {"pivot_with_spin.json",
       R"({"objects": [{"meshes": ["crate"], "pivot": [0, 0, 0], "spin": {"period": 1}}]})",
       {"unknown key", "'animation.objects[0].pivot'", "spin"}},
      {"no_motion.json", R"({"objects": [{"meshes": ["crate"]}]})",
       {"'animation.objects[0]'", "\"keys\""}},
      {"empty_path.json", R"({"paths": [{"name": "p", "keys": []}]})",
       {"'animation.paths[0].keys'", "empty"}},
      {"no_name.json", R"({"paths": [{"keys": [)" + key0 + "]}]}",
       {"'animation.paths[0].name'", "required"}},
      {"bad_name.json", R"({"paths": [{"name": "a b", "keys": [)" + key0 + "]}]}",
       {"'animation.paths[0].name'", "letters"}},
      {"same_name.json",
       R"({"paths": [{"name": "p", "keys": [)" + key0 + R"(]}, {"name": "p", "keys": [)" + key0 + "]}]}",
       {"'animation.paths[1].name'", "'p'"}},
      {"first_cut.json",
       R"({"paths": [{"name": "p", "keys": [{"time": 0, "position": [0, 1, 4], "target": [0, 0, 0], "cut": true}]}]})",
       {"'animation.paths[0].keys[0].cut'", "first key"}},
      {"same_point.json",
       R"({"paths": [{"name": "p", "keys": [{"time": 0, "position": [0, 1, 4], "target": [0, 1, 4]}]}]})",
       {"'animation.paths[0].keys[0].target'", "differ"}},
      {"negative_time.json", R"({"paths": [{"name": "p", "keys": [{"time": -1, "position": [0, 1, 4], "target": [0, 0, 0]}]}]})",
       {"'animation.paths[0].keys[0].time'", "[0, "}},
      {"zero_scale.json",
       R"({"objects": [{"meshes": ["crate"], "keys": [{"time": 0, "scale": [1, 0, 1]}]}]})",
       {"'animation.objects[0].keys[0].scale'"}},
      {"not_object.json", R"([1, 2])", {"'animation'", "object"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const auto path = scene_file(c.file, c.animation);
    std::vector<std::string> fragments = c.fragments;
    fragments.push_back(c.file);
    expect_message(input_error([&] { ssr::load_scene(path.string()); }), fragments);
  }
}

}  // namespace
