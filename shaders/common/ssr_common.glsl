// What every screen-space tracer needs besides its own march: the depth hit test (constant
// thickness or back-face depth) and a per-pixel jitter. Include before defining trace_ray().
#include "common/brdf.glsl"
#include "common/gbuffer.glsl"
#include "shared/ray_options.h"
#include "shared/sampling.h"

layout(binding = TEX_BACK_DEPTH) uniform sampler2D g_back_depth;

// The result of one ray's march.
struct TraceResult {
  bool hit;
  vec2 uv;         // where the lit colour is fetched
  float steps;     // iterations spent (for the step heat map)
  float distance;  // view-space length from the origin to the hit
};

TraceResult trace_miss(float steps) { return TraceResult(false, vec2(0.0), steps, 0.0); }

// Back-face depth at a uv as view-space z (-1e30 where no back face was drawn).
float back_view_z(vec2 uv) {
  ivec2 p = clamp(ivec2(uv * frame.viewport.xy), ivec2(0), ivec2(frame.viewport.xy) - 1);
  float d = texelFetch(g_back_depth, p, 0).r;
  return is_background(d) ? -1e30 : view_z_from_depth(d);
}

// Is a ray point at view-space z `ray_z`, projected at `uv`, inside the surface seen there?
// Behind the visible (front) surface, and either within `thickness` of it or, with back-face
// thickness, in front of the back face behind it.
bool inside_surface(vec2 uv, float ray_z, float thickness, bool use_backfaces) {
  float front = scene_view_z(uv);
  if (ray_z > front) return false;  // in front of the visible surface
  // A surface seen from behind (open geometry) is its own back face: keep a sliver of the
  // constant thickness there, or it could never be hit.
  if (use_backfaces) return ray_z >= min(back_view_z(uv), front - thickness * 0.01);
  return front - ray_z < thickness;
}

// The planar reflector a ray from `pixel` starts on (0: none). A plane cannot reflect itself, so
// the tracers reject hits on it: with a normal map, rays skimming the plane otherwise "hit" it
// where the depth buffer's steps pass the ray (the false arcs on ripples). A ray that does not
// start on the depth buffer's surface (refraction: on glass in front of it) starts on no reflector.
uint origin_reflector(ivec2 pixel, vec3 origin) {
  float z = scene_view_z(pixel_to_uv(pixel));
  return abs(origin.z - z) <= 1e-4 * abs(z) ? texelFetch(g_material, pixel, 0).x : 0u;
}

// Whether the surface at pixel c may be a ray's hit: not the reflector it started on.
bool hittable(ivec2 c, uint own_reflector) {
  return own_reflector == 0u || texelFetch(g_material, c, 0).x != own_reflector;
}

// The centre of the pixel holding uv. A hit reads the lit image there, as the screen-space ideal
// does: a bilinear fetch between pixels mixes in what lies beside the hit (at a wall's base, the
// black mirror floor: a dark line along the junction).
vec2 pixel_centre_uv(vec2 uv) {
  return (min(floor(uv * frame.viewport.xy), frame.viewport.xy - 1.0) + 0.5) * frame.viewport.zw;
}

// A per-pixel, per-sample offset in [0, 1) (jittered starts hide banding from fixed strides).
float pixel_jitter(ivec2 p, int sample_index, int seed) {
  return uint_to_unit(pcg_hash(uint(p.x) * 1973u ^ uint(p.y) * 9277u ^ uint(sample_index) * 26699u ^ uint(seed)));
}
