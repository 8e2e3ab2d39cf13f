// Void-and-cluster (Ulichney 1993) on a torus, for one map or several slices ranked in lockstep.
//
// Energy of pixel p in slice s: the sum, over the "on" pixels q of the same slice, of a Gaussian
// of their toroidal distance (sigma_s, truncated at 3 sigma), plus, over the other slices s' where
// the same pixel p is on, a Gaussian of the cyclic slice distance (sigma_t, times a weight). The
// first term makes each slice blue noise; the second pushes a pixel's rank in one slice away from
// its ranks in the neighbouring slices, so values along time at a pixel are spread apart. With one
// slice it is Ulichney's method exactly. Pixels interact only within their slice or along their
// own time line, never diagonally in space-time: a 3D Gaussian would make the volume blue in 3D,
// and 3D blue noise is not blue in its 2D slices (the point Wolfe et al. 2022 start from).
//
// Every slice gets one pixel per rank step (the slices take turns, the first of each turn
// rotating), so each slice holds each rank exactly once: uniform histograms per slice.
//
// Speed: energies are updated incrementally (add or subtract the kernel around the changed pixel)
// and each row of each slice caches its largest void (lowest-energy 0) and tightest cluster
// (highest-energy 1). A change only invalidates a row's cache when it makes that row's cached
// pixel worse, so a search mostly reads N cached rows instead of N*N pixels. Energies are integers
// (16.16 fixed point): exact, so the result is the same bytes on every machine and compiler.
#include "core/blue_noise.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "core/errors.h"

namespace ssr {
namespace {

// The temporal term: sigma_t in slices, weight relative to the spatial Gaussian's peak (1).
// Measured on 128 x 128 x 8 (low/high power: spatial per slice, worst; temporal per pixel):
//   independent maps (weight 0)    0.0002  1.00
//   weight 0.25                    0.0003  0.074
//   weight 0.5 (chosen)            0.0004  0.054
//   weight 1                       0.0006  0.041
//   weight 2                       0.0011  0.034
// (sigma_t 0.7 / 1.5 at weight 1: 0.0005 / 0.0009 spatial, 0.070 / 0.039 temporal.) Past 0.5 the
// time line gains little and the slices lose more; the slices stay far bluer than white (1.0).
constexpr float kSigmaT = 1.0f;
constexpr float kTemporalWeight = 0.5f;
constexpr double kFixed = 65536.0;

// splitmix64: a small, fully specified generator (std::uniform_*_distribution is not portable).
struct SplitMix {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t below(std::uint64_t n) { return next() % n; }  // bias < n / 2^64: irrelevant here
};

class Lockstep {
 public:
  Lockstep(int size, int slices, float sigma, std::uint32_t seed) : n_(size), s_(slices), nn_(size * size) {
    // The spatial kernel as one run of taps per kernel row (a disc of radius 3 sigma).
    const int r = static_cast<int>(std::ceil(3.0f * sigma));
    for (int dy = -r; dy <= r; ++dy) {
      Span span{dy, 0, 0, weights_.size()};
      for (int dx = -r; dx <= r; ++dx) {
        if (dx * dx + dy * dy > r * r) continue;
        if (span.count == 0) span.dx0 = dx;
        const double w = std::exp(-(dx * dx + dy * dy) / (2.0 * sigma * sigma));
        weights_.push_back(static_cast<std::int32_t>(std::lround(w * kFixed)));
        ++span.count;
      }
      spans_.push_back(span);
    }
    radius_ = r;
    wrap_.resize(static_cast<std::size_t>(size + 2 * r));
    for (int i = -r; i < size + r; ++i) wrap_[static_cast<std::size_t>(i + r)] = ((i % size) + size) % size;
    temporal_.assign(static_cast<std::size_t>(slices), 0);
    for (int d = 1; d < slices; ++d) {
      const int c = std::min(d, slices - d);  // the slices loop: the last is next to the first
      temporal_[static_cast<std::size_t>(d)] = static_cast<std::int32_t>(
          std::lround(kTemporalWeight * std::exp(-(c * c) / (2.0 * kSigmaT * kSigmaT)) * kFixed));
    }
    const std::size_t total = static_cast<std::size_t>(s_) * nn_;
    on_.assign(total, 0);
    energy_.assign(total, 0);
    rank_.assign(total, 0);
    voids_.assign(static_cast<std::size_t>(s_) * n_, Best{});
    clusters_.assign(static_cast<std::size_t>(s_) * n_, Best{});

    // Initial binary pattern: the same number of random ones (~10%) in every slice.
    SplitMix rng{seed * 0x2545F4914F6CDD1Dull + 1};
    ones_ = std::max(1, nn_ / 10);
    std::vector<int> order(static_cast<std::size_t>(nn_));
    for (int s = 0; s < s_; ++s) {
      for (int i = 0; i < nn_; ++i) order[static_cast<std::size_t>(i)] = i;
      for (int i = 0; i < ones_; ++i) {  // partial Fisher-Yates
        const auto j = i + static_cast<int>(rng.below(static_cast<std::uint64_t>(nn_ - i)));
        std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(j)]);
        set(s, order[static_cast<std::size_t>(i)], true);
      }
    }
  }

