// The pass-floor microbenchmark (eval/pass_floor.h, `ssrlab passfloor`) compares like with like:
// every mode (compute group shapes, fragment) writes every pixel of every kind the same, and the
// kinds compute what they say, so its timings differ by how a pass is issued, not by its output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "eval/pass_floor.h"
#include "gl_test_env.h"

using namespace ssr;

namespace {

// What kind `k` writes at pixel (x, y) of a w x h image (GL rows), from pass_floor_source().
void expected_pixel(const PassFloorKind& k, int w, int h, int x, int y, float out[4]) {
  const std::string name = k.name;
  if (name == "empty") {
    std::fill(out, out + 4, 0.0f);  // the target as cleared: nothing ran
  } else if (name == "store") {
    const float c[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    std::copy(c, c + 4, out);
  } else if (name == "copy") {
    pass_floor_source(x, y, out);
  } else {
    const int r = name == "taps3x3" ? 1 : 2;
    std::fill(out, out + 4, 0.0f);
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        float s[4];
        pass_floor_source(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1), s);
        for (int c = 0; c < 4; ++c) out[c] += s[c] * (1.0f + 0.125f * static_cast<float>(dx + 2 * dy));
      }
    for (int c = 0; c < 4; ++c) out[c] /= static_cast<float>((2 * r + 1) * (2 * r + 1));
  }
}

}  // namespace

TEST(PassFloor, EveryModeWritesWhatItsKindSays) {
  // Odd sides: the compute groups overhang the image on both axes.
  const int w = 37, h = 23;
  PassFloorBench bench(gl::ShaderSource(), w, h);
  ASSERT_GE(pass_floor_modes().size(), 2u);
  for (const PassFloorMode& m : pass_floor_modes())
    for (const PassFloorKind& k : pass_floor_kinds()) {
      const RgbaImageF out = bench.run_once(m, k);
      ASSERT_EQ(out.pixels.size(), static_cast<std::size_t>(w * h * 4));
      int wrong = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          float e[4];
          expected_pixel(k, w, h, x, y, e);
          for (int c = 0; c < 4; ++c)
            // RGBA16F: 11 significant bits; the values are below 2, so 2^-10 covers one rounding.
            if (!(std::abs(out.at(x, y)[c] - e[c]) <= 1.0f / 1024.0f)) ++wrong;
        }
      EXPECT_EQ(wrong, 0) << m.name << " / " << k.name;
    }
  test::expect_no_gl_errors();
}

TEST(PassFloor, TimesEveryCaseWithAFiniteFigure) {
  PassFloorBench bench(gl::ShaderSource(), 16, 16);
  for (const PassFloorMode& m : pass_floor_modes()) {
    const double ms = bench.time_ms(m, pass_floor_kind("copy"), 2, 2, gl::PassTimer::Clock::Cpu);
    EXPECT_TRUE(std::isfinite(ms) && ms > 0.0) << m.name << ": " << ms;
  }
  EXPECT_THROW(pass_floor_mode("cs7x7"), InputError);
  EXPECT_THROW(pass_floor_kind("taps9x9"), InputError);
}
