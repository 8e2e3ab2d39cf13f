// Error metrics (ARCHITECTURE §5) on synthetic images with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "eval/metrics.h"

using namespace ssr;

namespace {

RgbaImageF make_image(int w, int h, float r, float g, float b) {
  RgbaImageF img;
  img.width = w;
  img.height = h;
  img.pixels.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
  for (std::size_t i = 0; i < img.pixels.size(); i += 4) {
    img.pixels[i + 0] = r;
    img.pixels[i + 1] = g;
    img.pixels[i + 2] = b;
    img.pixels[i + 3] = 1.0f;
  }
  return img;
}

void set_rgb(RgbaImageF& img, std::size_t i, float r, float g, float b) {
  img.pixels[i * 4 + 0] = r;
  img.pixels[i * 4 + 1] = g;
  img.pixels[i * 4 + 2] = b;
}

// 4x4: row 0 not reflective, row 1 traceable, row 2 missing, row 3 sky.
std::vector<PixelClass> four_rows() {
  std::vector<PixelClass> cls(16);
  for (std::size_t i = 0; i < 16; ++i) cls[i] = static_cast<PixelClass>(i / 4);
  return cls;
}

// Every figure present (the 4x4 frames have pixels of each class) and finite.
void expect_all_finite(const ErrorMetrics& m) {
  for (const std::optional<double>* v : {&m.rmse, &m.psnr, &m.rmse_traceable, &m.psnr_traceable, &m.rmse_missing, &m.coverage}) {
    ASSERT_TRUE(v->has_value());
    EXPECT_TRUE(std::isfinite(**v));
  }
}

}  // namespace

