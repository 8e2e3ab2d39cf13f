// JSON scene files: load_scene_json.
//
// ---- schema ---------------------------------------------------------------------------------
// One object; every key below is optional unless marked (required). Unknown keys are an error,
// wrong types are an error, duplicate keys are an error; // and /* */ comments are allowed.
// Vectors are arrays of 3 numbers. Paths are relative to the JSON file's directory and must
// stay inside it (no absolute paths, no "..", no symlink leading out). Units as in scene.h.
//
//   "name": "pedestal",                    scene name (default: the file name without .json)
//   "description": "...",                  free text, ignored
//   "ambient": 0.3,                        >= 0, scales the environment's diffuse light
//   "environment": {"type": "sky", "zenith": v3, "horizon": v3, "ground": v3, "intensity": 1}
//               or {"type": "constant", "color": v3, "intensity": 1}
//   "materials": {"<name>": {"albedo": v3 in [0,1], "metallic": [0,1], "roughness": [0,1],
//                 "reflectance": [0,1], "emission": v3 >= 0, "albedo_texture": "x.png",
//                 "normal_texture": "n.png", "normal_strength": [0,4], "transparent": bool,
//                 "ior": [1,3]}, ...}
//       The material named "default" (grey, created if not given) is used by OBJ faces without
//       a material and by primitives without "material".
//   "meshes": [{"obj": "meshes/x.obj" (required), "material": "<name>" (replaces the MTL's),
//               "translate": v3, "rotate_deg": v3, "scale": s > 0 or v3 > 0,
//               "reflector": {"center": v3, "tangent": v3, "bitangent": v3,
//                             "half_extents": [hx, hy] > 0}}, ...]
//   "primitives": [{"type": "plane" | "box" | "sphere" | "cylinder" (required), "name": "...",
//                   plane: "size": [x, z], "uv_scale": s;  box: "extents": v3;
//                   sphere: "radius", "segments", "rings";  cylinder: "radius", "height",
//                   "segments"; "material", "translate", "rotate_deg", "scale",
//                   "reflector": true (planes: the plane's own rectangle) or an object as above
//                  }, ...]
//   "lights": [{"type": "point", "position": v3 (required), "color": v3, "intensity", "range"}
//           or {"type": "directional", "direction": v3 (required), "color": v3, "intensity"}]
//   "cameras": [{"name", "position", "target", "up", "fov_y" (degrees), "near", "far"}, ...]
//       The first camera is the default; without "cameras" one camera frames the whole scene.
//   "animation": {"duration": s >= 0 (default: the last key time of any path or keyframed
//                               motion; 4 when there are only spins and orbits),
//       "paths": [{"name" (required; letters, digits, _ - .), "description",
//                  "keys" (required, non-empty): [{"time" (required), "position" (required),
//                          "target" (required), "fov_y" (default: the default camera's),
//                          "cut": bool (jump here at this time; not on the first key)}]}],
//       "objects": [{"meshes": ["<mesh name>", ...] (required; every mesh of each name) and
//                    one of
//                      "keys": [{"time" (required), "translate", "rotate_deg", "scale"}],
//                      "pivot": v3 (with keys; default: the meshes' bounding-box centre)
//                    or "spin": {"axis": v3 (default [0, 1, 0]), "period" (required, s per
//                                turn, != 0, sign = direction), "pivot": v3 (default: centre)}
//                    or "orbit": {"axis", "period" as spin, "center": v3 (required)}}]}
//       Times in seconds, >= 0, strictly increasing within a path or motion. Mesh names are
//       Scene::meshes' names: a primitive's "name" (default "<type><index>"); an OBJ object's
//       name (else the file name without .obj), plus ":<material>" when it has several.
//       Planar reflectors cannot move. animation.h has the interpolation and motion formulas;
//       at time 0 (a rest first key, whole turns) nothing moves.
//
// Transforms are M = T * Rz * Ry * Rx * S (scale first, then rotate about X, Y, Z, then
// translate). Explicit reflector rectangles are in world space (not moved by the transform);
// the normal is cross(bitangent, tangent).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "core/json_reader.h"
#include "scene/meshgen.h"
#include "scene/scene_json.h"
#include "scene/scene_io.h"
#include "scene/scene_io_internal.h"

