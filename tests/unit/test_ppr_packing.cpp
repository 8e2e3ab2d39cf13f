// PPR intermediate-buffer packing (shaders/shared/ppr_packing.h) on the C++ side: round trips in
// every orientation, negative offsets with fractions, 4K / 8K extremes, clamping, ordering for
// imageAtomicMin and the empty value. The GL tests check that GLSL gives the same bits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "shared/ppr_packing.h"

namespace sh = ssr::shared;

namespace {

float step_of(std::uint32_t fb) { return std::ldexp(1.0f, -static_cast<int>(fb)); }

// The value the packing should return for one component: rounded to the nearest step (ties up).
double quantised(double v, std::uint32_t fb) {
  const double s = std::ldexp(1.0, static_cast<int>(fb));
  return std::floor(v * s + 0.5) / s;
}

// The unpacked value of component `axis` (0 = x, 1 = y): the major distance rounds as a distance
// (ties away from the source pixel), the minor offset as a signed value (ties toward +infinity).
float expected_component(glm::vec2 o, int axis, std::uint32_t fb) {
  const bool x_major = std::abs(o.y) < std::abs(o.x);
  const float v = axis == 0 ? o.x : o.y;
  if (x_major == (axis == 0)) return static_cast<float>(std::copysign(quantised(std::abs(v), fb), v));
  return static_cast<float>(quantised(v, fb));
}

// Round trip of one offset: exact against the quantised expectation and within half a step.
void expect_round_trip(glm::vec2 o, std::uint32_t fb) {
  const std::uint32_t p = sh::ppr_pack(o, fb);
  EXPECT_FALSE(sh::ppr_is_empty(p));
  EXPECT_EQ(p >> 31, 0u) << "reserved bit";
  const glm::vec2 u = sh::ppr_unpack(p, fb);
  const float half = 0.5f * step_of(fb);
  EXPECT_LE(std::abs(u.x - o.x), half) << "x of (" << o.x << ", " << o.y << ") fb " << fb;
  EXPECT_LE(std::abs(u.y - o.y), half) << "y of (" << o.x << ", " << o.y << ") fb " << fb;
  EXPECT_EQ(u.x, expected_component(o, 0, fb)) << "(" << o.x << ", " << o.y << ") fb " << fb;
  EXPECT_EQ(u.y, expected_component(o, 1, fb)) << "(" << o.x << ", " << o.y << ") fb " << fb;
  // The orientation bits tell the dominant direction.
  const std::uint32_t orient = sh::ppr_orientation(p);
  if (std::abs(o.y) < std::abs(o.x))
    EXPECT_EQ(orient, o.x < 0 ? sh::PPR_NEG_X : sh::PPR_POS_X);
  else
    EXPECT_EQ(orient, o.y < 0 ? sh::PPR_NEG_Y : sh::PPR_POS_Y);
}

// Major-axis distance of an offset after quantisation (what the packing compares).
float quantised_major(glm::vec2 o, std::uint32_t fb) {
  const bool x_major = std::abs(o.y) < std::abs(o.x);
  return static_cast<float>(quantised(std::abs(x_major ? o.x : o.y), fb));
}

}  // namespace

TEST(PprPacking, FractionBitsPerSize) {
  EXPECT_EQ(sh::ppr_fraction_bits(1, 1), 14u);
  EXPECT_EQ(sh::ppr_fraction_bits(0, 0), 14u);
  EXPECT_EQ(sh::ppr_fraction_bits(64, 64), 8u);
  EXPECT_EQ(sh::ppr_fraction_bits(1024, 768), 4u);
  EXPECT_EQ(sh::ppr_fraction_bits(1025, 768), 3u);
  EXPECT_EQ(sh::ppr_fraction_bits(1280, 720), 3u);
  EXPECT_EQ(sh::ppr_fraction_bits(1920, 1080), 3u);
  EXPECT_EQ(sh::ppr_fraction_bits(1080, 1920), 3u);  // portrait: the largest dimension counts
  EXPECT_EQ(sh::ppr_fraction_bits(2048, 2048), 3u);
  EXPECT_EQ(sh::ppr_fraction_bits(2560, 1440), 2u);
  EXPECT_EQ(sh::ppr_fraction_bits(3840, 2160), 2u);
  EXPECT_EQ(sh::ppr_fraction_bits(4096, 4096), 2u);
  EXPECT_EQ(sh::ppr_fraction_bits(4097, 16), 1u);
  EXPECT_EQ(sh::ppr_fraction_bits(7680, 4320), 1u);
  EXPECT_EQ(sh::ppr_fraction_bits(8192, 8192), 1u);
  EXPECT_EQ(sh::ppr_fraction_bits(8193, 8192), 0u);
  EXPECT_EQ(sh::ppr_fraction_bits(16384, 16384), 0u);
  EXPECT_EQ(sh::ppr_fraction_bits(32768, 32768), 0u);  // capped: offsets past 16383 clamp
  // Integer bits always hold the largest in-image offset (< max dimension).
  for (std::uint32_t d : {1u, 2u, 3u, 97u, 1920u, 3840u, 4096u, 7680u, 8192u, 16384u}) {
    const std::uint32_t i = sh::ppr_integer_bits(d, 1);
    EXPECT_GE(1u << i, d) << d;
    EXPECT_EQ(i + sh::ppr_fraction_bits(d, 1), sh::PPR_VALUE_BITS);
  }
}

