// Parameters of `linear-binary` (Roberts): a linear march to max_distance in linear_steps,
// then binary_steps of bisection between the last two samples.
#pragma once
#include "shared/ray_options.h"

SSR_SHARED_BEGIN

struct LinearBinaryParams {
  // Edge fade: auto (on with the Roberts blend, as in the paper; the roberts-* presets set it).
  RayOptions ray;
  int linear_steps SSR_DEFAULT(300);      // SSR_linearsteps: samples between the origin and max_distance (the paper: 100)
  int binary_steps SSR_DEFAULT(10);       // bisection steps after the first hit
  float thickness SSR_DEFAULT(0.0f);      // t_ray: how far behind the depth buffer still counts (world units); 0 auto
  float max_distance SSR_DEFAULT(0.0f);   // D_max: the ray's length (world units); 0 auto
};

SSR_SHARED_END
