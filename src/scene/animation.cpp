#include "scene/animation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/errors.h"
#include "scene/meshgen.h"
#include "scene/scene.h"

namespace ssr {

namespace {

// NaN would slip through every clamp below; treat it as time 0.
float sane(float t) { return std::isnan(t) ? 0.0f : t; }

// T(pivot + translate) * L * T(-pivot). Exact identity for L = I and translate = 0.
glm::mat4 about(const glm::mat3& linear, glm::vec3 pivot, glm::vec3 translate) {
  glm::mat4 m(linear);
  m[3] = glm::vec4(pivot + translate - linear * pivot, 1.0f);
  return m;
}

glm::quat euler_quat(glm::vec3 deg) {  // Rz * Ry * Rx
  return glm::angleAxis(glm::radians(deg.z), glm::vec3(0, 0, 1)) *
         glm::angleAxis(glm::radians(deg.y), glm::vec3(0, 1, 0)) *
         glm::angleAxis(glm::radians(deg.x), glm::vec3(1, 0, 0));
}

// The rotation about `axis` by 360 * time / period degrees, or nothing at a whole number of
// turns (so time 0 and every period are the identity exactly). In double: time / period may be
// far beyond float's range for a tiny period.
bool turn(glm::vec3 axis, float time, float period, glm::mat3& out) {
  const double turns = static_cast<double>(time) / static_cast<double>(period);
  const double frac = turns - std::floor(turns);  // [0, 1); a negative period turns backwards
  if (!std::isfinite(frac) || frac == 0.0) return false;
  const float angle = static_cast<float>(2.0 * std::numbers::pi * frac);
  out = glm::mat3(glm::rotate(glm::mat4(1.0f), angle, axis));
  return true;
}

glm::mat4 keyframes(const ObjectMotion& m, float t) {
  const std::vector<TransformKey>& k = m.keys;
  if (k.empty()) return glm::mat4(1.0f);
  glm::vec3 translate, scale;
  glm::quat rotation;
  if (t <= k.front().time || k.size() == 1 || t >= k.back().time) {
    const TransformKey& key = t <= k.front().time ? k.front() : k.back();
    if (key.translate == glm::vec3(0.0f) && key.rotate_deg == glm::vec3(0.0f) &&
        key.scale == glm::vec3(1.0f))
      return glm::mat4(1.0f);  // the rest pose
    translate = key.translate;
    scale = key.scale;
    rotation = euler_quat(key.rotate_deg);
  } else {
    const auto next = std::upper_bound(k.begin(), k.end(), t,
                                       [](float v, const TransformKey& key) { return v < key.time; });
    const TransformKey& a = *(next - 1);
    const TransformKey& b = *next;
    const float u = std::clamp((t - a.time) / (b.time - a.time), 0.0f, 1.0f);
    translate = glm::mix(a.translate, b.translate, u);
    scale = glm::mix(a.scale, b.scale, u);
    // slerp takes the shorter way: keys 180 degrees or more apart need a key in between.
    rotation = glm::slerp(euler_quat(a.rotate_deg), euler_quat(b.rotate_deg), u);
  }
  glm::mat3 linear = glm::mat3_cast(glm::normalize(rotation));
  for (int c = 0; c < 3; ++c) linear[c] *= scale[c];
  return about(linear, m.pivot, translate);
}

// The centre of the axis-aligned box around the motion's meshes at rest.
glm::vec3 rest_centre(const Scene& scene, const ObjectMotion& m) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (int i : m.meshes) {
    if (i < 0 || i >= static_cast<int>(scene.meshes.size())) continue;
    for (const Vertex& v : scene.meshes[static_cast<std::size_t>(i)].vertices) {
      lo = glm::min(lo, v.position);
      hi = glm::max(hi, v.position);
    }
  }
  return hi.x >= lo.x ? 0.5f * (lo + hi) : glm::vec3(0.0f);
}

glm::mat4 motion_matrix(const Scene& scene, const ObjectMotion& m, float t) {
  glm::mat3 r;
  switch (m.kind) {
    case ObjectMotion::Kind::Keyframes:
      return keyframes(m, t);
    case ObjectMotion::Kind::Spin:
      return turn(m.axis, t, m.period, r) ? about(r, m.pivot, glm::vec3(0.0f)) : glm::mat4(1.0f);
    case ObjectMotion::Kind::Orbit: {
      // Revolve the meshes' rest centre c0 about the pivot, keeping their orientation.
      if (!turn(m.axis, t, m.period, r)) return glm::mat4(1.0f);
      const glm::vec3 c0 = rest_centre(scene, m);
      return glm::translate(glm::mat4(1.0f), r * (c0 - m.pivot) + m.pivot - c0);
    }
  }
  return glm::mat4(1.0f);
}

bool moves(const ObjectMotion& m, int mesh) {
  return std::find(m.meshes.begin(), m.meshes.end(), mesh) != m.meshes.end();
}

}  // namespace

glm::mat4 mesh_transform(const Scene& scene, int mesh, float time) {
  time = sane(time);
  glm::mat4 out(1.0f);
  for (const ObjectMotion& m : scene.animation.objects)
    if (moves(m, mesh)) out = motion_matrix(scene, m, time) * out;
  return out;
}

