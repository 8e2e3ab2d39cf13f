#include "eval/breakdown.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/errors.h"

namespace ssr {
namespace {

double sq_error(const float* a, const float* b) {
  double s = 0;
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(a[c]) || !std::isfinite(b[c])) {
      s += 1.0;  // a non-finite value is the maximal error on [0,1], as in metrics.cpp
      continue;
    }
    const double d = static_cast<double>(a[c]) - static_cast<double>(b[c]);
    s += d * d;
  }
  return s;
}

const float* px(const RgbaImageF* im, std::size_t i) { return &im->pixels[i * 4]; }

// Sum of squared errors over a set of pixels, and its PSNR (null for an empty set).
struct Accum {
  double sum = 0;
  std::size_t n = 0;
  void add(const float* a, const float* b) {
    sum += sq_error(a, b);
    ++n;
  }
  std::optional<double> psnr() const {
    if (n == 0) return std::nullopt;
    return psnr_from_rmse(std::sqrt(sum / (3.0 * static_cast<double>(n))));
  }
};

std::optional<double> share(std::size_t part, std::size_t whole) {
  if (whole == 0) return std::nullopt;
  return static_cast<double>(part) / static_cast<double>(whole);
}

void check_size(const RgbaImageF* im, const PixelLabels& l, const char* what) {
  if (!im) return;
  if (im->width != l.width || im->height != l.height ||
      im->pixels.size() != static_cast<std::size_t>(l.width) * l.height * 4)
    throw std::invalid_argument(std::string("breakdown: image '") + what + "' does not match the frame's size.");
}

void check_inputs(const PixelLabels& l, const TechniqueImages& t, const ReferenceImages& r) {
  const std::size_t n = static_cast<std::size_t>(l.width) * static_cast<std::size_t>(l.height);
  if (l.classes.size() != n || l.reflector.size() != n || l.roughness.size() != n ||
      !(l.glass.empty() || l.glass.size() == n))
    throw std::invalid_argument("breakdown: the pixel labels do not match the frame's size.");
  if (!t.final || !t.reflected || !t.confidence || !r.truth || !r.ideal || !r.truth_reflected ||
      !r.ideal_reflected)
    throw std::invalid_argument("breakdown: an image is missing.");
  check_size(t.final, l, "technique");
  check_size(t.reflected, l, "technique reflected");
  check_size(r.truth, l, "truth");
  check_size(r.ideal, l, "ideal");
  check_size(r.truth_reflected, l, "truth reflected");
  check_size(r.ideal_reflected, l, "ideal reflected");
  check_size(r.ideal_at_samples, l, "ideal at the technique's samples");
  if (t.confidence->size() != n) throw std::invalid_argument("breakdown: the confidence map does not match the frame's size.");
}

// Accumulators of one class within one region.
struct ClassAccum {
  Accum truth, ideal, refl_truth, refl_ideal, noise;
  std::size_t claimed = 0, correct = 0, false_claims = 0;
  ClassFigures figures(PixelClass c, bool has_noise_floor) const {
    ClassFigures f;
    f.pixels = truth.n;
    f.psnr = truth.psnr();
    f.psnr_reflection = refl_truth.psnr();
    if (c == PixelClass::Traceable) {
      f.psnr_ideal = ideal.psnr();
      f.psnr_reflection_ideal = refl_ideal.psnr();
      f.coverage = share(claimed, truth.n);
      f.correct_coverage = share(correct, truth.n);
      f.correct_pixels = correct;
      if (has_noise_floor) f.noise_floor_psnr = noise.psnr();
    } else {
      f.false_hit_rate = share(false_claims, truth.n);
    }
    return f;
  }
};

// Every region kind in report order with its name ("reflector" stands for reflector:N).
constexpr std::pair<RegionKind, const char*> kRegionNames[] = {
    {RegionKind::All, "all"},       {RegionKind::Planar, "planar"}, {RegionKind::Reflector, "reflector"},
    {RegionKind::Other, "other"},   {RegionKind::Mirror, "mirror"}, {RegionKind::Glossy, "glossy"},
    {RegionKind::Rough, "rough"},   {RegionKind::Refractive, "refractive"}};

}  // namespace

std::string region_names() {
  std::string out;
  for (const auto& [k, n] : kRegionNames)
    out += (out.empty() ? "" : ",") + std::string(n) + (k == RegionKind::Reflector ? ":N" : "");
  return out;
}

std::string Region::name() const {
  for (const auto& [k, n] : kRegionNames)
    if (k == kind) return k == RegionKind::Reflector ? std::string(n) + ":" + std::to_string(reflector) : n;
  return "?";
}

