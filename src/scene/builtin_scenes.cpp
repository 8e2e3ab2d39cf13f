// The built-in scenes. 1 unit = 1 m, +Y up, right-handed. Every scene passes validate().
//
// gallery  (default) 32 x 17 m mirror floor (planar reflector 1, metallic 1, roughness 0) with
//          boxes, spheres, columns, a brick back wall and a red emissive "marker" sphere.
// cornell  5 x 5 x 5 m box open at the front (+Z): red left, green right, white back and
//          ceiling, glossy metal floor (roughness 0.3, no planar reflector), two white boxes.
// corridor 4 m wide, 3.5 m high, 40 m long, near-mirror floor (planar reflector 1, roughness
//          0.05), pillars and coloured panels along both walls, 8 ceiling lights.
//
// Default-camera framing (16:9, fov_y 60, glm::lookAt + glm::perspective, NDC in [-1,1], +y up)
// is worked out in the comments next to each camera and checked by tests/unit.
#include "scene/builtin_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/errors.h"
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

// ---- gallery ------------------------------------------------------------------------------------

Scene gallery() {
  Builder b;
  b.s.name = "gallery";

  // Floor: x in [-16, 16], z in [-7, 10], y = 0; a perfect mirror and planar reflector 1.
  const int mirror = b.material(mat("mirror_floor", glm::vec3(0.9f), 0.0f, 1.0f, 1.0f));
  const int refl = b.floor_reflector({0, 0, 1.5f}, {16.0f, 8.5f});
  b.mesh(meshgen::plane({32.0f, 17.0f}), "floor", mirror, translate({0, 0, 1.5f}), refl);

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
  b.s.environment.type = Environment::Type::Sky;
  b.s.ambient = 0.35f;
  return b.s;
}

struct Entry {
  BuiltinSceneInfo info;
  Scene (*make)();
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> list = {
      {{"gallery",
        "mirror floor (planar reflector) with coloured boxes, spheres, columns, a brick wall and "
        "a red marker sphere"},
       &gallery},
      {{"cornell",
        "5 m Cornell box, open at the front, with a glossy metal floor (roughness 0.3) and two "
        "boxes"},
       &cornell},
      {{"corridor",
        "40 m corridor with a near-mirror floor (planar reflector, roughness 0.05), pillars and "
        "coloured panels"},
       &corridor},
      {{"glass", "refraction: a glass sphere (ior 1.5) and a tilted slab (ior 1.33) before a brick wall"},
       &glass},
  };
  return list;
}

}  // namespace

const std::vector<BuiltinSceneInfo>& builtin_scenes() {
  static const std::vector<BuiltinSceneInfo> infos = [] {
    std::vector<BuiltinSceneInfo> v;
    for (const Entry& e : entries()) v.push_back(e.info);
    return v;
  }();
  return infos;
}

Scene make_builtin_scene(const std::string& name) {
  for (const Entry& e : entries()) {
    if (e.info.name == name) {
      Scene s = e.make();
      validate(s);
      return s;
    }
  }
  std::ostringstream known;
  for (std::size_t i = 0; i < entries().size(); ++i)
    known << (i ? ", " : "") << entries()[i].info.name;
  throw InputError("unknown built-in scene '" + name + "' (built-in scenes: " + known.str() + ")");
}

}  // namespace ssr
