// Parameters of `reference`, the ray-traced ground truth (Embree). C++ only: the GPU pass
// takes its inputs as buffers.
#pragma once
#include "shared/interop.h"

SSR_SHARED_BEGIN

struct ReferenceParams {
  int samples SSR_DEFAULT(256);            // GGX VNDF samples per rough pixel (mirrors use 1)
  int seed SSR_DEFAULT(1);                 // random seed: same seed, same image
  float mirror_roughness SSR_DEFAULT(0.01f);  // below this perceptual roughness one mirror ray is traced
  float depth_tolerance SSR_DEFAULT(0.02f);   // relative depth difference that still counts as "visible on screen"
  int bounces SSR_DEFAULT(1);              // ray segments per sample: 2+ shades reflective hits with their own reflection
};

SSR_SHARED_END
