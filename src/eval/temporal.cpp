#include "eval/temporal.h"

#include <cmath>

namespace ssr {

std::vector<int> reproject(const TemporalFrame& now, const TemporalFrame& before) {
  const int w = now.width, h = now.height;
  std::vector<int> out(static_cast<std::size_t>(w) * h, -1);
  if (before.width != w || before.height != h) return out;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const glm::vec2 m = now.motion[i];
      if (!std::isfinite(m.x) || !std::isfinite(m.y)) continue;
      // GL pixel centre (y up) + motion -> the previous frame's pixel (row 0 = top).
      const float px = static_cast<float>(x) + 0.5f + m.x;
      const float py = static_cast<float>(h - 1 - y) + 0.5f + m.y;
      if (px < 0 || py < 0 || px >= static_cast<float>(w) || py >= static_cast<float>(h)) continue;
      const int bx = static_cast<int>(px), by = h - 1 - static_cast<int>(py);
      const std::size_t j = static_cast<std::size_t>(by) * w + bx;
      if (before.object[j] == now.object[i]) out[i] = static_cast<int>(j);
    }
  return out;
}

std::vector<float> excess_change(const std::vector<int>& previous, const TemporalFrame& now,
                                 const TemporalFrame& before, const RgbaImageF& technique_now,
                                 const RgbaImageF& technique_before, const RgbaImageF& truth_now,
                                 const RgbaImageF& truth_before) {
  std::vector<float> out;
  for (float v : excess_change_map(previous, now, before, technique_now, technique_before, truth_now, truth_before))
    if (v >= 0.0f) out.push_back(v);
  return out;
}

namespace {

// Mean over RGB of |a[i] - b[j]|.
float change(const RgbaImageF& a, std::size_t i, const RgbaImageF& b, std::size_t j) {
  float s = 0;
  for (std::size_t c = 0; c < 3; ++c) s += std::abs(a.pixels[i * 4 + c] - b.pixels[j * 4 + c]);
  return s / 3.0f;
}

// Calls f(i, j) for every pixel i of `now` that the change metrics measure: reflective in both
// frames and seen before, at pixel j of `before`. The one definition of that set.
template <typename F>
void for_each_measured(const std::vector<int>& previous, const TemporalFrame& now, const TemporalFrame& before, F f) {
  for (std::size_t i = 0; i < previous.size(); ++i) {
    if (previous[i] < 0 || !now.reflective[i]) continue;
    const auto j = static_cast<std::size_t>(previous[i]);
    if (before.reflective[j]) f(i, j);
  }
}

}  // namespace

std::vector<float> excess_change_map(const std::vector<int>& previous, const TemporalFrame& now,
                                     const TemporalFrame& before, const RgbaImageF& technique_now,
                                     const RgbaImageF& technique_before, const RgbaImageF& truth_now,
                                     const RgbaImageF& truth_before, ChangeTotals* totals) {
  std::vector<float> out(previous.size(), -1.0f);
  for_each_measured(previous, now, before, [&](std::size_t i, std::size_t j) {
    const float moved = change(technique_now, i, technique_before, j), truth = change(truth_now, i, truth_before, j);
    // A non-finite image is flicker without bound; the metric must not hide it as NaN.
    const float excess = moved - truth;
    out[i] = std::isfinite(excess) ? std::max(excess, 0.0f) : 1.0f;
    if (totals) {
      totals->technique += std::isfinite(moved) ? moved : 1.0;
      totals->truth += truth;
      ++totals->pixels;
    }
  });
  return out;
}

ChangeTotals change_totals(const std::vector<int>& previous, const TemporalFrame& now, const TemporalFrame& before,
                           const RgbaImageF& technique_now, const RgbaImageF& technique_before,
                           const RgbaImageF& truth_now, const RgbaImageF& truth_before) {
  ChangeTotals t;
  excess_change_map(previous, now, before, technique_now, technique_before, truth_now, truth_before, &t);
  return t;
}

std::optional<double> noise_in_change(const std::vector<int>& previous, const TemporalFrame& now,
                                      const TemporalFrame& before, const RgbaImageF& a_now, const RgbaImageF& a_before,
                                      const RgbaImageF& b_now, const RgbaImageF& b_before) {
  double sum = 0;
  std::size_t n = 0;
  for_each_measured(previous, now, before, [&](std::size_t i, std::size_t j) {
    double d = 0;
    for (std::size_t c = 0; c < 3; ++c)
      d += std::abs((a_now.pixels[i * 4 + c] - a_before.pixels[j * 4 + c]) -
                    (b_now.pixels[i * 4 + c] - b_before.pixels[j * 4 + c]));
    sum += d / 3.0;
    ++n;
  });
  if (!n) return std::nullopt;
  return sum / static_cast<double>(n) / std::sqrt(2.0);
}

void add_change_moments(const std::vector<int>& previous, const TemporalFrame& now, const TemporalFrame& before,
                        const RgbaImageF& technique_now, const RgbaImageF& technique_before, const RgbaImageF& a_now,
                        const RgbaImageF& a_before, const RgbaImageF& b_now, const RgbaImageF& b_before,
                        ChangeMoments& m) {
  for_each_measured(previous, now, before, [&](std::size_t i, std::size_t j) {
    double square = 0, truth_square = 0, product = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const double t = technique_now.pixels[i * 4 + c] - technique_before.pixels[j * 4 + c];
      const double da = a_now.pixels[i * 4 + c] - a_before.pixels[j * 4 + c];
      square += std::isfinite(t) ? t * t : 1.0;
      truth_square += da * da;
      product += da * (b_now.pixels[i * 4 + c] - b_before.pixels[j * 4 + c]);
    }
    m.technique_square += square / 3.0;
    m.truth_square += truth_square / 3.0;
    m.truth_product += product / 3.0;
    ++m.pixels;
  });
}

std::optional<double> noise_free_change_ratio(const ChangeMoments& m) {
  if (!m.pixels || !(m.truth_product > 0)) return std::nullopt;
  return std::sqrt(m.technique_square / m.truth_product);
}

std::optional<double> rms_change_ratio(const ChangeMoments& m) {
  if (!m.pixels || !(m.truth_square > 0)) return std::nullopt;
  return std::sqrt(m.technique_square / m.truth_square);
}

std::vector<int> update_ages(const std::vector<int>& previous, const TemporalFrame& now,
                             const TemporalFrame& before, const std::vector<int>& ages_before,
                             bool cut, int settled) {
  std::vector<int> ages(previous.size(), 0);
  if (ages_before.empty()) {
    ages.assign(previous.size(), settled);
    return ages;
  }
  if (cut) return ages;
  for (std::size_t i = 0; i < previous.size(); ++i) {
    if (previous[i] < 0) continue;  // disoccluded: 0
    const auto j = static_cast<std::size_t>(previous[i]);
    if (now.reflective[i] && !before.reflective[j]) continue;  // newly reflective: 0
    ages[i] = std::min(ages_before[j] + 1, settled);
  }
  return ages;
}

}  // namespace ssr
