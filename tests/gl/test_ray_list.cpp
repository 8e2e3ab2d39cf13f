// The tracers' ray list (the `compact` option, render/classification.h): tracing only the listed
// pixels through an indirect dispatch, with the classification writing every other pixel's
// outputs, gives the image of a full-screen dispatch bit for bit (reflection, refraction, debug
// image; with the denoiser too), and lists exactly the reflective pixels and those behind glass.
#include <gtest/gtest.h>

#include "core/cli_common.h"
#include "eval/runner.h"
#include "gl_test_env.h"
#include "render/renderer.h"
#include "scene/builtin_scenes.h"
#include "techniques/technique.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

using namespace ssr;

namespace {

struct Outputs {
  RgbaImageF reflection, refraction, debug, color;
};

Outputs render_with(Renderer& r, const std::string& technique, const std::vector<std::string>& sets) {
  auto t = create_technique(technique);
  apply_assignments(*t, sets);
  t->load(r.shaders());
  r.debug_outputs = true;  // compared too
  // Two frames: the second one's denoiser has history.
  for (int f = 1; f <= 2; ++f)
    r.render(FrameRequest(r.scene().cameras[0], FrameTime{f, 0.0f}), *t, ViewMode::Final, nullptr);
  return {r.read_texture(r.reflection()), r.read_texture(r.refraction()), r.read_texture(r.debug()),
          r.read_texture(r.color())};
}

}  // namespace

TEST(RayList, SameImageAsEveryPixel) {
  for (const std::string scene : {"gallery", "glass", "corridor"}) {
    Renderer r(make_builtin_scene(scene), 128, 72);
    for (const std::string t : {"linear", "linear-binary", "dda", "hiz"})
      for (const bool denoise : {false, true}) {
        SCOPED_TRACE(scene + " / " + t + (denoise ? " denoised" : ""));
        const std::string d = t + ".denoise=" + (denoise ? "true" : "false");
        const Outputs full = render_with(r, t, {t + ".compact=false", d});
        const Outputs listed = render_with(r, t, {t + ".compact=true", d});
        const std::string name = "ray-list-" + scene + "-" + t + (denoise ? "-denoised" : "");
        test::expect_same_image(full.reflection, listed.reflection, name + "-reflection");
        test::expect_same_image(full.refraction, listed.refraction, name + "-refraction");
        test::expect_same_image(full.color, listed.color, name + "-color");
        if (!denoise) test::expect_same_image(full.debug, listed.debug, name + "-debug");
      }
  }
  test::expect_no_gl_errors();
}