TEST(Metrics, PsnrFromRmse) {
  EXPECT_EQ(psnr_from_rmse(0.0), kPsnrCap);
  EXPECT_NEAR(psnr_from_rmse(0.1), 20.0, 1e-12);
  EXPECT_NEAR(psnr_from_rmse(0.01), 40.0, 1e-12);
  EXPECT_NEAR(psnr_from_rmse(1.0), 0.0, 1e-12);
  EXPECT_EQ(psnr_from_rmse(1e-300), kPsnrCap);  // would exceed the cap
  EXPECT_TRUE(std::isfinite(psnr_from_rmse(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::isfinite(psnr_from_rmse(std::numeric_limits<double>::infinity())));
}

TEST(Metrics, IdenticalImagesGiveZeroErrorAndCap) {
  const auto img = make_image(4, 4, 0.25f, 0.5f, 0.75f);
  std::vector<float> conf(16, 1.0f);
  const ErrorMetrics m = compute_metrics(img, img, img, four_rows(), conf);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.psnr, kPsnrCap);
  EXPECT_EQ(m.rmse_traceable, 0.0);
  EXPECT_EQ(m.psnr_traceable, kPsnrCap);
  EXPECT_EQ(m.rmse_missing, 0.0);
  EXPECT_EQ(m.nonfinite, 0u);
  EXPECT_EQ(m.reflective, 12u);
  EXPECT_EQ(m.traceable, 4u);
  EXPECT_EQ(m.missing, 4u);
  EXPECT_EQ(m.sky, 4u);
  EXPECT_EQ(m.coverage, 1.0);
}

// 0.1 is not a float: a float offset of "0.1" differs from 0.1 by ~1.5e-9, so PSNR is 20 dB
// within ~1.3e-7. The rmse is checked to float precision, PSNR to 1e-6.
TEST(Metrics, ConstantOffsetPointOne) {
  const auto truth = make_image(4, 4, 0.0f, 0.0f, 0.0f);
  const auto tech = make_image(4, 4, 0.1f, 0.1f, 0.1f);
  std::vector<float> conf(16, 1.0f);
  const ErrorMetrics m = compute_metrics(tech, truth, truth, four_rows(), conf);
  EXPECT_NEAR(m.rmse.value(), 0.1, 1e-8);
  EXPECT_NEAR(m.psnr.value(), 20.0, 1e-6);
  EXPECT_NEAR(m.rmse_traceable.value(), 0.1, 1e-8);
  EXPECT_NEAR(m.psnr_traceable.value(), 20.0, 1e-6);
  EXPECT_NEAR(m.rmse_missing.value(), 0.1, 1e-8);
}

// With an offset that floats represent exactly the answer is exact: the arithmetic is in double.
TEST(Metrics, ConstantOffsetExact) {
  // Truth 0.5, technique 0.625 / 0.375 alternating: |diff| = 0.125 everywhere.
  auto truth = make_image(4, 4, 0.5f, 0.5f, 0.5f);
  auto tech = make_image(4, 4, 0.625f, 0.625f, 0.625f);
  for (std::size_t i = 0; i < 16; i += 2) set_rgb(tech, i, 0.375f, 0.375f, 0.375f);
  std::vector<float> conf(16, 1.0f);
  const ErrorMetrics m = compute_metrics(tech, truth, truth, four_rows(), conf);
  EXPECT_NEAR(m.rmse.value(), 0.125, 1e-15);
  EXPECT_NEAR(m.psnr.value(), 20.0 * std::log10(8.0), 1e-9);
  EXPECT_NEAR(m.rmse_traceable.value(), 0.125, 1e-15);
  EXPECT_NEAR(m.rmse_missing.value(), 0.125, 1e-15);

  // 1/1024 on one channel only: mean of squares over 3 channels.
  auto tech2 = truth;
  for (std::size_t i = 0; i < 16; ++i) tech2.pixels[i * 4 + 1] = 0.5f + 1.0f / 1024.0f;
  const ErrorMetrics m2 = compute_metrics(tech2, truth, truth, four_rows(), conf);
  EXPECT_NEAR(m2.rmse.value(), (1.0 / 1024.0) / std::sqrt(3.0), 1e-15);
}

TEST(Metrics, ClassMasksAreHonoured) {
  const auto truth = make_image(4, 4, 0.5f, 0.5f, 0.5f);
  const auto ideal = make_image(4, 4, 0.25f, 0.25f, 0.25f);
  std::vector<float> conf(16, 1.0f);
  const auto cls = four_rows();

  // Technique equal to the ideal on traceable pixels, the truth elsewhere; then scramble the
  // non-reflective row: nothing may change.
  auto tech = truth;
  for (std::size_t i = 4; i < 8; ++i) set_rgb(tech, i, 0.25f, 0.25f, 0.25f);
  const ErrorMetrics a = compute_metrics(tech, truth, ideal, cls, conf);
  EXPECT_EQ(a.rmse_traceable, 0.0);
  EXPECT_EQ(a.rmse_missing, 0.0);
  EXPECT_GT(a.rmse.value(), 0.0);  // traceable pixels differ from the truth
  // rmse over 12 reflective pixels, 4 of them off by 0.25 on every channel.
  EXPECT_NEAR(a.rmse.value(), std::sqrt(4.0 * 3 * 0.0625 / 36.0), 1e-15);

  auto scrambled = tech;
  for (std::size_t i = 0; i < 4; ++i) set_rgb(scrambled, i, 7.0f, -3.0f, 0.9f);
  const ErrorMetrics b = compute_metrics(scrambled, truth, ideal, cls, conf);
  EXPECT_EQ(b.rmse, a.rmse);
  EXPECT_EQ(b.rmse_traceable, a.rmse_traceable);
  EXPECT_EQ(b.rmse_missing, a.rmse_missing);

  // Changing the missing row touches rmse and rmse_missing but not rmse_traceable.
  auto missing_changed = tech;
  for (std::size_t i = 8; i < 12; ++i) set_rgb(missing_changed, i, 0.0f, 0.0f, 0.0f);
  const ErrorMetrics c = compute_metrics(missing_changed, truth, ideal, cls, conf);
  EXPECT_EQ(c.rmse_traceable, a.rmse_traceable);
  EXPECT_NEAR(c.rmse_missing.value(), 0.5, 1e-15);
  EXPECT_GT(c.rmse.value(), a.rmse);

  // Changing the sky row touches only rmse.
  auto sky_changed = tech;
  for (std::size_t i = 12; i < 16; ++i) set_rgb(sky_changed, i, 0.0f, 0.0f, 0.0f);
  const ErrorMetrics d = compute_metrics(sky_changed, truth, ideal, cls, conf);
  EXPECT_EQ(d.rmse_traceable, a.rmse_traceable);
  EXPECT_EQ(d.rmse_missing, a.rmse_missing);
  EXPECT_GT(d.rmse.value(), a.rmse);

  // Changing the ideal outside the traceable row changes nothing.
  auto ideal2 = ideal;
  for (std::size_t i : {0u, 9u, 14u}) set_rgb(ideal2, i, 1.0f, 0.0f, 1.0f);
  const ErrorMetrics e = compute_metrics(tech, truth, ideal2, cls, conf);
  EXPECT_EQ(e.rmse_traceable, a.rmse_traceable);

  // rmse_where agrees with compute_metrics.
  EXPECT_EQ(rmse_where(tech, truth, cls, [](PixelClass k) { return k != PixelClass::NotReflective; }),
            a.rmse);
  EXPECT_EQ(rmse_where(tech, ideal, cls, [](PixelClass k) { return k == PixelClass::Traceable; }),
            0.0);
  EXPECT_EQ(rmse_where(tech, truth, std::vector<PixelClass>(16, PixelClass::NotReflective),
                       [](PixelClass k) { return k == PixelClass::Traceable; }),
            std::nullopt);  // no pixel selected
}

TEST(Metrics, Coverage) {
  const auto img = make_image(4, 4, 0.5f, 0.5f, 0.5f);
  const auto cls = four_rows();
  std::vector<float> conf(16, 1.0f);
  // Traceable pixels 4..7: confidences 0.9, 0.5 (not > 0.5), 0.51, 0.0.
  conf[4] = 0.9f;
  conf[5] = 0.5f;
  conf[6] = 0.51f;
  conf[7] = 0.0f;
  // Other classes with low confidence do not matter.
  conf[0] = conf[9] = conf[13] = 0.0f;
  const ErrorMetrics m = compute_metrics(img, img, img, cls, conf);
  EXPECT_DOUBLE_EQ(m.coverage.value(), 0.5);

  // No traceable pixels: no coverage and no traceable figures (not 0%, not 100 dB).
  std::vector<PixelClass> none(16, PixelClass::Missing);
  const ErrorMetrics n = compute_metrics(img, img, img, none, conf);
  EXPECT_EQ(n.traceable, 0u);
  EXPECT_EQ(n.coverage, std::nullopt);
  EXPECT_EQ(n.rmse_traceable, std::nullopt);
  EXPECT_EQ(n.psnr_traceable, std::nullopt);
  EXPECT_EQ(n.missing, 16u);
  EXPECT_EQ(n.psnr, kPsnrCap);  // identical images over 16 pixels: the cap
}

// A frame where nothing reflects has no figure at all: a technique is not 100 dB there.
TEST(Metrics, NothingReflectiveHasNoFigures) {
  const auto img = make_image(4, 4, 0.5f, 0.5f, 0.5f);
  const auto other = make_image(4, 4, 0.0f, 1.0f, 0.0f);
  std::vector<float> conf(16, 1.0f);
  std::vector<PixelClass> nothing(16, PixelClass::NotReflective);
  const ErrorMetrics z = compute_metrics(other, img, img, nothing, conf);
  EXPECT_EQ(z.reflective, 0u);
  for (const std::optional<double>* v : {&z.rmse, &z.psnr, &z.rmse_traceable, &z.psnr_traceable, &z.rmse_missing, &z.coverage})
    EXPECT_EQ(*v, std::nullopt);
  EXPECT_EQ(rmse_where(other, img, nothing, [](PixelClass k) { return k != PixelClass::NotReflective; }), std::nullopt);
  EXPECT_EQ(psnr_from_rmse(std::optional<double>()), std::nullopt);
}

TEST(Metrics, NonFiniteIsCountedAndMaximal) {
  const auto truth = make_image(4, 4, 0.5f, 0.5f, 0.5f);
  std::vector<float> conf(16, 1.0f);
  const auto cls = four_rows();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();

  auto tech = truth;
  tech.pixels[4 * 4 + 0] = nan;  // traceable pixel, one channel
  tech.pixels[9 * 4 + 2] = inf;  // missing pixel, one channel
  const ErrorMetrics m = compute_metrics(tech, truth, truth, cls, conf);
  EXPECT_EQ(m.nonfinite, 2u);
  expect_all_finite(m);
  // Each bad channel counts as squared error 1.
  EXPECT_NEAR(m.rmse.value(), std::sqrt(2.0 / 36.0), 1e-15);
  EXPECT_NEAR(m.rmse_traceable.value(), std::sqrt(1.0 / 12.0), 1e-15);
  EXPECT_NEAR(m.rmse_missing.value(), std::sqrt(1.0 / 12.0), 1e-15);
  EXPECT_LT(m.psnr.value(), kPsnrCap);

  // A NaN on a non-reflective pixel, in alpha, or in the confidence still counts.
  auto tech2 = truth;
  tech2.pixels[0] = nan;
  tech2.pixels[5 * 4 + 3] = nan;
  auto conf2 = conf;
  conf2[6] = nan;
  const ErrorMetrics m2 = compute_metrics(tech2, truth, truth, cls, conf2);
  EXPECT_EQ(m2.nonfinite, 3u);
  EXPECT_EQ(m2.rmse, 0.0);  // none of them is an RGB value of a reflective pixel
  EXPECT_DOUBLE_EQ(m2.coverage.value(), 0.75);
  expect_all_finite(m2);

  // An all-NaN image: never looks good, never produces NaN.
  const auto all_nan = make_image(4, 4, nan, nan, nan);
  const ErrorMetrics m3 = compute_metrics(all_nan, truth, truth, cls, conf);
  expect_all_finite(m3);
  EXPECT_EQ(m3.nonfinite, 48u);
  EXPECT_NEAR(m3.rmse.value(), 1.0, 1e-15);
  EXPECT_NEAR(m3.psnr.value(), 0.0, 1e-12);
  EXPECT_NEAR(m3.psnr_traceable.value(), 0.0, 1e-12);

  EXPECT_EQ(count_nonfinite({1.0f, nan, inf, -inf, 0.0f}), 3u);
  EXPECT_EQ(count_nonfinite({}), 0u);
}

TEST(Metrics, SizeMismatchThrows) {
  const auto a = make_image(4, 4, 0.5f, 0.5f, 0.5f);
  const auto b = make_image(4, 3, 0.5f, 0.5f, 0.5f);
  const auto c = make_image(2, 8, 0.5f, 0.5f, 0.5f);
  std::vector<float> conf(16, 1.0f);
  const auto cls = four_rows();
  EXPECT_THROW(compute_metrics(a, b, a, cls, conf), std::invalid_argument);
  EXPECT_THROW(compute_metrics(a, a, b, cls, conf), std::invalid_argument);
  EXPECT_THROW(compute_metrics(b, a, a, cls, conf), std::invalid_argument);
  EXPECT_THROW(compute_metrics(a, c, a, cls, conf), std::invalid_argument);  // same pixel count
  EXPECT_THROW(compute_metrics(a, a, a, std::vector<PixelClass>(15), conf), std::invalid_argument);
  EXPECT_THROW(compute_metrics(a, a, a, cls, std::vector<float>(17)), std::invalid_argument);
  auto broken = a;
  broken.pixels.pop_back();
  EXPECT_THROW(compute_metrics(broken, a, a, cls, conf), std::invalid_argument);
  EXPECT_THROW(rmse_where(a, b, cls, nullptr), std::invalid_argument);
}
