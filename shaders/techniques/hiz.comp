// `hiz` (Uludag, GPU Pro 5): hierarchical-Z trace over the max-depth pyramid (see
// src/techniques/hiz.cpp and common/hiz_trace.glsl).
#include "common/ssr_common.glsl"
#include "common/hiz_trace.glsl"
#include "shared/hiz.h"

layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { HizParams params; };

TraceResult trace_ray(ivec2 pixel, vec3 origin, vec3 dir, float jitter) {
  return hiz_trace(origin, dir, HizTrace(params.max_distance, params.max_iterations, params.start_level,
                                         params.max_level, params.thickness, params.ray.backface_thickness != 0,
                                         origin_reflector(pixel, origin)));
}

#include "common/ssr_main.glsl"

void main() { ssr_tracer_pass(); }
