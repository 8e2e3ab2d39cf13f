// Parameters of `stochastic` (Diligent's stochastic SSR / AMD FidelityFX SSSR): tile
// classification, a Hi-Z trace of one GGX VNDF ray per traced pixel with blue-noise samples,
// then the denoiser (shared/denoise.h). Described once in src/techniques/stochastic.cpp.
#pragma once
#include "shared/classification.h"
#include "shared/denoise.h"

SSR_SHARED_BEGIN

struct StochasticParams {
  float roughness_threshold SSR_DEFAULT(1.0f);  // rougher pixels get the environment (1: none)
  int rays_per_quad SSR_DEFAULT(2);             // choice 0,1,2: 1, 2 or 4 rays per 2x2 quad above quad_roughness
  float quad_roughness SSR_DEFAULT(0.3f);       // pixels at or below it trace one ray each
  float ggx_bias SSR_DEFAULT(0.0f);             // 0..1: pulls samples towards the lobe's centre
  int half_resolution SSR_DEFAULT(0);           // trace one pixel of each 2x2 block
  int previous_frame SSR_DEFAULT(0);            // hits read the previous final colour (2nd bounce)
  int max_iterations SSR_DEFAULT(0);            // Hi-Z cell visits; 0 auto (half the image diagonal)
  int glossy_iterations SSR_DEFAULT(128);       // cap for rays from pixels rougher than glossy_roughness; 0 auto
  float glossy_roughness SSR_DEFAULT(0.25f);    // where glossy_iterations starts to apply
  int max_level SSR_DEFAULT(10);                // coarsest Hi-Z level
  float thickness SSR_DEFAULT(0.15f);           // world units behind the depth buffer that count as a hit
  float max_distance SSR_DEFAULT(0.0f);         // ray length, world units; 0 auto (scene diagonal)
  int seed SSR_DEFAULT(0);                      // offsets the blue-noise pattern
  int pad0 SSR_DEFAULT(0), pad1 SSR_DEFAULT(0), pad2 SSR_DEFAULT(0);  // std140: the struct below starts at 16 bytes
  DenoiseParams denoise SSR_DEFAULT((DenoiseParams{1}));
};

SSR_SHARED_END
