// The built-in scenes. 1 unit = 1 m, +Y up, right-handed. Every scene passes validate().
//
// gallery  (default) 32 x 17 m mirror floor (planar reflector 1, metallic 1, roughness 0) with
//          boxes, spheres, columns, a brick back wall and a red emissive "marker" sphere.
//          Options (`gallery:reflectors=5,normal_map=tiles`):
//            reflectors=1..16 (default 1): N planar reflectors. N = 1 is the plain floor; N >= 2
//              adds a vertical mirror panel on the left (x = -8, facing +X), N >= 4 a second one
//              on the right (x = +9.5, facing -X), and the floor is split into the remaining
//              F = N - panels tiles (F = 1: the whole floor, still named "floor"), 4 cm apart
//              over a dark grout plane 1 cm below. Ids: floor tiles 1..F (back row first, left
//              to right), then the left panel, then the right one. Every tile is partly in view
//              of the default camera, and the floor tiles' rectangles run on behind the panels,
//              so reflectors overlap in screen space.
//            normal_map=ripples|tiles|none (default none): a procedural tangent-space normal map
//              on the mirror floor (ripples: concentric ripples from a few drops plus a faint
//              sine swell, 4 m per repeat; tiles: 0.5 m bevelled square tiles, 2 m per repeat).
//              The floor stays a planar reflector with the same rectangle(s).
//            floor_roughness=R, R a number in [0, 1] (default 0): the perceptual roughness of
//              the floor (every floor tile when reflectors > 1; the wall mirrors stay mirrors).
//              The PPR thesis's charts 5 and 6 (section 5.4, figures 31-37: a floor that is one
//              planar reflector at roughness 0.2, 0.5, 1.0, with and without a normal map) are
//              gallery:floor_roughness=0.2|0.5|1 and gallery:normal_map=tiles,floor_roughness=...
// cornell  5 x 5 x 5 m box open at the front (+Z): red left, green right, white back and
//          ceiling, glossy metal floor (roughness 0.3, no planar reflector), two white boxes.
// corridor 4 m wide, 3.5 m high, 40 m long, near-mirror floor (planar reflector 1, roughness
//          0.05), pillars and coloured panels along both walls, 8 ceiling lights.
// ramp     the roughness ramp (issue 14): a metal floor (metallic 1, albedo 0.9) in 11 bands of
//          perceptual roughness 0.0, 0.1, ..., 1.0, 0.7 m wide and 14 m long, side by side left
//          to right and running along the view, each its own mesh "band_0.0" .. "band_1.0" and
//          planar reflector: band k (roughness k/10) is reflector k + 1, so the breakdown's
//          "reflector:N" is the band of roughness (N - 1)/10. On it stand tall boxes and columns
//          (back row) and spheres and cubes (front row), one object per band, each its own
//          colour, with a glowing sphere on band_0.5; behind, a 12 m brick wall with a glowing
//          strip across it. Nothing but the bands is reflective. No moving objects.
// hard-*   stability scenes (issue 7): hard-grazing, hard-mirror-box, hard-thin,
//          hard-depth-range, hard-far-origin, hard-degenerate, hard-roughness, hard-reflectors;
//          described above their builders and in docs/ROBUSTNESS.md.
//
// Animation (scene/animation.h): every scene has named camera paths, chosen with the option
// path=NAME (e.g. gallery:path=pan, which sets Animation::default_path), and some move objects;
// assets/scenes/README.md lists them. Together they cover a dolly, an orbit, a fast pan, an
// object moving over a mirror, an object entering the view and camera cuts. At time 0 every
// scene is exactly the static scene built here (motions are the identity, paths start at the
// default camera): single-frame figures and tests are unchanged.
//
// Default-camera framing (16:9, fov_y 60, glm::lookAt + glm::perspective, NDC in [-1,1], +y up)
// is worked out in the comments next to each camera and checked by tests/unit.
#include "scene/builtin_scenes.h"

#include <algorithm>
#include <cmath>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/errors.h"
#include "core/params.h"
#include "scene/animation.h"
#include "scene/meshgen.h"

namespace ssr {

namespace {

// ---- small helpers -------------------------------------------------------------------------------

glm::mat4 translate(glm::vec3 t) { return glm::translate(glm::mat4(1.0f), t); }
glm::mat4 rotate_x(float deg) {
  return glm::rotate(glm::mat4(1.0f), glm::radians(deg), glm::vec3(1, 0, 0));
}
glm::mat4 rotate_y(float deg) {
  return glm::rotate(glm::mat4(1.0f), glm::radians(deg), glm::vec3(0, 1, 0));
}
glm::mat4 rotate_z(float deg) {
  return glm::rotate(glm::mat4(1.0f), glm::radians(deg), glm::vec3(0, 0, 1));
}

void scale_uv(Mesh& m, glm::vec2 s) {
  for (Vertex& v : m.vertices) v.uv *= s;
}

struct Builder {
  Scene s;

  int material(Material m) {
    s.materials.push_back(std::move(m));
    return static_cast<int>(s.materials.size()) - 1;
  }
  int image(Image im) {
    s.images.push_back(std::move(im));
    return static_cast<int>(s.images.size()) - 1;
  }
  // Adds `m` (already in its local frame) transformed by `xf`; returns its index.
  std::size_t mesh(Mesh m, std::string name, int mat, const glm::mat4& xf = glm::mat4(1.0f),
                   int reflector = 0) {
    meshgen::transform(m, xf);
    m.name = std::move(name);
    m.material = mat;
    m.reflector = reflector;
    s.meshes.push_back(std::move(m));
    return s.meshes.size() - 1;
  }
  void light(glm::vec3 pos, glm::vec3 color, float intensity, float range) {
    Light l;
    l.type = Light::Type::Point;
    l.position = pos;
    l.color = color;
    l.intensity = intensity;
    l.range = range;
    s.lights.push_back(l);
  }
  void camera(std::string name, glm::vec3 pos, glm::vec3 target, float fov = 60.0f) {
    Camera c;
    c.name = std::move(name);
    c.position = pos;
    c.target = target;
    c.up = {0, 1, 0};
    c.fov_y_deg = fov;
    c.near_plane = 0.05f;
    c.far_plane = 200.0f;
    s.cameras.push_back(c);
  }
  // ---- animation ----
  int mesh_index(const std::string& name) const {
    for (std::size_t i = 0; i < s.meshes.size(); ++i)
      if (s.meshes[i].name == name) return static_cast<int>(i);
    throw std::logic_error("built-in scene '" + s.name + "' has no mesh '" + name + "'");
  }
  void path(std::string name, std::string description, std::vector<CameraKey> keys) {
    s.animation.paths.push_back({std::move(name), std::move(description), std::move(keys)});
  }
  // `m` moving the named meshes; keyframes and spins turn about the meshes' bounding-box centre
  // (orbits keep m.pivot, their centre).
  void motion(ObjectMotion m, const std::vector<std::string>& names) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const std::string& n : names) {
      m.meshes.push_back(mesh_index(n));
      for (const Vertex& v : s.meshes[static_cast<std::size_t>(m.meshes.back())].vertices) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
      }
    }
    if (m.kind != ObjectMotion::Kind::Orbit) m.pivot = 0.5f * (lo + hi);
    s.animation.objects.push_back(std::move(m));
  }
  // A horizontal (+Y facing) planar reflector rectangle; returns its 1-based id.
  int floor_reflector(glm::vec3 center, glm::vec2 half_extents) {
    Reflector r;
    r.center = center;
    r.tangent = {1, 0, 0};
    // normal() = normalize(cross(bitangent, tangent)) = cross(+Z, +X) = +Y.
    r.bitangent = {0, 0, 1};
    r.half_extents = half_extents;
    s.reflectors.push_back(r);
    return static_cast<int>(s.reflectors.size());
  }
};

Material mat(std::string name, glm::vec3 albedo, float roughness, float metallic = 0.0f,
             float reflectance = 0.5f, glm::vec3 emission = glm::vec3(0.0f)) {
  Material m;
  m.name = std::move(name);
  m.albedo = albedo;
  m.roughness = roughness;
  m.metallic = metallic;
  m.reflectance = reflectance;
  m.emission = emission;
  return m;
}

// ---- animation helpers --------------------------------------------------------------------------
// Every motion is the identity at time 0 and every path starts at (or next to) the default
// camera, so time 0 is the static scene exactly.

CameraKey key(float time, glm::vec3 position, glm::vec3 target, float fov = 60.0f,
              bool cut = false) {
  return CameraKey{time, position, target, fov, cut};
}
CameraKey key(float time, const Camera& c, bool cut = false) {
  return key(time, c.position, c.target, c.fov_y_deg, cut);
}

glm::vec3 yawed(glm::vec3 v, float deg) { return glm::vec3(rotate_y(deg) * glm::vec4(v, 0.0f)); }

// Keys every `step` seconds over [0, duration]: camera `c` (position and target) turned by
// angle(t) degrees about the vertical axis through `centre` (+ = counter-clockwise from above).
template <class Angle>
std::vector<CameraKey> orbit_keys(const Camera& c, glm::vec3 centre, float duration, float step,
                                  Angle angle) {
  std::vector<CameraKey> keys;
  const int n = static_cast<int>(std::lround(duration / step));
  for (int i = 0; i <= n; ++i) {
    const float t = static_cast<float>(i) * step, a = angle(t);
    keys.push_back(a == 0.0f ? key(t, c)
                             : key(t, centre + yawed(c.position - centre, a),
                                   centre + yawed(c.target - centre, a), c.fov_y_deg));
  }
  return keys;
}

// A pan: camera `c` stays put and turns by the given (time, degrees) pairs (+ = to the left).
std::vector<CameraKey> pan_keys(const Camera& c, std::initializer_list<std::pair<float, float>> turns) {
  std::vector<CameraKey> keys;
  for (const auto& [t, deg] : turns)
    keys.push_back(deg == 0.0f ? key(t, c)
                               : key(t, c.position, c.position + yawed(c.target - c.position, deg),
                                     c.fov_y_deg));
  return keys;
}

ObjectMotion keyframes(std::vector<TransformKey> keys) {
  ObjectMotion m;
  m.kind = ObjectMotion::Kind::Keyframes;
  m.keys = std::move(keys);
  return m;
}
ObjectMotion spin(glm::vec3 axis, float period) {
  ObjectMotion m;
  m.kind = ObjectMotion::Kind::Spin;
  m.axis = glm::normalize(axis);
  m.period = period;
  return m;
}
ObjectMotion orbit(glm::vec3 centre, glm::vec3 axis, float period) {
  ObjectMotion m;
  m.kind = ObjectMotion::Kind::Orbit;
  m.pivot = centre;
  m.axis = glm::normalize(axis);
  m.period = period;
  return m;
}
// A translation-only key.
TransformKey slide(float time, glm::vec3 translate = glm::vec3(0.0f)) {
  return TransformKey{time, translate, glm::vec3(0.0f), glm::vec3(1.0f)};
}

std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
float hash01(std::uint32_t x) { return static_cast<float>(hash32(x) & 0xffffffU) / 16777215.0f; }