namespace ssr {

using namespace scene_io_detail;

namespace {

using json = nlohmann::json;

constexpr std::uintmax_t kMaxJsonBytes = 16ull << 20;  // 16 MiB

json parse_json_file(const fs::path& path) {
  return parse_json_object(read_text_file(path, kMaxJsonBytes, "scene file"), "scene file " + q(path));
}

// "scale": a number or a v3, > 0 (1 when absent).
glm::vec3 read_scale(const JsonReader& r, const json& obj, const std::string& where) {
  if (!obj.contains("scale")) return glm::vec3(1.0f);
  const std::string w = JsonReader::join(where, "scale");
  if (obj["scale"].is_number()) return glm::vec3(r.number(obj["scale"], w, 1e-6f, kSceneValueMax));
  if (!obj["scale"].is_array()) r.fail_at(w, "must be a number or an array of 3 numbers");
  return r.vec3(obj["scale"], w, 1e-6f, kSceneValueMax);
}

glm::mat4 read_transform(const JsonReader& r, const json& obj, const std::string& where) {
  const glm::vec3 t = r.vec3(obj, where, "translate", glm::vec3(0.0f));
  const glm::vec3 rot = r.vec3(obj, where, "rotate_deg", glm::vec3(0.0f), -36000.0f, 36000.0f);
  const glm::vec3 s = read_scale(r, obj, where);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), t);
  m = glm::rotate(m, glm::radians(rot.z), glm::vec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rot.y), glm::vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rot.x), glm::vec3(1, 0, 0));
  return glm::scale(m, s);
}

Reflector read_reflector(const JsonReader& r, const json& j, const std::string& where) {
  r.object(j, where);
  r.keys(j, where, {"center", "tangent", "bitangent", "half_extents"});
  Reflector refl;
  refl.center = r.required_vec3(j, where, "center");
  for (const char* k : {"tangent", "bitangent"})
    if (!j.contains(k)) r.fail_at(JsonReader::join(where, k), "is required");
  refl.tangent = r.direction(j["tangent"], JsonReader::join(where, "tangent"));
  refl.bitangent = r.direction(j["bitangent"], JsonReader::join(where, "bitangent"));
  if (std::abs(glm::dot(refl.tangent, refl.bitangent)) > 1e-3f)
    r.fail_at(where, "needs orthogonal tangent and bitangent");
  const std::string he = JsonReader::join(where, "half_extents");
  if (!j.contains("half_extents")) r.fail_at(he, "is required");
  refl.half_extents = r.vec2(j["half_extents"], he, 0.0f, 1e7f);
  if (!(refl.half_extents.x > 0.0f) || !(refl.half_extents.y > 0.0f))
    r.fail_at(he, "must be positive (zero-area reflectors are not allowed)");
  return refl;
}

// Adds `refl`, returning its 1-based id.
int add_reflector(Scene& s, const JsonReader& r, const std::string& where, const Reflector& refl) {
  if (s.reflectors.size() >= static_cast<std::size_t>(Scene::kMaxReflectors))
    r.fail_at(where, "is reflector number " + std::to_string(s.reflectors.size() + 1) +
                         ", more than the " + std::to_string(Scene::kMaxReflectors) + " supported");
  s.reflectors.push_back(refl);
  return static_cast<int>(s.reflectors.size());
}

void read_environment(const JsonReader& r, const json& j, Environment& env,
                      const std::string& where = "environment") {
  r.object(j, where);
  const std::string type = r.string(j, where, "type", "sky");
  if (type == "sky") {
    r.keys(j, where, {"type", "zenith", "horizon", "ground", "intensity"});
    env.type = Environment::Type::Sky;
    env.zenith = r.vec3(j, where, "zenith", env.zenith, 0.0f, kSceneValueMax);
    env.horizon = r.vec3(j, where, "horizon", env.horizon, 0.0f, kSceneValueMax);
    env.ground = r.vec3(j, where, "ground", env.ground, 0.0f, kSceneValueMax);
  } else if (type == "constant") {
    r.keys(j, where, {"type", "color", "intensity"});
    env.type = Environment::Type::Constant;
    env.constant = r.vec3(j, where, "color", env.constant, 0.0f, kSceneValueMax);
  } else {
    r.fail_at(where + ".type", "must be \"sky\" or \"constant\", not " + q(type));
  }
  env.intensity = r.number(j, where, "intensity", env.intensity, 0.0f, kSceneValueMax);
}

