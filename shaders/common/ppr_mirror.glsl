// PPR: where a point's mirror image across a planar reflector lands on screen (include-only;
// the projection and resolve passes share it).
#include "common/frame.glsl"
#include "shared/ppr.h"

// The continuous pixel position of the mirror image (across r) of view-space point p_vs;
// false where it is at or behind the camera plane.
bool mirror_to_pixel(vec3 p_vs, PprReflector r, out vec2 px) {
  vec3 x = view_to_world_pos(p_vs);
  vec3 m = x - 2.0 * (dot(r.plane.xyz, x) + r.plane.w) * r.plane.xyz;
  vec2 uv;
  float depth;
  px = vec2(0.0);
  if (!project_to_uv((frame.view * vec4(m, 1.0)).xyz, uv, depth)) return false;
  px = uv * frame.viewport.xy;
  return true;
}
