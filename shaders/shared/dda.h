// Parameters of `dda` (McGuire & Mara 2014): a perspective-correct march over the screen, one
// pixel (times `stride`) along the ray's major axis per step, with bisection inside the last
// stride. The same struct is the C++ Params (with defaults) and the GLSL uniform block.
#pragma once
#include "shared/ray_options.h"

SSR_SHARED_BEGIN

struct DdaParams {
  RayOptions ray;                         // shared tracer options (src/techniques/ray_options.h)
  int max_steps SSR_DEFAULT(0);           // march iterations before giving up (steps); 0 auto
  float stride SSR_DEFAULT(1.0f);         // pixels along the major axis per step (pixels)
  float thickness SSR_DEFAULT(0.15f);     // how far behind the depth buffer still counts as a hit (world units)
  float max_distance SSR_DEFAULT(0.0f);   // longest reflection ray (world units); 0 auto
  int refine_steps SSR_DEFAULT(4);        // bisection steps inside the last stride (stride > 1 only)
  int jitter SSR_DEFAULT(0);              // 1: shift each pixel's step grid by a random fraction of the stride
  int pad0, pad1;                         // std140 blocks are whole vec4s: keep sizeof a multiple of 16
};

SSR_SHARED_END