void read_materials(const JsonReader& r, const json& j, Scene& s, LoadContext& ctx,
                    const fs::path& dir) {
  r.object(j, "materials");
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string where = "materials." + it.key();
    const json& m = r.object(it.value(), where);
    r.keys(m, where,
           {"albedo", "metallic", "roughness", "reflectance", "emission", "albedo_texture",
            "normal_texture", "normal_strength", "transparent", "ior"});
    Material mat;
    mat.name = it.key();
    if (mat.name.empty()) r.fail_at(where, "needs a non-empty name");
    mat.albedo = r.vec3(m, where, "albedo", mat.albedo, 0.0f, 1.0f);
    mat.metallic = r.number(m, where, "metallic", mat.metallic, 0.0f, 1.0f);
    mat.roughness = r.number(m, where, "roughness", mat.roughness, 0.0f, 1.0f);
    mat.reflectance = r.number(m, where, "reflectance", mat.reflectance, 0.0f, 1.0f);
    mat.emission = r.vec3(m, where, "emission", mat.emission, 0.0f, kSceneValueMax);
    mat.normal_strength = r.number(m, where, "normal_strength", mat.normal_strength, 0.0f, 4.0f);
    mat.transparent = r.boolean(m, where, "transparent", mat.transparent);
    mat.ior = r.number(m, where, "ior", mat.ior, 1.0f, 3.0f);
    for (const char* key : {"albedo_texture", "normal_texture"}) {
      if (!m.contains(key)) continue;
      const std::string w = JsonReader::join(where, key);
      const std::string context = "scene file " + q(r.file()) + ": " + q(w) + ": ";
      const fs::path p = resolve_inside(dir, dir, r.string(m[key], w), context, "texture");
      const int image = add_image(s, ctx, p, context);
      (std::string_view(key) == "albedo_texture" ? mat.albedo_texture : mat.normal_texture) = image;
    }
    s.materials.push_back(mat);
  }
}

// Material name -> index of the first material of that name, extended as materials are appended
// (OBJ files add theirs): a linear search per mesh and primitive was quadratic (found while
// fuzzing: 20000 materials and primitives, 1.4 MB, took half a minute).
class MaterialNames {
 public:
  int find(const Scene& s, const std::string& name) {
    for (; indexed_ < s.materials.size(); ++indexed_)
      first_.try_emplace(s.materials[indexed_].name, static_cast<int>(indexed_));
    const auto it = first_.find(name);
    return it == first_.end() ? -1 : it->second;
  }

 private:
  std::map<std::string, int> first_;
  std::size_t indexed_ = 0;
};

int find_material(const JsonReader& r, const Scene& s, MaterialNames& names, const json& obj,
                  const std::string& where) {
  const std::string name = r.string(obj["material"], JsonReader::join(where, "material"));
  if (const int i = names.find(s, name); i >= 0) return i;
  std::string list;
  for (const Material& m : s.materials) list += (list.empty() ? "" : ", ") + m.name;
  r.fail_at(JsonReader::join(where, "material"),
            "names the unknown material " + q(name) +
                " (materials: " + (list.empty() ? "none" : list) + ")");
}

