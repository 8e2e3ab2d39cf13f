// The deferred frame against analytic values, and the first technique on a mirror floor.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/errors.h"
#include "gl_test_env.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/meshgen.h"
#include "techniques/technique.h"
#include "registry/registry.h"

using namespace ssr;
using ssr::test::texel;

namespace {

// A wall in the plane z = 0 facing +Z, seen from (0, 1, 5) straight on, and a floor at y = 0.
Scene wall_scene() {
  Scene s;
  s.name = "wall";
  s.materials.push_back(Material{.name = "grey"});
  Mesh wall = meshgen::plane({20.0f, 20.0f});
  meshgen::transform(wall, glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0)));
  wall.name = "wall";
  s.meshes.push_back(wall);
  Mesh floor = meshgen::plane({20.0f, 20.0f});
  meshgen::transform(floor, glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 10)));
  floor.name = "floor";
  s.meshes.push_back(floor);
  s.lights.push_back(Light{.position = {0, 3, 3}});
  s.cameras.push_back(Camera{.name = "default", .position = {0, 1, 5}, .target = {0, 1, 0},
                             .fov_y_deg = 60, .near_plane = 0.1f, .far_plane = 100});
  validate(s);
  return s;
}

// Centroid (pixels, y down) of pixels where `pred(rgba)` holds; count in `n`.
template <class Pred>
glm::vec2 centroid(const RgbaImageF& im, Pred pred, int& n) {
  glm::dvec2 sum{0};
  n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      if (pred(texel(im, x, y))) {
        sum += glm::dvec2(x + 0.5, y + 0.5);
        ++n;
      }
  return n ? glm::vec2(sum / double(n)) : glm::vec2(-1);
}

}  // namespace

TEST(Frame, GBufferMatchesAnalyticPlane) {
  const Scene scene = wall_scene();
  const int w = 96, h = 64;
  Renderer r(scene, w, h);
  auto none = create_technique("none");
  none->load(r.shaders());
  r.render(scene.cameras[0], *none, ViewMode::Final, nullptr);
  const std::vector<float> depth = r.read_depth();
  const RgbaImageF normals = r.read_texture(r.gbuffer().normal_roughness);
  const CameraMatrices m = camera_matrices(scene.cameras[0], w, h);
  const glm::mat4 inv_vp = glm::inverse(m.proj * m.view);
  const Camera& cam = scene.cameras[0];
  int wall_pixels = 0, floor_pixels = 0;
  for (int y = 0; y < h; y += 7)
    for (int x = 0; x < w; x += 5) {
      // The camera ray through the pixel centre (y down), intersected with both planes.
      const glm::vec2 ndc((x + 0.5f) / w * 2 - 1, 1 - (y + 0.5f) / h * 2);
      glm::vec4 far_pt = inv_vp * glm::vec4(ndc, 0.0f, 1.0f);
      const glm::vec3 dir = glm::normalize(glm::vec3(far_pt) / far_pt.w - cam.position);
      const float t_wall = -cam.position.z / dir.z;                          // z = 0
      const float t_floor = dir.y < 0 ? -cam.position.y / dir.y : 1e30f;     // y = 0
      const bool wall = t_wall < t_floor;
      const float t = wall ? t_wall : t_floor;
      const glm::vec3 hit = cam.position + dir * t;
      if (std::abs(hit.x) > 9.5f || std::abs(hit.y - (wall ? 10.0f : 0.0f)) > 9.5f) continue;
      glm::vec2 px;
      float expected_depth;
      ASSERT_TRUE(project_to_pixel(m, w, h, hit, px, expected_depth));
      const float d = depth[static_cast<std::size_t>(y) * w + x];
      EXPECT_NEAR(d, expected_depth, 2e-5f) << "pixel " << x << "," << y;
      const glm::vec3 n_ws = wall ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
      const glm::vec3 n_vs = glm::mat3(m.view) * n_ws;
      const float* n = texel(normals, x, y);
      EXPECT_NEAR(n[0], n_vs.x, 2e-3f);
      EXPECT_NEAR(n[1], n_vs.y, 2e-3f);
      EXPECT_NEAR(n[2], n_vs.z, 2e-3f);
      (wall ? wall_pixels : floor_pixels)++;
    }
  EXPECT_GT(wall_pixels, 20);
  EXPECT_GT(floor_pixels, 10);
  // The camera looks straight at the wall: the centre pixel's depth is that of z_view = -5.
  const float a = m.proj[2][2], b = m.proj[3][2];
  EXPECT_NEAR(depth[static_cast<std::size_t>(h / 2) * w + w / 2], b / 5.0f - a, 1e-6f);
  ssr::test::expect_no_gl_errors();
}

