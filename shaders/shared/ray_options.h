// Options every screen-space tracer shares (described once: src/techniques/ray_options.h adds
// them to each technique's table). Each tracer's Params struct starts with `RayOptions ray;`.
#pragma once
#include "shared/denoise.h"

SSR_SHARED_BEGIN

struct RayOptions {
  int samples SSR_DEFAULT(1);                 // GGX VNDF rays per rough pixel (mirrors trace 1)
  float roughness SSR_DEFAULT(-1.0f);         // < 0: the G-buffer's roughness; else used everywhere
  int backface_thickness SSR_DEFAULT(0);      // 1: a hit lies between the front and back-face depth
  float falloff_distance SSR_DEFAULT(0.0f);   // > 0: confidence fades out towards this ray length
  int edge_fade SSR_DEFAULT(-1);              // 1: confidence *= clamp(1 - |u-.5| - |v-.5|, 0, 1); -1 auto (resolved on the CPU)
  int fresnel SSR_DEFAULT(0);                 // 1 (Roberts blend): weight *= Schlick Fresnel
  int blend SSR_DEFAULT(0);                   // 0: standard composite; 1: Roberts blend
  int seed SSR_DEFAULT(0);                    // random seed of the rough samples and jitter
  int compact SSR_DEFAULT(0);                 // 1: trace the classification's ray list (indirect); 0: every pixel
  int pad0 SSR_DEFAULT(0);                    // std140 starts the nested struct below at a 16-byte boundary
  int pad1 SSR_DEFAULT(0);
  int pad2 SSR_DEFAULT(0);
  DenoiseParams denoise;                      // enabled: the denoiser runs on the samples
};

// The options of most runs (every default): one ray a pixel, no fades, the standard composite.
// A tracer runs a variant compiled with SSR_PLAIN_RAY for them (techniques/tracer.h), where
// ssr_main.glsl reads them through plain_ray(): as constants the compiler folds the sample loop
// and the weights away: the trace runs faster (H200, 1080p: hiz 4-15%, linear-binary 16-23%,
// dda 22%; linear 5% faster on gallery, 5% slower on corridor; docs/RESULTS.md). edge_fade must
// be resolved (not auto).
SSR_FN bool is_plain_ray(RayOptions o) {
  return o.samples == 1 && o.edge_fade == 0 && o.falloff_distance == 0.0f && o.blend == 0;
}
SSR_FN RayOptions plain_ray(RayOptions o) {
  o.samples = 1;
  o.edge_fade = 0;
  o.falloff_distance = 0.0f;
  o.blend = 0;
  return o;
}

SSR_SHARED_END