void read_meshes(const JsonReader& r, const json& j, Scene& s, LoadContext& ctx,
                 MaterialNames& names, const fs::path& dir) {
  r.array(j, "meshes");
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = JsonReader::index("meshes", i);
    const json& m = r.object(j[i], where);
    r.keys(m, where, {"obj", "material", "translate", "rotate_deg", "scale", "reflector"});
    if (!m.contains("obj")) r.fail_at(where + ".obj", "is required");
    const std::string rel = r.string(m["obj"], where + ".obj");
    const std::string context = "scene file " + q(r.file()) + ": " + q(where + ".obj") + ": ";
    const fs::path obj = resolve_inside(dir, dir, rel, context, "OBJ");
    std::error_code ec;
    if (!fs::is_regular_file(obj, ec))
      fail(context + "OBJ file " + q(obj) +
           (fs::exists(obj, ec) ? " is not a regular file" : " does not exist"));
    const int material = m.contains("material") ? find_material(r, s, names, m, where) : -1;
    const glm::mat4 transform = read_transform(r, m, where);
    int reflector = 0;
    if (m.contains("reflector")) {
      if (!m["reflector"].is_object())
        r.fail_at(where + ".reflector",
                  "must be an object with center, tangent, bitangent and half_extents");
      reflector = add_reflector(s, r, where + ".reflector",
                                read_reflector(r, m["reflector"], where + ".reflector"));
    }
    const std::size_t first = s.meshes.size();
    try {
      append_obj_impl(s, ctx, obj, dir, transform, material);
    } catch (const InputError& e) {
      fail(context + e.what());
    }
    for (std::size_t k = first; k < s.meshes.size(); ++k) s.meshes[k].reflector = reflector;
  }
}

void read_primitives(const JsonReader& r, const json& j, Scene& s, MaterialNames& names) {
  r.array(j, "primitives");
  std::size_t triangles = s.triangle_count();  // the OBJ meshes'
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = JsonReader::index("primitives", i);
    const json& p = r.object(j[i], where);
    if (!p.contains("type")) r.fail_at(where + ".type", "is required");
    const std::string type = r.string(p["type"], where + ".type");
    const std::initializer_list<std::string_view> common = {
        "type", "name", "material", "translate", "rotate_deg", "scale", "reflector"};
    auto allowed = [&](std::initializer_list<std::string_view> extra) {
      std::vector<std::string_view> all(common);
      all.insert(all.end(), extra);
      r.keys(p, where, all, " for a " + type);
    };
    Mesh mesh;
    glm::vec2 plane_size(0.0f);
    if (type == "plane") {
      allowed({"size", "uv_scale"});
      if (!p.contains("size")) r.fail_at(where + ".size", "is required");
      plane_size = r.vec2(p["size"], where + ".size", 1e-6f, kSceneValueMax);
      mesh = meshgen::plane(plane_size, r.number(p, where, "uv_scale", 1.0f, 1e-6f, kSceneValueMax));
    } else if (type == "box") {
      allowed({"extents"});
      mesh = meshgen::box(r.vec3(p, where, "extents", glm::vec3(1.0f), 1e-6f, kSceneValueMax));
    } else if (type == "sphere") {
      allowed({"radius", "segments", "rings"});
      mesh = meshgen::sphere(r.number(p, where, "radius", 0.5f, 1e-6f, kSceneValueMax),
                             r.integer(p, where, "segments", 48, 3, 1024),
                             r.integer(p, where, "rings", 24, 2, 1024));
    } else if (type == "cylinder") {
      allowed({"radius", "height", "segments"});
      mesh = meshgen::cylinder(r.number(p, where, "radius", 0.5f, 1e-6f, kSceneValueMax),
                               r.number(p, where, "height", 1.0f, 1e-6f, kSceneValueMax),
                               r.integer(p, where, "segments", 32, 3, 1024));
    } else {
      r.fail_at(where + ".type",
                "must be \"plane\", \"box\", \"sphere\" or \"cylinder\", not " + q(type));
    }
    // Counted as each one is made: a 50-byte sphere can be 2M triangles, and checking only
    // after the last one let a 2 KB file allocate gigabytes first (found while fuzzing).
    triangles += mesh.indices.size() / 3;
    if (triangles > kMaxTriangles)
      r.fail_at(where, "brings the scene above " + std::to_string(kMaxTriangles) +
                           " triangles, more than supported");
    const glm::mat4 transform = read_transform(r, p, where);
    meshgen::transform(mesh, transform);
    mesh.name = r.string(p, where, "name", type + std::to_string(i));
    if (p.contains("material")) {
      mesh.material = find_material(r, s, names, p, where);
    } else {
      const int d = names.find(s, "default");
      mesh.material = d >= 0 ? d : default_material(s);
    }
    if (p.contains("reflector")) {
      const std::string w = where + ".reflector";
      const json& rj = p["reflector"];
      if (rj.is_boolean()) {
        if (rj.get<bool>()) {  // false asks nothing of any primitive
          if (type != "plane") r.fail_at(w, "can be true only for a plane; give a rectangle object");
          Reflector refl;
          const glm::vec3 tx(transform * glm::vec4(1, 0, 0, 0)),
              tz(transform * glm::vec4(0, 0, 1, 0));
          refl.center = glm::vec3(transform * glm::vec4(0, 0, 0, 1));
          refl.tangent = glm::normalize(tx);
          refl.bitangent = glm::normalize(tz);
          refl.half_extents = 0.5f * plane_size * glm::vec2(glm::length(tx), glm::length(tz));
          mesh.reflector = add_reflector(s, r, w, refl);
        }
      } else if (rj.is_object()) {
        mesh.reflector = add_reflector(s, r, w, read_reflector(r, rj, w));
      } else {
        r.fail_at(w, "must be true, false or a rectangle object");
      }
    }
    s.meshes.push_back(std::move(mesh));
  }
}

