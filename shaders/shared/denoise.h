// Parameters of the reflection denoiser (Diligent's stochastic SSR document; Stachowiak 2015):
// spatial reconstruction with the ratio estimator, temporal accumulation, cross-bilateral
// cleanup. `stochastic` always runs it; the tracers run it with `denoise=true`. Described once
// in src/techniques/denoiser.h (with_denoise_options).
#pragma once
#include "shared/interop.h"

SSR_SHARED_BEGIN

struct DenoiseParams {
  int enabled SSR_DEFAULT(0);               // tracers: run the denoiser on their samples
  int spatial SSR_DEFAULT(1);               // stage 1: ratio-estimator reuse of neighbours' rays
  int spatial_samples SSR_DEFAULT(8);       // neighbours read per pixel (besides its own ray)
  float spatial_radius SSR_DEFAULT(6.0f);   // pixels, at roughness >= 0.5 (scales with roughness)
  int temporal SSR_DEFAULT(1);              // stage 2: accumulation over frames
  int history SSR_DEFAULT(16);              // frames the accumulation averages at most
  float clip_gamma SSR_DEFAULT(1.25f);      // history clipped to mean +- gamma * sigma of 3x3
  float variance_stability SSR_DEFAULT(0.8f);  // share of the variance taken from history
  int bilateral SSR_DEFAULT(1);             // stage 3: cross-bilateral cleanup
  int bilateral_radius SSR_DEFAULT(2);      // pixels: a (2r+1)^2 window
  float bilateral_sigma SSR_DEFAULT(2.0f);  // pixels: spatial sigma at full variance
  int firefly SSR_DEFAULT(1);               // stage 1: reused rays weigh 1 / (1 + luminance), less with history
  float young_sigma SSR_DEFAULT(2.0f);      // stage 3: sigma >= young_sigma / frames of history (sampled lobes)
  int pad0 SSR_DEFAULT(0), pad1 SSR_DEFAULT(0), pad2 SSR_DEFAULT(0);  // std140: DenoisePass.trace starts at a 16-byte boundary
};

// What one denoiser stage reads besides its parameters (UBO_PASS).
struct DenoisePass {
  DenoiseParams params;
  // x: trace divisor (1, 2); yz: this frame's traced pixel of each 2x2 block; w: the spatial
  // stage's divisor (2: it ran on the trace grid, one texel per block at its traced pixel, and
  // the temporal stage upsamples; Denoiser::spatial_divisor).
  ivec4 trace;
};

SSR_SHARED_END
