// Per-ray telemetry (render/telemetry.h): what an instrumented trace records agrees with what
// the plain trace writes in its debug image, counted again here on the CPU, and instrumenting a
// technique does not change its image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "core/cli_common.h"
#include "registry/variants.h"
#include "eval/runner.h"
#include "gl_test_env.h"
#include "render/renderer.h"
#include "render/telemetry.h"
#include "scene/builtin_scenes.h"
#include "techniques/technique.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

using namespace ssr;

namespace {

constexpr int kW = 160, kH = 90;

struct FrameRun {
  RgbaImageF reflection, debug;
  TelemetryFrame telemetry;
};

// One frame of `technique` on gallery with every surface a mirror (one ray a pixel, so the
// debug image's steps are the ray's iterations), plain or instrumented; `compact`: over the ray
// list (else one lane per screen pixel, whose warps the CPU can form again).
FrameRun run_once(Renderer& r, const std::string& technique, bool instrumented, bool compact = false) {
  auto t = create_technique(technique);
  apply_assignments(*t, {technique + ".roughness=0", technique + ".compact=" + (compact ? "true" : "false")});
  t->load(instrumented ? r.shaders().with_defines({"SSR_TELEMETRY"}) : r.shaders());
  r.telemetry().begin(kW, kH);
  r.debug_outputs = true;  // steps, read against the telemetry
  r.render(FrameRequest(r.scene().cameras[0]), *t, ViewMode::Final, nullptr);
  return {r.read_texture(r.reflection()), r.read_texture(r.debug()), r.telemetry().read()};
}

}  // namespace

TEST(Telemetry, MatchesTheDebugImageAndChangesNothing) {
  Renderer r(make_builtin_scene("gallery"), kW, kH);
  for (const std::string technique : {"hiz", "linear-binary", "dda"}) {
    SCOPED_TRACE(technique);
    const FrameRun plain = run_once(r, technique, false);
    const FrameRun inst = run_once(r, technique, true);
    // Instrumented, the same image bit for bit (and the plain build records nothing).
    test::expect_same_image(plain.reflection, inst.reflection, "telemetry-" + technique + "-instrumented");
    EXPECT_FALSE(plain.telemetry.stats().has_value());

    // The CPU's count from the debug image (rows read top first; the telemetry's GL order is
    // bottom first): the histogram, and the idle share of 32-lane warps (8x4 halves of the 8x8
    // work groups, lanes outside the image idle).
    const std::vector<bool> traced = scored_pixels(r);  // gallery has no glass: the reflective pixels
    std::vector<std::uint32_t> hist(TELEMETRY_BINS, 0);
    std::uint64_t busy = 0, slots = 0;
    std::size_t word_mismatches = 0;
    for (int wy = 0; wy < kH; wy += 4)
      for (int wx = 0; wx < kW; wx += 8) {
        std::uint32_t sum = 0, top = 0;
        for (int y = wy; y < std::min(wy + 4, kH); ++y)
          for (int x = wx; x < std::min(wx + 8, kW); ++x) {
            const std::size_t top_row = static_cast<std::size_t>(kH - 1 - y) * kW + x;
            const auto n = static_cast<std::uint32_t>(plain.debug.pixels[top_row * 4]);
            if (traced[top_row]) ++hist[std::min<std::uint32_t>(n, TELEMETRY_BINS - 1)];
            sum += n;
            top = std::max(top, n);
            const std::uint32_t word = inst.telemetry.pixels[static_cast<std::size_t>(y) * kW + x];
            word_mismatches += n > 0 && shared::telemetry_iterations(word) != n;
          }
        busy += sum;
        slots += top * TELEMETRY_WARP;
      }
    EXPECT_EQ(word_mismatches, 0u);
    EXPECT_TRUE(inst.telemetry.histogram == hist);
    const auto s = inst.telemetry.stats();
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->rays, static_cast<std::uint64_t>(std::count(traced.begin(), traced.end(), true)));
    ASSERT_TRUE(s->idle_lanes.has_value());
    EXPECT_DOUBLE_EQ(*s->idle_lanes, 1.0 - double(busy) / double(slots));
    EXPECT_GT(s->mean, 1.0);
    EXPECT_LE(s->p50, s->p95);
    EXPECT_LE(s->p95, s->max);

    // Over the ray list: the same image and the same rays, in no more warps (they hold listed
    // pixels only). Its idle share depends on the list's order, which the GPU's scheduling sets:
    // it is not compared (on gallery the iteration spread among reflective pixels dominates it).
    const FrameRun listed = run_once(r, technique, true, true);
    test::expect_same_image(plain.reflection, listed.reflection, "telemetry-" + technique + "-listed");
    EXPECT_TRUE(listed.telemetry.histogram == hist);
    EXPECT_LE(listed.telemetry.header.warps, inst.telemetry.header.warps);
  }
  test::expect_no_gl_errors();
}

// Techniques that do not iterate record nothing: bench writes null, not zeros.
TEST(Telemetry, NoneForTechniquesThatDoNotIterate) {
  Renderer r(make_builtin_scene("gallery"), kW, kH);
  const Camera camera = r.scene().cameras[0];
  EXPECT_FALSE(measure_telemetry(r, camera, Variant{"ppr", "", {}}).has_value());
  EXPECT_FALSE(measure_telemetry(r, camera, Variant{"none", "", {}}).has_value());
  const auto hiz = measure_telemetry(r, camera, Variant{"hiz", "", {}});
  ASSERT_TRUE(hiz.has_value());
  EXPECT_GT(hiz->rays, 0u);
  test::expect_no_gl_errors();
}