Light read_light(const JsonReader& r, const json& j, const std::string& where) {
  const json& l = r.object(j, where);
  if (!l.contains("type")) r.fail_at(where + ".type", "is required");
  const std::string type = r.string(l["type"], where + ".type");
  Light light;
  if (type == "point") {
    r.keys(l, where, {"type", "position", "color", "intensity", "range"});
    light.type = Light::Type::Point;
    light.position = r.required_vec3(l, where, "position");
    light.range = r.number(l, where, "range", light.range, 1e-6f, 1e7f);
  } else if (type == "directional") {
    r.keys(l, where, {"type", "direction", "color", "intensity"});
    light.type = Light::Type::Directional;
    if (!l.contains("direction")) r.fail_at(where + ".direction", "is required");
    light.direction = r.direction(l["direction"], where + ".direction");
  } else {
    r.fail_at(where + ".type", "must be \"point\" or \"directional\", not " + q(type));
  }
  light.color = r.vec3(l, where, "color", light.color, 0.0f, kSceneValueMax);
  light.intensity = r.number(l, where, "intensity", light.intensity, 0.0f, 1e9f);
  return light;
}

void read_lights(const JsonReader& r, const json& j, Scene& s) {
  r.array(j, "lights");
  for (std::size_t i = 0; i < j.size(); ++i)
    s.lights.push_back(read_light(r, j[i], JsonReader::index("lights", i)));
}

Camera read_camera(const JsonReader& r, const json& j, const std::string& where,
                   const std::string& default_name) {
  const json& c = r.object(j, where);
  r.keys(c, where, {"name", "position", "target", "up", "fov_y", "near", "far"});
  Camera cam;
  cam.name = r.string(c, where, "name", default_name);
  cam.position = r.vec3(c, where, "position", cam.position);
  cam.target = r.vec3(c, where, "target", cam.target);
  if (c.contains("up")) cam.up = r.direction(c["up"], where + ".up");
  cam.fov_y_deg = r.number(c, where, "fov_y", cam.fov_y_deg, 1.001f, 178.999f);
  cam.near_plane = r.number(c, where, "near", cam.near_plane, 1e-6f, 1e7f);
  cam.far_plane = r.number(c, where, "far", cam.far_plane, 1e-6f, 1e7f);
  if (!(cam.far_plane > cam.near_plane)) r.fail_at(where + ".far", "must be greater than near");
  if (glm::length(cam.target - cam.position) < 1e-6f)
    r.fail_at(where + ".target", "must differ from the position");
  if (up_along_view(cam.target - cam.position, cam.up))
    r.fail_at(where + ".up", "must not be parallel to the view direction");
  return cam;
}

void read_cameras(const JsonReader& r, const json& j, Scene& s) {
  r.array(j, "cameras");
  if (j.empty()) r.fail_at("cameras", "must not be empty (leave it out to frame the scene)");
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = JsonReader::index("cameras", i);
    Camera cam = read_camera(r, j[i], where, i == 0 ? "default" : "camera" + std::to_string(i));
    for (const Camera& other : s.cameras)
      if (other.name == cam.name)
        r.fail_at(where + ".name", "repeats the camera name " + q(cam.name));
    s.cameras.push_back(std::move(cam));
  }
}

// ---- animation ------------------------------------------------------------------------------

constexpr float kMaxTime = 1e6f;  // seconds, for key times and the duration