TEST(PprPacking, RoundTripEveryOrientation) {
  for (std::uint32_t fb = 0; fb <= 14; ++fb) {
    const float s = step_of(fb);
    const std::vector<glm::vec2> offsets = {
        {0, 5 * s}, {5 * s, 0}, {0, -5 * s}, {-5 * s, 0},          // the 4 axes
        {1 * s, 3 * s}, {3 * s, -1 * s}, {-1 * s, -3 * s}, {-3 * s, 2 * s},  // off axis
        {2 * s, 2 * s}, {-2 * s, 2 * s}, {2 * s, -2 * s}, {-2 * s, -2 * s},  // ties go to y
    };
    for (const glm::vec2& o : offsets) expect_round_trip(o, fb);
  }
  EXPECT_EQ(sh::ppr_orientation(sh::ppr_pack({0.0f, 3.0f}, 3)), sh::PPR_POS_Y);
  EXPECT_EQ(sh::ppr_orientation(sh::ppr_pack({3.0f, 0.5f}, 3)), sh::PPR_POS_X);
  EXPECT_EQ(sh::ppr_orientation(sh::ppr_pack({0.5f, -3.0f}, 3)), sh::PPR_NEG_Y);
  EXPECT_EQ(sh::ppr_orientation(sh::ppr_pack({-3.0f, -0.5f}, 3)), sh::PPR_NEG_X);
  EXPECT_EQ(sh::ppr_orientation(sh::ppr_pack({-2.0f, 2.0f}, 3)), sh::PPR_POS_Y);
  EXPECT_EQ(sh::ppr_orientation(sh::ppr_pack({2.0f, -2.0f}, 3)), sh::PPR_NEG_Y);
}

// The seeds took frac() of negative offsets but int() truncated them: -3.25 came back wrong.
TEST(PprPacking, NegativeOffsetsKeepTheirFraction) {
  const std::uint32_t fb4k = sh::ppr_fraction_bits(3840, 2160);  // 2: quarter pixels
  for (float v : {-3.25f, -0.5f, -0.25f, -0.75f, -1.0f, -4095.75f, -4095.5f, -2048.25f, -1.75f}) {
    for (float other : {0.0f, 0.25f, -0.25f}) {
      const glm::vec2 major_x{v, other}, major_y{other, v};
      EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack(major_x, fb4k), fb4k), major_x) << v;
      EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack(major_y, fb4k), fb4k), major_y) << v;
    }
    // As the minor component too (the major a bit larger, if that stays in range).
    if (std::abs(v) + 1.0f > 4095.75f) continue;
    const glm::vec2 minor_y{std::abs(v) + 1.0f, v}, minor_x{v, -(std::abs(v) + 1.0f)};
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack(minor_y, fb4k), fb4k), minor_y) << v;
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack(minor_x, fb4k), fb4k), minor_x) << v;
  }
  // With 3 fraction bits (1080p) eighths survive in every direction.
  for (float v : {-3.125f, -0.875f, -2047.875f, -0.125f}) {
    for (const glm::vec2 o : {glm::vec2(v, 0.375f), glm::vec2(-0.375f, v), glm::vec2(-v, -0.625f),
                              glm::vec2(0.625f, -v)})
      EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack(o, 3), 3), o) << o.x << ", " << o.y;
  }
  // Not on the grid: rounds to the nearest step (floor-consistent, so -3.3 -> -3.25 at F = 2).
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({-3.3f, 0.0f}, 2), 2), glm::vec2(-3.25f, 0.0f));
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({0.1f, -3.4f}, 2), 2), glm::vec2(0.0f, -3.5f));
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({-0.6f, -7.0f}, 2), 2), glm::vec2(-0.5f, -7.0f));
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({-0.65f, -7.0f}, 2), 2), glm::vec2(-0.75f, -7.0f));
  // Ties: the major distance rounds away from the source pixel, the minor toward +infinity.
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({-3.125f, 0.0f}, 2), 2), glm::vec2(-3.25f, 0.0f));
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({3.125f, 0.0f}, 2), 2), glm::vec2(3.25f, 0.0f));
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({-3.125f, 7.0f}, 2), 2), glm::vec2(-3.0f, 7.0f));
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({3.125f, 7.0f}, 2), 2), glm::vec2(3.25f, 7.0f));
}