std::vector<glm::mat4> mesh_transforms(const Scene& scene, float time) {
  time = sane(time);
  std::vector<glm::mat4> out(scene.meshes.size(), glm::mat4(1.0f));
  std::vector<std::size_t> stamp(scene.meshes.size(), 0);  // a mesh listed twice moves once
  std::size_t n = 0;
  for (const ObjectMotion& m : scene.animation.objects) {
    ++n;
    const glm::mat4 mat = motion_matrix(scene, m, time);
    for (int i : m.meshes) {
      if (i < 0 || i >= static_cast<int>(out.size())) continue;
      const auto k = static_cast<std::size_t>(i);
      if (stamp[k] == n) continue;
      stamp[k] = n;
      out[k] = mat * out[k];  // as mesh_transform: the same products in the same order
    }
  }
  return out;
}

Scene posed_scene(const Scene& scene, float time) {
  Scene posed = scene;
  const std::vector<glm::mat4> xf = mesh_transforms(scene, time);
  for (std::size_t i = 0; i < posed.meshes.size(); ++i)
    if (xf[i] != glm::mat4(1.0f)) meshgen::transform(posed.meshes[i], xf[i]);
  return posed;
}

Camera camera_at(const CameraPath& path, float time, const Camera& base) {
  Camera c = base;
  const std::vector<CameraKey>& k = path.keys;
  if (k.empty()) return c;
  const float t = std::clamp(sane(time), k.front().time, k.back().time);
  // i: the last key at or before t.
  const std::size_t i = static_cast<std::size_t>(
      std::upper_bound(k.begin(), k.end(), t,
                       [](float v, const CameraKey& key) { return v < key.time; }) -
      k.begin() - 1);
  if (i + 1 == k.size() || k[i + 1].cut) {  // the end, or holding until a cut
    c.position = k[i].position;
    c.target = k[i].target;
    c.fov_y_deg = k[i].fov_y_deg;
    return c;
  }
  // The run of keys [first, last] around segment i -> i+1 (no cut inside it).
  std::size_t first = i, last = i + 1;
  while (first > 0 && !k[first].cut) --first;
  while (last + 1 < k.size() && !k[last + 1].cut) ++last;
  const CameraKey &a = k[i], &b = k[i + 1];
  const float h = b.time - a.time;
  // Catmull-Rom tangents (per second, one-sided at the run's ends) times the segment's length
  // h: h / (t[hi] - t[lo]) is in (0, 1], so this stays finite however close the keys are.
  auto tangent = [&](std::size_t j, glm::vec3 CameraKey::*p) {
    const std::size_t lo = j > first ? j - 1 : j, hi = j < last ? j + 1 : j;
    return (k[hi].*p - k[lo].*p) * (h / (k[hi].time - k[lo].time));
  };
  const float u = std::clamp((t - a.time) / h, 0.0f, 1.0f);
  const float u2 = u * u, u3 = u2 * u;
  const float h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
  // The cubic Hermite basis with h00 = 1 - h01 folded in: exactly a at u = 0, and exactly a
  // everywhere between two equal keys of a held camera.
  auto hermite = [&](glm::vec3 CameraKey::*p) {
    return a.*p + (h01 * (b.*p - a.*p) + h10 * tangent(i, p) + h11 * tangent(i + 1, p));
  };
  c.position = hermite(&CameraKey::position);
  c.target = hermite(&CameraKey::target);
  c.fov_y_deg = a.fov_y_deg + (b.fov_y_deg - a.fov_y_deg) * (u2 * (3 - 2 * u));  // smoothstep
  // The spline of two distinct points can still meet: keep a view direction (key a's).
  if (glm::length(c.target - c.position) < 1e-6f * (1.0f + glm::length(c.position)))
    c.target = c.position + (a.target - a.position);
  // Or look along the up vector (a camera passing over its target), where the view has no roll:
  // there the top of the image points where the keys head, across the up vector.
  if (up_along_view(c.target - c.position, c.up)) {
    const glm::vec3 up = glm::normalize(c.up);
    for (const CameraKey* key : {&a, &b}) {
      const glm::vec3 d = key->target - key->position;
      if (up_along_view(d, up)) continue;
      c.up = d - glm::dot(d, up) * up;
      break;
    }
    if (up_along_view(c.target - c.position, c.up))  // both keys along it too (validation refuses those)
      c.up = glm::abs(up.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
  }
  return c;
}

bool cut_between(const CameraPath& path, float t0, float t1) {
  for (const CameraKey& key : path.keys)
    if (key.cut && key.time > t0 && key.time <= t1) return true;
  return false;
}

const CameraPath& find_path(const Scene& scene, const std::string& name) {
  for (const CameraPath& p : scene.animation.paths)
    if (p.name == name) return p;
  if (scene.animation.paths.empty())
    throw InputError("scene '" + scene.name + "' has no camera paths, so none named '" + name +
                     "'.");
  std::string names;
  for (const CameraPath& p : scene.animation.paths) names += (names.empty() ? "" : ", ") + p.name;
  throw InputError("scene '" + scene.name + "' has no camera path '" + name + "' (paths: " +
                   names + ").");
}

}  // namespace ssr
