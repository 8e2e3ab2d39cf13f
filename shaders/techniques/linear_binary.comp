// `linear-binary` (Roberts): linear march, then bisection (see src/techniques/linear_binary.cpp).
#include "common/ssr_common.glsl"
#include "shared/linear_binary.h"

layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { LinearBinaryParams params; };

#include "common/linear_binary_trace.glsl"

TraceResult trace_ray(ivec2 pixel, vec3 origin, vec3 dir, float jitter) { return linear_binary_trace(pixel, origin, dir, jitter); }

#include "common/ssr_main.glsl"

void main() { ssr_tracer_pass(); }
