// The tracers' plain variant (shared/ray_options.h: the plain options as constants, compiled
// with SSR_PLAIN_RAY): it renders what the general code renders from the same options, bit for
// bit, and the plain options are exactly the defaults.
#include <gtest/gtest.h>

#include <cstring>

#include "gl_test_env.h"
#include "tracer_test_util.h"
#include "render/renderer.h"
#include "scene/builtin_scenes.h"
#include "shared/hiz.h"
#include "shared/ray_options.h"
#include "techniques/tracer.h"

using namespace ssr;

TEST(PlainRay, TheDefaultsArePlainAndPlainRayKeepsThem) {
  const shared::RayOptions defaults{};
  const shared::RayOptions resolved = TracerTechnique<shared::HizParams>::resolved_ray(defaults);
  EXPECT_TRUE(shared::is_plain_ray(resolved));
  const shared::RayOptions same = shared::plain_ray(resolved);
  EXPECT_EQ(std::memcmp(&same, &resolved, sizeof same), 0) << "plain_ray changed plain options";
  // Each option away from its plain value makes the options general.
  for (int field = 0; field < 4; ++field) {
    shared::RayOptions o = resolved;
    if (field == 0) o.samples = 2;
    if (field == 1) o.edge_fade = 1;
    if (field == 2) o.falloff_distance = 5.0f;
    if (field == 3) o.blend = 1;
    EXPECT_FALSE(shared::is_plain_ray(o)) << "field " << field;
  }
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
        const std::string name = "plain-ray-" + scene + "-" + t + (denoise ? "-denoised" : "");
        const test::TechniqueOutputs plain = test::render_outputs(r, t, sets, r.shaders());
        const test::TechniqueOutputs full = test::render_outputs(r, t, sets, general);
        test::expect_same_outputs(full, plain, name, !denoise);
        if (!denoise) {  // and the variants without the debug image (what bench times)
          const test::TechniqueOutputs plain_nodebug = test::render_outputs(r, t, sets, r.shaders(), false);
          const test::TechniqueOutputs full_nodebug = test::render_outputs(r, t, sets, general, false);
          test::expect_same_outputs(full_nodebug, plain_nodebug, name + "-nodebug", false);
        }
      }
  }
  test::expect_no_gl_errors();
}