// A running-bond brick texture (sRGB RGBA8): `rows` courses of `cols` bricks per tile, every
// other course offset by half a brick, per-brick tint and per-pixel grain. Tiles seamlessly
// when rows is even.
Image bricks(int size, int rows, int cols, glm::vec3 brick_srgb, glm::vec3 mortar_srgb,
             std::uint32_t seed) {
  Image im;
  im.width = im.height = size;
  im.rgba.resize(static_cast<std::size_t>(size) * size * 4);
  const int bh = size / rows, bw = size / cols, mortar = std::max(2, size / 96);
  for (int y = 0; y < size; ++y) {
    const int row = y / bh;
    const int shift = (row % 2) ? bw / 2 : 0;
    for (int x = 0; x < size; ++x) {
      const int xs = (x + shift) % size;
      const int col = xs / bw;
      const bool is_mortar = (y % bh) < mortar || (xs % bw) < mortar;
      const float grain = 0.92f + 0.08f * hash01(seed ^ static_cast<std::uint32_t>(y * size + x));
      glm::vec3 c;
      if (is_mortar) {
        c = mortar_srgb * grain;
      } else {
        const std::uint32_t id = static_cast<std::uint32_t>(row * cols + col) * 2654435761U + seed;
        const float tint = 0.8f + 0.3f * hash01(id);
        const float warm = 0.06f * (hash01(id + 17U) - 0.5f);
        c = brick_srgb * tint * grain + glm::vec3(warm, 0.0f, -warm);
      }
      c = glm::clamp(c, 0.0f, 1.0f);
      std::uint8_t* p = &im.rgba[(static_cast<std::size_t>(y) * size + x) * 4];
      p[0] = static_cast<std::uint8_t>(std::lround(c.x * 255.0f));
      p[1] = static_cast<std::uint8_t>(std::lround(c.y * 255.0f));
      p[2] = static_cast<std::uint8_t>(std::lround(c.z * 255.0f));
      p[3] = 255;
    }
  }
  return im;
}

// ---- normal maps --------------------------------------------------------------------------------
// Tangent-space normal maps (linear RGBA8, n * 0.5 + 0.5) built from a periodic height field
// H(u, v) in units of one repeat of the map, u to the right and v *up* in the image, row 0 on
// top (as every Image): pixel (x, row) samples u = (x + 0.5) / S, v = 1 - (row + 0.5) / S. The
// normal is normalize(-dH/du, -dH/dv, 1) by central differences with wrap-around, so it is
// seamless; its +X is the mesh tangent (+u) and its +Y the bitangent (+v, image up).

