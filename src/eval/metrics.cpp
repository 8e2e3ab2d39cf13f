// Error metrics of ARCHITECTURE §5. Every output is finite, or absent over an empty pixel set: a
// non-finite input value counts as the maximal error (1 per channel on images in [0,1]) and is
// counted in `nonfinite`.
#include "eval/metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ssr {
namespace {

std::size_t pixel_count(const RgbaImageF& img) {
  return static_cast<std::size_t>(std::max(img.width, 0)) *
         static_cast<std::size_t>(std::max(img.height, 0));
}

void check_image(const RgbaImageF& img, const char* what) {
  if (img.width < 0 || img.height < 0 || img.pixels.size() != pixel_count(img) * 4) {
    throw std::invalid_argument(std::string("metrics: image '") + what +
                                "' has a pixel buffer that does not match its size.");
  }
}

void check_same_size(const RgbaImageF& a, const char* an, const RgbaImageF& b, const char* bn) {
  check_image(a, an);
  check_image(b, bn);
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument(std::string("metrics: images '") + an + "' (" +
                                std::to_string(a.width) + "x" + std::to_string(a.height) +
                                ") and '" + bn + "' (" + std::to_string(b.width) + "x" +
                                std::to_string(b.height) + ") differ in size.");
  }
}

// Squared error of one channel; a non-finite operand is the maximal error on [0,1].
double channel_sq_error(float a, float b) {
  if (!std::isfinite(a) || !std::isfinite(b)) return 1.0;
  const double d = static_cast<double>(a) - static_cast<double>(b);
  const double sq = d * d;
  return std::isfinite(sq) ? sq : 1.0;
}

// Sum of squared RGB errors of pixel i.
double pixel_sq_error(const RgbaImageF& a, const RgbaImageF& b, std::size_t i) {
  const float* pa = &a.pixels[i * 4];
  const float* pb = &b.pixels[i * 4];
  return channel_sq_error(pa[0], pb[0]) + channel_sq_error(pa[1], pb[1]) +
         channel_sq_error(pa[2], pb[2]);
}

std::optional<double> rmse_of(double sum_sq, std::size_t pixels) {
  if (pixels == 0) return std::nullopt;
  const double r = std::sqrt(sum_sq / (3.0 * static_cast<double>(pixels)));
  return std::isfinite(r) ? r : 1.0;  // unreachable for finite sums; keeps the promise anyway
}

// RMSE of a vs b over the pixels i for which keep(i) holds (both rmse_where overloads).
template <class Keep>
std::optional<double> rmse_over(const RgbaImageF& a, const RgbaImageF& b, Keep keep) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0, n = pixel_count(a); i < n; ++i) {
    if (!keep(i)) continue;
    sum += pixel_sq_error(a, b, i);
    ++count;
  }
  return rmse_of(sum, count);
}

std::size_t count_nonfinite_rgb(const RgbaImageF& img, std::size_t i) {
  const float* p = &img.pixels[i * 4];
  return static_cast<std::size_t>(!std::isfinite(p[0])) +
         static_cast<std::size_t>(!std::isfinite(p[1])) +
         static_cast<std::size_t>(!std::isfinite(p[2]));
}

}  // namespace

double psnr_from_rmse(double rmse) {
  if (std::isnan(rmse)) return 0.0;
  if (rmse <= 0.0) return kPsnrCap;
  const double p = 20.0 * std::log10(1.0 / rmse);
  if (!std::isfinite(p)) return p > 0 ? kPsnrCap : -kPsnrCap;
  return std::clamp(p, -kPsnrCap, kPsnrCap);
}

std::optional<double> psnr_from_rmse(const std::optional<double>& rmse) {
  if (!rmse) return std::nullopt;
  return psnr_from_rmse(*rmse);
}