// Key times: required, in [0, kMaxTime], each greater than the one before (`previous` < 0 for
// the first key).
float read_key_time(const JsonReader& r, const json& key, const std::string& where,
                    float previous) {
  const std::string w = where + ".time";
  if (!key.contains("time")) r.fail_at(w, "is required");
  const float t = r.number(key["time"], w, 0.0f, kMaxTime);
  if (previous >= 0.0f && !(t > previous))
    r.fail_at(w, "must be greater than the previous key's time " + JsonReader::fmt(previous) +
                     " (key times strictly increase)");
  return t;
}

// A non-empty array of objects at `parent`.`key`, required.
const json& key_array(const JsonReader& r, const json& obj, const std::string& parent,
                      const char* key) {
  const std::string w = JsonReader::join(parent, key);
  if (!obj.contains(key)) r.fail_at(w, "is required");
  r.array(obj[key], w);
  if (obj[key].empty()) r.fail_at(w, "must not be empty");
  return obj[key];
}

CameraPath read_path(const JsonReader& r, const json& j, const std::string& where,
                     const Scene& s) {
  const json& p = r.object(j, where);
  r.keys(p, where, {"name", "description", "keys"});
  CameraPath path;
  if (!p.contains("name")) r.fail_at(where + ".name", "is required");
  path.name = r.string(p["name"], where + ".name");
  for (char c : path.name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
      r.fail_at(where + ".name", "may use only letters, digits, '_', '-' and '.', not " +
                                     q(path.name));
  for (const CameraPath& other : s.animation.paths)
    if (other.name == path.name) r.fail_at(where + ".name", "repeats the path name " + q(path.name));
  if (p.contains("description")) path.description = r.text(p["description"], where + ".description");  // free text
  const json& keys = key_array(r, p, where, "keys");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string w = JsonReader::index(where + ".keys", i);
    const json& k = r.object(keys[i], w);
    r.keys(k, w, {"time", "position", "target", "fov_y", "cut"});
    CameraKey key;
    key.time = read_key_time(r, k, w, i ? path.keys.back().time : -1.0f);
    key.position = r.required_vec3(k, w, "position");
    key.target = r.required_vec3(k, w, "target");
    if (glm::length(key.target - key.position) < 1e-6f)
      r.fail_at(w + ".target", "must differ from the position");
    // Without fov_y a key keeps the default camera's.
    key.fov_y_deg = r.number(k, w, "fov_y", s.cameras.at(0).fov_y_deg, 1.001f, 178.999f);
    key.cut = r.boolean(k, w, "cut", false);
    if (key.cut && i == 0) r.fail_at(w + ".cut", "cannot be true on a path's first key");
    path.keys.push_back(key);
  }
  return path;
}