namespace {
const float kMirrorBound = as_stored_roughness(MIRROR_BAND_BELOW);
const float kRoughBound = as_stored_roughness(ROUGH_BAND_ABOVE);
}  // namespace

bool Region::contains(const PixelLabels& l, std::size_t i) const {
  if (l.classes[i] == PixelClass::NotReflective) return false;
  if (l.is_glass(i)) return kind == RegionKind::All || kind == RegionKind::Refractive;
  const float r = l.roughness[i];
  switch (kind) {
    case RegionKind::All: return true;
    case RegionKind::Planar: return l.reflector[i] > 0;
    case RegionKind::Reflector: return l.reflector[i] == reflector;
    case RegionKind::Other: return l.reflector[i] == 0;
    case RegionKind::Mirror: return r < kMirrorBound;
    case RegionKind::Glossy: return r >= kMirrorBound && r <= kRoughBound;
    case RegionKind::Rough: return r > kRoughBound;
    case RegionKind::Refractive: return false;
  }
  return false;
}

std::vector<Region> frame_regions(const PixelLabels& labels) {
  std::vector<Region> out;
  for (const auto& [k, n] : kRegionNames) {
    if (k != RegionKind::Reflector) out.push_back({k, 0});
    else
      for (int r = 1; r <= labels.reflectors; ++r) out.push_back({k, r});
  }
  return out;
}

