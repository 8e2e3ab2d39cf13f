// Error metrics of ARCHITECTURE §5, computed on tone-mapped images in [0,1] over reflective pixels.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/image.h"
#include "reference/pixel_class.h"

namespace ssr {

struct ErrorMetrics {
  double rmse = 0, psnr = 0;                        // technique vs truth, all reflective pixels
  double rmse_traceable = 0, psnr_traceable = 0;    // technique vs screen-space ideal, traceable
  double rmse_missing = 0;                          // technique vs truth, missing pixels
  double coverage = 0;                              // traceable pixels with confidence > 0.5
  std::size_t nonfinite = 0;                        // non-finite values in the inputs given
  std::size_t reflective = 0, traceable = 0, missing = 0, sky = 0;  // pixel counts
};

// PSNR for a peak of 1. Identical images (rmse 0) give kPsnrCap, so results stay finite JSON.
constexpr double kPsnrCap = 100.0;
double psnr_from_rmse(double rmse);

// Root mean square over the RGB channels of the pixels where mask(i) holds; 0 when none.
// `a` and `b` are RGBA images of the same size (alpha ignored).
double rmse_where(const RgbaImageF& a, const RgbaImageF& b, const std::vector<PixelClass>& cls,
                  bool (*mask)(PixelClass));

// All metrics at once. technique/truth/ideal: tone-mapped final images in [0,1];
// confidence: the technique's reflection alpha per pixel; cls: per-pixel class.
// Non-finite values are counted (and those pixels count as maximal error, 1 per channel).
ErrorMetrics compute_metrics(const RgbaImageF& technique, const RgbaImageF& truth,
                             const RgbaImageF& ideal, const std::vector<PixelClass>& cls,
                             const std::vector<float>& confidence);

std::size_t count_nonfinite(const std::vector<float>& values);

// PSNR of a vs b (display values) over the pixels where mask[i] holds; nullopt when none does.
// The viewer's A-vs-B figure: over the reflective pixels of the final image it is compare's
// `psnr` when B is the reference.
std::optional<double> psnr_where(const RgbaImageF& a, const RgbaImageF& b, const std::vector<bool>& mask);

}  // namespace ssr