ObjectMotion read_motion(const JsonReader& r, const json& j, const std::string& where,
                         const Scene& s, const std::map<std::string, std::vector<int>>& by_name) {
  const json& o = r.object(j, where);
  std::vector<std::string> kinds;
  for (const char* k : {"keys", "spin", "orbit"})
    if (o.contains(k)) kinds.push_back(k);
  if (kinds.empty()) r.fail_at(where, "needs one of \"keys\", \"spin\" or \"orbit\"");
  if (kinds.size() > 1)
    r.fail_at(where, "has both " + q(kinds[0]) + " and " + q(kinds[1]) +
                         " (give one of \"keys\", \"spin\" or \"orbit\")");
  ObjectMotion m;
  if (kinds[0] == "keys") {
    r.keys(o, where, {"meshes", "keys", "pivot"}, " for a keyframed motion");
  } else {
    r.keys(o, where, {"meshes", kinds[0]}, " for a" + std::string(kinds[0] == "spin" ? "" : "n") +
                                                   " " + kinds[0] + " motion");
  }

  // Every mesh of each name moves.
  const json& names = key_array(r, o, where, "meshes");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string w = JsonReader::index(where + ".meshes", i);
    const std::string name = r.string(names[i], w);
    const auto it = by_name.find(name);
    if (it == by_name.end()) r.fail_at(w, "names the unknown mesh " + q(name));
    for (std::size_t k = 0; k < i; ++k)
      if (names[k] == names[i]) r.fail_at(w, "repeats the mesh name " + q(name));
    for (int mesh : it->second) {
      if (s.meshes[static_cast<std::size_t>(mesh)].reflector != 0)
        r.fail_at(w, "names " + q(name) +
                         ", a planar reflector, but planar reflectors are fixed rectangles and "
                         "cannot move");
      m.meshes.push_back(mesh);
    }
  }
  // The default pivot: the centre of the box around the meshes at rest.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (int mesh : m.meshes)
    for (const Vertex& v : s.meshes[static_cast<std::size_t>(mesh)].vertices) {
      lo = glm::min(lo, v.position);
      hi = glm::max(hi, v.position);
    }
  const glm::vec3 centre = 0.5f * (lo + hi);

  if (kinds[0] == "keys") {
    m.kind = ObjectMotion::Kind::Keyframes;
    m.pivot = r.vec3(o, where, "pivot", centre);
    const json& keys = key_array(r, o, where, "keys");
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const std::string w = JsonReader::index(where + ".keys", i);
      const json& k = r.object(keys[i], w);
      r.keys(k, w, {"time", "translate", "rotate_deg", "scale"});
      TransformKey key;
      key.time = read_key_time(r, k, w, i ? m.keys.back().time : -1.0f);
      key.translate = r.vec3(k, w, "translate", key.translate);
      key.rotate_deg = r.vec3(k, w, "rotate_deg", key.rotate_deg, -36000.0f, 36000.0f);
      key.scale = read_scale(r, k, w);
      m.keys.push_back(key);
    }
  } else {
    const bool spin = kinds[0] == "spin";
    const std::string w = where + "." + kinds[0];
    const json& t = r.object(o[kinds[0]], w);
    r.keys(t, w, {"axis", "period", spin ? "pivot" : "center"});
    m.kind = spin ? ObjectMotion::Kind::Spin : ObjectMotion::Kind::Orbit;
    if (t.contains("axis")) m.axis = r.direction(t["axis"], w + ".axis");
    if (!t.contains("period")) r.fail_at(w + ".period", "is required");
    m.period = r.number(t["period"], w + ".period", -kMaxTime, kMaxTime);
    if (m.period == 0.0f) r.fail_at(w + ".period", "must not be 0 (seconds per turn)");
    if (spin)
      m.pivot = r.vec3(t, w, "pivot", centre);
    else
      m.pivot = r.required_vec3(t, w, "center");
  }
  return m;
}

void read_animation(const JsonReader& r, const json& j, Scene& s) {
  r.object(j, "animation");
  r.keys(j, "animation", {"duration", "paths", "objects"});
  Animation& a = s.animation;
  if (j.contains("paths")) {
    r.array(j["paths"], "animation.paths");
    for (std::size_t i = 0; i < j["paths"].size(); ++i)
      a.paths.push_back(read_path(r, j["paths"][i], JsonReader::index("animation.paths", i), s));
  }
  if (j.contains("objects")) {
    r.array(j["objects"], "animation.objects");
    std::map<std::string, std::vector<int>> by_name;
    for (std::size_t i = 0; i < s.meshes.size(); ++i)
      by_name[s.meshes[i].name].push_back(static_cast<int>(i));
    for (std::size_t i = 0; i < j["objects"].size(); ++i)
      a.objects.push_back(
          read_motion(r, j["objects"][i], JsonReader::index("animation.objects", i), s, by_name));
  }
  // Default duration: the last key time of any path or keyframed motion; 4 s of spinning and
  // orbiting when that is 0.
  float last = 0.0f;
  bool turns = false;
  for (const CameraPath& p : a.paths) last = std::max(last, p.keys.back().time);
  for (const ObjectMotion& m : a.objects) {
    if (m.kind == ObjectMotion::Kind::Keyframes) last = std::max(last, m.keys.back().time);
    turns |= m.kind != ObjectMotion::Kind::Keyframes;
  }
  a.duration = r.number(j, "animation", "duration", last == 0.0f && turns ? 4.0f : last, 0.0f,
                        kMaxTime);
}

}  // namespace

// ---- public API -----------------------------------------------------------------------------

