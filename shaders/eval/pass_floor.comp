// The pass-floor microbenchmark as a compute pass (src/eval/pass_floor.h): one invocation a
// pixel, PF_LOCAL_X x PF_LOCAL_Y invocations a group. `pf_skip`: every invocation returns
// before any work (a uniform the compiler cannot fold), so the pass costs its launch alone.
#include "eval/pass_floor.glsl"

layout(local_size_x = PF_LOCAL_X, local_size_y = PF_LOCAL_Y) in;

layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D pf_dst;
layout(location = 0) uniform int pf_skip;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (pf_skip != 0 || any(greaterThanEqual(p, imageSize(pf_dst)))) return;
  imageStore(pf_dst, p, pass_floor_value(p));
}
