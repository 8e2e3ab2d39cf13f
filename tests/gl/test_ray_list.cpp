// The tracers' ray list (the `compact` option, render/classification.h): tracing only the listed
// pixels through an indirect dispatch, with the classification writing every other pixel's
// outputs, gives the image of a full-screen dispatch bit for bit (reflection, refraction, debug
// image; with the denoiser too; in the plain variant and the general code), and lists exactly the
// reflective pixels and those behind glass.
#include <gtest/gtest.h>

#include "core/cli_common.h"
#include "eval/runner.h"
#include "gl_test_env.h"
#include "tracer_test_util.h"
#include "render/renderer.h"
#include "scene/builtin_scenes.h"
#include "techniques/technique.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

using namespace ssr;

TEST(RayList, SameImageAsEveryPixel) {
  for (const std::string scene : {"gallery", "glass", "corridor"}) {
    Renderer r(make_builtin_scene(scene), 128, 72);
    for (const std::string t : {"linear", "linear-binary", "dda", "hiz"})
      for (const bool denoise : {false, true})
        for (const bool plain : {true, false}) {  // the plain variant (defaults) and the general code (2 rays)
          const std::string what = t + (denoise ? "-denoised" : "") + (plain ? "" : "-2-rays");
          SCOPED_TRACE(scene + " / " + what);
          const std::string d = t + ".denoise=" + (denoise ? "true" : "false");
          const std::string n = t + ".samples=" + (plain ? "1" : "2");
          const test::TechniqueOutputs full = test::render_outputs(r, t, {t + ".compact=false", d, n}, r.shaders());
          const test::TechniqueOutputs listed = test::render_outputs(r, t, {t + ".compact=true", d, n}, r.shaders());
          test::expect_same_outputs(full, listed, "ray-list-" + scene + "-" + what, !denoise);
        }
  }
  test::expect_no_gl_errors();
}
