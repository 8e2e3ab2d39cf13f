// PPR projection pass: every pixel is mirrored across each planar reflector; where the camera
// sees that mirror image through the reflector, the destination pixel keeps (atomic min) the
// packed offset back to this pixel: the closest such source wins (shared/ppr_packing.h).
#include "common/gbuffer.glsl"
#include "shared/ppr.h"
#include "shared/ppr_packing.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { PprParams params; };
layout(std430, binding = SSBO_PPR_REFLECTORS) readonly buffer Reflectors { PprReflector reflectors[]; };
layout(binding = IMG_PPR_INTERMEDIATE, r32ui) uniform coherent uimage2D intermediate;
layout(location = 0) uniform uint u_fraction_bits;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (any(greaterThanEqual(p, size))) return;
  GSample g = gbuffer_fetch(p);
  if (is_background(g.depth)) return;
  vec3 x = view_to_world_pos(g.pos_vs);
  vec3 eye = frame.camera_pos.xyz;
  // Every reflector: a projection that misses one must not stop the others (DESIGN §10).
  for (int k = 0; k < params.reflector_count; ++k) {
    PprReflector r = reflectors[k];
    vec3 n = r.plane.xyz;
    float dist = dot(n, x) + r.plane.w;
    if (dist <= 0.0 || uint(k + 1) == g.reflector) continue;  // behind the mirror, or on it
    vec3 mirrored = x - 2.0 * dist * n;
    // The camera ray towards the mirror image crosses the plane at t in (0, 1).
    float e = dot(n, eye) + r.plane.w;  // > 0: the technique orients planes towards the camera
    float t = e / (e - dot(n, mirrored) - r.plane.w);
    if (!(t > 0.0 && t < 1.0)) continue;
    vec3 hit = eye + t * (mirrored - eye);
    vec3 local = hit - r.center.xyz;
    if (abs(dot(local, r.tangent.xyz)) > r.tangent.w || abs(dot(local, r.bitangent.xyz)) > r.bitangent.w)
      continue;  // outside the rectangle
    vec2 uv;
    float depth;
    if (!project_to_uv((frame.view * vec4(hit, 1.0)).xyz, uv, depth) || !uv_on_screen(uv)) continue;
    vec2 dest = uv * frame.viewport.xy;  // continuous pixel coordinates
    ivec2 q = ivec2(dest);
    // The destination must show this reflector (not an occluder, not another reflector).
    if (texelFetch(g_material, q, 0).x != uint(k + 1)) continue;
    vec2 offset = (vec2(p) + 0.5) - dest;  // from the destination back to this source pixel
    imageAtomicMin(intermediate, q, ppr_pack(offset, u_fraction_bits));
  }
}
