// Parameters of `linear`, the brute-force view-space march (Kim 2018, section 2.3.1):
// the same struct is the C++ Params (with defaults) and the GLSL uniform block.
#pragma once
#include "shared/ray_options.h"

SSR_SHARED_BEGIN

struct LinearParams {
  RayOptions ray;                         // shared tracer options (src/techniques/ray_options.h)
  int max_steps SSR_DEFAULT(1024);        // march iterations (steps)
  float step_size SSR_DEFAULT(0.0f);      // distance between samples along the ray (world units); 0 auto
  float thickness SSR_DEFAULT(0.15f);     // how far behind the depth buffer still counts as a hit (world units)
  float max_distance SSR_DEFAULT(0.0f);   // longest reflection ray (world units); 0 auto
  int depth_interp SSR_DEFAULT(1);        // 1: refine the hit by linear interpolation of depths [Val14]
  int pad0, pad1, pad2;
};

SSR_SHARED_END
