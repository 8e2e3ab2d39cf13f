// `linear`: brute-force view-space march (see src/techniques/linear.cpp).
#include "common/ssr_common.glsl"
#include "shared/linear.h"

layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { LinearParams params; };

#include "common/linear_trace.glsl"

TraceResult trace_ray(ivec2 pixel, vec3 origin, vec3 dir, float jitter) { return linear_trace(pixel, origin, dir, jitter); }

#include "common/ssr_main.glsl"

void main() { ssr_tracer_pass(); }