TEST(PprPacking, ZeroOffset) {
  for (std::uint32_t fb = 0; fb <= 14; ++fb) {
    for (const glm::vec2 z : {glm::vec2(0.0f), glm::vec2(-0.0f, -0.0f), glm::vec2(-0.0f, 0.0f)}) {
      const std::uint32_t p = sh::ppr_pack(z, fb);
      EXPECT_FALSE(sh::ppr_is_empty(p));
      EXPECT_EQ(sh::ppr_unpack(p, fb), glm::vec2(0.0f));
      EXPECT_EQ(sh::ppr_major_distance(p, fb), 0.0f);
    }
    // Zero is the smallest distance: it wins against any other offset.
    EXPECT_LT(sh::ppr_pack({0.0f, 0.0f}, fb), sh::ppr_pack({0.0f, step_of(fb)}, fb));
  }
  // The exact bits: major 0, minor 0 (biased), orientation +y.
  EXPECT_EQ(sh::ppr_pack({0.0f, 0.0f}, 3), sh::PPR_MINOR_BIAS << sh::PPR_MINOR_SHIFT);
}

// Every in-image offset at 3840x2160 and 7680x4320 survives, the largest ones included.
TEST(PprPacking, ExtremesAt4kAnd8k) {
  struct Size {
    std::uint32_t w, h;
  };
  for (const Size sz : {Size{3840, 2160}, Size{7680, 4320}, Size{2160, 3840}}) {
    const std::uint32_t fb = sh::ppr_fraction_bits(sz.w, sz.h);
    const float s = step_of(fb);
    const float mx = static_cast<float>(sz.w - 1), my = static_cast<float>(sz.h - 1);
    const float fx = mx + 1.0f - s, fy = my + 1.0f - s;  // with the largest fraction below 1
    const std::vector<glm::vec2> offsets = {
        {mx, 0}, {-mx, 0}, {0, my}, {0, -my},   {mx, my},   {-mx, my},  {mx, -my},  {-mx, -my},
        {fx, 0}, {-fx, 0}, {0, fy}, {0, -fy},   {fx, fy},   {-fx, -fy}, {fx, -fy},  {-fx, fy},
        {mx, s}, {-mx, -s}, {s, my}, {-s, -my}, {mx, -fy}, {-fx, my},
    };
    for (const glm::vec2& o : offsets) {
      ASSERT_LT(std::abs(o.x), static_cast<float>(sz.w));
      ASSERT_LT(std::abs(o.y), static_cast<float>(sz.h));
      expect_round_trip(o, fb);
      EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack(o, fb), fb), o) << o.x << ", " << o.y << " at " << sz.w;
    }
  }
  // The seeds' 12-bit fields wrapped at 4096: these must not.
  const std::uint32_t fb8k = sh::ppr_fraction_bits(7680, 4320);
  for (const glm::vec2 o : {glm::vec2(4095.5f, -1.0f), glm::vec2(-4095.5f, 1.0f), glm::vec2(4096.0f, 0.0f),
                            glm::vec2(0.0f, 4096.0f), glm::vec2(-4096.5f, -4095.5f), glm::vec2(5000.5f, 4319.5f),
                            glm::vec2(-7679.0f, -4319.5f)})
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack(o, fb8k), fb8k), o) << o.x << ", " << o.y;
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({7679.5f, -4319.0f}, fb8k), fb8k), glm::vec2(7679.5f, -4319.0f));
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({-4319.5f, -7679.0f}, fb8k), fb8k), glm::vec2(-4319.5f, -7679.0f));
}

// Beyond the representable range the components clamp (the orientation stays right); nothing wraps.
TEST(PprPacking, BeyondTheRangeClamps) {
  for (std::uint32_t fb = 0; fb <= 14; ++fb) {
    const float s = step_of(fb);
    const float top = std::ldexp(1.0f, 14 - static_cast<int>(fb));  // 2^I
    const float major_max = top - s;
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({top * 3, 0}, fb), fb), glm::vec2(major_max, 0)) << fb;
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({-top * 3, 0}, fb), fb), glm::vec2(-major_max, 0)) << fb;
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({0, top * 3}, fb), fb), glm::vec2(0, major_max)) << fb;
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({0, -1e30f}, fb), fb), glm::vec2(0, -major_max)) << fb;
    // The minor component clamps to its own range [-2^I, 2^I - step].
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({1e9f, -top * 2}, fb), fb), glm::vec2(major_max, -top)) << fb;
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({-top * 2, 1e9f}, fb), fb), glm::vec2(-top, major_max)) << fb;
    // Just past the largest value (rounding up to 2^I) clamps to the largest value.
    EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({major_max + 0.75f * s, 0}, fb), fb), glm::vec2(major_max, 0)) << fb;
    // A clamped offset is never closer than an in-range one.
    EXPECT_LT(sh::ppr_pack({major_max - s, 0}, fb), sh::ppr_pack({top * 100, 0}, fb)) << fb;
  }
  // 8K without clamping: no 4096 wrap; at F = 1 the limit is 8191.5.
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({9000.0f, 10.0f}, 1), 1), glm::vec2(8191.5f, 10.0f));
  EXPECT_EQ(sh::ppr_unpack(sh::ppr_pack({-9000.0f, -10.0f}, 1), 1), glm::vec2(-8191.5f, -10.0f));
}

