// `dda` (McGuire & Mara): as accurate as the densest linear-binary march, and finite on rays
// that come straight back towards the camera.
#include <gtest/gtest.h>

#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "core/cli_common.h"
#include "gl_test_env.h"
#include "render/renderer.h"
#include "scene/meshgen.h"
#include "techniques/technique.h"
#include "tracer_test_util.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

using namespace ssr;

// One step per pixel visits every pixel the ray crosses, so it must match linear-binary with
// 500 view-space steps (to 0.5 dB) on the traceable pixels of gallery.
TEST(Dda, MatchesDenseLinearBinary) {
  constexpr int w = 192, h = 108;
  const auto dda = test::score_technique("gallery", w, h, "dda", {"dda.max_steps=512", "dda.stride=1"});
  const auto lb = test::score_technique(
      "gallery", w, h, "linear-binary",
      {"linear-binary.linear_steps=500", "linear-binary.max_distance=30", "linear-binary.thickness=0.15",
       "linear-binary.edge_fade=false"});
  std::printf("dda max_steps=512 stride=1: psnr_traceable %.2f dB, coverage %.1f%%\n", dda.error.psnr_traceable.value(),
              dda.error.coverage.value() * 100);
  std::printf("linear-binary linear_steps=500: psnr_traceable %.2f dB, coverage %.1f%%\n", lb.error.psnr_traceable.value(),
              lb.error.coverage.value() * 100);
  EXPECT_EQ(dda.error.nonfinite, 0u);
  EXPECT_GE(dda.error.psnr_traceable.value(), lb.error.psnr_traceable.value() - 0.5);
  test::expect_no_gl_errors();
}

// A mirror wall seen head-on at an odd size: the centre pixel's mirror ray comes straight back
// along its view ray (it projects to a point), the others head towards the camera and are
// clipped at the near plane; rough samples add rays in every direction.
TEST(Dda, RaysBackTowardsTheCameraStayFinite) {
  Scene s;
  s.name = "mirror-wall";
  s.materials.push_back(Material{.name = "mirror", .metallic = 1.0f, .roughness = 0.0f});
  s.materials.push_back(Material{.name = "grey"});
  Mesh wall = meshgen::plane({20.0f, 20.0f});  // y = 0, facing +Y: turned to z = 0, facing +Z
  meshgen::transform(wall, glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0)));
  wall.name = "wall";
  wall.material = 0;
  s.meshes.push_back(wall);
  Mesh floor = meshgen::plane({20.0f, 20.0f});
  meshgen::transform(floor, glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 10)));
  floor.name = "floor";
  floor.material = 1;
  s.meshes.push_back(floor);
  s.lights.push_back(Light{.position = {0, 3, 3}});
  s.cameras.push_back(Camera{.name = "default", .position = {0, 1, 5}, .target = {0, 1, 0},
                             .fov_y_deg = 60, .near_plane = 0.1f, .far_plane = 100});
  validate(s);

  constexpr int w = 97, h = 55;
  Renderer r(s, w, h);
  for (const char* stride : {"1", "7"})
    for (const char* rough : {"auto", "0.6"}) {
      auto dda = create_technique("dda");
      apply_assignments(*dda, {std::string("dda.stride=") + stride, "dda.jitter=true", "dda.samples=4",
                               std::string("dda.roughness=") + rough});
      dda->load(r.shaders());
      r.debug_outputs = true;  // steps, read below
      r.render(s.cameras[0], *dda, ViewMode::Final, nullptr);
      const RgbaImageF refl = r.read_texture(r.reflection());
      EXPECT_EQ(test::count_nonfinite(refl), 0u) << "stride " << stride << " roughness " << rough;
      EXPECT_EQ(test::count_nonfinite(r.read_texture(r.color())), 0u) << "stride " << stride;
      for (std::size_t i = 3; i < refl.pixels.size(); i += 4) {
        ASSERT_GE(refl.pixels[i], 0.0f);
        ASSERT_LE(refl.pixels[i], 1.0f);
      }
      // The wall really is a mirror whose rays were marched (debug x = steps per ray).
      const RgbaImageF debug = r.read_texture(r.debug());
      EXPECT_EQ(test::count_nonfinite(debug), 0u);
      int traced = 0;
      for (std::size_t i = 0; i < debug.pixels.size(); i += 4) traced += debug.pixels[i] > 0.0f;
      EXPECT_GT(traced, w * h / 4) << "stride " << stride;
    }
  test::expect_no_gl_errors();
}
