#include "scene/scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/errors.h"

namespace ssr {

const Camera& Scene::camera(const std::string& wanted) const {
  for (const Camera& c : cameras)
    if (c.name == wanted) return c;
  std::ostringstream names;
  for (std::size_t i = 0; i < cameras.size(); ++i) names << (i ? ", " : "") << cameras[i].name;
  throw InputError("scene '" + name + "' has no camera '" + wanted + "' (cameras: " +
                   names.str() + ")");
}

std::size_t Scene::triangle_count() const {
  std::size_t n = 0;
  for (const Mesh& m : meshes) n += m.indices.size() / 3;
  return n;
}

namespace {

bool finite(float v) { return std::isfinite(v); }
template <int N>
bool finite(const glm::vec<N, float>& v) {
  for (int i = 0; i < N; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}
bool in01(float v) { return v >= 0.0f && v <= 1.0f; }
bool unit(const glm::vec3& v) { return finite(v) && std::abs(glm::length(v) - 1.0f) < 1e-3f; }

[[noreturn]] void fail(const Scene& s, const std::string& what) {
  throw InputError("scene '" + s.name + "': " + what + ".");
}

void validate_animation(const Scene& s) {
  const Animation& a = s.animation;
  if (!finite(a.duration) || a.duration < 0) fail(s, "animation duration must be finite and >= 0");
  const int npaths = static_cast<int>(a.paths.size());
  if (a.default_path < -1 || a.default_path >= npaths)
    fail(s, "animation default path index is out of range");
  for (std::size_t i = 0; i < a.paths.size(); ++i) {
    const CameraPath& p = a.paths[i];
    if (p.name.empty()) fail(s, "camera path " + std::to_string(i) + " has no name");
    const std::string where = "camera path '" + p.name + "' ";
    // Names are chosen on command lines (path=NAME inside "scene:key=value,..."), so no
    // separators or spaces.
    for (char c : p.name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
        fail(s, where + "may use only letters, digits, '_', '-' and '.' in its name");
    for (std::size_t j = 0; j < i; ++j)
      if (a.paths[j].name == p.name) fail(s, where + "is defined twice");
    if (p.keys.empty()) fail(s, where + "has no keys");
    for (std::size_t j = 0; j < p.keys.size(); ++j) {
      const CameraKey& k = p.keys[j];
      const std::string kw = where + "key " + std::to_string(j) + " ";
      if (!finite(k.time) || k.time < 0) fail(s, kw + "time must be finite and >= 0");
      if (j > 0 && !(k.time > p.keys[j - 1].time))
        fail(s, kw + "time must be greater than the previous key's (times strictly increase)");
      if (k.cut && j == 0) fail(s, kw + "is a cut, but the first key cannot be one");
      if (!finite(k.position) || !finite(k.target)) fail(s, kw + "has a non-finite vector");
      const glm::vec3 fwd = k.target - k.position;
      if (glm::length(fwd) < 1e-6f) fail(s, kw + "target equals its position");
      if (!s.cameras.empty() && up_along_view(fwd, s.cameras[0].up))
        fail(s, kw + "view direction is parallel to the default camera's up vector");
      if (!finite(k.fov_y_deg) || k.fov_y_deg <= 1.0f || k.fov_y_deg >= 179.0f)
        fail(s, kw + "fov must be in (1,179) degrees");
    }
  }
  const int nmeshes = static_cast<int>(s.meshes.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const ObjectMotion& m = a.objects[i];
    const std::string where = "animation object " + std::to_string(i) + " ";
    if (m.meshes.empty()) fail(s, where + "moves no mesh");
    for (std::size_t j = 0; j < m.meshes.size(); ++j) {
      const int k = m.meshes[j];
      if (k < 0 || k >= nmeshes) fail(s, where + "has a mesh index out of range");
      if (std::find(m.meshes.begin(), m.meshes.begin() + static_cast<std::ptrdiff_t>(j), k) !=
          m.meshes.begin() + static_cast<std::ptrdiff_t>(j))
        fail(s, where + "lists mesh '" + s.meshes[static_cast<std::size_t>(k)].name + "' twice");
      if (s.meshes[static_cast<std::size_t>(k)].reflector != 0)
        fail(s, where + "moves mesh '" + s.meshes[static_cast<std::size_t>(k)].name +
                    "', a planar reflector, but planar reflectors are fixed rectangles and "
                    "cannot move");
    }
    if (!finite(m.pivot)) fail(s, where + "pivot is not finite");
    if (m.kind == ObjectMotion::Kind::Keyframes) {
      if (m.keys.empty()) fail(s, where + "needs at least one key");
      for (std::size_t j = 0; j < m.keys.size(); ++j) {
        const TransformKey& k = m.keys[j];
        const std::string kw = where + "key " + std::to_string(j) + " ";
        if (!finite(k.time) || k.time < 0) fail(s, kw + "time must be finite and >= 0");
        if (j > 0 && !(k.time > m.keys[j - 1].time))
          fail(s, kw + "time must be greater than the previous key's (times strictly increase)");
        if (!finite(k.translate) || !finite(k.rotate_deg) || !finite(k.scale))
          fail(s, kw + "has a non-finite vector");
        if (k.scale.x <= 0 || k.scale.y <= 0 || k.scale.z <= 0) fail(s, kw + "scale must be > 0");
      }
    } else {
      if (!unit(m.axis)) fail(s, where + "axis must be a unit vector");
      if (!finite(m.period) || m.period == 0.0f) fail(s, where + "period must be finite and not 0");
    }
  }
}

}  // namespace

void validate_lighting(const Scene& s) {
  if (s.lights.size() > static_cast<std::size_t>(Scene::kMaxLights))
    fail(s, "has " + std::to_string(s.lights.size()) + " lights, more than the " +
                std::to_string(Scene::kMaxLights) + " supported");
  if (!finite(s.ambient) || s.ambient < 0.0f) fail(s, "ambient must be finite and >= 0");
  for (const Light& l : s.lights) {
    if (!finite(l.position) || !finite(l.color) || !finite(l.intensity) || !finite(l.range))
      fail(s, "a light has a non-finite value");
    if (l.intensity < 0 || l.color.x < 0 || l.color.y < 0 || l.color.z < 0)
      fail(s, "a light has a negative colour or intensity");
    if (l.type == Light::Type::Point && l.range <= 0) fail(s, "a point light needs range > 0");
    if (l.type == Light::Type::Directional && !unit(l.direction))
      fail(s, "a directional light needs a unit direction");
  }

  const Environment& e = s.environment;
  if (!finite(e.zenith) || !finite(e.horizon) || !finite(e.ground) || !finite(e.constant) ||
      !finite(e.intensity) || e.intensity < 0)
    fail(s, "environment has a non-finite or negative value");
}

void validate(const Scene& s) {
  if (s.meshes.empty()) fail(s, "has no meshes");
  if (s.materials.empty()) fail(s, "has no materials");
  if (s.cameras.empty()) fail(s, "has no camera");
  if (s.meshes.size() > static_cast<std::size_t>(Scene::kMaxMeshes))
    fail(s, "has " + std::to_string(s.meshes.size()) + " meshes, more than the " +
                std::to_string(Scene::kMaxMeshes) + " supported");
  if (s.reflectors.size() > static_cast<std::size_t>(Scene::kMaxReflectors))
    fail(s, "has " + std::to_string(s.reflectors.size()) + " reflectors, more than the " +
                std::to_string(Scene::kMaxReflectors) + " supported");
  validate_lighting(s);

  for (std::size_t i = 0; i < s.images.size(); ++i) {
    const Image& im = s.images[i];
    if (im.width <= 0 || im.height <= 0 ||
        im.rgba.size() != static_cast<std::size_t>(im.width) * im.height * 4)
      fail(s, "image " + std::to_string(i) + " has inconsistent size");
  }
  const int nimages = static_cast<int>(s.images.size());
  for (const Material& m : s.materials) {
    const std::string where = "material '" + m.name + "' ";
    if (!finite(m.albedo) || !in01(m.albedo.x) || !in01(m.albedo.y) || !in01(m.albedo.z))
      fail(s, where + "albedo must be in [0,1]");
    if (!finite(m.metallic) || !in01(m.metallic)) fail(s, where + "metallic must be in [0,1]");
    if (!finite(m.roughness) || !in01(m.roughness)) fail(s, where + "roughness must be in [0,1]");
    if (!finite(m.reflectance) || !in01(m.reflectance))
      fail(s, where + "reflectance must be in [0,1]");
    if (!finite(m.emission) || m.emission.x < 0 || m.emission.y < 0 || m.emission.z < 0)
      fail(s, where + "emission must be finite and >= 0");
    if (m.albedo_texture < -1 || m.albedo_texture >= nimages)
      fail(s, where + "albedo texture index is out of range");
    if (m.normal_texture < -1 || m.normal_texture >= nimages)
      fail(s, where + "normal texture index is out of range");
    if (!finite(m.normal_strength) || m.normal_strength < 0 || m.normal_strength > 4)
      fail(s, where + "normal strength must be in [0,4]");
    if (!finite(m.ior) || m.ior < 1.0f || m.ior > 3.0f) fail(s, where + "ior must be in [1,3]");
  }

  const int nmat = static_cast<int>(s.materials.size());
  const int nrefl = static_cast<int>(s.reflectors.size());
  for (const Mesh& m : s.meshes) {
    const std::string where = "mesh '" + m.name + "' ";
    if (m.indices.empty() || m.indices.size() % 3 != 0)
      fail(s, where + "must have a positive multiple of 3 indices");
    if (m.material < 0 || m.material >= nmat) fail(s, where + "material index is out of range");
    if (m.reflector < 0 || m.reflector > nrefl) fail(s, where + "reflector id is out of range");
    for (std::uint32_t idx : m.indices)
      if (idx >= m.vertices.size())
        fail(s, where + "has vertex index " + std::to_string(idx) + " but only " +
                    std::to_string(m.vertices.size()) + " vertices");
    for (const Vertex& v : m.vertices) {
      if (!finite(v.position) || std::abs(v.position.x) > 1e7f || std::abs(v.position.y) > 1e7f ||
          std::abs(v.position.z) > 1e7f)
        fail(s, where + "has a vertex position that is not finite or beyond 1e7");
      if (!unit(v.normal)) fail(s, where + "has a normal that is not unit length");
      if (!finite(v.uv)) fail(s, where + "has a non-finite uv");
      if (!finite(v.tangent)) fail(s, where + "has a non-finite tangent");
    }
  }

  for (std::size_t i = 0; i < s.reflectors.size(); ++i) {
    const Reflector& r = s.reflectors[i];
    const std::string where = "reflector " + std::to_string(i + 1) + " ";
    if (!finite(r.center)) fail(s, where + "center is not finite");
    if (!unit(r.tangent) || !unit(r.bitangent)) fail(s, where + "tangent frame is not unit");
    if (std::abs(glm::dot(r.tangent, r.bitangent)) > 1e-3f)
      fail(s, where + "tangent and bitangent are not orthogonal");
    if (!finite(r.half_extents) || r.half_extents.x <= 0 || r.half_extents.y <= 0)
      fail(s, where + "must have positive half extents (zero-area reflectors are not allowed)");
  }

  for (const Camera& c : s.cameras) {
    const std::string where = "camera '" + c.name + "' ";
    if (!finite(c.position) || !finite(c.target) || !finite(c.up))
      fail(s, where + "has a non-finite vector");
    const glm::vec3 fwd = c.target - c.position;
    if (glm::length(fwd) < 1e-6f) fail(s, where + "target equals its position");
    if (up_along_view(fwd, c.up))
      fail(s, where + "up vector is parallel to the view direction");
    if (!finite(c.fov_y_deg) || c.fov_y_deg <= 1.0f || c.fov_y_deg >= 179.0f)
      fail(s, where + "fov must be in (1,179) degrees");
    if (!finite(c.near_plane) || !finite(c.far_plane) || c.near_plane <= 0 ||
        c.far_plane <= c.near_plane)
      fail(s, where + "needs 0 < near < far");
  }
  validate_animation(s);
}

float bounding_diagonal(const Scene& scene) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const Mesh& m : scene.meshes)
    for (const Vertex& v : m.vertices) {
      lo = glm::min(lo, v.position);
      hi = glm::max(hi, v.position);
    }
  return hi.x >= lo.x ? glm::length(hi - lo) : 0.0f;
}

glm::vec3 material_f0(const Material& m) {
  return glm::mix(glm::vec3(0.16f * m.reflectance * m.reflectance), m.albedo, m.metallic);
}

bool has_reflective_surfaces(const Scene& scene, float reflective_f0) {
  for (const Mesh& mesh : scene.meshes) {
    const Material& m = scene.materials[static_cast<std::size_t>(mesh.material)];
    const glm::vec3 f0 = material_f0(m);
    if (mesh.reflector > 0 || m.transparent || std::max({f0.x, f0.y, f0.z}) >= reflective_f0) return true;
  }
  return false;
}

}  // namespace ssr
