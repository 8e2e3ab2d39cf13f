// The hard-case matrix (issue 7, items 1-2): every technique except `reference` on every
// built-in `hard-*` scene (default camera, 96x54) against the reference (64 samples per rough
// pixel): no non-finite value in the reflection or the final colour, PSNR over the reflective
// pixels at or above the floor written for that case in kHardTolerances, and no GL error
// (the GL test main turns the KHR_debug callback on). Then odd, tiny and large frame sizes on
// `gallery` for every technique: finite output and no GL error.
//
// The measured figures in the table's comments come from llvmpipe (LLVM 15.0.6) on 2 cores:
// `ssrlab_gl_tests --gtest_filter='Hard*'` prints one "hard-case" line per cell; the same
// figures are in docs/ROBUSTNESS.md. Each floor is the measurement minus 3 dB, rounded down to
// 0.5 dB, never below 5 dB. A technique or hard-* scene without a row fails the test.
// Where a technique measures within 3 dB of `none` (every tracer on hard-mirror-box, whose
// mirrors facing mirrors screen space cannot follow, scores below it; linear on hard-grazing and
// hard-depth-range), the floor shows only that the error stays bounded, not that it traced:
// Tracers.HardCasesStayFiniteAndBounded holds each tracer above `none` on its cases.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/cli_common.h"
#include "eval/runner.h"
#include "gl_test_env.h"
#include "render/renderer.h"
#include "scene/builtin_scenes.h"
#include "techniques/technique.h"
#include "tracer_test_util.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

using namespace ssr;

