// The temporal metrics' CPU parts: reprojection, flicker beyond the truth's, history ages.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "eval/temporal.h"

using namespace ssr;

namespace {

TemporalFrame frame(int w, int h, glm::vec2 motion, std::uint32_t object = 1) {
  TemporalFrame f;
  f.width = w;
  f.height = h;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  f.motion.assign(n, motion);
  f.object.assign(n, object);
  f.reflective.assign(n, true);
  return f;
}

RgbaImageF image(int w, int h, float v) {
  return RgbaImageF{w, h, std::vector<float>(static_cast<std::size_t>(w) * h * 4, v)};
}

// Two truths (a, b) of two frames, 64x64, where the scene goes from 0.5 to 0.6 and each truth
// carries Gaussian noise of `sigma` a channel, drawn anew for every image.
struct NoisyTruths {
  static constexpr int w = 64, h = 64;
  RgbaImageF a0, a1, b0, b1;
  explicit NoisyTruths(float sigma, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> noise(0.0f, sigma);
    auto noisy = [&](float v) {
      RgbaImageF im = image(w, h, v);
      for (float& p : im.pixels) p += noise(rng);
      return im;
    };
    a0 = noisy(0.5f), a1 = noisy(0.6f), b0 = noisy(0.5f), b1 = noisy(0.6f);
  }
};

}  // namespace

TEST(Temporal, StillFrameReprojectsToItself) {
  const TemporalFrame a = frame(8, 6, {0, 0}), b = frame(8, 6, {0, 0});
  const std::vector<int> q = reproject(b, a);
  ASSERT_EQ(q.size(), 48u);  // one per pixel: an empty answer would check nothing
  for (std::size_t i = 0; i < q.size(); ++i) EXPECT_EQ(q[i], static_cast<int>(i));
}

TEST(Temporal, MotionShiftsAndLeavesTheScreen) {
  // Everything was 2 pixels to the right (+x) and 1 up (+y, GL) a frame ago.
  const TemporalFrame before = frame(8, 6, {0, 0}), now = frame(8, 6, {2, 1});
  const std::vector<int> q = reproject(now, before);
  // Pixel (x=1, row 3 from the top) came from (3, row 2).
  EXPECT_EQ(q[3 * 8 + 1], 2 * 8 + 3);
  EXPECT_EQ(q[3 * 8 + 6], -1);  // x + 2 = 8: off screen
  EXPECT_EQ(q[0 * 8 + 1], -1);  // the top row came from above the screen
}

TEST(Temporal, AnotherObjectThereIsADisocclusion) {
  TemporalFrame before = frame(4, 4, {0, 0}), now = frame(4, 4, {0, 0});
  before.object[5] = 7;  // something else stood in front of pixel 5
  const std::vector<int> q = reproject(now, before);
  EXPECT_EQ(q[5], -1);
  EXPECT_EQ(q[6], 6);
}