TEST(Frame, LinearPutsMarkerReflectionAtMirroredPixel) {
  Scene scene = make_builtin_scene("gallery");
  // The marker: find it by name, and make it the only strongly green thing in the frame.
  const Mesh* marker = nullptr;
  for (const Mesh& m : scene.meshes)
    if (m.name == "marker") marker = &m;
  ASSERT_NE(marker, nullptr);
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const Vertex& v : marker->vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  const glm::vec3 centre = (lo + hi) * 0.5f;
  Material& mat = scene.materials[static_cast<std::size_t>(marker->material)];
  mat.albedo = glm::vec3(0.0f);
  mat.emission = glm::vec3(0.0f, 20.0f, 0.0f);
  ASSERT_FALSE(scene.reflectors.empty());
  const Reflector& floor = scene.reflectors[0];
  const glm::vec3 n = floor.normal();
  const glm::vec3 mirrored = centre - 2.0f * glm::dot(centre - floor.center, n) * n;

  const int w = 320, h = 180;
  Renderer r(scene, w, h);
  auto linear = create_technique("linear");
  linear->load(r.shaders());
  r.render(scene.cameras[0], *linear, ViewMode::Final, nullptr);
  const RgbaImageF lit = r.read_texture(r.lit());
  const RgbaImageF refl = r.read_texture(r.reflection());
  auto green = [](const float* p) { return p[1] > 5.0f && p[1] > 10.0f * std::max(p[0], p[2]); };
  int n_direct = 0, n_reflected = 0;
  const glm::vec2 direct = centroid(lit, green, n_direct);
  const glm::vec2 reflected = centroid(refl, green, n_reflected);

  const CameraMatrices m = camera_matrices(scene.cameras[0], w, h);
  glm::vec2 expect_direct, expect_reflected;
  float dd;
  ASSERT_TRUE(project_to_pixel(m, w, h, centre, expect_direct, dd));
  ASSERT_TRUE(project_to_pixel(m, w, h, mirrored, expect_reflected, dd));
  ASSERT_GT(n_direct, 20) << "the marker is not in view";
  ASSERT_GT(n_reflected, 20) << "the marker's reflection was not found";
  EXPECT_LT(glm::distance(direct, expect_direct), 2.0f)
      << "direct " << direct.x << "," << direct.y << " expected " << expect_direct.x << "," << expect_direct.y;
  EXPECT_LT(glm::distance(reflected, expect_reflected), 2.0f)
      << "reflected " << reflected.x << "," << reflected.y << " expected " << expect_reflected.x
      << "," << expect_reflected.y;
  // The reflection and the object are different pixels: the march did not just return itself.
  EXPECT_GT(glm::distance(reflected, direct), 5.0f);
  ssr::test::expect_no_gl_errors();
}

// Every built-in scene x technique x view: all targets finite, no GL error.
TEST(Frame, AllScenesTechniquesViewsFinite) {
  for (const BuiltinSceneInfo& info : builtin_scenes()) {
    const Scene scene = make_builtin_scene(info.name);
    Renderer r(scene, 96, 54);
    for (const TechniqueInfo& t : technique_registry()) {
      auto tech = t.create();
      tech->load(r.shaders());
      for (const Camera& cam : scene.cameras) {
        r.render(cam, *tech, ViewMode::Final, nullptr);
        for (const gl::Texture2D* target : {&r.lit(), &r.reflection(), &r.color()})
          EXPECT_EQ(test::count_nonfinite(r.read_texture(*target)), 0u)
              << info.name << " / " << t.name << " / camera " << cam.name;
        const RgbaImageF refl = r.read_texture(r.reflection());
        for (std::size_t i = 3; i < refl.pixels.size(); i += 4) {
          ASSERT_GE(refl.pixels[i], 0.0f);
          ASSERT_LE(refl.pixels[i], 1.0f);
        }
      }
      for (std::size_t v = 0; v < view_mode_names().size(); ++v) {
        r.redisplay(static_cast<ViewMode>(v));
        EXPECT_EQ(test::count_nonfinite(r.read_linear()), 0u) << info.name << " view " << v;
      }
    }
  }
  ssr::test::expect_no_gl_errors();
}