Region parse_region(const std::string& name, int reflectors) {
  for (const auto& [k, n] : kRegionNames)
    if (k != RegionKind::Reflector && name == n) return {k, 0};
  const std::string prefix = "reflector:";
  if (name.rfind(prefix, 0) == 0) {
    const std::string id = name.substr(prefix.size());
    const bool digits = !id.empty() && id.size() < 4 && std::all_of(id.begin(), id.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int k = digits ? std::stoi(id) : 0;
    if (k >= 1 && k <= reflectors) return {RegionKind::Reflector, k};
    throw InputError("region '" + name + "' names no reflector of this scene (it has " +
                     std::to_string(reflectors) + ").");
  }
  throw InputError("unknown region '" + name + "' (known: " + region_names() + ").");
}

HitClass classify_hit(PixelClass c, float confidence, const float* reflected, const float* expected) {
  if (c == PixelClass::NotReflective) return HitClass::NotReflective;
  const bool claimed = confidence > kHitConfidence;  // false for NaN
  if (!claimed) return c == PixelClass::Traceable ? HitClass::Missed : HitClass::CorrectMiss;
  for (int k = 0; k < 3; ++k)  // NaN fails the comparison: a wrong colour
    if (!(std::abs(reflected[k] - expected[k]) <= kCorrectHitTolerance)) return HitClass::False;
  return HitClass::Correct;
}

std::vector<HitClass> hit_classes(const PixelLabels& labels, const TechniqueImages& t,
                                  const ReferenceImages& r, bool planar_only) {
  check_inputs(labels, t, r);
  std::vector<HitClass> out(labels.classes.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = planar_only && (labels.reflector[i] == 0 || labels.is_glass(i)) &&
                     labels.classes[i] != PixelClass::NotReflective
                 ? HitClass::NotHandled
                 : classify_hit(labels.classes[i], (*t.confidence)[i], px(t.reflected, i),
                                px(labels.classes[i] == PixelClass::Traceable ? r.ideal_reflected : r.truth_reflected, i));
  return out;
}

Breakdown compute_breakdown(const PixelLabels& labels, const TechniqueImages& t,
                            const ReferenceImages& r, bool planar_only) {
  check_inputs(labels, t, r);
  const std::vector<HitClass> hits = hit_classes(labels, t, r, planar_only);
  Breakdown b;
  for (const Region& region : frame_regions(labels)) {
    RegionFigures f;
    f.region = region;
    ClassAccum acc[4];  // by PixelClass
    bool any_rough_traceable = false;
    for (std::size_t i = 0; i < labels.classes.size(); ++i) {
      if (!region.contains(labels, i)) continue;
      ++f.pixels;
      if (planar_only && (labels.reflector[i] == 0 || labels.is_glass(i))) continue;
      ++f.handled_pixels;
      const PixelClass c = labels.classes[i];
      ClassAccum& a = acc[static_cast<int>(c)];
      a.truth.add(px(t.final, i), px(r.truth, i));
      a.refl_truth.add(px(t.reflected, i), px(r.truth_reflected, i));
      const HitClass h = hits[i];
      a.claimed += h == HitClass::Correct || h == HitClass::False;
      a.false_claims += h == HitClass::False;
      switch (h) {
        case HitClass::Correct: ++f.hits.correct; break;
        case HitClass::False: ++f.hits.false_hits; break;
        case HitClass::Missed: ++f.hits.missed; break;
        case HitClass::CorrectMiss: ++f.hits.correct_miss; break;
        default: break;
      }
      if (c == PixelClass::Traceable) {
        a.ideal.add(px(t.final, i), px(r.ideal, i));
        a.refl_ideal.add(px(t.reflected, i), px(r.ideal_reflected, i));
        a.correct += h == HitClass::Correct;
        if (r.ideal_at_samples && labels.roughness[i] >= kMirrorBound && !labels.is_glass(i)) {
          a.noise.add(px(r.ideal_at_samples, i), px(r.ideal, i));
          any_rough_traceable = true;
        }
      }
    }
    f.handled = f.handled_pixels == f.pixels;
    const bool noise = r.ideal_at_samples != nullptr && any_rough_traceable;
    f.traceable = acc[static_cast<int>(PixelClass::Traceable)].figures(PixelClass::Traceable, noise);
    f.missing = acc[static_cast<int>(PixelClass::Missing)].figures(PixelClass::Missing, false);
    f.sky = acc[static_cast<int>(PixelClass::Sky)].figures(PixelClass::Sky, false);
    b.regions.push_back(std::move(f));
  }
  return b;
}

const RegionFigures* Breakdown::find(const std::string& name) const {
  for (const RegionFigures& f : regions)
    if (f.region.name() == name) return &f;
  return nullptr;
}

InherentFigures compute_inherent(const PixelLabels& labels, const ReferenceImages& r) {
  if (!r.truth || !r.ideal) throw std::invalid_argument("breakdown: an image is missing.");
  check_size(r.truth, labels, "truth");
  check_size(r.ideal, labels, "ideal");
  Accum acc[4];
  for (std::size_t i = 0; i < labels.classes.size(); ++i)
    acc[static_cast<int>(labels.classes[i])].add(px(r.ideal, i), px(r.truth, i));
  return {acc[static_cast<int>(PixelClass::Traceable)].psnr(), acc[static_cast<int>(PixelClass::Missing)].psnr(),
          acc[static_cast<int>(PixelClass::Sky)].psnr()};
}

OracleAgreement compare_oracles(const PixelLabels& labels, const RgbaImageF& planar_reflected,
                                const RgbaImageF& truth_reflected, const std::vector<bool>& eligible,
                                float max_roughness) {
  check_size(&planar_reflected, labels, "planar reflected");
  check_size(&truth_reflected, labels, "truth reflected");
  if (eligible.size() != labels.classes.size())
    throw std::invalid_argument("breakdown: the eligibility mask does not match the frame's size.");
  auto on_edge = [&](std::size_t i) {
    const int x = static_cast<int>(i % static_cast<std::size_t>(labels.width));
    const int y = static_cast<int>(i / static_cast<std::size_t>(labels.width));
    for (int c = 0; c < 3; ++c) {
      float lo = 1e30f, hi = -1e30f;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = std::clamp(x + dx, 0, labels.width - 1), ny = std::clamp(y + dy, 0, labels.height - 1);
          const float v = truth_reflected.at(nx, ny)[c];
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
      if (!(hi - lo <= kOracleEdgeContrast)) return true;
    }
    return false;
  };
  Accum acc, off_edges;
  std::size_t within = 0, edges = 0;
  for (std::size_t i = 0; i < labels.classes.size(); ++i) {
    if (labels.classes[i] == PixelClass::NotReflective || labels.reflector[i] == 0 || labels.is_glass(i) || !eligible[i] ||
        !(labels.roughness[i] < max_roughness))
      continue;
    const float* a = px(&planar_reflected, i);
    const float* b = px(&truth_reflected, i);
    acc.add(a, b);
    if (on_edge(i)) ++edges;
    else off_edges.add(a, b);
    bool ok = true;
    for (int c = 0; c < 3; ++c) ok = ok && std::abs(a[c] - b[c]) <= 1.0f / 255.0f;
    within += ok;
  }
  OracleAgreement o;
  o.pixels = acc.n;
  o.psnr = acc.psnr();
  o.within_1_255 = share(within, acc.n);
  o.edge_pixels = edges;
  o.psnr_off_edges = off_edges.psnr();
  return o;
}

}  // namespace ssr
