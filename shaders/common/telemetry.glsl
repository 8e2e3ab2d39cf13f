// Per-ray telemetry (shared/telemetry.h), compiled in only with SSR_TELEMETRY; without it the
// calls are empty. telemetry_ray() once per traced ray; telemetry_lanes() once at the end of
// main() by every invocation of the work group (it has barriers), with the pixel the lane
// stands for and its iterations over all of its rays.
#include "shared/telemetry.h"

#ifdef SSR_TELEMETRY
layout(std430, binding = SSBO_TELEMETRY) buffer TelemetryBlock {
  TelemetryHeader telemetry;
  uint telemetry_hist[TELEMETRY_BINS];
  uint telemetry_pixels[];
};
shared uint telemetry_warp_max[TELEMETRY_MAX_WARPS];
shared uint telemetry_warp_sum[TELEMETRY_MAX_WARPS];

void telemetry_ray(float iterations) {
  atomicAdd(telemetry.rays, 1u);
  atomicAdd(telemetry_hist[min(uint(max(iterations, 0.0)), uint(TELEMETRY_BINS - 1))], 1u);
}

// A 64-bit sum from two words: the carry goes to `hi` when `lo` wraps.
#define TELEMETRY_ADD64(lo, hi, v) if (atomicAdd(lo, v) + (v) < (v)) atomicAdd(hi, 1u)

void telemetry_lanes(ivec2 pixel, bool valid, float iterations) {
  uint warp = gl_LocalInvocationIndex / uint(TELEMETRY_WARP);
  uint lane = gl_LocalInvocationIndex % uint(TELEMETRY_WARP);
  uint n = valid ? uint(max(iterations, 0.0)) : 0u;
  if (lane == 0u) {
    telemetry_warp_max[warp] = 0u;
    telemetry_warp_sum[warp] = 0u;
  }
  barrier();
  atomicMax(telemetry_warp_max[warp], n);
  atomicAdd(telemetry_warp_sum[warp], n);
  barrier();
  uint top = telemetry_warp_max[warp], sum = telemetry_warp_sum[warp];
  if (top == 0u) return;
  uint slots = top * uint(TELEMETRY_WARP);
  if (valid) telemetry_pixels[uint(pixel.y) * telemetry.width + uint(pixel.x)] =
      telemetry_pack(n, 1.0 - float(sum) / float(slots));
  if (lane == 0u) {
    TELEMETRY_ADD64(telemetry.busy_lo, telemetry.busy_hi, sum);
    TELEMETRY_ADD64(telemetry.slots_lo, telemetry.slots_hi, slots);
    atomicAdd(telemetry.warps, 1u);
  }
}
#else
void telemetry_ray(float iterations) {}
void telemetry_lanes(ivec2 pixel, bool valid, float iterations) {}
#endif