Scene load_scene_json(const fs::path& path) {
  const json j = parse_json_file(path);
  const JsonReader r("scene file " + q(path), path);
  const fs::path dir = directory_of(path);
  r.keys(j, "",
         {"name", "description", "ambient", "environment", "materials", "meshes", "primitives",
          "lights", "cameras", "animation"});
  Scene s;
  LoadContext ctx;
  s.name = r.string(j, "", "name", path.stem().string());
  if (j.contains("description")) r.text(j["description"], "description");  // free text: empty too
  s.ambient = r.number(j, "", "ambient", s.ambient, 0.0f, kSceneValueMax);
  if (j.contains("environment")) read_environment(r, j["environment"], s.environment);
  if (j.contains("materials")) read_materials(r, j["materials"], s, ctx, dir);
  MaterialNames names;
  if (j.contains("meshes")) read_meshes(r, j["meshes"], s, ctx, names, dir);
  if (j.contains("primitives")) read_primitives(r, j["primitives"], s, names);
  if (s.meshes.empty()) fail("scene file " + q(path) + " has no meshes or primitives");
  if (s.triangle_count() > kMaxTriangles)
    fail("scene file " + q(path) + " has more than " + std::to_string(kMaxTriangles) +
         " triangles, more than supported");
  if (j.contains("lights")) read_lights(r, j["lights"], s);
  if (s.lights.size() > static_cast<std::size_t>(Scene::kMaxLights))
    r.fail_at("lights", "has " + std::to_string(s.lights.size()) + " lights, more than the " +
                            std::to_string(Scene::kMaxLights) + " supported");
  if (j.contains("cameras"))
    read_cameras(r, j["cameras"], s);
  else
    s.cameras.push_back(framing_camera(s));
  if (j.contains("animation")) read_animation(r, j["animation"], s);
  validate_file(s, path);
  return s;
}

// ---- pieces shared with other JSON files (scene_json.h) -------------------------------------

namespace scene_json {

json parse(const std::string& text, const std::string& label) {
  return parse_json_object(text, label);
}

Light read_light(const json& j, const std::string& label, const std::string& where) {
  return ::ssr::read_light(JsonReader(label), j, where);
}

Environment read_environment(const json& j, const std::string& label, const std::string& where) {
  Environment env;
  ::ssr::read_environment(JsonReader(label), j, env, where);
  return env;
}

Camera read_camera(const json& j, const std::string& label, const std::string& where,
                   const std::string& default_name) {
  return ::ssr::read_camera(JsonReader(label), j, where, default_name);
}

double json_float(float v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::strtod(std::string(buf, r.ptr).c_str(), nullptr);
}

nlohmann::ordered_json json_vec3(const glm::vec3& v) {
  return {json_float(v.x), json_float(v.y), json_float(v.z)};
}

nlohmann::ordered_json write_light(const Light& l) {
  nlohmann::ordered_json j;
  if (l.type == Light::Type::Point) {
    j["type"] = "point";
    j["position"] = json_vec3(l.position);
  } else {
    j["type"] = "directional";
    j["direction"] = json_vec3(l.direction);
  }
  j["color"] = json_vec3(l.color);
  j["intensity"] = json_float(l.intensity);
  if (l.type == Light::Type::Point) j["range"] = json_float(l.range);
  return j;
}

nlohmann::ordered_json write_environment(const Environment& e) {
  nlohmann::ordered_json j;
  if (e.type == Environment::Type::Sky) {
    j["type"] = "sky";
    j["zenith"] = json_vec3(e.zenith);
    j["horizon"] = json_vec3(e.horizon);
    j["ground"] = json_vec3(e.ground);
  } else {
    j["type"] = "constant";
    j["color"] = json_vec3(e.constant);
  }
  j["intensity"] = json_float(e.intensity);
  return j;
}

nlohmann::ordered_json write_camera(const Camera& c) {
  nlohmann::ordered_json j;
  if (!c.name.empty()) j["name"] = c.name;
  j["position"] = json_vec3(c.position);
  j["target"] = json_vec3(c.target);
  j["up"] = json_vec3(c.up);
  j["fov_y"] = json_float(c.fov_y_deg);
  j["near"] = json_float(c.near_plane);
  j["far"] = json_float(c.far_plane);
  return j;
}

}  // namespace scene_json

}  // namespace ssr
