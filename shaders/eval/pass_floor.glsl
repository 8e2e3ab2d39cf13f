// The pass-floor microbenchmark's pixel (src/eval/pass_floor.h): one of its kinds, chosen by a
// define, the same arithmetic in the compute and the fragment form. PF_TAPS_RADIUS r: a
// (2r+1)^2 box of texel fetches (clamped at the edges), weighted so no fetch can be dropped.
#include "shared/bindings.h"

// The source, bound where a denoiser stage reads its input.
layout(binding = TEX_STAGE_IN) uniform sampler2D pf_src;

vec4 pass_floor_value(ivec2 p) {
#if defined(PF_STORE)
  return vec4(0.25, 0.5, 0.75, 1.0);
#elif defined(PF_COPY)
  return texelFetch(pf_src, p, 0);
#else
  vec4 sum = vec4(0.0);
  ivec2 last = textureSize(pf_src, 0) - 1;
  for (int y = -PF_TAPS_RADIUS; y <= PF_TAPS_RADIUS; ++y)
    for (int x = -PF_TAPS_RADIUS; x <= PF_TAPS_RADIUS; ++x)
      sum += texelFetch(pf_src, clamp(p + ivec2(x, y), ivec2(0), last), 0) * (1.0 + 0.125 * float(x + 2 * y));
  return sum / float((2 * PF_TAPS_RADIUS + 1) * (2 * PF_TAPS_RADIUS + 1));
#endif
}
