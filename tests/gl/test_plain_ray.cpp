// The tracers' plain variant (shared/ray_options.h: the plain options as constants, compiled
// with SSR_PLAIN_RAY): it renders what the general code renders from the same options, bit for
// bit, and the plain options are exactly the defaults.
#include <gtest/gtest.h>

#include <cstring>

#include "gl_test_env.h"
#include "render/renderer.h"
#include "scene/builtin_scenes.h"
#include "shared/hiz.h"
#include "shared/ray_options.h"
#include "techniques/assignments.h"
#include "techniques/tracer.h"
#include "registry/registry.h"

using namespace ssr;

namespace {

struct Outputs {
  RgbaImageF reflection, refraction, debug, color;
};

// Two frames at the technique's defaults (the second one's denoiser has history), from `shaders`.
Outputs render_with(Renderer& r, const std::string& technique, const std::vector<std::string>& sets,
                    const gl::ShaderSource& shaders) {
  auto t = create_technique(technique);
  apply_assignments(*t, sets);
  t->load(shaders);
  r.debug_outputs = true;  // compared too
  for (int f = 1; f <= 2; ++f)
    r.render(FrameRequest(r.scene().cameras[0], FrameTime{f, 0.0f}), *t, ViewMode::Final, nullptr);
  return {r.read_texture(r.reflection()), r.read_texture(r.refraction()), r.read_texture(r.debug()),
          r.read_texture(r.color())};
}

}  // namespace

TEST(PlainRay, TheDefaultsArePlainAndPlainRayKeepsThem) {
  const shared::RayOptions defaults{};
  const shared::RayOptions resolved = TracerTechnique<shared::HizParams>::resolved_ray(defaults);
  EXPECT_TRUE(shared::is_plain_ray(resolved));
  const shared::RayOptions same = shared::plain_ray(resolved);
  EXPECT_EQ(std::memcmp(&same, &resolved, sizeof same), 0) << "plain_ray changed plain options";
  // Options that are not plain become plain, and only the four fields change.
  shared::RayOptions other = resolved;
  other.samples = 4;
  other.edge_fade = 1;
  other.falloff_distance = 3.0f;
  other.blend = 1;
  other.seed = 7;
  EXPECT_FALSE(shared::is_plain_ray(other));
  const shared::RayOptions made = shared::plain_ray(other);
  EXPECT_TRUE(shared::is_plain_ray(made));
  EXPECT_EQ(made.seed, 7);
  EXPECT_EQ(made.fresnel, other.fresnel);
}

TEST(PlainRay, SameImageAsTheGeneralCode) {
  for (const std::string scene : {"gallery", "glass", "cornell"}) {
    Renderer r(make_builtin_scene(scene), 128, 72);
    const gl::ShaderSource general = r.shaders().with_defines({"SSR_TEST_GENERAL_RAY"});
    for (const std::string t : {"linear", "linear-binary", "dda", "hiz"})
      for (const bool denoise : {false, true}) {
        SCOPED_TRACE(scene + " / " + t + (denoise ? " denoised" : ""));
        const std::vector<std::string> sets = {t + ".denoise=" + (denoise ? "true" : "false")};
        const Outputs plain = render_with(r, t, sets, r.shaders());
        const Outputs full = render_with(r, t, sets, general);
        const std::string name = "plain-ray-" + scene + "-" + t + (denoise ? "-denoised" : "");
        test::expect_same_image(full.reflection, plain.reflection, name + "-reflection");
        test::expect_same_image(full.refraction, plain.refraction, name + "-refraction");
        test::expect_same_image(full.color, plain.color, name + "-color");
        if (!denoise) test::expect_same_image(full.debug, plain.debug, name + "-debug");
      }
  }
  test::expect_no_gl_errors();
}
