// Per-ray telemetry (src/eval/telemetry.h): what an instrumented build (SSR_TELEMETRY defined,
// common/telemetry.glsl) of a tracing pass records in one frame. Timed runs never carry it.
//
// Idle lanes are counted under NVIDIA's grouping of compute invocations: TELEMETRY_WARP
// consecutive local invocations run in lockstep, so a warp costs its busiest lane's iterations
// on every lane; the idle share is 1 - sum(lane iterations) / (TELEMETRY_WARP * max).
#pragma once
#include "shared/interop.h"

#define TELEMETRY_BINS 4097   // iteration histogram: bins 0 .. 4095, the last holds 4096 and more
#define TELEMETRY_WARP 32     // lanes that run in lockstep
#define TELEMETRY_MAX_WARPS 8 // per work group (256 invocations at most)

SSR_SHARED_BEGIN

// The buffer: this header, TELEMETRY_BINS histogram counts, then one packed word per pixel
// (telemetry_pack: the lane's iterations and its warp's idle share; 0 where no lane ran).
struct TelemetryHeader {
  uint rays;       // rays recorded
  uint width;      // pixels per row of the per-pixel words (set by the host)
  uint busy_lo;    // sum of lane iterations over warps with work (64 bits, lo/hi)
  uint busy_hi;
  uint slots_lo;   // sum of TELEMETRY_WARP * max lane iterations over those warps (64 bits)
  uint slots_hi;
  uint warps;      // warps with work
  uint pad;
};

// Lane iterations (16 bits, saturated) and the warp's idle share (16 bits, 0..65535).
SSR_FN uint telemetry_pack(uint iterations, float idle) {
  return min(iterations, 65535u) | (uint(clamp(idle, 0.0f, 1.0f) * 65535.0f + 0.5f) << 16u);
}
SSR_FN uint telemetry_iterations(uint word) { return word & 65535u; }
SSR_FN float telemetry_idle(uint word) { return float(word >> 16u) / 65535.0f; }

SSR_SHARED_END
