// The pass-floor microbenchmark as a fragment pass (src/eval/pass_floor.h): the same pixel as
// pass_floor.comp, written to a colour attachment. `pf_skip`: every fragment is discarded.
layout(location = 0) uniform int pf_skip;
layout(location = 0) out vec4 pf_out;

#include "eval/pass_floor.glsl"

void main() {
  if (pf_skip != 0) discard;
  pf_out = pass_floor_value(ivec2(gl_FragCoord.xy));
}