  // Ranks 0..N*N-1 of every slice, slice-major.
  std::vector<int> run() {
    track(true, true);
    relax();
    const std::vector<std::uint8_t> proto_on = on_;
    const std::vector<std::int32_t> proto_energy = energy_;

    // Phase 1: remove the tightest cluster of the prototype, one per slice per step; ranks below.
    track(false, true);
    for (int r = ones_ - 1; r >= 0; --r)
      for (int i = 0; i < s_; ++i) {
        const int s = (r + i) % s_;
        const int p = find<kCluster>(s);
        set(s, p, false);
        rank_[index(s, p)] = r;
      }

    // Phases 2 and 3: from the prototype, fill the largest void until every pixel is on. Ulichney
    // switches at half to "remove the tightest cluster of zeros"; on a torus the energy that the
    // zeros give a pixel is a constant minus the energy the ones give it, so that is the same
    // pixel: one loop.
    on_ = proto_on;
    energy_ = proto_energy;
    track(true, false);
    for (int r = ones_; r < nn_; ++r)
      for (int i = 0; i < s_; ++i) {
        const int s = (r + i) % s_;
        const int p = find<kVoid>(s);
        set(s, p, true);
        rank_[index(s, p)] = r;
      }
    return rank_;
  }

 private:
  struct Span {  // one row of the kernel: taps dx0 .. dx0 + count - 1 at dy
    int dy, dx0, count;
    std::size_t first;  // into weights_
  };
  // Per row of a slice, the best candidate: the void (lowest-energy 0) or the cluster
  // (highest-energy 1), ties to the lowest index, p = -1 if the row has none; dirty when a change
  // may have dethroned it (then the row is rescanned at the next search).
  struct Best {
    std::int32_t e = 0;
    int p = -1;
    bool dirty = true;
  };
  static constexpr bool kVoid = true, kCluster = false;

  std::size_t index(int s, int p) const { return static_cast<std::size_t>(s) * nn_ + p; }
  std::vector<Best>& cache(bool voids) { return voids ? voids_ : clusters_; }

  // Which caches are kept up to date (a phase needs one kind only); switching one on rebuilds it.
  void track(bool voids, bool clusters) {
    for (Best& b : voids_) b.dirty = true;
    for (Best& b : clusters_) b.dirty = true;
    track_voids_ = voids;
    track_clusters_ = clusters;
  }

  // Pixel p of a row changed energy or state: keep the row's cached best or mark it dirty.
  template <bool kMin>
  static void offer(Best& b, int p, bool eligible, std::int32_t e) {
    if (b.dirty) return;
    const bool better = kMin ? e < b.e : e > b.e;
    if (p == b.p) {
      if (eligible && (better || e == b.e)) b.e = e;
      else b.dirty = true;
    } else if (eligible && (b.p < 0 || better || (e == b.e && p < b.p))) {
      b.e = e;
      b.p = p;
    }
  }
  void touch(int s, int p, int y) {
    const std::size_t i = index(s, p), row = static_cast<std::size_t>(s) * n_ + y;
    if (track_voids_) offer<kVoid>(voids_[row], p, on_[i] == 0, energy_[i]);
    if (track_clusters_) offer<kCluster>(clusters_[row], p, on_[i] != 0, energy_[i]);
  }

