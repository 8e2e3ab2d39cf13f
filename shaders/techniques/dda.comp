// `dda` (McGuire & Mara 2014): perspective-correct per-pixel screen-space march
// (see src/techniques/dda.cpp).
#include "common/ssr_common.glsl"
#include "shared/dda.h"

layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { DdaParams params; };

#include "common/dda_trace.glsl"

TraceResult trace_ray(ivec2 pixel, vec3 origin, vec3 dir, float jitter) { return dda_trace(pixel, origin, dir, jitter); }

#include "common/ssr_main.glsl"

void main() { ssr_tracer_pass(); }
