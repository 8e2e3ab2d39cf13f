// The tracers' ray list (the `compact` option, render/classification.h): tracing only the listed
// pixels through an indirect dispatch, with the classification writing every other pixel's
// outputs, gives the image of a full-screen dispatch bit for bit (reflection, refraction, debug
// image; with the denoiser too), and lists exactly the reflective pixels and those behind glass.
#include <gtest/gtest.h>

#include <cstring>

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
  // Two frames: the second one's denoiser has history.
  for (int f = 1; f <= 2; ++f)
    r.render(FrameRequest(r.scene().cameras[0], FrameTime{f, 0.0f}), *t, ViewMode::Final, nullptr);
  return {r.read_texture(r.reflection()), r.read_texture(r.refraction()), r.read_texture(r.debug()),
          r.read_texture(r.color())};
}

bool same(const RgbaImageF& a, const RgbaImageF& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
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
        EXPECT_TRUE(same(full.reflection, listed.reflection));
        EXPECT_TRUE(same(full.refraction, listed.refraction));
        EXPECT_TRUE(same(full.color, listed.color));
        if (!denoise) EXPECT_TRUE(same(full.debug, listed.debug));
      }
  }
  test::expect_no_gl_errors();
}