  template <bool kMin>
  void refresh(int s, int y) {
    // Branch-free: the pattern is random, so branching on it would mispredict half the time.
    constexpr std::int32_t kWorst = kMin ? std::numeric_limits<std::int32_t>::max()
                                         : std::numeric_limits<std::int32_t>::min();
    std::int32_t best = kWorst;
    int best_p = -1;
    const std::uint8_t* on = &on_[index(s, 0)];
    const std::int32_t* energy = &energy_[index(s, 0)];
    for (int p = y * n_; p < (y + 1) * n_; ++p) {
      const bool eligible = kMin ? on[p] == 0 : on[p] != 0;
      const std::int32_t e = eligible ? energy[p] : kWorst;
      const bool better = kMin ? e < best : e > best;
      best_p = better ? p : best_p;
      best = better ? e : best;
    }
    cache(kMin)[static_cast<std::size_t>(s) * n_ + y] = Best{best, best_p, false};
  }

  // The largest void (kVoid) or tightest cluster (kCluster) of slice s, -1 if there is none.
  template <bool kMin>
  int find(int s) {
    constexpr std::int32_t kWorst = kMin ? std::numeric_limits<std::int32_t>::max()
                                         : std::numeric_limits<std::int32_t>::min();
    Best* rows = &cache(kMin)[static_cast<std::size_t>(s) * n_];
    // A row without candidates holds kWorst (refresh's sentinel), so no test for p < 0 here.
    std::int32_t best = kWorst;
    int best_p = -1;
    for (int y = 0; y < n_; ++y) {
      if (rows[y].dirty) refresh<kMin>(s, y);
      const bool better = kMin ? rows[y].e < best : rows[y].e > best;
      best_p = better ? rows[y].p : best_p;
      best = better ? rows[y].e : best;
    }
    return best_p;
  }

  // Energies at pixels row0 + wx[0 .. count-1] (one row, wx[] consecutive mod N) just moved in
  // one direction. If that makes candidates worse (a void's energy rose, a cluster's fell), the
  // cached best stays best unless it was among them; if better, the best of them competes with it.
  // The pixel whose state flipped is always among them and its move agrees: turned on, its energy
  // rose (no longer a void, maybe a cluster); turned off, it fell (no longer a cluster, maybe a void).
  template <bool kMin>
  void span_changed(int s, int qy, const int* wx, int count, bool rose) {
    Best& b = cache(kMin)[static_cast<std::size_t>(s) * n_ + qy];
    if (b.dirty) return;
    const int row0 = qy * n_;
    auto touched = [&](int q) {
      int d = q - row0 - wx[0];
      if (d < 0) d += n_;
      return count >= n_ || d < count;
    };
    if (rose == kMin) {  // worse
      if (b.p >= 0 && touched(b.p)) b.dirty = true;
      return;
    }
    const std::size_t base = index(s, 0);
    if (b.p >= 0 && touched(b.p)) b.e = energy_[base + b.p];
    for (int k = 0; k < count; ++k) {
      const int q = row0 + wx[k];
      if ((on_[base + q] == 0) != kMin) continue;  // not a candidate of this kind
      const std::int32_t e = energy_[base + q];
      if (b.p < 0 || (kMin ? e < b.e : e > b.e) || (e == b.e && q < b.p)) b.e = e, b.p = q;
    }
  }