std::optional<double> rmse_where(const RgbaImageF& a, const RgbaImageF& b, const std::vector<PixelClass>& cls,
                  bool (*mask)(PixelClass)) {
  check_same_size(a, "a", b, "b");
  const std::size_t n = pixel_count(a);
  if (cls.size() != n) {
    throw std::invalid_argument("metrics: the class map has " + std::to_string(cls.size()) +
                                " entries for " + std::to_string(n) + " pixels.");
  }
  return rmse_over(a, b, [&](std::size_t i) { return !mask || mask(cls[i]); });
}

ErrorMetrics compute_metrics(const RgbaImageF& technique, const RgbaImageF& truth,
                             const RgbaImageF& ideal, const std::vector<PixelClass>& cls,
                             const std::vector<float>& confidence) {
  check_same_size(technique, "technique", truth, "truth");
  check_same_size(technique, "technique", ideal, "ideal");
  const std::size_t n = pixel_count(technique);
  if (cls.size() != n) {
    throw std::invalid_argument("metrics: the class map has " + std::to_string(cls.size()) +
                                " entries for " + std::to_string(n) + " pixels.");
  }
  if (confidence.size() != n) {
    throw std::invalid_argument("metrics: the confidence map has " +
                                std::to_string(confidence.size()) + " entries for " +
                                std::to_string(n) + " pixels.");
  }

  ErrorMetrics m;
  // Technique and confidence: every value counts, wherever it is (a NaN anywhere is a bug).
  m.nonfinite = count_nonfinite(technique.pixels) + count_nonfinite(confidence);

  double sum_all = 0.0, sum_traceable = 0.0, sum_missing = 0.0;
  std::size_t covered = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const PixelClass c = cls[i];
    if (c == PixelClass::NotReflective) continue;
    ++m.reflective;
    // Truth and ideal: only the values a metric actually reads.
    m.nonfinite += count_nonfinite_rgb(truth, i);
    const double err_truth = pixel_sq_error(technique, truth, i);
    sum_all += err_truth;
    switch (c) {
      case PixelClass::Traceable:
        ++m.traceable;
        m.nonfinite += count_nonfinite_rgb(ideal, i);
        sum_traceable += pixel_sq_error(technique, ideal, i);
        if (confidence[i] > 0.5f) ++covered;  // false for NaN
        break;
      case PixelClass::Missing:
        ++m.missing;
        sum_missing += err_truth;
        break;
      case PixelClass::Sky:
        ++m.sky;
        break;
      default:
        break;
    }
  }

  m.rmse = rmse_of(sum_all, m.reflective);
  m.psnr = psnr_from_rmse(m.rmse);
  m.rmse_traceable = rmse_of(sum_traceable, m.traceable);
  m.psnr_traceable = psnr_from_rmse(m.rmse_traceable);
  m.rmse_missing = rmse_of(sum_missing, m.missing);
  if (m.traceable > 0) m.coverage = static_cast<double>(covered) / static_cast<double>(m.traceable);
  return m;
}

std::optional<double> rmse_where(const RgbaImageF& a, const RgbaImageF& b, const std::vector<bool>& mask) {
  check_same_size(a, "a", b, "b");
  if (mask.size() != pixel_count(a))
    throw std::invalid_argument("metrics: the mask has " + std::to_string(mask.size()) + " entries for " +
                                std::to_string(pixel_count(a)) + " pixels.");
  return rmse_over(a, b, [&](std::size_t i) { return bool(mask[i]); });
}

std::optional<double> psnr_where(const RgbaImageF& a, const RgbaImageF& b, const std::vector<bool>& mask) {
  return psnr_from_rmse(rmse_where(a, b, mask));
}

std::optional<double> noise_floor_psnr(const std::optional<double>& rmse_between_truths) {
  return rmse_between_truths ? psnr_from_rmse(std::optional<double>(*rmse_between_truths / std::sqrt(2.0)))
                             : std::nullopt;
}

std::size_t count_nonfinite(const std::vector<float>& values) {
  std::size_t n = 0;
  for (float v : values) n += static_cast<std::size_t>(!std::isfinite(v));
  return n;
}

}  // namespace ssr