TEST(Temporal, ExcessChangeIsChangeBeyondTheTruths) {
  const TemporalFrame a = frame(4, 2, {0, 0}), b = frame(4, 2, {0, 0});
  const std::vector<int> q = reproject(b, a);
  // Truth brightens by 0.1 everywhere; the technique by 0.1 (same), then by 0.3 (0.2 too much),
  // then not at all (less change than the truth: no excess).
  const RgbaImageF t0 = image(4, 2, 0.5f), t1 = image(4, 2, 0.6f);
  auto near = [](float a, float b) { return std::abs(a - b) < 1e-5f; };
  for (float v : excess_change(q, b, a, image(4, 2, 0.2f), image(4, 2, 0.1f), t1, t0)) EXPECT_TRUE(near(v, 0.0f));
  for (float v : excess_change(q, b, a, image(4, 2, 0.4f), image(4, 2, 0.1f), t1, t0)) EXPECT_TRUE(near(v, 0.2f));
  for (float v : excess_change(q, b, a, image(4, 2, 0.1f), image(4, 2, 0.1f), t1, t0)) EXPECT_TRUE(near(v, 0.0f));
  // A non-finite technique pixel counts as the largest flicker, not as NaN.
  RgbaImageF bad = image(4, 2, 0.1f);
  bad.pixels[0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(excess_change(q, b, a, bad, image(4, 2, 0.1f), t1, t0)[0], 1.0f);
}

TEST(Temporal, ChangeTotalsCompareTheTechniquesChangeWithTheTruths) {
  const TemporalFrame a = frame(4, 2, {0, 0});
  TemporalFrame b = frame(4, 2, {0, 0});
  b.reflective[3] = false;  // not measured: not reflective now
  const std::vector<int> q = reproject(b, a);
  // Truth brightens by 0.1, the technique by 0.3: three times the scene's change, on 7 pixels.
  const ChangeTotals c = change_totals(q, b, a, image(4, 2, 0.4f), image(4, 2, 0.1f), image(4, 2, 0.6f),
                                       image(4, 2, 0.5f));
  EXPECT_EQ(c.pixels, 7u);
  EXPECT_NEAR(c.technique / c.pixels, 0.3, 1e-5);
  EXPECT_NEAR(c.truth / c.pixels, 0.1, 1e-5);
  EXPECT_NEAR(c.technique / c.truth, 3.0, 1e-4);
}

TEST(Temporal, NoiseInChangeIsTheNoisesPartOfTheTruthsChange) {
  // The scene brightens by 0.1 from one frame to the next; two truths carry independent Gaussian
  // noise (sigma 0.02 a channel) that changes every frame. The noise's own mean change is
  // E|n1 - n0| = sigma * sqrt(2) * sqrt(2 / pi) = 0.0226; the scene's change cancels out.
  const int w = NoisyTruths::w, h = NoisyTruths::h;
  const TemporalFrame a = frame(w, h, {0, 0}), b = frame(w, h, {0, 0});
  const std::vector<int> q = reproject(b, a);
  const auto [a0, a1, b0, b1] = NoisyTruths(0.02f, 7);
  const std::optional<double> n = noise_in_change(q, b, a, a1, a0, b1, b0);
  ASSERT_TRUE(n);
  EXPECT_NEAR(*n, 0.02 * 2.0 / std::sqrt(3.14159265), 0.0015);
  // Noise fixed in time (the same pattern in both frames of each truth): none of the change.
  EXPECT_NEAR(*noise_in_change(q, b, a, image(w, h, 0.6f), image(w, h, 0.5f), image(w, h, 0.6f), image(w, h, 0.5f)),
              0.0, 1e-6);
  RgbaImageF a1_fixed = a0, b1_fixed = b0;
  for (float& p : a1_fixed.pixels) p += 0.1f;
  for (float& p : b1_fixed.pixels) p += 0.1f;
  EXPECT_NEAR(*noise_in_change(q, b, a, a1_fixed, a0, b1_fixed, b0), 0.0, 1e-5);
  // Nothing measured: no figure.
  TemporalFrame dark = b;
  dark.reflective.assign(dark.reflective.size(), false);
  EXPECT_FALSE(noise_in_change(q, dark, a, a1, a0, b1, b0));
}

TEST(Temporal, NoiseFreeChangeRatioSeesThroughTheTruthsNoise) {
  // The scene brightens by 0.1; each truth's noise (sigma 0.05 a channel) is drawn anew every
  // frame, so a truth's change carries noise of variance 2 * 0.05^2 = 0.005 besides the scene's
  // 0.01. The technique changes by 0.2: twice the scene's change.
  const int w = NoisyTruths::w, h = NoisyTruths::h;
  const TemporalFrame a = frame(w, h, {0, 0}), b = frame(w, h, {0, 0});
  const std::vector<int> q = reproject(b, a);
  const auto [a0, a1, b0, b1] = NoisyTruths(0.05f, 11);
  const RgbaImageF t0 = image(w, h, 0.1f), t1 = image(w, h, 0.3f);
  ChangeMoments two;
  add_change_moments(q, b, a, t1, t0, a1, a0, b1, b0, two);
  ASSERT_EQ(two.pixels, static_cast<std::size_t>(w * h));
  EXPECT_NEAR(two.technique_square / two.pixels, 0.04, 1e-6);
  EXPECT_NEAR(two.truth_product / two.pixels, 0.01, 4e-4);
  EXPECT_NEAR(*noise_free_change_ratio(two), 2.0, 0.05);
  // Against truth a's change with its noise (0.01 + 0.005): what the noise takes off the ratio.
  EXPECT_NEAR(two.truth_square / two.pixels, 0.015, 6e-4);
  EXPECT_NEAR(*rms_change_ratio(two), std::sqrt(0.04 / 0.015), 0.05);
  // One truth twice: its noise counts as the scene's change (0.015), and the ratio flatters.
  ChangeMoments one;
  add_change_moments(q, b, a, t1, t0, a1, a0, a1, a0, one);
  EXPECT_NEAR(*noise_free_change_ratio(one), std::sqrt(0.04 / 0.015), 0.05);
  // A truth that does not change: no ratio.
  ChangeMoments still;
  add_change_moments(q, b, a, t1, t0, image(w, h, 0.5f), image(w, h, 0.5f), image(w, h, 0.5f), image(w, h, 0.5f), still);
  EXPECT_FALSE(noise_free_change_ratio(still));
}

TEST(Temporal, AgesGrowAndRestart) {
  const TemporalFrame a = frame(4, 2, {0, 0});
  TemporalFrame b = a;
  b.reflective[2] = true;
  TemporalFrame a2 = a;
  a2.reflective[2] = false;  // pixel 2 becomes reflective in b
  const std::vector<int> q = reproject(b, a2);
  std::vector<int> ages = update_ages(q, b, a2, {}, false, 4);
  for (int v : ages) EXPECT_EQ(v, 4);  // the first frame is settled
  ages.assign(ages.size(), 1);
  const std::vector<int> next = update_ages(q, b, a2, ages, false, 4);
  EXPECT_EQ(next[0], 2);
  EXPECT_EQ(next[2], 0);  // newly reflective
  for (int v : update_ages(q, b, a2, ages, /*cut=*/true, 4)) EXPECT_EQ(v, 0);
}