// For imageAtomicMin: a smaller quantised major distance always gives a smaller packed value, in
// the same orientation (and, with this layout, across orientations too).
TEST(PprPacking, OrderingKeepsTheClosest) {
  std::mt19937 rng(1234);
  for (std::uint32_t fb : {0u, 1u, 2u, 3u, 4u, 8u}) {
    const float range = std::ldexp(1.0f, 14 - static_cast<int>(fb));
    std::uniform_real_distribution<float> big(-range, range), small(-8.0f, 8.0f);
    int same_orientation = 0;
    for (int i = 0; i < 200000; ++i) {
      auto& dist = (i & 1) ? big : small;
      glm::vec2 a{dist(rng), dist(rng)}, b{dist(rng), dist(rng)};
      if (i % 3 == 0) b = glm::vec2(a.x * 1.5f, a.y * 1.5f);  // same orientation, farther
      const float ma = quantised_major(a, fb), mb = quantised_major(b, fb);
      const std::uint32_t pa = sh::ppr_pack(a, fb), pb = sh::ppr_pack(b, fb);
      if (ma >= range || mb >= range) continue;  // clamped: equal distances are allowed
      same_orientation += sh::ppr_orientation(pa) == sh::ppr_orientation(pb);
      if (ma < mb) {
        ASSERT_LT(pa, pb) << a.x << "," << a.y << " vs " << b.x << "," << b.y << " fb " << fb;
      } else if (mb < ma) {
        ASSERT_LT(pb, pa) << a.x << "," << a.y << " vs " << b.x << "," << b.y << " fb " << fb;
      }
      ASSERT_EQ(sh::ppr_major_distance(pa, fb), ma);
    }
    EXPECT_GT(same_orientation, 40000) << fb;
  }
  // The closest of several candidates for one destination wins atomicMin.
  const std::uint32_t fb = 2;
  std::uint32_t cell = sh::PPR_EMPTY;
  for (const glm::vec2 o : {glm::vec2(0, 40.25f), glm::vec2(3.5f, 12.75f), glm::vec2(-0.25f, 12.5f),
                            glm::vec2(0, 300)})
    cell = std::min(cell, sh::ppr_pack(o, fb));
  EXPECT_EQ(sh::ppr_unpack(cell, fb), glm::vec2(-0.25f, 12.5f));
}

TEST(PprPacking, NeverEmpty) {
  EXPECT_TRUE(sh::ppr_is_empty(sh::PPR_EMPTY));
  EXPECT_EQ(sh::PPR_EMPTY, 0xFFFFFFFFu);
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> any(-40000.0f, 40000.0f);
  for (std::uint32_t fb = 0; fb <= 14; ++fb) {
    // The largest possible value: maximal major, maximal minor, orientation 3.
    const std::uint32_t p = sh::ppr_pack({-1e30f, 1e30f * 0.5f}, fb);
    EXPECT_FALSE(sh::ppr_is_empty(p));
    EXPECT_EQ(p, 0x7FFFFFFFu) << fb;
    for (int i = 0; i < 20000; ++i) {
      const std::uint32_t q = sh::ppr_pack({any(rng), any(rng)}, fb);
      ASSERT_FALSE(sh::ppr_is_empty(q));
      ASSERT_LT(q, 0x80000000u);
    }
  }
}

// Random offsets of every size: the round trip is the quantised offset, within half a step.
TEST(PprPacking, RandomRoundTrips) {
  std::mt19937 rng(7);
  for (std::uint32_t fb = 0; fb <= 14; ++fb) {
    const float range = std::ldexp(1.0f, 14 - static_cast<int>(fb)) - step_of(fb);
    std::uniform_real_distribution<float> dist(-range, range);
    for (int i = 0; i < 20000; ++i) {
      const glm::vec2 o{dist(rng), dist(rng)};
      if (std::abs(quantised(o.x, fb)) > range || std::abs(quantised(o.y, fb)) > range) continue;
      expect_round_trip(o, fb);
      if (testing::Test::HasFailure()) return;
    }
  }
}
