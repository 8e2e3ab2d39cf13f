// PPR projection pass: every pixel is mirrored across each planar reflector; where the camera
// sees that mirror image through the reflector, the destination pixel keeps (atomic min) the
// packed offset back to this pixel: the closest such source wins (shared/ppr_packing.h).
#include "common/gbuffer.glsl"
#include "common/ppr_mirror.glsl"
#include "shared/ppr_packing.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { PprParams params; };
layout(std430, binding = SSBO_PPR_REFLECTORS) readonly buffer Reflectors { PprReflector reflectors[]; };
layout(binding = IMG_PPR_INTERMEDIATE, r32ui) uniform coherent uimage2D intermediate;
layout(location = 0) uniform uint u_fraction_bits;

// Every pixel reads the first reflector of each plane and the one it lands on. A single one
// comes from a uniform block (its fields become constant operands); several are copied once per
// work group into shared memory, sized for the most a scene may have (a 64-entry copy made the
// pass slower even with one reflector; the uniform block indexed by the loop ran 4x slower with
// 16: docs/RESULTS.md, Speed).
layout(std140, binding = UBO_PPR_REFLECTORS) uniform FirstReflector { PprReflector first_reflector; };
#define SHARED_REFLECTORS PPR_MAX_REFLECTORS
shared PprReflector group_reflectors[SHARED_REFLECTORS];
bool one_reflector() { return params.reflector_count == 1; }
PprReflector reflector(int k) {
  if (one_reflector()) return first_reflector;
  return k < SHARED_REFLECTORS ? group_reflectors[k] : reflectors[k];  // never past the copy's end
}

#include "common/ppr_project.glsl"

void main() {
  if (!one_reflector()) {  // uniform: every invocation reaches the barrier or none does
    for (uint i = gl_LocalInvocationIndex; i < uint(min(params.reflector_count, SHARED_REFLECTORS)); i += 64u)
      group_reflectors[i] = reflectors[i];
    barrier();
  }
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  GSample g = gbuffer_fetch(p);
  if (is_background(g.depth)) return;
  vec3 x = view_to_world_pos(g.pos_vs);
  // Every plane: a projection that misses one must not stop the others (ARCHITECTURE §9).
  // Consecutive reflectors on one plane (a tiled floor) share the mirror image, and only the
  // one the destination pixel shows can take it: that one is read off the G-buffer there
  // instead of testing every rectangle of the plane.
  for (int k = 0; k < params.reflector_count;) {
    PprReflector r = reflector(k);
    int end = max(int(r.center.w), k + 1);  // one past this plane's last reflector
    vec3 hit;
    if (ppr_mirror_crossing(x, r.plane, hit)) {  // else behind the mirror
      int m = k;
      vec2 dest;
      if (end - k > 1) m = ppr_destination(hit, dest) ? int(texelFetch(g_material, ivec2(dest), 0).x) - 1 : -1;
      if (m >= k && m < end && uint(m + 1) != g.reflector)  // not the reflector it lies on
        ppr_project_onto(p, g, m, m == k ? r : reflector(m), hit);
    }
    k = end;
  }
}
