// Parameters of `linear-binary` (Roberts): a linear march to max_distance in linear_steps,
// then binary_steps of bisection between the last two samples.
#pragma once
#include "shared/ray_options.h"

SSR_SHARED_BEGIN

struct LinearBinaryParams {
  // The paper fades at the screen edges: edge_fade on by default here.
  RayOptions ray SSR_DEFAULT((RayOptions{1, -1.0f, 0, 0.0f, 1, 0, 0, 0}));
  int linear_steps SSR_DEFAULT(100);      // SSR_linearsteps: samples between the origin and max_distance
  int binary_steps SSR_DEFAULT(10);       // bisection steps after the first hit
  float thickness SSR_DEFAULT(0.1f);      // t_ray: how far behind the depth buffer still counts (world units)
  float max_distance SSR_DEFAULT(9.0f);   // D_max: the ray's length (world units)
};

SSR_SHARED_END
