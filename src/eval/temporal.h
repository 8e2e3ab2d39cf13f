// Temporal metrics of `ssrlab sequence` (CPU, no GL): reprojection by the G-buffer's motion
// vectors, flicker beyond the truth's, and the age of each pixel's history (for ghosting).
//
// Reprojection is nearest-pixel: a pixel's previous position (its centre + motion, shared/frame.h)
// is rounded to a pixel of the previous frame; it counts as "seen before" only when that pixel
// shows the same object. A surface that was hidden behind another one, or off screen, is
// disoccluded; self-occlusion within one object is not detected (a documented limit).
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"

namespace ssr {

// What the temporal metrics read of one frame (row 0 = top, as read-back images).
struct TemporalFrame {
  int width = 0, height = 0;
  std::vector<glm::vec2> motion;       // pixels, GL convention (+y up)
  std::vector<std::uint32_t> object;   // mesh index + 1; 0 = background (sky)
  std::vector<bool> reflective;        // the pixel is scored: reflection work, or behind glass (refraction)
};

// For each pixel of `now`: the index of the pixel it was in `before`, or -1 when it was off
// screen or another object was there (disoccluded).
std::vector<int> reproject(const TemporalFrame& now, const TemporalFrame& before);

// Flicker beyond the scene's: on pixels reflective in both frames and seen before, the change
// of the technique's image from its reprojected previous value minus the truth's change,
// clamped at 0 (mean over RGB of display values). One value per such pixel.
std::vector<float> excess_change(const std::vector<int>& previous, const TemporalFrame& now,
                                 const TemporalFrame& before, const RgbaImageF& technique_now,
                                 const RgbaImageF& technique_before, const RgbaImageF& truth_now,
                                 const RgbaImageF& truth_before);

// How much the technique's and the truth's images changed on the pixels excess_change measures:
// sums of the per-pixel change (mean over RGB of display values). Their ratio says how much
// more the technique moves than the scene does.
struct ChangeTotals {
  double technique = 0, truth = 0;
  std::size_t pixels = 0;
};
ChangeTotals change_totals(const std::vector<int>& previous, const TemporalFrame& now, const TemporalFrame& before,
                           const RgbaImageF& technique_now, const RgbaImageF& technique_before,
                           const RgbaImageF& truth_now, const RgbaImageF& truth_before);
// excess_change per pixel of `now` (-1 where it is not measured), for breakdowns by region;
// with `totals`, the change totals of the same pass added to it.
std::vector<float> excess_change_map(const std::vector<int>& previous, const TemporalFrame& now,
                                     const TemporalFrame& before, const RgbaImageF& technique_now,
                                     const RgbaImageF& technique_before, const RgbaImageF& truth_now,
                                     const RgbaImageF& truth_before, ChangeTotals* totals = nullptr);

// The part of the truth's change between two frames that is its own sampling noise, from two
// truths of each frame with independent seeds (a, b): on the pixels excess_change measures, the
// two changes differ by the difference of the two noises' changes, so the mean over RGB of
// |change_a - change_b| / sqrt(2) (exact for Gaussian noise) estimates the noise's mean change.
// With a per-pixel seed the noise is fixed to the screen, so it changes between frames only as
// far as what a pixel sees moves. None when no pixel is measured.
std::optional<double> noise_in_change(const std::vector<int>& previous, const TemporalFrame& now,
                                      const TemporalFrame& before, const RgbaImageF& a_now, const RgbaImageF& a_before,
                                      const RgbaImageF& b_now, const RgbaImageF& b_before);

// Second moments of the changes between two frames on the pixels excess_change measures, from the
// technique and two truths with independent seeds (a, b; pass a twice where the truth samples
// nothing). The two truths' noises are independent, so change_a * change_b averages to the
// square of the truth's change without its noise (unbiased; its mean may come out negative where
// the truth hardly moves). Each term is the mean over RGB; a non-finite technique change counts 1.
struct ChangeMoments {
  double technique_square = 0;  // sum of the technique's squared change
  double truth_square = 0;      // sum of change_a squared (noise included)
  double truth_product = 0;     // sum of change_a * change_b
  std::size_t pixels = 0;
};
void add_change_moments(const std::vector<int>& previous, const TemporalFrame& now, const TemporalFrame& before,
                        const RgbaImageF& technique_now, const RgbaImageF& technique_before, const RgbaImageF& a_now,
                        const RgbaImageF& a_before, const RgbaImageF& b_now, const RgbaImageF& b_before,
                        ChangeMoments& m);
// The technique's root-mean-square change over the noise-free truth's: "x truth" without the
// truth's noise. None where nothing was measured or the truth's own change is not positive.
std::optional<double> noise_free_change_ratio(const ChangeMoments& m);
// The same ratio against truth a's change, noise included: beside noise_free_change_ratio it
// tells the truth's noise (the two differ by it alone) from the change of norm against the
// mean absolute "x truth".
std::optional<double> rms_change_ratio(const ChangeMoments& m);

// Frames since each pixel was disoccluded or became reflective (0: this frame). `ages_before`
// empty (the first frame) starts every pixel at `settled`; a cut restarts every pixel at 0.
std::vector<int> update_ages(const std::vector<int>& previous, const TemporalFrame& now,
                             const TemporalFrame& before, const std::vector<int>& ages_before,
                             bool cut, int settled);

}  // namespace ssr