template <class HeightFn>
Image normal_map_from_height(int size, HeightFn height) {
  std::vector<float> h(static_cast<std::size_t>(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      h[static_cast<std::size_t>(y) * size + x] =
          height((static_cast<float>(x) + 0.5f) / static_cast<float>(size),
                 1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(size));
  auto at = [&](int x, int y) {
    x = (x + size) % size;
    y = (y + size) % size;
    return h[static_cast<std::size_t>(y) * size + x];
  };
  Image im;
  im.width = im.height = size;
  im.rgba.resize(static_cast<std::size_t>(size) * size * 4);
  const float half_s = 0.5f * static_cast<float>(size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const float dhdu = (at(x + 1, y) - at(x - 1, y)) * half_s;
      const float dhdv = (at(x, y - 1) - at(x, y + 1)) * half_s;  // row y - 1 is higher up (+v)
      const glm::vec3 n = glm::normalize(glm::vec3(-dhdu, -dhdv, 1.0f));
      std::uint8_t* p = &im.rgba[(static_cast<std::size_t>(y) * size + x) * 4];
      for (int c = 0; c < 3; ++c)
        p[c] = static_cast<std::uint8_t>(std::lround(std::clamp(n[c] * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
      p[3] = 255;
    }
  }
  return im;
}

// Concentric ripples around three drops (each windowed smoothly to zero within its radius,
// measured on the torus so the map tiles) over a faint diagonal sine swell. Steepest ripple
// slope ~0.18 (10 deg), the swell's 0.04.
Image ripples_normal_map(int size) {
  constexpr float two_pi = 2.0f * std::numbers::pi_v<float>;
  struct Drop {
    float u, v, radius, wavelength;
  };
  static constexpr Drop drops[] = {{0.30f, 0.62f, 0.45f, 0.055f},
                                   {0.74f, 0.30f, 0.40f, 0.070f},
                                   {0.82f, 0.84f, 0.28f, 0.045f}};
  return normal_map_from_height(size, [&](float u, float v) {
    float h = 0.04f / (two_pi * std::sqrt(13.0f)) * std::sin(two_pi * (2.0f * u + 3.0f * v));
    for (const Drop& d : drops) {
      float du = u - d.u, dv = v - d.v;
      du -= std::round(du);
      dv -= std::round(dv);
      const float r = std::sqrt(du * du + dv * dv) / d.radius;
      if (r >= 1.0f) continue;
      const float w = (1.0f - r * r) * (1.0f - r * r);
      h += 0.18f * d.wavelength / two_pi * w * std::cos(two_pi * r * d.radius / d.wavelength);
    }
    return h;
  });
}

// `per_side` x `per_side` square tiles per repeat: flat tops, a bevel 10% of a tile wide
// sloping down at ~31 deg (slope 0.6) to a flat groove 6% of a tile wide between tiles.
Image tiles_normal_map(int size, int per_side) {
  constexpr float groove = 0.03f, bevel = 0.10f, slope = 0.6f;  // in units of one tile
  const float n = static_cast<float>(per_side);
  return normal_map_from_height(size, [&](float u, float v) {
    const float a = u * n - std::floor(u * n), c = v * n - std::floor(v * n);
    const float e = std::min(std::min(a, 1.0f - a), std::min(c, 1.0f - c));  // to the nearest edge
    return slope * bevel / n * std::clamp((e - groove) / bevel, 0.0f, 1.0f);
  });
}

// ---- options ------------------------------------------------------------------------------------
// "name:key=value,key=value". The options are parameter rows (core/params.h, the same
// description techniques use) over one struct; each scene lists the rows it takes, and
// parse_options checks keys and values against them, so a maker reads typed values.

struct SceneOptions {
  std::int32_t reflectors = 1;
  std::int32_t normal_map = 2;  // ripples, tiles, none
  float floor_roughness = 0.0f;
  std::int32_t path = -1;       // a choice of the scene's paths; -1: none (the scene's default)
};
const SceneOptions kDefaultOptions{};

const ParamDesc kReflectorsOption = SSR_PARAM_INT(SceneOptions, reflectors, 1, Scene::kMaxReflectors, "",
                                                  "planar reflectors: floor tiles, then wall mirrors");
const ParamDesc kNormalMapOption = SSR_PARAM_CHOICE(SceneOptions, normal_map, "a procedural normal map on the floor",
                                                    "ripples", "tiles", "none");
const ParamDesc kFloorRoughnessOption = SSR_PARAM_FLOAT(SceneOptions, floor_roughness, 0, 1, 0.05, "",
                                                        "the mirror floor's roughness (0: a mirror)");

// "path=NAME": the scene's camera path names (as its maker adds them; a unit test compares),
// none by default.
ParamDesc path_option(std::vector<const char*> names) {
  ParamDesc d = SSR_PARAM_CHOICE(SceneOptions, path, "the camera path a sequence or the viewer starts on", "");
  d.choices = std::move(names);
  d.max = static_cast<double>(d.choices.size()) - 1;
  d.auto_value = -1;  // none: the scene's default
  return d;
}

// What `key=` takes: "1..16", "0.0..1.0" (a real number) or "a|b|c".
std::string allowed(const ParamDesc& d) {
  if (d.type == ParamType::Choice) {
    std::string s;
    for (const char* c : d.choices) s += (s.empty() ? "" : "|") + std::string(c);
    return s;
  }
  char buf[64];
  if (d.type == ParamType::Float) std::snprintf(buf, sizeof buf, "%.1f..%.1f", d.min, d.max);
  else std::snprintf(buf, sizeof buf, "%d..%d", static_cast<int>(d.min), static_cast<int>(d.max));
  return buf;
}

// A decimal number as the whole of `text` (no sign but '-', no spaces; locale-independent), if
// it is one and finite.
std::optional<double> parse_number(std::string_view text) {
  double v = 0.0;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, v, std::chars_format::general);
  if (text.empty() || ec != std::errc() || end != last || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string options_help(const std::vector<ParamDesc>& rows) {
  std::string s;
  for (const ParamDesc& o : rows) s += (s.empty() ? "" : ", ") + std::string(o.name) + "=" + allowed(o);
  return s;
}

// ---- gallery ------------------------------------------------------------------------------------

Scene gallery(const SceneOptions& opt) {
  Builder b;
  b.s.name = "gallery";
  const int n_reflectors = opt.reflectors;
  const std::string normal_map = kNormalMapOption.choices[static_cast<std::size_t>(opt.normal_map)];
  // + 0.0f: "-0" gives roughness +0.
  const float floor_roughness = opt.floor_roughness + 0.0f;

  // Floor: x in [-16, 16], z in [-7, 10], y = 0; planar reflector 1, metallic; a perfect mirror
  // (roughness 0) unless floor_roughness says otherwise.
  Material mirror_floor = mat("mirror_floor", glm::vec3(0.9f), floor_roughness, 1.0f, 1.0f);
  float normal_period = 1.0f;  // metres of floor per repeat of the normal map
  if (normal_map != "none") {
    normal_period = normal_map == "ripples" ? 4.0f : 2.0f;
    mirror_floor.normal_texture =
        b.image(normal_map == "ripples" ? ripples_normal_map(256) : tiles_normal_map(256, 4));
    mirror_floor.normal_strength = 1.0f;
  }
  const int mirror = b.material(mirror_floor);
  // The floor meshes come from meshgen::plane: tangent +X (w = +1), normal +Y, so the shader's
  // bitangent cross(n, t) * w = -Z is dP/dv. A normal map's +Y (image up) therefore points
  // away from the default camera (-Z) and its +X to the right (+X). World-anchored uvs keep the
  // pattern continuous across floor tiles.
  auto floor_uv = [&](Mesh& m) {
    if (normal_map == "none") return;
    for (Vertex& v : m.vertices)
      v.uv = glm::vec2(v.position.x + 16.0f, 10.0f - v.position.z) / normal_period;
  };
  const int wall_panels = n_reflectors >= 4 ? 2 : (n_reflectors >= 2 ? 1 : 0);
  const int tiles = n_reflectors - wall_panels;
  if (tiles == 1) {
    const int refl = b.floor_reflector({0, 0, 1.5f}, {16.0f, 8.5f});
    Mesh floor = meshgen::plane({32.0f, 17.0f});
    meshgen::transform(floor, translate({0, 0, 1.5f}));
    floor_uv(floor);
    b.mesh(std::move(floor), "floor", mirror, glm::mat4(1.0f), refl);
  } else {
    // Rows split z in [-7, 10] with inner boundaries spread evenly over [-7, 5] (the default
    // camera sees the floor up to z ~ 4.9); within a row the inner column boundaries are spread
    // over +-0.8 (7 - z_far) (a bit inside the frame at the row's far edge), the outer tiles
    // running on to x = +-16. So every tile shows in the default view. Tiles are 4 cm apart.
    constexpr float gap = 0.04f;
    const int rows = std::clamp(static_cast<int>(std::lround(std::sqrt(tiles / 2.0f))), 1, 4);
    auto row_z = [&](int i) {
      return i == rows ? 10.0f : -7.0f + 12.0f * static_cast<float>(i) / static_cast<float>(rows);
    };
    int id_in_order = 0;
    for (int i = 0; i < rows; ++i) {
      const int cols = tiles / rows + (i < tiles % rows ? 1 : 0);  // extra tiles in the back rows
      const float z0 = row_z(i) + (i > 0 ? 0.5f * gap : 0.0f);
      const float z1 = row_z(i + 1) - (i + 1 < rows ? 0.5f * gap : 0.0f);
      const float span = std::min(15.0f, 0.8f * (7.0f - row_z(i)));
      auto col_x = [&](int j) {
        if (j == 0) return -16.0f;
        if (j == cols) return 16.0f;
        return -span + 2.0f * span * static_cast<float>(j) / static_cast<float>(cols);
      };
      for (int j = 0; j < cols; ++j) {
        const float x0 = col_x(j) + (j > 0 ? 0.5f * gap : 0.0f);
        const float x1 = col_x(j + 1) - (j + 1 < cols ? 0.5f * gap : 0.0f);
        const glm::vec3 c(0.5f * (x0 + x1), 0.0f, 0.5f * (z0 + z1));
        const glm::vec2 size(x1 - x0, z1 - z0);
        const int refl = b.floor_reflector(c, 0.5f * size);
        Mesh tile = meshgen::plane(size);
        meshgen::transform(tile, translate(c));
        floor_uv(tile);
        b.mesh(std::move(tile), "floor_tile_" + std::to_string(++id_in_order), mirror,
               glm::mat4(1.0f), refl);
      }
    }
    // What shows through the gaps: a dark matte plane just under the tiles.
    b.mesh(meshgen::plane({32.0f, 17.0f}), "floor_grout",
           b.material(mat("grout", glm::vec3(0.04f), 0.9f)), translate({0, -0.01f, 1.5f}));
  }
  if (wall_panels > 0) {
    // Vertical mirrors standing on the floor, each on a dark frame box that hides its back.
    const int wall_mirror = b.material(mat("wall_mirror", glm::vec3(0.95f), 0.0f, 1.0f, 1.0f));
    const int frame = b.material(mat("mirror_frame", {0.12f, 0.10f, 0.09f}, 0.6f));
    struct Panel {
      const char* name;
      float x, z, length;  // plane x, centre z, length along z; y in [0.2, 3.2]
      float facing;        // +1: faces +X, -1: faces -X
    };
    const Panel panels[2] = {{"mirror_left", -8.0f, -3.5f, 6.0f, 1.0f},
                             {"mirror_right", 9.5f, -4.0f, 5.0f, -1.0f}};
    for (int k = 0; k < wall_panels; ++k) {
      const Panel& p = panels[k];
      Reflector r;
      r.center = {p.x, 1.7f, p.z};
      // normal() = cross(bitangent, tangent) = cross(+Y, +-Z) = +-X.
      r.tangent = {0.0f, 0.0f, p.facing};
      r.bitangent = {0.0f, 1.0f, 0.0f};
      r.half_extents = {0.5f * p.length, 1.5f};
      b.s.reflectors.push_back(r);
      const int refl = static_cast<int>(b.s.reflectors.size());
      // plane() faces +Y; rotating by -+90 deg about Z turns it to face +-X (its x -> height).
      b.mesh(meshgen::plane({3.0f, p.length}), p.name, wall_mirror,
             translate(r.center) * rotate_z(-90.0f * p.facing), refl);
      b.mesh(meshgen::box({0.1f, 3.4f, p.length + 0.3f}), std::string(p.name) + "_frame", frame,
             translate({p.x - p.facing * 0.06f, 1.7f, p.z}));
    }
  }

  // Back wall: z = -7, facing +Z, x in [-16, 16], y in [0, 7]; sandstone bricks, 2 m per tile.
  const int brick_img = b.image(bricks(256, 8, 4, {0.78f, 0.70f, 0.55f}, {0.55f, 0.55f, 0.53f}, 7U));
  Material wall = mat("brick_wall", glm::vec3(1.0f), 0.85f);
  wall.albedo_texture = brick_img;
  const int wall_mat = b.material(wall);
  Mesh back = meshgen::plane({32.0f, 7.0f});
  scale_uv(back, {16.0f, 3.5f});
  b.mesh(std::move(back), "back_wall", wall_mat, translate({0, 3.5f, -7.0f}) * rotate_x(90.0f));

  // The marker: a small saturated, emissive red sphere standing on the floor. Centre (world):
  // (-0.9, 0.3, 2.5), radius 0.3; its mirror image is centred at (-0.9, -0.3, 2.5). Tests find
  // it by the mesh name "marker". Nothing else in the scene is red.
  const int red = b.material(
      mat("marker_red", {1.0f, 0.04f, 0.03f}, 0.4f, 0.0f, 0.5f, {4.0f, 0.12f, 0.06f}));
  b.mesh(meshgen::sphere(0.3f, 32, 16), "marker", red, translate({-0.9f, 0.3f, 2.5f}));

  // Objects (all behind or beside the marker as seen from the default camera).
  const int gold = b.material(mat("gold", {1.0f, 0.78f, 0.34f}, 0.25f, 1.0f, 0.5f));
  const int green = b.material(mat("green", {0.15f, 0.65f, 0.25f}, 0.5f));
  const int blue = b.material(mat("blue", {0.15f, 0.30f, 0.85f}, 0.45f));
  const int yellow = b.material(mat("yellow", {0.90f, 0.75f, 0.20f}, 0.6f));
  const int purple = b.material(mat("purple", {0.55f, 0.25f, 0.80f}, 0.5f));
  const int teal = b.material(mat("teal", {0.10f, 0.60f, 0.60f}, 0.5f));
  const int white = b.material(mat("white", {0.85f, 0.85f, 0.85f}, 0.3f));
  const int marble = b.material(mat("marble", {0.85f, 0.82f, 0.76f}, 0.35f));

  b.mesh(meshgen::sphere(0.8f), "sphere_gold", gold, translate({1.4f, 0.8f, -1.2f}));
  b.mesh(meshgen::sphere(0.6f), "sphere_green", green, translate({3.8f, 0.6f, 1.0f}));
  b.mesh(meshgen::box({1.2f, 1.2f, 1.2f}), "box_blue", blue,
         translate({-3.2f, 0.6f, -0.8f}) * rotate_y(25.0f));
  b.mesh(meshgen::box({0.8f, 2.4f, 0.8f}), "box_tall_yellow", yellow,
         translate({-1.0f, 1.2f, -3.2f}) * rotate_y(-15.0f));
  b.mesh(meshgen::box({0.6f, 0.6f, 0.6f}), "box_small_purple", purple,
         translate({2.4f, 0.3f, -3.6f}) * rotate_y(40.0f));
  b.mesh(meshgen::cylinder(0.5f, 0.9f), "pedestal_teal", teal, translate({-4.8f, 0.0f, 2.0f}));
  b.mesh(meshgen::sphere(0.35f), "sphere_white", white, translate({-4.8f, 1.25f, 2.0f}));
  const glm::vec2 columns[] = {{-6.0f, -4.5f}, {6.0f, -4.5f}, {-6.0f, 0.5f}, {6.0f, 0.5f}};
  for (int i = 0; i < 4; ++i)
    b.mesh(meshgen::cylinder(0.35f, 5.0f), "column_" + std::to_string(i + 1), marble,
           translate({columns[i].x, 0.0f, columns[i].y}));

  // Lights: warm left, cool right, magenta near the wall, white key above the camera.
  b.light({-4.5f, 4.0f, 3.0f}, {1.0f, 0.75f, 0.5f}, 60.0f, 25.0f);
  b.light({4.5f, 3.5f, 2.0f}, {0.5f, 0.7f, 1.0f}, 60.0f, 25.0f);
  b.light({0.0f, 2.5f, -5.5f}, {1.0f, 0.3f, 0.85f}, 25.0f, 15.0f);
  b.light({0.0f, 6.0f, 5.0f}, {1.0f, 1.0f, 1.0f}, 40.0f, 25.0f);

  // Default camera: eye 1.6 m, ~6.9 deg down. At 16:9 the marker centre lands at NDC
  // (-0.19, -0.28) and its mirror image at (-0.19, -0.50) (uv (0.41, 0.36) and (0.41, 0.25),
  // y up); the wall's base line is at NDC y = +0.01, so the mirror floor fills the lower half
  // of the frame; the wall's reflection reaches down to NDC y = -0.79, the sky's below that.
  // The front columns run off the top edge and their reflections off the bottom edge.
  b.camera("default", {0.0f, 1.6f, 7.0f}, {0.0f, 0.75f, 0.0f});
  b.camera("low", {0.0f, 0.35f, 7.5f}, {0.0f, 0.6f, 0.0f});     // grazing view of the mirror
  b.camera("high", {0.0f, 7.5f, 9.0f}, {0.0f, 0.0f, -0.5f});    // steep look down
  b.camera("side", {9.0f, 2.2f, 5.0f}, {0.0f, 0.8f, -1.0f});    // oblique, from the right

  // Motions: sphere_green slides 4.4 m left over the mirror floor and back (2.2 m/s; it passes
  // 1.5 m behind the marker and 2.2 m in front of the gold sphere); the teal pedestal with its
  // white sphere (at the default view's left edge) moves 5 m left, out of view, and comes back.
  b.motion(keyframes({slide(0), slide(2, {-4.4f, 0, 0}), slide(4)}), {"sphere_green"});
  b.motion(keyframes({slide(0), slide(1.5f, {-5, 0, 0}), slide(2.5f, {-5, 0, 0}), slide(4)}),
           {"pedestal_teal", "sphere_white"});
  const Camera& cam = b.s.cameras[0];
  const glm::vec3 to_target = cam.target - cam.position;
  b.path("dolly", "camera dolly: 3.5 m in along the default view, halfway to its target (4 s)",
         {key(0, cam), key(2, cam.position + 0.25f * to_target, cam.target),
          key(4, cam.position + 0.5f * to_target, cam.target)});
  b.path("orbit",
         "camera orbit: swings 50 deg to either side of the default view about the vertical axis "
         "through the floor's centre (6 s)",
         orbit_keys(cam, glm::vec3(0.0f), 6.0f, 0.25f,
                    [](float t) { return 50.0f * std::sin(std::numbers::pi_v<float> * t / 3.0f); }));
  b.path("pan",
         "fast pan: from the default position turns 40 deg left, 80 deg right and back in 2 s (up "
         "to ~110 deg/s): disocclusion at the screen edges",
         pan_keys(cam, {{0.0f, 0.0f}, {0.5f, 40.0f}, {1.25f, -40.0f}, {2.0f, 0.0f}}));
  b.path("slide",
         "object over the mirror: the default camera holds while sphere_green slides across the "
         "mirror floor and back and the teal pedestal leaves the view on the left and returns (4 s)",
         {key(0, cam), key(4, cam)});
  b.path("enter",
         "object entering the screen: the default camera zoomed in (fov 28): sphere_green enters "
         "from the right edge at ~0.2 s, crosses the frame and leaves again at ~3.8 s (4 s)",
         {key(0, cam.position, cam.target, 28.0f), key(4, cam.position, cam.target, 28.0f)});
  const Camera& side = b.s.cameras[3];
  b.path("cut",
         "camera cut: the default view for 2 s, then a cut to the side camera, which moves 1.6 m "
         "closer (4 s)",
         {key(0, cam), key(2, side, /*cut=*/true),
          key(4, side.position + 0.15f * (side.target - side.position), side.target)});
  b.s.animation.duration = 6.0f;

  b.s.environment.type = Environment::Type::Sky;
  b.s.ambient = 0.3f;
  return b.s;
}

// ---- cornell ------------------------------------------------------------------------------------

Scene cornell() {
  Builder b;
  b.s.name = "cornell";
  // Interior x in [-2.5, 2.5], y in [0, 5], z in [-2.5, 2.5]; walls are 0.2 m thick boxes whose
  // inner faces bound the interior. The front (z = +2.5) is open.
  constexpr float t = 0.2f;
  const int floor_mat = b.material(mat("glossy_metal_floor", glm::vec3(0.85f), 0.3f, 1.0f, 1.0f));
  const int white = b.material(mat("white", glm::vec3(0.73f), 0.8f));
  const int red = b.material(mat("red", {0.65f, 0.05f, 0.05f}, 0.8f));
  const int green = b.material(mat("green", {0.12f, 0.45f, 0.15f}, 0.8f));
  const int lamp = b.material(mat("lamp", glm::vec3(1.0f), 0.5f, 0.0f, 0.5f, {8.0f, 7.4f, 6.4f}));

  b.mesh(meshgen::box({5.0f + 2 * t, t, 5.0f + t}), "floor", floor_mat,
         translate({0.0f, -0.5f * t, -0.5f * t}));
  b.mesh(meshgen::box({5.0f + 2 * t, t, 5.0f + t}), "ceiling", white,
         translate({0.0f, 5.0f + 0.5f * t, -0.5f * t}));
  b.mesh(meshgen::box({5.0f + 2 * t, 5.0f, t}), "back_wall", white,
         translate({0.0f, 2.5f, -2.5f - 0.5f * t}));
  b.mesh(meshgen::box({t, 5.0f, 5.0f}), "left_wall", red, translate({-2.5f - 0.5f * t, 2.5f, 0.0f}));
  b.mesh(meshgen::box({t, 5.0f, 5.0f}), "right_wall", green, translate({2.5f + 0.5f * t, 2.5f, 0.0f}));
  // A 1.2 m emissive panel just under the ceiling, facing down.
  b.mesh(meshgen::plane({1.2f, 1.2f}), "light_panel", lamp,
         translate({0.0f, 4.99f, 0.0f}) * rotate_z(180.0f));

  b.mesh(meshgen::box({1.3f, 2.8f, 1.3f}), "tall_box", white,
         translate({-0.95f, 1.4f, -0.9f}) * rotate_y(18.0f));
  b.mesh(meshgen::box({1.3f, 1.3f, 1.3f}), "short_box", white,
         translate({1.0f, 0.65f, 0.6f}) * rotate_y(-17.0f));

  b.light({0.0f, 4.5f, 0.3f}, {1.0f, 0.9f, 0.78f}, 30.0f, 14.0f);

  // Default: 3 m in front of the open side, eye at mid height, ~3 deg down. The back wall
  // spans NDC x in [-0.30, 0.30], the side walls' front edges are at x = +-0.81 (beyond them
  // the dark environment), the floor is visible from z ~ 1.7 to the back wall (NDC y from -1
  // to -0.44) and the ceiling's lamp panel sits near the top edge (NDC y ~ 0.9).
  b.camera("default", {0.0f, 2.5f, 5.5f}, {0.0f, 2.2f, 0.0f});
  b.camera("inside", {0.0f, 2.6f, 2.2f}, {0.0f, 1.3f, -2.5f});
  b.camera("low", {0.0f, 0.45f, 5.5f}, {0.0f, 0.9f, -2.5f});
  b.camera("corner", {2.1f, 4.2f, 2.1f}, {-0.8f, 0.6f, -1.2f});

  // The short box spins on the glossy floor (one turn in 4 s; its corners stay 0.6 m from the
  // walls and the tall box).
  b.motion(spin({0, 1, 0}, 4.0f), {"short_box"});
  b.path("dolly",
         "camera dolly: from the default view through the open front into the box (4 s)",
         {key(0, b.s.cameras[0]), key(4, {0.0f, 2.3f, 2.3f}, {0.0f, 1.8f, -2.5f})});
  b.s.animation.duration = 4.0f;

  b.s.environment.type = Environment::Type::Constant;
  b.s.environment.constant = glm::vec3(0.06f, 0.06f, 0.07f);
  b.s.ambient = 1.0f;
  return b.s;
}

// ---- corridor -----------------------------------------------------------------------------------

Scene corridor() {
  Builder b;
  b.s.name = "corridor";
  // x in [-2, 2], y in [0, 3.5], z in [-40, 0]; closed at both ends.
  constexpr float W = 4.0f, H = 3.5f, L = 40.0f;
  const int floor_mat = b.material(mat("polished_floor", glm::vec3(0.85f), 0.05f, 1.0f, 1.0f));
  const int wall_img =
      b.image(bricks(256, 8, 4, {0.62f, 0.66f, 0.72f}, {0.80f, 0.80f, 0.78f}, 23U));
  Material wall = mat("tiled_wall", glm::vec3(1.0f), 0.7f);
  wall.albedo_texture = wall_img;
  const int wall_mat = b.material(wall);
  const int ceiling_mat = b.material(mat("ceiling", glm::vec3(0.8f), 0.9f));
  const int end_mat =
      b.material(mat("end_wall_glow", {0.9f, 0.9f, 0.85f}, 0.6f, 0.0f, 0.5f, {1.2f, 1.1f, 0.9f}));
  const int near_mat = b.material(mat("near_wall", {0.6f, 0.6f, 0.62f}, 0.8f));
  const int pillar_mat = b.material(mat("pillar", {0.85f, 0.82f, 0.76f}, 0.5f));
  const int fixture_mat =
      b.material(mat("light_fixture", glm::vec3(1.0f), 0.5f, 0.0f, 0.5f, {6.0f, 5.8f, 5.2f}));
  const glm::vec3 panel_colors[6] = {{0.95f, 0.45f, 0.10f}, {0.95f, 0.85f, 0.20f},
                                     {0.20f, 0.80f, 0.30f}, {0.10f, 0.70f, 0.85f},
                                     {0.20f, 0.30f, 0.95f}, {0.85f, 0.20f, 0.75f}};
  const char* panel_names[6] = {"panel_orange", "panel_yellow", "panel_green",
                                "panel_cyan", "panel_blue", "panel_magenta"};
  int panel_mat[6];
  for (int i = 0; i < 6; ++i)
    panel_mat[i] = b.material(mat(panel_names[i], panel_colors[i], 0.4f, 0.0f, 0.5f,
                                  0.35f * panel_colors[i]));

  const int refl = b.floor_reflector({0.0f, 0.0f, -0.5f * L}, {0.5f * W, 0.5f * L});
  b.mesh(meshgen::plane({W, L}), "floor", floor_mat, translate({0.0f, 0.0f, -0.5f * L}), refl);
  b.mesh(meshgen::plane({W, L}), "ceiling", ceiling_mat,
         translate({0.0f, H, -0.5f * L}) * rotate_x(180.0f));
  // Side walls: a plane (length along x, height along z) stood up facing +Z, then turned.
  auto side_wall = [&] {
    Mesh m = meshgen::plane({L, H});
    scale_uv(m, {L / 2.0f, H / 2.0f});  // 2 m per brick tile
    return m;
  };
  b.mesh(side_wall(), "left_wall", wall_mat,
         translate({-0.5f * W, 0.5f * H, -0.5f * L}) * rotate_y(90.0f) * rotate_x(90.0f));
  b.mesh(side_wall(), "right_wall", wall_mat,
         translate({0.5f * W, 0.5f * H, -0.5f * L}) * rotate_y(-90.0f) * rotate_x(90.0f));
  b.mesh(meshgen::plane({W, H}), "far_wall", end_mat, translate({0.0f, 0.5f * H, -L}) * rotate_x(90.0f));
  b.mesh(meshgen::plane({W, H}), "near_wall", near_mat,
         translate({0.0f, 0.5f * H, 0.0f}) * rotate_x(-90.0f));

  // Pillars every 4 m on both sides (z = -2, -6, ..., -38), 0.4 m deep into the corridor;
  // coloured panels on the walls between them (z = -4, -8, ..., -36).
  for (int k = 0; k < 10; ++k) {
    const float z = -2.0f - 4.0f * static_cast<float>(k);
    for (int side = 0; side < 2; ++side) {
      const float x = (side ? 1.0f : -1.0f) * (0.5f * W - 0.2f);
      b.mesh(meshgen::box({0.4f, H, 0.5f}), std::string(side ? "pillar_r" : "pillar_l") +
                                                std::to_string(k), pillar_mat,
             translate({x, 0.5f * H, z}));
    }
  }
  for (int k = 0; k < 9; ++k) {
    const float z = -4.0f - 4.0f * static_cast<float>(k);
    for (int side = 0; side < 2; ++side) {
      const float x = (side ? 1.0f : -1.0f) * (0.5f * W - 0.03f);
      b.mesh(meshgen::box({0.06f, 1.4f, 2.6f}),
             std::string(side ? "panel_r" : "panel_l") + std::to_string(k),
             panel_mat[(k + 3 * side) % 6], translate({x, 1.5f, z}));
    }
  }
  // 8 ceiling lights with a glowing fixture just above each.
  for (int k = 0; k < 8; ++k) {
    const float z = -2.5f - 5.0f * static_cast<float>(k);
    const glm::vec3 color = (k % 2) ? glm::vec3(0.75f, 0.85f, 1.0f) : glm::vec3(1.0f, 0.85f, 0.65f);
    b.light({0.0f, 3.0f, z}, color, 10.0f, 9.0f);
    b.mesh(meshgen::box({0.8f, 0.05f, 0.3f}), "fixture_" + std::to_string(k), fixture_mat,
           translate({0.0f, H - 0.03f, z}));
  }

  // Default: eye 1.7 m, 1 m in from the near wall, looking down the length ~1.7 deg down: the
  // floor's reflection of walls, pillars and panels runs from the bottom edge to the far wall.
  b.camera("default", {0.0f, 1.7f, -1.0f}, {0.0f, 1.1f, -20.0f});
  b.camera("low", {0.0f, 0.3f, -1.0f}, {0.0f, 0.4f, -25.0f});     // grazing
  b.camera("side", {1.3f, 2.6f, -3.0f}, {-1.6f, 0.6f, -12.0f});  // oblique, toward the left wall
  b.camera("back", {0.0f, 1.7f, -39.0f}, {0.0f, 1.1f, -20.0f});  // from the far end

  const Camera& cam = b.s.cameras[0];
  const glm::vec3 walk(0.0f, 0.0f, -12.0f);
  b.path("dolly", "camera dolly: walks 12 m down the corridor at 2 m/s (6 s)",
         {key(0, cam), key(6, cam.position + walk, cam.target + walk)});
  b.path("pan",
         "fast pan: from the default position turns 50 deg left, 100 deg right and back in 2 s: "
         "walls, pillars and panels sweep in at the screen edges",
         pan_keys(cam, {{0.0f, 0.0f}, {0.5f, 50.0f}, {1.25f, -50.0f}, {2.0f, 0.0f}}));
  b.s.animation.duration = 6.0f;

  b.s.environment.type = Environment::Type::Sky;
  b.s.ambient = 0.25f;
  return b.s;
}

// ---- glass ---------------------------------------------------------------------------------------
// Refraction (2012 blog): a glass sphere (ior 1.5) and a glass slab (ior 1.33) stand in front of a
// brick wall and coloured boxes on a matte floor; the camera looks through both.
Scene glass() {
  Builder b;
  b.s.name = "glass";
  const int brick_img = b.image(bricks(256, 8, 4, {0.72f, 0.42f, 0.30f}, {0.80f, 0.78f, 0.74f}, 7u));
  Material wall = mat("brick_wall", glm::vec3(1.0f), 0.85f);
  wall.albedo_texture = brick_img;
  const int wall_mat = b.material(wall);
  Mesh back = meshgen::plane({16.0f, 6.0f}, 1.0f);
  scale_uv(back, {8.0f, 3.0f});
  b.mesh(std::move(back), "back_wall", wall_mat, translate({0, 3.0f, -4.0f}) * rotate_x(90.0f));
  b.mesh(meshgen::plane({16.0f, 12.0f}), "floor", b.material(mat("floor", {0.55f, 0.55f, 0.52f}, 0.7f)),
         translate({0, 0, 1.0f}));
  const glm::vec3 colors[] = {{0.8f, 0.15f, 0.1f}, {0.1f, 0.6f, 0.2f}, {0.15f, 0.3f, 0.85f}, {0.9f, 0.75f, 0.1f}};
  for (int i = 0; i < 4; ++i)
    b.mesh(meshgen::box({0.8f, 1.2f, 0.8f}), "box" + std::to_string(i),
           b.material(mat("box" + std::to_string(i), colors[i], 0.6f)),
           translate({-3.0f + 2.0f * static_cast<float>(i), 0.6f, -2.5f}));
  Material glass_sphere = mat("glass_sphere", {0.95f, 0.97f, 1.0f}, 0.0f);
  glass_sphere.transparent = true;
  glass_sphere.ior = 1.5f;
  b.mesh(meshgen::sphere(0.9f, 48, 24), "glass_sphere", b.material(glass_sphere), translate({-1.2f, 0.9f, 0.5f}));
  Material water = mat("glass_slab", {0.85f, 0.95f, 1.0f}, 0.0f);
  water.transparent = true;
  water.ior = 1.33f;
  b.mesh(meshgen::box({1.6f, 1.8f, 0.3f}), "glass_slab", b.material(water),
         translate({1.4f, 0.9f, 0.6f}) * rotate_y(25.0f));
  b.light({0.0f, 4.0f, 3.0f}, {1.0f, 0.95f, 0.9f}, 30.0f, 20.0f);
  b.light({-4.0f, 2.5f, 1.0f}, {0.6f, 0.7f, 1.0f}, 10.0f, 12.0f);
  b.camera("default", {0.0f, 1.5f, 5.5f}, {0.0f, 1.0f, 0.0f});
  b.camera("close", {-1.0f, 1.2f, 2.8f}, {-1.2f, 0.9f, 0.0f});
  // The slab turns about its vertical axis (one turn in 6 s; 0.8 m clear of the sphere).
  b.motion(spin({0, 1, 0}, 6.0f), {"glass_slab"});
  b.path("orbit",
         "camera orbit: swings 35 deg to either side of the default view about the vertical axis "
         "through its target (4 s)",
         orbit_keys(b.s.cameras[0], b.s.cameras[0].target, 4.0f, 0.25f,
                    [](float t) { return 35.0f * std::sin(std::numbers::pi_v<float> * t / 2.0f); }));
  b.s.animation.duration = 4.0f;
  b.s.environment.type = Environment::Type::Sky;
  b.s.ambient = 0.35f;
  return b.s;
}

// ---- ramp ---------------------------------------------------------------------------------------
// The roughness ramp (issue 14): a metal floor in 11 bands of perceptual roughness 0.0, 0.1, ...,
// 1.0, each its own mesh ("band_0.0" ... "band_1.0") and planar reflector (id k + 1 for the band
// of roughness k / 10), so every per-reflector figure ("reflector:N") is a per-roughness figure.
// The bands run along the view, side by side, left (0.0) to right (1.0): each spans the floor's
// whole depth, so every band sees the same mix of near and far floor, of reflections on screen
// and off it; only the roughness (and what stands above it) differs. Bands across the view would
// give the near bands nothing on screen to reflect and the far ones only grazing angles.
constexpr int kRampBands = 11;
constexpr float kRampBandWidth = 0.7f;  // metres along x; the floor is 7.7 m wide

float ramp_band_x(int k) { return (static_cast<float>(k) - 5.0f) * kRampBandWidth; }  // centre

Scene ramp() {
  Builder b;
  b.s.name = "ramp";
  // Bands: x in [-3.85, 3.85] (band k over [ramp_band_x(k) -+ 0.35]), z in [-8, 6], y = 0; metal
  // (albedo 0.9, metallic 1), no gaps. Roughness k / 10.0f: the float nearest k / 10, as the
  // literals 0.1f, 0.2f, ... are.
  for (int k = 0; k < kRampBands; ++k) {
    const float r = static_cast<float>(k) / 10.0f;
    char label[8];
    std::snprintf(label, sizeof label, "%.1f", static_cast<double>(r));
    const int m = b.material(mat(std::string("metal_r") + label, glm::vec3(0.9f), r, 1.0f, 1.0f));
    const glm::vec3 c(ramp_band_x(k), 0.0f, -1.0f);
    const int refl = b.floor_reflector(c, {0.5f * kRampBandWidth, 7.0f});
    b.mesh(meshgen::plane({kRampBandWidth, 14.0f}), std::string("band_") + label, m, translate(c),
           refl);
  }
  // A matte, non-reflective surround 1 cm below the bands (what the frame shows beside them).
  b.mesh(meshgen::plane({32.0f, 16.0f}), "surround",
         b.material(mat("surround", {0.22f, 0.22f, 0.24f}, 0.9f)), translate({0, -0.01f, 0.0f}));

  // Back wall: z = -8, facing +Z, x in [-16, 16], y in [0, 12]; grey-blue bricks, 2 m per tile;
  // taller than the frame, so most rough lobes end on it rather than on the bright sky. An
  // emissive strip runs across its whole width at 2 m: every band reflects it, blurred by its
  // roughness.
  const int brick_img = b.image(bricks(256, 8, 4, {0.62f, 0.60f, 0.66f}, {0.80f, 0.79f, 0.76f}, 31U));
  Material wall = mat("brick_wall", glm::vec3(1.0f), 0.85f);
  wall.albedo_texture = brick_img;
  Mesh back = meshgen::plane({32.0f, 12.0f});
  scale_uv(back, {16.0f, 6.0f});
  b.mesh(std::move(back), "back_wall", b.material(wall), translate({0, 6.0f, -8.0f}) * rotate_x(90.0f));
  b.mesh(meshgen::box({32.0f, 0.3f, 0.05f}), "light_strip",
         b.material(mat("light_strip", glm::vec3(1.0f), 0.5f, 0.0f, 0.5f, {2.6f, 3.0f, 3.6f})),
         translate({0.0f, 2.0f, -7.97f}));

  // Objects, each standing on the middle of one band (non-metallic: the bands are the only
  // reflective surfaces). A back row at z = -5 on the even bands (tall boxes and columns) and a
  // front row at z = -1.5 on the odd bands (spheres, cubes and the bright "glow" sphere),
  // every object its own colour. A mirror image keeps its object's screen x and falls on the
  // floor in front of it, on its band and the next ones towards the middle of the frame.
  const int orange = b.material(mat("orange", {0.95f, 0.45f, 0.10f}, 0.5f));
  const int green = b.material(mat("green", {0.15f, 0.65f, 0.25f}, 0.5f));
  const int marble = b.material(mat("marble", {0.85f, 0.82f, 0.76f}, 0.35f));
  const int blue = b.material(mat("blue", {0.15f, 0.30f, 0.85f}, 0.45f));
  const int magenta = b.material(mat("magenta", {0.85f, 0.20f, 0.70f}, 0.5f));
  const int yellow = b.material(mat("yellow", {0.90f, 0.75f, 0.20f}, 0.6f));
  const int teal = b.material(mat("teal", {0.10f, 0.60f, 0.60f}, 0.5f));
  const int purple = b.material(mat("purple", {0.50f, 0.25f, 0.80f}, 0.5f));
  const int red = b.material(mat("red", {0.80f, 0.10f, 0.08f}, 0.5f));
  const int lime = b.material(mat("lime", {0.60f, 0.85f, 0.15f}, 0.5f));
  const int glow =
      b.material(mat("glow", {1.0f, 0.9f, 0.7f}, 0.5f, 0.0f, 0.5f, {5.0f, 4.2f, 2.6f}));
  constexpr float zb = -5.0f, za = -1.5f;
  b.mesh(meshgen::cylinder(0.25f, 2.6f), "column_orange", orange, translate({ramp_band_x(0), 0.0f, zb}));
  b.mesh(meshgen::box({0.5f, 1.8f, 0.5f}), "box_tall_green", green,
         translate({ramp_band_x(2), 0.9f, zb}) * rotate_y(20.0f));
  b.mesh(meshgen::cylinder(0.22f, 3.0f), "column_white", marble, translate({ramp_band_x(4), 0.0f, zb}));
  b.mesh(meshgen::box({0.5f, 2.2f, 0.5f}), "box_tall_blue", blue,
         translate({ramp_band_x(6), 1.1f, zb}) * rotate_y(-25.0f));
  b.mesh(meshgen::cylinder(0.25f, 2.0f), "column_magenta", magenta, translate({ramp_band_x(8), 0.0f, zb}));
  b.mesh(meshgen::box({0.5f, 2.6f, 0.5f}), "box_tall_yellow", yellow,
         translate({ramp_band_x(10), 1.3f, zb}) * rotate_y(15.0f));
  b.mesh(meshgen::sphere(0.3f, 32, 16), "sphere_teal", teal, translate({ramp_band_x(1), 0.3f, za}));
  b.mesh(meshgen::box({0.5f, 0.5f, 0.5f}), "cube_purple", purple,
         translate({ramp_band_x(3), 0.25f, za}) * rotate_y(30.0f));
  b.mesh(meshgen::sphere(0.3f, 32, 16), "glow", glow, translate({ramp_band_x(5), 0.3f, za}));
  b.mesh(meshgen::box({0.5f, 0.5f, 0.5f}), "cube_red", red,
         translate({ramp_band_x(7), 0.25f, za}) * rotate_y(-20.0f));
  b.mesh(meshgen::sphere(0.3f, 32, 16), "sphere_lime", lime, translate({ramp_band_x(9), 0.3f, za}));

  // Lights: white key above the objects, warm left and cool right beside the wall, a weak fill
  // before the front row. Weak lights and ambient 1 (the sky's diffuse light, which the metal
  // bands do not get): the wall and the objects stay bright while the point lights' highlights
  // on the rough bands stay dim, so the bands show mostly their reflections.
  b.light({0.0f, 6.0f, -3.0f}, glm::vec3(1.0f), 15.0f, 25.0f);
  b.light({-6.0f, 4.0f, -5.0f}, {1.0f, 0.8f, 0.6f}, 12.0f, 20.0f);
  b.light({6.0f, 4.0f, -5.0f}, {0.6f, 0.75f, 1.0f}, 12.0f, 20.0f);
  b.light({0.0f, 3.0f, 2.0f}, glm::vec3(1.0f), 4.0f, 12.0f);

  // Default camera: eye 1.7 m, 1 m behind the bands' near end, 5.1 deg down, looking along the
  // bands. At 16:9 each band runs from the bottom edge to the wall's foot (NDC y = -0.04, where
  // the bands span NDC x in [-0.25, 0.25]); the outer two leave the frame at the bottom corners.
  // The bands fill ~37% of the frame: ~2% each for the outer two, 3.2-3.7% for the others, of
  // which 85-97% reflect, as a mirror, something that is itself on screen (tests/unit counts).
  // The front row stands at NDC y ~ -0.19, the strip's mirror image crosses every band at
  // NDC y ~ -0.27; the wall runs off the top edge (no sky in view).
  b.camera("default", {0.0f, 1.7f, 7.0f}, {0.0f, 0.8f, -3.0f});
  b.camera("low", {0.0f, 0.4f, 7.0f}, {0.0f, 0.5f, -3.0f});    // grazing
  b.camera("high", {0.0f, 6.0f, 8.0f}, {0.0f, 0.0f, -2.0f});   // steep look down on the ramp
  b.camera("side", {6.0f, 2.0f, 4.0f}, {-1.0f, 0.5f, -3.0f});  // oblique, from the right

  const Camera& cam = b.s.cameras[0];
  b.path("dolly", "camera dolly: 4 m in along the default view, over the front row (4 s)",
         {key(0, cam), key(4, cam.position + 0.4f * (cam.target - cam.position), cam.target)});
  b.path("orbit",
         "slow camera orbit: swings 20 deg to either side of the default view about the vertical "
         "axis through its target, the bands turning across the frame (6 s)",
         orbit_keys(cam, cam.target, 6.0f, 0.25f,
                    [](float t) { return 20.0f * std::sin(std::numbers::pi_v<float> * t / 3.0f); }));
  b.path("pan",
         "slow pan: from the default position turns 10 deg left, 20 deg right and back (6 s)",
         pan_keys(cam, {{0.0f, 0.0f}, {1.5f, 10.0f}, {4.5f, -10.0f}, {6.0f, 0.0f}}));
  b.s.animation.duration = 6.0f;

  b.s.environment.type = Environment::Type::Sky;
  b.s.ambient = 1.0f;
  return b.s;
}

// ---- hard cases ---------------------------------------------------------------------------------
// Stability scenes for issue 7 (tests/gl/test_hard_cases.cpp runs every technique on each one's
// default camera against the reference; docs/ROBUSTNESS.md lists what each exercises). Every one
// has a mesh named "floor" that the default camera sees (tests/unit checks it), lights inside the
// geometry's bounds and 2..4 cameras.

void set_planes(Scene& s, float near_plane, float far_plane) {
  for (Camera& c : s.cameras) {
    c.near_plane = near_plane;
    c.far_plane = far_plane;
  }
}

// A planar reflector rectangle facing `normal` (unit) with `tangent` (unit, in the plane) and
// the mesh that fills it exactly (a meshgen::plane turned so that +X -> tangent, +Y -> normal,
// +Z -> bitangent). Returns the mesh index.
std::size_t mirror_rect(Builder& b, const std::string& name, int material, glm::vec3 center,
                        glm::vec3 normal, glm::vec3 tangent, glm::vec2 half_extents) {
  Reflector r;
  r.center = center;
  r.tangent = tangent;
  r.bitangent = glm::cross(tangent, normal);  // so that normal() = cross(bitangent, tangent)
  r.half_extents = half_extents;
  b.s.reflectors.push_back(r);
  const int id = static_cast<int>(b.s.reflectors.size());
  glm::mat4 xf(1.0f);
  xf[0] = glm::vec4(tangent, 0.0f);
  xf[1] = glm::vec4(normal, 0.0f);
  xf[2] = glm::vec4(r.bitangent, 0.0f);
  xf[3] = glm::vec4(center, 1.0f);
  return b.mesh(meshgen::plane(2.0f * half_extents), name, material, xf, id);
}

// A few coloured props standing on y = 0 around (0, 0, z0), for something to reflect.
void props(Builder& b, float z0) {
  const int red = b.material(mat("prop_red", {0.8f, 0.1f, 0.08f}, 0.5f));
  const int blue = b.material(mat("prop_blue", {0.12f, 0.25f, 0.85f}, 0.4f));
  const int yellow = b.material(mat("prop_yellow", {0.9f, 0.75f, 0.2f}, 0.6f));
  b.mesh(meshgen::box({1.0f, 1.0f, 1.0f}), "prop_box", red, translate({-1.8f, 0.5f, z0}) * rotate_y(20.0f));
  b.mesh(meshgen::sphere(0.6f, 24, 12), "prop_sphere", blue, translate({1.5f, 0.6f, z0 - 1.0f}));
  b.mesh(meshgen::box({0.6f, 2.0f, 0.6f}), "prop_tall", yellow, translate({0.2f, 1.0f, z0 - 3.0f}));
}

// Camera 5 cm above a 400 m mirror floor, looking along it: every floor pixel is grazing.
Scene hard_grazing() {
  Builder b;
  b.s.name = "hard-grazing";
  const int mirror = b.material(mat("mirror_floor", glm::vec3(0.9f), 0.0f, 1.0f, 1.0f));
  mirror_rect(b, "floor", mirror, {0, 0, -150.0f}, {0, 1, 0}, {1, 0, 0}, {200.0f, 200.0f});
  props(b, -4.0f);
  const int wall = b.material(mat("far_wall", {0.6f, 0.6f, 0.55f}, 0.8f));
  b.mesh(meshgen::box({30.0f, 6.0f, 0.5f}), "far_wall", wall, translate({0, 3.0f, -40.0f}));
  b.light({0.0f, 3.0f, -2.0f}, glm::vec3(1.0f), 40.0f, 30.0f);
  b.light({-3.0f, 2.0f, -10.0f}, {1.0f, 0.8f, 0.6f}, 40.0f, 30.0f);
  b.camera("default", {0.0f, 0.05f, 2.0f}, {0.0f, 0.05f, -10.0f});
  b.camera("skim", {0.0f, 0.01f, 2.0f}, {0.0f, 0.02f, -10.0f});   // 1 cm, looking a hair up
  b.camera("shallow", {0.0f, 0.3f, 3.0f}, {0.0f, 0.0f, -30.0f});  // ~0.6 deg down
  set_planes(b.s, 0.01f, 500.0f);
  const glm::vec3 ahead(0.0f, 0.0f, -2.0f);
  b.path("dolly", "camera dolly: 2 m forward, still 5 cm above the mirror (4 s)",
         {key(0, b.s.cameras[0]),
          key(4, b.s.cameras[0].position + ahead, b.s.cameras[0].target + ahead)});
  b.s.animation.duration = 4.0f;
  b.s.environment.type = Environment::Type::Sky;
  b.s.ambient = 0.3f;
  return b.s;
}

// Camera inside a closed 4 x 3 x 4 m box whose six faces are perfect mirrors (6 planar
// reflectors): reflection rays come straight back at the camera and cross its near plane.
Scene hard_mirror_box() {
  Builder b;
  b.s.name = "hard-mirror-box";
  constexpr float hx = 2.0f, hz = 2.0f, H = 3.0f;
  const int floor_mat = b.material(mat("mirror_floor", glm::vec3(0.9f), 0.0f, 1.0f, 1.0f));
  const int wall_mat = b.material(mat("mirror_wall", {0.85f, 0.9f, 0.95f}, 0.0f, 1.0f, 1.0f));
  const int ceil_mat = b.material(mat("mirror_ceiling", {0.95f, 0.9f, 0.85f}, 0.0f, 1.0f, 1.0f));
  mirror_rect(b, "floor", floor_mat, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {hx, hz});
  mirror_rect(b, "ceiling", ceil_mat, {0, H, 0}, {0, -1, 0}, {1, 0, 0}, {hx, hz});
  mirror_rect(b, "wall_back", wall_mat, {0, 0.5f * H, -hz}, {0, 0, 1}, {1, 0, 0}, {hx, 0.5f * H});
  mirror_rect(b, "wall_front", wall_mat, {0, 0.5f * H, hz}, {0, 0, -1}, {1, 0, 0}, {hx, 0.5f * H});
  mirror_rect(b, "wall_left", wall_mat, {-hx, 0.5f * H, 0}, {1, 0, 0}, {0, 0, 1}, {hz, 0.5f * H});
  mirror_rect(b, "wall_right", wall_mat, {hx, 0.5f * H, 0}, {-1, 0, 0}, {0, 0, 1}, {hz, 0.5f * H});
  const int red = b.material(mat("red", {0.8f, 0.1f, 0.08f}, 0.5f));
  const int green = b.material(mat("green", {0.15f, 0.65f, 0.25f}, 0.5f));
  const int lamp = b.material(mat("lamp", glm::vec3(1.0f), 0.5f, 0.0f, 0.5f, {3.0f, 2.8f, 2.5f}));
  b.mesh(meshgen::box({0.6f, 0.6f, 0.6f}), "cube_red", red, translate({-1.0f, 0.3f, -1.0f}) * rotate_y(30.0f));
  b.mesh(meshgen::sphere(0.35f, 24, 12), "sphere_green", green, translate({1.0f, 0.8f, -0.6f}));
  b.mesh(meshgen::sphere(0.1f, 12, 6), "lamp", lamp, translate({0.0f, 2.7f, 0.0f}));
  b.light({0.0f, 2.5f, 0.0f}, {1.0f, 0.95f, 0.9f}, 15.0f, 10.0f);
  // default: looking at the back wall, a little down; the wall's reflection rays run straight
  // back through the camera. toward: square on, eye at mid height. corner: into a corner.
  b.camera("default", {0.0f, 1.5f, 1.2f}, {0.0f, 1.0f, -2.0f});
  b.camera("toward", {0.0f, 1.5f, 1.5f}, {0.0f, 1.5f, -2.0f});
  b.camera("corner", {1.2f, 2.4f, 1.2f}, {-2.0f, 0.5f, -2.0f});
  set_planes(b.s, 0.05f, 50.0f);
  // The green sphere circles a point beside it (radius 0.54 m, 4 s a turn), clear of the cube
  // and the walls; the camera turns a full circle in place.
  b.motion(orbit({0.5f, 0.8f, -0.4f}, {0, 1, 0}, 4.0f), {"sphere_green"});
  b.path("turn",
         "camera pan: turns a full circle in place (90 deg/s) while the green sphere circles (4 s)",
         orbit_keys(b.s.cameras[0], b.s.cameras[0].position, 4.0f, 0.25f,
                    [](float t) { return 90.0f * t; }));
  b.s.animation.duration = 4.0f;
  b.s.environment.type = Environment::Type::Constant;
  b.s.environment.constant = glm::vec3(0.05f);
  b.s.ambient = 1.0f;
  return b.s;
}

// A 2 cm pole and 1 cm fins on a mirror floor: thinner than a pixel at the test sizes, so depth
// buffers see them in a few pixels only and thickness heuristics decide what a ray hits.
Scene hard_thin() {
  Builder b;
  b.s.name = "hard-thin";
  const int mirror = b.material(mat("mirror_floor", glm::vec3(0.9f), 0.0f, 1.0f, 1.0f));
  mirror_rect(b, "floor", mirror, {0, 0, -2.0f}, {0, 1, 0}, {1, 0, 0}, {10.0f, 10.0f});
  const int pole = b.material(mat("pole", {0.9f, 0.15f, 0.1f}, 0.4f, 0.0f, 0.5f, {1.5f, 0.2f, 0.1f}));
  const int fin = b.material(mat("fin", {0.15f, 0.5f, 0.9f}, 0.5f));
  const int fin2 = b.material(mat("fin_edge_on", {0.2f, 0.8f, 0.3f}, 0.5f));
  b.mesh(meshgen::box({0.02f, 3.0f, 0.02f}), "pole", pole, translate({-0.6f, 1.5f, -1.0f}));
  for (int i = 0; i < 3; ++i)  // fins turned 0, 30, 60 degrees from facing the camera
    b.mesh(meshgen::box({1.0f, 1.5f, 0.01f}), "fin_" + std::to_string(i), fin,
           translate({0.6f + 1.3f * static_cast<float>(i), 0.75f, -1.5f}) *
               rotate_y(30.0f * static_cast<float>(i)));
  b.mesh(meshgen::box({0.01f, 1.5f, 1.5f}), "fin_edge_on", fin2, translate({-2.0f, 0.75f, -1.5f}));
  const int wall = b.material(mat("back_wall", {0.7f, 0.68f, 0.62f}, 0.85f));
  b.mesh(meshgen::box({20.0f, 5.0f, 0.2f}), "back_wall", wall, translate({0, 2.5f, -8.0f}));
  b.light({0.0f, 3.0f, 1.0f}, glm::vec3(1.0f), 40.0f, 20.0f);
  b.light({-3.0f, 2.0f, -4.0f}, {0.6f, 0.7f, 1.0f}, 20.0f, 15.0f);
  b.camera("default", {0.0f, 1.2f, 5.0f}, {0.0f, 0.8f, 0.0f});
  b.camera("close", {0.0f, 0.4f, 1.0f}, {-0.3f, 0.6f, -1.5f});
  const Camera& cam = b.s.cameras[0];
  const glm::vec3 right(1.5f, 0.0f, 0.0f);
  b.path("truck",
         "camera truck: slides 1.5 m right and back keeping its direction: the pole and the fins "
         "move across their reflections (4 s)",
         {key(0, cam), key(2, cam.position + right, cam.target + right), key(4, cam)});
  b.s.animation.duration = 4.0f;
  return b.s;
}

// near 0.001, far 1e5: a 2 cm ball 1 cm from the eye and blocks at 1, 10, 100, 1e3, 1e4 and
// 5e4 m (each 10% of its distance across) on a 1.2e5 m mirror floor.
Scene hard_depth_range() {
  Builder b;
  b.s.name = "hard-depth-range";
  const int mirror = b.material(mat("mirror_floor", glm::vec3(0.9f), 0.0f, 1.0f, 1.0f));
  mirror_rect(b, "floor", mirror, {0, 0, -5.0e4f}, {0, 1, 0}, {1, 0, 0}, {6.0e4f, 6.0e4f});
  const glm::vec3 eye(0.0f, 1.0f, 0.0f);
  const int near_mat = b.material(mat("near_ball", {0.9f, 0.2f, 0.6f}, 0.4f));
  // 1 cm ahead, up and to the right of the view centre (the default camera looks along -Z).
  b.mesh(meshgen::sphere(0.002f, 12, 6), "near_ball", near_mat, translate(eye + glm::vec3(0.004f, 0.002f, -0.01f)));
  const float dist[] = {1.0f, 10.0f, 100.0f, 1.0e3f, 1.0e4f, 5.0e4f};
  const glm::vec3 colors[] = {{0.8f, 0.1f, 0.1f}, {0.9f, 0.6f, 0.1f}, {0.8f, 0.8f, 0.1f},
                              {0.1f, 0.7f, 0.2f}, {0.1f, 0.4f, 0.9f}, {0.6f, 0.2f, 0.8f}};
  for (int i = 0; i < 6; ++i) {
    const float d = dist[i], s = 0.1f * d;
    const float side = (i % 2) ? 1.0f : -1.0f;  // alternate sides so none hides the next
    const int m = b.material(mat("block_" + std::to_string(i), colors[i], 0.5f, 0.0f, 0.5f, 0.3f * colors[i]));
    // The 1 m block floats at 0.85 m (on the floor it would be below the frame).
    b.mesh(meshgen::box({s, s, s}), "block_" + std::to_string(i), m,
           translate({side * 0.15f * d, i == 0 ? 0.85f : 0.5f * s, -d}));
  }
  b.light({0.0f, 1.0f, -0.5f}, glm::vec3(1.0f), 5.0f, 20.0f);
  b.light({0.0f, 500.0f, -1000.0f}, glm::vec3(1.0f), 1.0e6f, 3.0e4f);
  b.camera("default", eye, eye + glm::vec3(0.0f, -0.15f, -1.0f));
  b.camera("far", {0.0f, 50.0f, 0.0f}, {0.0f, 0.0f, -2.0e4f});
  set_planes(b.s, 0.001f, 1.0e5f);
  const glm::vec3 back(0.0f, 0.0f, 1.0f);
  b.path("dolly", "camera dolly out: backs 1 m away, the 1 cm ball receding to 1 m (4 s)",
         {key(0, b.s.cameras[0]),
          key(4, b.s.cameras[0].position + back, b.s.cameras[0].target + back)});
  b.s.animation.duration = 4.0f;
  b.s.environment.type = Environment::Type::Sky;
  b.s.ambient = 0.4f;
  return b.s;
}

// The gallery moved 1e4 m along +X and -Z (camera, lights, reflectors too): world-space
// positions lose about 3 decimal digits of float precision.
Scene hard_far_origin() {
  Scene s = gallery(SceneOptions{});
  s.name = "hard-far-origin";
  const glm::vec3 o(1.0e4f, 0.0f, -1.0e4f);
  for (Mesh& m : s.meshes) meshgen::transform(m, translate(o));
  for (Light& l : s.lights) l.position += o;
  for (Camera& c : s.cameras) {
    c.position += o;
    c.target += o;
  }
  for (Reflector& r : s.reflectors) r.center += o;
  for (CameraPath& p : s.animation.paths)
    for (CameraKey& k : p.keys) {
      k.position += o;
      k.target += o;
    }
  for (ObjectMotion& m : s.animation.objects) m.pivot += o;
  return s;
}

// Degenerate normals and background: unit normals that disagree with their faces (lying in the
// face, flipped, cancelling across a quad so they interpolate through zero), a zero-area
// triangle, a sliver seen edge-on, all mirrors; a small floor and a view half full of sky.
Scene hard_degenerate() {
  Builder b;
  b.s.name = "hard-degenerate";
  const int mirror = b.material(mat("mirror_floor", glm::vec3(0.9f), 0.0f, 1.0f, 1.0f));
  mirror_rect(b, "floor", mirror, {0, 0, -1.0f}, {0, 1, 0}, {1, 0, 0}, {4.0f, 4.0f});
  const int chrome = b.material(mat("chrome", glm::vec3(0.95f), 0.0f, 1.0f, 1.0f));
  const int glossy = b.material(mat("glossy", {0.8f, 0.3f, 0.2f}, 0.2f, 1.0f, 1.0f));
  auto quad = [](glm::vec3 origin, glm::vec3 U, glm::vec3 V, const glm::vec3 normals[4]) {
    Mesh m;
    const glm::vec4 t(glm::normalize(U), 1.0f);
    const glm::vec2 st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i)
      m.vertices.push_back(Vertex{origin + st[i].x * U + st[i].y * V, normals[i], st[i], t});
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
  };
  // A vertical 1.2 m quad facing the camera (+Z) whose normals lie in the face (+X).
  const glm::vec3 in_face[4] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  b.mesh(quad({-2.6f, 0.3f, -1.0f}, {1.2f, 0, 0}, {0, 1.2f, 0}, in_face), "normals_in_face", chrome);
  // Facing the camera with normals pointing away from it (-Z).
  const glm::vec3 flipped[4] = {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
  b.mesh(quad({-1.0f, 0.3f, -1.5f}, {1.2f, 0, 0}, {0, 1.2f, 0}, flipped), "normals_flipped", chrome);
  // Left and right edges have opposite normals (-X, +X): the interpolated normal passes
  // through zero down the middle of the quad.
  const glm::vec3 cancel[4] = {{-1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
  b.mesh(quad({0.6f, 0.3f, -1.2f}, {1.2f, 0, 0}, {0, 1.2f, 0}, cancel), "normals_cancel", glossy);
  // A zero-area triangle (collinear corners) next to a proper one, in one mesh.
  {
    Mesh m;
    const glm::vec3 n(0, 0, 1);
    const glm::vec4 t(1, 0, 0, 1);
    m.vertices = {Vertex{{2.2f, 0.3f, -1.0f}, n, {0, 0}, t}, Vertex{{2.8f, 0.3f, -1.0f}, n, {1, 0}, t},
                  Vertex{{3.4f, 0.3f, -1.0f}, n, {2, 0}, t}, Vertex{{2.8f, 1.3f, -1.0f}, n, {1, 1}, t}};
    m.indices = {0, 1, 2, 0, 1, 3};
    b.mesh(std::move(m), "zero_area", glossy);
  }
  // A 3 m sliver in the plane x = 0.3, seen almost exactly edge-on by the default camera.
  b.mesh(meshgen::plane({0.5f, 3.0f}), "sliver", chrome,
         translate({0.3f, 1.2f, -2.0f}) * rotate_y(2.0f) * rotate_z(-90.0f));
  // A 4 m column at the back left (the only thing above the horizon).
  b.mesh(meshgen::cylinder(0.15f, 4.0f, 16), "column", b.material(mat("column", {0.8f, 0.78f, 0.7f}, 0.5f)),
         translate({-3.5f, 0.0f, -4.5f}));
  b.light({0.0f, 2.5f, 1.0f}, glm::vec3(1.0f), 30.0f, 20.0f);
  b.light({-2.0f, 1.5f, -3.0f}, {0.7f, 0.8f, 1.0f}, 15.0f, 12.0f);
  // default: eye 1.5 m, level: the upper half of the frame and the band beyond the floor's
  // far edge are sky. up: looking 35 deg up, almost nothing but sky.
  b.camera("default", {0.3f, 1.5f, 4.0f}, {0.3f, 1.5f, -4.0f});
  b.camera("up", {0.0f, 1.0f, 4.0f}, {0.0f, 6.6f, -4.0f});
  b.path("pan",
         "fast pan: turns 40 deg left, 80 deg right and back in 2 s over the degenerate quads",
         pan_keys(b.s.cameras[0], {{0.0f, 0.0f}, {0.5f, 40.0f}, {1.25f, -40.0f}, {2.0f, 0.0f}}));
  b.s.animation.duration = 2.0f;
  b.s.environment.type = Environment::Type::Sky;
  b.s.ambient = 0.3f;
  return b.s;
}

// A metal floor split down x = 0: roughness exactly 0 on the left ("floor", reflector 1) and
// exactly 1 on the right ("floor_rough", reflector 2): the two ends of the GGX lobe.
Scene hard_roughness() {
  Builder b;
  b.s.name = "hard-roughness";
  const int smooth = b.material(mat("metal_r0", glm::vec3(0.9f), 0.0f, 1.0f, 1.0f));
  const int rough = b.material(mat("metal_r1", glm::vec3(0.9f), 1.0f, 1.0f, 1.0f));
  mirror_rect(b, "floor", smooth, {-5.0f, 0, -2.0f}, {0, 1, 0}, {1, 0, 0}, {5.0f, 8.0f});
  mirror_rect(b, "floor_rough", rough, {5.0f, 0, -2.0f}, {0, 1, 0}, {1, 0, 0}, {5.0f, 8.0f});
  props(b, -2.0f);
  const int emissive = b.material(mat("glow", {1.0f, 1.0f, 1.0f}, 0.5f, 0.0f, 0.5f, {3.0f, 2.5f, 1.5f}));
  b.mesh(meshgen::sphere(0.3f, 16, 8), "glow_left", emissive, translate({-2.5f, 0.3f, 0.5f}));
  b.mesh(meshgen::sphere(0.3f, 16, 8), "glow_right", emissive, translate({2.5f, 0.3f, 0.5f}));
  const int wall = b.material(mat("back_wall", {0.7f, 0.6f, 0.5f}, 0.9f));
  b.mesh(meshgen::box({20.0f, 4.0f, 0.2f}), "back_wall", wall, translate({0, 2.0f, -10.0f}));
  b.light({0.0f, 3.0f, 2.0f}, glm::vec3(1.0f), 40.0f, 25.0f);
  b.light({-3.0f, 2.0f, -4.0f}, {1.0f, 0.7f, 0.5f}, 30.0f, 20.0f);
  b.light({3.0f, 2.0f, -4.0f}, {0.5f, 0.7f, 1.0f}, 30.0f, 20.0f);
  // The split line x = 0 runs up the frame just right of the centre.
  b.camera("default", {-0.25f, 1.6f, 6.0f}, {-0.25f, 0.6f, 0.0f});
  b.camera("low", {-0.25f, 0.4f, 6.0f}, {-0.25f, 0.5f, 0.0f});
  b.path("orbit",
         "camera orbit: swings 30 deg to either side about the vertical axis through the default "
         "target, the roughness split sweeping across the frame (4 s)",
         orbit_keys(b.s.cameras[0], b.s.cameras[0].target, 4.0f, 0.25f,
                    [](float t) { return 30.0f * std::sin(std::numbers::pi_v<float> * t / 2.0f); }));
  b.s.animation.duration = 4.0f;
  return b.s;
}

// Planar reflectors seen edge-on by the default camera (a horizontal mirror at eye height and a
// vertical one in the plane x = 0 through the eye), one at a grazing angle, and one behind the
// camera facing the scene, all on a mirror floor (5 reflectors).
Scene hard_reflectors() {
  Builder b;
  b.s.name = "hard-reflectors";
  const glm::vec3 eye(0.0f, 1.5f, 6.0f);
  const int mirror = b.material(mat("mirror_floor", glm::vec3(0.9f), 0.0f, 1.0f, 1.0f));
  const int glass = b.material(mat("wall_mirror", glm::vec3(0.95f), 0.0f, 1.0f, 1.0f));
  mirror_rect(b, "floor", mirror, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {8.0f, 10.0f});
  mirror_rect(b, "mirror_eye_level", glass, {-2.0f, eye.y, -2.5f}, {0, 1, 0}, {1, 0, 0}, {1.0f, 1.5f});
  mirror_rect(b, "mirror_edge_on", glass, {0.0f, 1.7f, -3.5f}, {1, 0, 0}, {0, 0, 1}, {1.5f, 0.7f});
  mirror_rect(b, "mirror_grazing", glass, {4.0f, 1.5f, -2.0f},
              glm::normalize(glm::vec3(-1.0f, 0.0f, 0.05f)), glm::normalize(glm::vec3(0.05f, 0.0f, 1.0f)),
              {3.0f, 1.5f});
  mirror_rect(b, "mirror_behind", glass, {0.0f, 1.5f, 8.0f}, {0, 0, -1}, {1, 0, 0}, {3.0f, 1.5f});
  props(b, -3.0f);
  const int wall = b.material(mat("back_wall", {0.65f, 0.65f, 0.7f}, 0.85f));
  b.mesh(meshgen::box({16.0f, 4.0f, 0.2f}), "back_wall", wall, translate({0, 2.0f, -10.0f}));
  b.light({0.0f, 3.0f, 2.0f}, glm::vec3(1.0f), 40.0f, 25.0f);
  b.light({-3.0f, 2.5f, -5.0f}, {1.0f, 0.8f, 0.6f}, 30.0f, 20.0f);
  b.camera("default", eye, {0.0f, 1.5f, 0.0f});                 // level: both edge-on mirrors
  b.camera("turned", {0.0f, 1.5f, 2.0f}, {0.0f, 1.3f, 8.0f});   // facing the mirror behind
  b.camera("high", {0.0f, 4.0f, 7.0f}, {0.0f, 0.0f, -3.0f});
  // Rises 0.4 m out of the edge-on plane, then two cuts: to "turned" at 2 s, to "high" at 4 s.
  const std::vector<Camera>& c = b.s.cameras;
  b.path("cut",
         "camera cuts: rises 0.4 m from the edge-on view, cuts to the mirror behind at 2 s and "
         "to the high view at 4 s, then descends 1 m (6 s)",
         {key(0, c[0]), key(1.8f, c[0].position + glm::vec3(0, 0.4f, 0), c[0].target),
          key(2, c[1], /*cut=*/true), key(4, c[2], /*cut=*/true),
          key(6, c[2].position - glm::vec3(0, 1.0f, 0), c[2].target)});
  b.s.animation.duration = 6.0f;
  return b.s;
}

struct Entry {
  BuiltinSceneInfo info;
  std::vector<ParamDesc> options;
  Scene (*make)(const SceneOptions&);
};


const std::vector<Entry>& entries() {
  static const std::vector<Entry> list = {
      {{"gallery",
        "mirror floor (planar reflector) with coloured boxes, spheres, columns, a brick wall and "
        "a red marker sphere; options gallery:reflectors=1..16 (floor tiles plus wall mirrors), "
        "normal_map=ripples|tiles|none, floor_roughness=0.0..1.0 (default 0: a mirror) (e.g. "
        "gallery:reflectors=5,normal_map=tiles or gallery:floor_roughness=0.5)"},
       {kReflectorsOption, kNormalMapOption, kFloorRoughnessOption,
        path_option({"dolly", "orbit", "pan", "slide", "enter", "cut"})},
       &gallery},
      {{"cornell",
        "5 m Cornell box, open at the front, with a glossy metal floor (roughness 0.3) and two "
        "boxes"},
       {path_option({"dolly"})},
       [](const SceneOptions&) { return cornell(); }},
      {{"corridor",
        "40 m corridor with a near-mirror floor (planar reflector, roughness 0.05), pillars and "
        "coloured panels"},
       {path_option({"dolly", "pan"})},
       [](const SceneOptions&) { return corridor(); }},
      {{"glass", "refraction: a glass sphere (ior 1.5) and a tilted slab (ior 1.33) before a brick wall"},
       {path_option({"orbit"})},
       [](const SceneOptions&) { return glass(); }},
      {{"ramp",
        "roughness ramp: a metal floor in 11 bands of roughness 0.0, 0.1, ..., 1.0 side by side "
        "(band_0.0 .. band_1.0, planar reflectors 1..11: reflector:N is roughness (N-1)/10), "
        "coloured boxes, spheres and columns on it, a glowing sphere and strip, a brick wall"},
       {path_option({"dolly", "orbit", "pan"})},
       [](const SceneOptions&) { return ramp(); }},
      // Hard cases (issue 7): see the comments above each builder and docs/ROBUSTNESS.md.
      {{"hard-grazing", "hard case: camera 5 cm above a 400 m mirror floor, looking along it"},
       {path_option({"dolly"})},
       [](const SceneOptions&) { return hard_grazing(); }},
      {{"hard-mirror-box",
        "hard case: camera inside a closed box of six mirrors (rays back at the camera, through "
        "the near plane)"},
       {path_option({"turn"})},
       [](const SceneOptions&) { return hard_mirror_box(); }},
      {{"hard-thin", "hard case: a 2 cm pole and 1 cm fins standing on a mirror floor"},
       {path_option({"truck"})},
       [](const SceneOptions&) { return hard_thin(); }},
      {{"hard-depth-range",
        "hard case: near 0.001, far 1e5, objects from 0.01 to 5e4 m on a mirror floor"},
       {path_option({"dolly"})},
       [](const SceneOptions&) { return hard_depth_range(); }},
      {{"hard-far-origin", "hard case: the gallery moved 1e4 m from the origin (camera too)"},
       {path_option({"dolly", "orbit", "pan", "slide", "enter", "cut"})},
       [](const SceneOptions&) { return hard_far_origin(); }},
      {{"hard-degenerate",
        "hard case: normals in the face, flipped and cancelling, a zero-area triangle, an "
        "edge-on sliver, much sky"},
       {path_option({"pan"})},
       [](const SceneOptions&) { return hard_degenerate(); }},
      {{"hard-roughness", "hard case: a metal floor split into roughness exactly 0 and exactly 1"},
       {path_option({"orbit"})},
       [](const SceneOptions&) { return hard_roughness(); }},
      {{"hard-reflectors",
        "hard case: planar mirrors seen edge-on by the default camera, one grazing, one behind it"},
       {path_option({"cut"})},
       [](const SceneOptions&) { return hard_reflectors(); }},
  };
  return list;
}

// Parses the text after "name:" for entry `e`; `full` is the whole scene string (for messages).
SceneOptions parse_options(const Entry& e, const std::string& full, std::string_view text) {
  const std::string& name = e.info.name;
  std::string with_options;  // "; the scenes that take options: gallery (...)"
  for (const Entry& other : entries())
    if (!other.options.empty())
      with_options += (with_options.empty() ? "" : "; ") + other.info.name + " (" +
                      options_help(other.options) + ")";
  if (e.options.empty()) {
    const std::string key(text.substr(0, std::min(text.find('='), text.find(','))));
    throw InputError("built-in scene '" + name + "' takes no options" +
                     (key.empty() ? std::string() : " (not even '" + key + "')") + ", so '" +
                     full + "' is not a scene; options exist only for " + with_options);
  }
  const std::string help = options_help(e.options);
  if (text.empty())
    throw InputError("scene '" + full + "' has nothing after ':'; write " + name +
                     ":key=value[,key=value] with " + help);
  SceneOptions opt;
  ParamSet set(name, e.options, &opt, &kDefaultOptions);
  std::vector<std::string> given;
  std::size_t pos = 0;
  while (true) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    const std::string_view item = text.substr(pos, comma - pos);
    const std::size_t eq = item.find('=');
    const std::string key(item.substr(0, eq));
    if (item.empty())
      throw InputError("scene '" + full + "' has an empty option (options of " + name + ": " +
                       help + ")");
    if (key.empty())
      throw InputError("scene '" + full + "' has an option without a key (options of " + name +
                       ": " + help + ")");
    const int row = set.find(key);
    if (row < 0 || key.find('.') != std::string::npos)
      throw InputError("built-in scene '" + name + "' has no option '" + key + "' (options: " +
                       help + ")");
    const ParamDesc& d = e.options[static_cast<std::size_t>(row)];
    if (eq == std::string_view::npos)
      throw InputError("option '" + key + "' of built-in scene '" + name +
                       "' has no value; write " + key + "=" + allowed(d));
    const std::string value(item.substr(eq + 1));
    if (std::find(given.begin(), given.end(), key) != given.end())
      throw InputError("option '" + key + "' is given twice in '" + full + "' (allowed: " + key +
                       "=" + allowed(d) + ")");
    given.push_back(key);
    // The text is checked here (strict forms: no "auto", no spaces); the table's range too.
    double v = 0;
    if (d.type == ParamType::Float) {
      const std::optional<double> x = parse_number(value);
      if (!x || *x < d.min || *x > d.max)
        throw InputError("option '" + key + "' of built-in scene '" + name + "' must be a number in [" +
                         std::to_string(static_cast<int>(d.min)) + ", " + std::to_string(static_cast<int>(d.max)) +
                         "] (e.g. 0.5), not '" + value + "'");
      v = *x;
    } else if (d.type == ParamType::Int) {
      int i = 0;
      const char* first = value.data();
      const char* last = value.data() + value.size();
      const auto [end, ec] = std::from_chars(first, last, i);
      if (value.empty() || ec != std::errc() || end != last || i < d.min || i > d.max)
        throw InputError("option '" + key + "' of built-in scene '" + name +
                         "' must be an integer in " + allowed(d) + ", not '" + value + "'");
      v = i;
    } else {
      const auto c = std::find_if(d.choices.begin(), d.choices.end(), [&](const char* n) { return value == n; });
      if (c == d.choices.end())
        throw InputError("option '" + key + "' of built-in scene '" + name + "' must be one of " +
                         allowed(d) + ", not '" + value + "'");
      v = static_cast<double>(c - d.choices.begin());
    }
    set.set(static_cast<std::size_t>(row), v);
    if (comma == text.size()) break;
    pos = comma + 1;
  }
  return opt;
}

}  // namespace

const std::vector<BuiltinSceneInfo>& builtin_scenes() {
  static const std::vector<BuiltinSceneInfo> infos = [] {
    std::vector<BuiltinSceneInfo> v;
    for (const Entry& e : entries()) {
      v.push_back(e.info);
      SceneOptions defaults;
      const ParamSet set(e.info.name, e.options, &defaults, &kDefaultOptions);
      for (std::size_t i = 0; i < e.options.size(); ++i) {
        const ParamDesc& o = e.options[i];
        BuiltinSceneInfo::Option opt{o.name, set.is_auto(i) ? "" : set.default_string(i), {}};
        for (const char* c : o.choices) opt.values.push_back(c);
        if (o.type != ParamType::Choice) {
          const std::vector<double> picks = o.type == ParamType::Float ? std::vector<double>{0.0, 0.1, 0.25, 0.5, 1.0}
                                                                       : std::vector<double>{1, 2, 4, 5, 8, 16};
          for (double x : picks)
            if (x >= o.min && x <= o.max) {
              char buf[32];
              std::snprintf(buf, sizeof buf, "%g", x);
              opt.values.push_back(buf);
            }
        }
        v.back().options.push_back(std::move(opt));
      }
      // The camera paths, from the path option (the same names the scene has).
      for (const ParamDesc& o : e.options)
        if (std::string_view(o.name) == "path")
          v.back().description += "; camera paths (" + e.info.name + ":path=NAME): " + allowed(o);
      // The objects that move, from the scene's own motions: a still camera is not a still frame
      // there (sequence's flicker on cornell's `still` is the spinning box's).
      const Scene scene = e.make(kDefaultOptions);
      std::string moving;
      for (const ObjectMotion& m : scene.animation.objects)
        for (int mesh : m.meshes) moving += (moving.empty() ? "" : ", ") + scene.meshes[static_cast<std::size_t>(mesh)].name;
      if (!moving.empty()) v.back().description += "; moving objects: " + moving;
    }
    return v;
  }();
  return infos;
}

Scene make_builtin_scene(const std::string& name) {
  const std::size_t colon = name.find(':');
  const std::string base = name.substr(0, colon);
  for (const Entry& e : entries()) {
    if (e.info.name == base) {
      const SceneOptions opt = colon == std::string::npos
                                   ? SceneOptions{}
                                   : parse_options(e, name, std::string_view(name).substr(colon + 1));
      Scene s = e.make(opt);
      s.name = name;  // options included: results and file names record what was asked for
      if (opt.path >= 0) {
        const ParamDesc& path = *std::find_if(e.options.begin(), e.options.end(),
                                              [](const ParamDesc& d) { return std::string_view(d.name) == "path"; });
        s.animation.default_path =
            static_cast<int>(&find_path(s, path.choices[static_cast<std::size_t>(opt.path)]) - s.animation.paths.data());
      }
      validate(s);
      return s;
    }
  }
  std::ostringstream known;
  for (std::size_t i = 0; i < entries().size(); ++i)
    known << (i ? ", " : "") << entries()[i].info.name;
  throw InputError("unknown built-in scene '" + base + "' (built-in scenes: " + known.str() + ")");
}

}  // namespace ssr