  // Turns pixel p of slice s on or off and adds or subtracts its energy everywhere.
  void set(int s, int p, bool value) {
    on_[index(s, p)] = value ? 1 : 0;
    const std::int32_t sign = value ? 1 : -1;
    const int x = p % n_, y = p / n_;
    std::int32_t* e = &energy_[index(s, 0)];
    for (const Span& span : spans_) {
      const int qy = wrap_[static_cast<std::size_t>(y + span.dy + radius_)];
      const int* wx = &wrap_[static_cast<std::size_t>(x + span.dx0 + radius_)];
      const std::int32_t* w = &weights_[span.first];
      std::int32_t* er = e + qy * n_;
      for (int k = 0; k < span.count; ++k) er[wx[k]] += sign * w[k];
      if (track_voids_) span_changed<kVoid>(s, qy, wx, span.count, value);
      if (track_clusters_) span_changed<kCluster>(s, qy, wx, span.count, value);
    }
    for (int d = 1; d < s_; ++d) {
      const int other = (s + d) % s_;
      energy_[index(other, p)] += sign * temporal_[static_cast<std::size_t>(d)];
      touch(other, p, y);
    }
  }

  // Swap the tightest cluster into the largest void until the pattern is stable in every slice.
  void relax() {
    for (int round = 0; round < 4 * nn_; ++round) {  // converges long before; a safety bound
      bool moved = false;
      for (int s = 0; s < s_; ++s) {
        const int c = find<kCluster>(s);
        set(s, c, false);
        const int v = find<kVoid>(s);
        set(s, v, true);
        moved = moved || v != c;
      }
      if (!moved) return;
    }
  }

  int n_, s_, nn_, radius_ = 0, ones_ = 0;
  std::vector<Span> spans_;
  std::vector<std::int32_t> weights_;   // spatial kernel, 16.16
  std::vector<int> wrap_;               // (i mod N) for i in [-radius, N + radius)
  std::vector<std::int32_t> temporal_;  // by slice offset d = 0..S-1 (cyclic distance), 16.16
  std::vector<std::uint8_t> on_;        // slice-major binary pattern
  std::vector<std::int32_t> energy_;    // slice-major
  std::vector<Best> voids_, clusters_;  // per row of each slice, slice-major
  bool track_voids_ = false, track_clusters_ = false;
  std::vector<int> rank_;
};

void check(int size, int slices, float sigma) {
  // Upper bounds: sanity (memory, and int32 energies), far above any texture one would use.
  if (size < 2 || size > 512) throw InputError("blue noise: size must be in [2, 512], got " + std::to_string(size));
  if (slices < 1 || slices > 64)
    throw InputError("blue noise: slices must be in [1, 64], got " + std::to_string(slices));
  if (!(sigma >= 0.5f && sigma <= 8.0f))
    throw InputError("blue noise: sigma must be in [0.5, 8], got " + std::to_string(sigma));
}

// Ranks 0..n-1 to bytes, n/256 pixels per value (as even as n allows).
std::vector<std::uint8_t> to_bytes(const std::vector<int>& ranks, int per_slice) {
  std::vector<std::uint8_t> out(ranks.size());
  for (std::size_t i = 0; i < ranks.size(); ++i)
    out[i] = static_cast<std::uint8_t>(static_cast<std::int64_t>(ranks[i]) * 256 / per_slice);
  return out;
}

}  // namespace

std::vector<std::uint8_t> void_and_cluster(int size, std::uint32_t seed, float sigma) {
  check(size, 1, sigma);
  return to_bytes(Lockstep(size, 1, sigma, seed).run(), size * size);
}

std::uint8_t BlueNoise::at(int x, int y, int slice) const {
  auto wrap = [](int v, int n) { return ((v % n) + n) % n; };
  return texels[(static_cast<std::size_t>(wrap(slice, slices)) * size + wrap(y, size)) * size + wrap(x, size)];
}

BlueNoise spatiotemporal_blue_noise(int size, int slices, std::uint32_t seed) {
  check(size, slices, 1.9f);
  BlueNoise b;
  b.size = size;
  b.slices = slices;
  b.texels = to_bytes(Lockstep(size, slices, 1.9f, seed).run(), size * size);
  return b;
}

const BlueNoise& default_blue_noise() {
  static const BlueNoise noise = spatiotemporal_blue_noise(128, 8, 1);
  return noise;
}

}  // namespace ssr
