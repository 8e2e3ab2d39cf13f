// Parameters of `hiz` (Uludag, GPU Pro 5): a screen-space trace over a max-depth pyramid
// (reversed-Z: max = closest), climbing while the ray stays in front of a cell's closest depth
// and descending where it may pass behind it, with an iteration cap.
#pragma once
#include "shared/ray_options.h"

// Levels the pyramid's build writes per dispatch (render/hiz_pyramid.comp): a work group of 16x16
// reduces a 32x32 source footprint to one texel, so a 1080p chain takes 2 dispatches.
#define HIZ_LEVELS_PER_DISPATCH 5

SSR_SHARED_BEGIN

struct HizParams {
  RayOptions ray SSR_DEFAULT((RayOptions{}));
  int max_iterations SSR_DEFAULT(0);    // cap on pyramid cell visits per ray; 0 auto (half the image diagonal)
  int start_level SSR_DEFAULT(0);       // pyramid level of the first step
  int max_level SSR_DEFAULT(10);        // coarsest level the trace climbs to
  float thickness SSR_DEFAULT(0.15f);   // how far behind the depth buffer still counts (world units)
  float max_distance SSR_DEFAULT(0.0f);   // the ray's length (world units); 0 auto
  int pad0, pad1, pad2;                 // std140 rounds a block up to 16 bytes (test_layouts.cpp)
};

SSR_SHARED_END
