// Error metrics of ARCHITECTURE §5, computed on tone-mapped images in [0,1] over reflective pixels.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/image.h"
#include "reference/pixel_class.h"

namespace ssr {

// A figure over an empty set of pixels is nullopt (`null` in JSON, `-` in tables), never 100 dB
// or 0%: a frame with nothing reflective has no PSNR.
struct ErrorMetrics {
  std::optional<double> rmse, psnr;                      // technique vs truth, all reflective pixels
  std::optional<double> rmse_traceable, psnr_traceable;  // technique vs screen-space ideal, traceable
  std::optional<double> rmse_missing;                    // technique vs truth, missing pixels
  std::optional<double> coverage;                        // traceable pixels with confidence > 0.5
  std::size_t nonfinite = 0;                        // non-finite values in the inputs given
  std::size_t reflective = 0, traceable = 0, missing = 0, sky = 0;  // pixel counts
};

// PSNR for a peak of 1. Identical images (rmse 0) give kPsnrCap, so results stay finite JSON.
constexpr double kPsnrCap = 100.0;
double psnr_from_rmse(double rmse);
std::optional<double> psnr_from_rmse(const std::optional<double>& rmse);

// Root mean square over the RGB channels of the pixels where mask(i) holds; nullopt when none.
// `a` and `b` are RGBA images of the same size (alpha ignored).
std::optional<double> rmse_where(const RgbaImageF& a, const RgbaImageF& b, const std::vector<PixelClass>& cls,
                  bool (*mask)(PixelClass));

// All metrics at once. technique/truth/ideal: tone-mapped final images in [0,1];
// confidence: the technique's reflection alpha per pixel; cls: per-pixel class.
// Non-finite values are counted (and those pixels count as maximal error, 1 per channel).
ErrorMetrics compute_metrics(const RgbaImageF& technique, const RgbaImageF& truth,
                             const RgbaImageF& ideal, const std::vector<PixelClass>& cls,
                             const std::vector<float>& confidence);

std::size_t count_nonfinite(const std::vector<float>& values);

// RMSE and PSNR of a vs b (display values) over the pixels where mask[i] holds; nullopt when none
// does. The viewer's A-vs-B figure: over the reflective pixels of the final image it is compare's
// `psnr` when B is the reference.
std::optional<double> rmse_where(const RgbaImageF& a, const RgbaImageF& b, const std::vector<bool>& mask);
std::optional<double> psnr_where(const RgbaImageF& a, const RgbaImageF& b, const std::vector<bool>& mask);

// The truth's own noise from two truths of independent seeds, `rmse_between_truths` apart: half
// their mean squared difference is the noise variance one carries, and as PSNR it is what the
// noise-free truth would score against either (compare, bench, sequence and the viewer).
std::optional<double> noise_floor_psnr(const std::optional<double>& rmse_between_truths);

}  // namespace ssr