namespace {

constexpr int kW = 96, kH = 54;

struct Tolerance {
  const char* scene;
  const char* technique;
  double min_psnr;  // dB over the reflective pixels vs the reference; measured value in the comment
};

// clang-format off
constexpr Tolerance kHardTolerances[] = {
    // gallery (baseline, not a hard case)
    {"gallery", "none", 5.5},                       // measured 8.89 dB
    {"gallery", "linear", 14.5},                    // measured 17.42 dB
    {"gallery", "linear-binary", 15.0},             // measured 17.81 dB
    {"gallery", "dda", 13.0},                       // measured 16.19 dB
    {"gallery", "hiz", 13.0},                       // measured 16.17 dB
    {"gallery", "stochastic", 13.0},                // measured 16.24 dB (one frame, no history)
    {"gallery", "ppr", 12.5},                       // measured 15.97 dB
    {"gallery", "planar", 23.5},                    // measured 26.78 dB
    // hard-grazing
    {"hard-grazing", "none", 14.5},                 // measured 17.91 dB
    {"hard-grazing", "linear", 16.0},               // measured 19.05 dB
    {"hard-grazing", "linear-binary", 26.5},        // measured 29.26 dB
    {"hard-grazing", "dda", 24.5},                  // measured 27.72 dB
    {"hard-grazing", "hiz", 24.5},                  // measured 27.72 dB
    {"hard-grazing", "stochastic", 24.5},           // measured 27.72 dB (one frame, no history)
    {"hard-grazing", "ppr", 23.5},                  // measured 26.65 dB
    {"hard-grazing", "planar", 65.5},               // measured 68.66 dB
    // hard-mirror-box
    {"hard-mirror-box", "none", 8.5},               // measured 11.88 dB
    {"hard-mirror-box", "linear", 7.5},             // measured 10.85 dB
    {"hard-mirror-box", "linear-binary", 8.0},      // measured 10.78 dB
    {"hard-mirror-box", "dda", 7.5},                // measured 10.87 dB
    {"hard-mirror-box", "hiz", 7.5},                // measured 10.87 dB
    {"hard-mirror-box", "stochastic", 7.5},         // measured 10.87 dB (one frame, no history)
    {"hard-mirror-box", "ppr", 7.5},                // measured 10.84 dB
    {"hard-mirror-box", "planar", 69.0},            // measured 72.46 dB
    // hard-thin
    {"hard-thin", "none", 10.0},                    // measured 13.17 dB
    {"hard-thin", "linear", 26.0},                  // measured 29.18 dB
    {"hard-thin", "linear-binary", 26.0},           // measured 29.18 dB
    {"hard-thin", "dda", 25.5},                     // measured 28.56 dB
    {"hard-thin", "hiz", 26.0},                     // measured 29.10 dB
    {"hard-thin", "stochastic", 26.0},              // measured 29.10 dB (one frame, no history)
    {"hard-thin", "ppr", 20.5},                     // measured 23.79 dB
    {"hard-thin", "planar", 64.0},                  // measured 67.37 dB
    // hard-depth-range
    {"hard-depth-range", "none", 24.0},             // measured 27.43 dB
    {"hard-depth-range", "linear", 24.5},           // measured 27.43 dB (auto step: see ROBUSTNESS.md)
    {"hard-depth-range", "linear-binary", 26.0},    // measured 29.35 dB (auto step: see ROBUSTNESS.md)
    {"hard-depth-range", "dda", 34.0},              // measured 37.10 dB
    {"hard-depth-range", "hiz", 34.0},              // measured 37.10 dB
    {"hard-depth-range", "stochastic", 34.0},       // measured 37.10 dB (one frame, no history)
    {"hard-depth-range", "ppr", 24.5},              // measured 27.79 dB
    {"hard-depth-range", "planar", 77.0},           // measured 80.03 dB
    // hard-far-origin
    {"hard-far-origin", "none", 5.5},               // measured 8.91 dB
    {"hard-far-origin", "linear", 14.0},            // measured 17.01 dB
    {"hard-far-origin", "linear-binary", 14.5},     // measured 17.42 dB
    {"hard-far-origin", "dda", 12.5},               // measured 15.83 dB
    {"hard-far-origin", "hiz", 12.5},               // measured 15.82 dB
    {"hard-far-origin", "stochastic", 12.5},        // measured 15.87 dB (one frame, no history)
    {"hard-far-origin", "ppr", 12.5},               // measured 15.66 dB
    {"hard-far-origin", "planar", 20.5},            // measured 23.84 dB
    // hard-degenerate
    {"hard-degenerate", "none", 5.5},               // measured 8.52 dB
    {"hard-degenerate", "linear", 10.0},            // measured 13.24 dB
    {"hard-degenerate", "linear-binary", 10.5},     // measured 13.56 dB
    {"hard-degenerate", "dda", 8.5},                // measured 11.53 dB
    {"hard-degenerate", "hiz", 9.5},                // measured 12.91 dB
    {"hard-degenerate", "stochastic", 10.0},        // measured 13.38 dB (one frame, no history)
    {"hard-degenerate", "ppr", 9.0},                // measured 12.06 dB
    {"hard-degenerate", "planar", 11.0},            // measured 14.17 dB
    // hard-roughness
    {"hard-roughness", "none", 17.0},               // measured 20.26 dB
    {"hard-roughness", "linear", 28.0},             // measured 30.82 dB
    {"hard-roughness", "linear-binary", 28.0},      // measured 30.86 dB
    {"hard-roughness", "dda", 27.5},                // measured 30.99 dB
    {"hard-roughness", "hiz", 27.5},                // measured 30.91 dB
    {"hard-roughness", "stochastic", 30.0},         // measured 34.03 dB (one frame, no history)
    {"hard-roughness", "ppr", 23.5},                // measured 26.52 dB
    {"hard-roughness", "planar", 30.0},             // measured 33.22 dB
    // hard-reflectors
    {"hard-reflectors", "none", 5.0},               // measured 8.26 dB
    {"hard-reflectors", "linear", 12.5},            // measured 15.66 dB
    {"hard-reflectors", "linear-binary", 12.5},     // measured 15.72 dB
    {"hard-reflectors", "dda", 12.5},               // measured 15.90 dB
    {"hard-reflectors", "hiz", 12.5},               // measured 15.90 dB
    {"hard-reflectors", "stochastic", 12.5},        // measured 15.90 dB (one frame, no history)
    {"hard-reflectors", "ppr", 12.5},               // measured 15.50 dB
    {"hard-reflectors", "planar", 25.0},            // measured 28.20 dB
};
// clang-format on

// A floor under 5 dB would accept a black image; the table is checked where it is compiled.
constexpr bool floors_at_least(double db) {
  for (const Tolerance& t : kHardTolerances)
    if (t.min_psnr < db) return false;
  return true;
}
static_assert(floors_at_least(5.0), "a hard-case floor below 5 dB accepts a black image");

const Tolerance* find_tolerance(const std::string& scene, const std::string& technique) {
  for (const Tolerance& t : kHardTolerances)
    if (scene == t.scene && technique == t.technique) return &t;
  return nullptr;
}

// The hard-* scenes, after `gallery` as a baseline (hard-far-origin is the gallery moved).
std::vector<std::string> hard_scenes() {
  std::vector<std::string> v = {"gallery"};
  for (const BuiltinSceneInfo& s : builtin_scenes())
    if (s.name.rfind("hard-", 0) == 0) v.push_back(s.name);
  return v;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST(HardCases, EveryTechniqueOnEveryHardSceneIsFiniteAndBounded) {
  const std::vector<std::string> scenes = hard_scenes();
  ASSERT_EQ(scenes.size(), 9u);  // gallery + 8 hard cases
  for (const std::string& scene : scenes) {
    for (const TechniqueInfo& t : technique_registry()) {
      if (t.name == "reference") continue;
      const auto t0 = std::chrono::steady_clock::now();
      const auto s = test::score_technique(scene, kW, kH, t.name, {});
      std::printf("hard-case %-17s %-14s psnr %6.2f dB  nonfinite %zu  reflective %zu  (%.2f s)\n",
                  scene.c_str(), t.name.c_str(), s.error.psnr.value(), s.error.nonfinite, s.error.reflective,
                  seconds_since(t0));
      EXPECT_EQ(s.error.nonfinite, 0u) << scene << " / " << t.name;
      const Tolerance* tol = find_tolerance(scene, t.name);
      if (!tol) {
        ADD_FAILURE() << "no tolerance for " << scene << " / " << t.name
                      << " in kHardTolerances: measure it and add a row (measured "
                      << s.error.psnr.value() << " dB)";
        continue;
      }
      EXPECT_GE(s.error.psnr.value(), tol->min_psnr) << scene << " / " << t.name;
      test::expect_no_gl_errors();
    }
  }
  test::expect_no_gl_errors();
}

// Renders every technique (the reference with few samples) on the gallery at w x h and checks
// that the lit, reflection and final images are finite.
void expect_finite_at(Renderer& r, const Scene& scene, int w, int h) {
  r.resize(w, h);
  for (const TechniqueInfo& t : technique_registry()) {
    const auto t0 = std::chrono::steady_clock::now();
    auto tech = t.create();
    if (t.name == "reference") apply_assignments(*tech, {"reference.samples=4"});
    tech->load(r.shaders());
    r.render(scene.cameras[0], *tech, ViewMode::Final, nullptr);
    for (const gl::Texture2D* target : {&r.lit(), &r.reflection(), &r.color()})
      EXPECT_EQ(test::count_nonfinite(r.read_texture(*target)), 0u) << w << "x" << h << " " << t.name;
    // The display pass shows this frame at this size: its 8-bit image is the shared tone map of
    // the composited colour, pixel for pixel (a wrong size, row order or stale image differs).
    const RgbaImage8 disp = r.read_display();
    const RgbaImageF want = display_values(r.read_texture(r.color()), r.settings.exposure);
    std::size_t off = 0;
    for (std::size_t i = 0; i < want.pixels.size(); ++i)
      if ((i & 3) != 3 && std::abs(float(disp.pixels[i]) - want.pixels[i] * 255.0f) > 1.0f) ++off;
    EXPECT_EQ(off, 0u) << w << "x" << h << " " << t.name << ": display differs from the tone-mapped colour";
    std::printf("hard-size %dx%d %-14s finite (%.2f s)\n", w, h, t.name.c_str(), seconds_since(t0));
    test::expect_no_gl_errors();
  }
}

TEST(HardSizes, OddTinyAndLargeFramesStayFinite) {
  const Scene scene = make_builtin_scene("gallery");
  Renderer r(scene, 1, 1);
  for (auto [w, h] : {std::pair{1, 1}, {3, 7}, {1921, 1081}}) expect_finite_at(r, scene, w, h);
  test::expect_no_gl_errors();
}

// 7680x4320 (8K), every technique on gallery and on every hard-* scene: too slow for CI on
// llvmpipe (see docs/ROBUSTNESS.md); run on a GPU with
// --gtest_also_run_disabled_tests --gtest_filter='HardSizes.*'.
TEST(HardSizes, DISABLED_Frame8KStaysFinite) {
  for (const BuiltinSceneInfo& info : builtin_scenes()) {
    if (info.name != "gallery" && info.name.rfind("hard-", 0) != 0) continue;
    const Scene scene = make_builtin_scene(info.name);
    Renderer r(scene, 1, 1);
    std::printf("8K: %s\n", info.name.c_str());
    expect_finite_at(r, scene, 7680, 4320);
  }
  test::expect_no_gl_errors();
}

// Every parameter of every technique at each end of its range (each choice, both booleans,
// auto where it takes it), the others at their defaults, over three frames (history: the
// denoiser's, the previous colour) on the hard cases that stress it most: the lit, reflection and
// final images and every stage view stay finite, with no GL error. The defaults alone (above)
// leave a division by a parameter at its range's end unseen.
TEST(HardCases, EveryParameterAtItsRangeEndsStaysFinite) {
  constexpr int w = 40, h = 24;
  for (const char* name : {"hard-mirror-box", "hard-roughness", "hard-depth-range"}) {
    const Scene scene = make_builtin_scene(name);
    Renderer r(scene, w, h);
    const auto t0 = std::chrono::steady_clock::now();
    std::size_t cases = 0;
    for (const TechniqueInfo& t : technique_registry()) {
      if (t.truth) continue;  // the reference's own ranges: test_reference.cpp
      const std::size_t n = t.create()->params().size();
      for (std::size_t i = 0; i < n; ++i) {
        auto probe = t.create();
        ParamSet p = probe->params();
        const ParamDesc& d = p.table()[i];
        std::vector<double> values = {d.min, d.max};
        if (d.type == ParamType::Choice)
          for (std::size_t c = 0; c < d.choices.size(); ++c) values.push_back(static_cast<double>(c));
        if (d.has_auto()) values.push_back(d.auto_value);
        for (double v : values) {
          auto tech = t.create();
          ParamSet q = tech->params();
          q.set(i, v);
          const std::string what = std::string(name) + " " + q.key(i) + "=" + q.to_string(i);
          tech->load(r.shaders());
          for (int f = 0; f < 3; ++f) {
            r.debug_outputs = f == 2;  // the last frame runs the variants that write the debug image
            r.render(FrameRequest(scene.cameras[0], {f, f / 30.0f}), *tech, ViewMode::Final, nullptr);
            for (const gl::Texture2D* target : {&r.lit(), &r.reflection(), &r.color(), &r.debug()})
              ASSERT_EQ(test::count_nonfinite(r.read_texture(*target)), 0u) << what << " frame " << f;
          }
          r.debug_outputs = false;
          for (const StageView& s : tech->declare().stage_views) {
            r.redisplay(s.view);
            ASSERT_EQ(test::count_nonfinite(r.read_linear()), 0u) << what << " view " << view_info(s.view).name;
          }
          ++cases;
          test::expect_no_gl_errors();
        }
      }
    }
    std::printf("range ends on %s: %zu cases finite (%.1f s)\n", name, cases, seconds_since(t0));
  }
}