TEST(Frame, OddAndTinySizes) {
  const Scene scene = make_builtin_scene("gallery");
  Renderer r(scene, 1, 1);
  auto linear = create_technique("linear");
  linear->load(r.shaders());
  for (auto [w, h] : {std::pair{1, 1}, {3, 7}, {33, 17}}) {
    r.resize(w, h);
    r.render(scene.cameras[0], *linear, ViewMode::Final, nullptr);
    EXPECT_EQ(test::count_nonfinite(r.read_texture(r.color())), 0u) << w << "x" << h;
    const RgbaImage8 disp = r.read_display();
    EXPECT_EQ(disp.pixels.size(), static_cast<std::size_t>(w) * h * 4);
  }
  EXPECT_THROW(r.resize(0, 10), InputError);
  EXPECT_THROW(r.resize(1 << 20, 10), InputError);
  ssr::test::expect_no_gl_errors();
}

// The frame renders its inputs once per frame and caches them; a lighting change must still
// reach every technique, the planar oracle's own mirrored renders included.
TEST(Frame, LightingChangeReachesCachedInputs) {
  const Scene scene = make_builtin_scene("gallery");
  Renderer r(scene, 96, 54);
  for (const char* name : {"linear", "planar"}) {
    auto t = create_technique(name);
    t->load(r.shaders());
    r.set_lighting(scene.lights, scene.environment, scene.ambient);
    r.render(scene.cameras[0], *t, ViewMode::Final, nullptr);
    const RgbaImageF before = r.read_texture(r.reflection());
    std::vector<Light> dim = scene.lights;
    for (Light& l : dim) l.intensity *= 0.25f;
    r.set_lighting(dim, scene.environment, scene.ambient);
    r.render(scene.cameras[0], *t, ViewMode::Final, nullptr);
    const RgbaImageF after = r.read_texture(r.reflection());
    double sum_before = 0, sum_after = 0;
    for (std::size_t i = 0; i < before.pixels.size(); i += 4) {
      sum_before += before.pixels[i];
      sum_after += after.pixels[i];
    }
    EXPECT_LT(sum_after, 0.9 * sum_before) << name << ": the dimmed lights did not reach its reflection";
  }
}

// The debug image costs time (a fifth of linear-binary's on the H200): a technique writes it
// when the view shown is one of its debug views or when debug_outputs asks; else the frame
// clears it once, so no stale image is shown.
TEST(Frame, DebugImageWrittenOnlyWhenRead) {
  const Scene scene = make_builtin_scene("gallery");
  Camera moved = scene.cameras[0];
  moved.position += glm::vec3(0.4f, 0.1f, 0.0f);
  for (const char* name : {"hiz", "linear-binary", "ppr"}) {
    Renderer r(scene, 96, 54);
    auto t = create_technique(name);
    t->load(r.shaders());
    const ViewMode view = std::string(name) == "ppr" ? ViewMode::Offsets : ViewMode::Steps;
    r.render(scene.cameras[0], *t, view, nullptr);
    const std::vector<float> shown = r.read_texture(r.debug()).pixels;
    double sum = 0;
    for (float v : shown) sum += std::abs(v);
    ASSERT_GT(sum, 0.0) << name << ": its debug view shows an empty image";
    r.render(moved, *t, ViewMode::Final, nullptr);  // not written: cleared, as for a technique without one
    for (float v : r.read_texture(r.debug()).pixels) ASSERT_EQ(v, 0.0f) << name << ": wrote its debug image for the final view";
    r.debug_outputs = true;
    r.render(scene.cameras[0], *t, ViewMode::Final, nullptr);  // the first frame again
    r.render(moved, *t, ViewMode::Final, nullptr);
    EXPECT_NE(r.read_texture(r.debug()).pixels, shown) << name << ": debug_outputs did not write it";
  }
}
