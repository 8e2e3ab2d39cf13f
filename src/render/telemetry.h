// Per-ray telemetry: what an instrumented build of a technique (its shaders compiled with
// SSR_TELEMETRY, common/telemetry.glsl) records in one frame: iterations per ray as a histogram,
// iterations per pixel, and the share of idle lanes in lockstep warps (shared/telemetry.h says
// how they are counted). Timed frames never carry it: the atomics would be timed too.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "gl/objects.h"
#include "shared/telemetry.h"

namespace ssr {

struct IterationStats {
  std::uint64_t rays = 0;
  double mean = 0;
  int p50 = 0, p95 = 0, max = 0;  // histogram percentiles (the smallest bin holding the share)
  // Of the lane-iterations warps with work spent, the share idle lanes waited; absent when no
  // warp had work.
  std::optional<double> idle_lanes;
};

// What one instrumented frame recorded.
struct TelemetryFrame {
  shared::TelemetryHeader header{};
  std::vector<std::uint32_t> histogram;  // TELEMETRY_BINS counts
  std::vector<std::uint32_t> pixels;     // per pixel, row 0 = bottom (GL order): telemetry_pack words
  // Iteration statistics; no rays recorded (a technique that does not iterate) gives none.
  std::optional<IterationStats> stats() const;
};

// The buffer an instrumented technique writes (SSBO_TELEMETRY); the Renderer owns one.
class TelemetryBuffer {
 public:
  // Zeroes the counts for a w x h frame and binds the buffer at SSBO_TELEMETRY.
  void begin(int width, int height);
  // Reads what the frame recorded (stalls).
  TelemetryFrame read() const;
  // Binds it at SSBO_TELEMETRY for a w x h frame (the display pass's telemetry views), zeroed
  // first when it does not hold that size (nothing recorded shows as nothing).
  void bind_for(int width, int height);

 private:
  void bind() const;
  gl::Buffer buffer_;
  std::size_t capacity_ = 0;  // bytes
  int width_ = 0, height_ = 0;
};

}  // namespace ssr
