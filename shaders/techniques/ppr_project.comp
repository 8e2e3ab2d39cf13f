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

// The first reflectors, copied once per work group: every pixel reads every reflector.
#define SHARED_REFLECTORS 64
shared PprReflector group_reflectors[SHARED_REFLECTORS];
PprReflector reflector(int k) { return k < SHARED_REFLECTORS ? group_reflectors[k] : reflectors[k]; }

// How the mirror image moves on screen per source pixel (columns: source +x, +y), to first
// order from the source's tangent plane (its neighbours' eye rays); false where degenerate.
bool mirror_jacobian(GSample g, ivec2 p, vec2 dest, PprReflector r, out mat2 jacobian) {
  jacobian = mat2(1.0);
  for (int a = 0; a < 2; ++a) {
    vec3 ray = normalize(view_position(pixel_to_uv(p + (a == 0 ? ivec2(1, 0) : ivec2(0, 1))), 0.5));
    float denom = dot(ray, g.n_vs);
    if (abs(denom) < 1e-4) return false;
    vec2 moved;
    if (!mirror_to_pixel(ray * (dot(g.pos_vs, g.n_vs) / denom), r, moved)) return false;
    jacobian[a] = moved - dest;
  }
  return abs(determinant(jacobian)) >= 1e-6;
}

void main() {
  for (uint i = gl_LocalInvocationIndex; i < uint(min(params.reflector_count, SHARED_REFLECTORS)); i += 64u)
    group_reflectors[i] = reflectors[i];
  barrier();
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (any(greaterThanEqual(p, size))) return;
  GSample g = gbuffer_fetch(p);
  if (is_background(g.depth)) return;
  vec3 x = view_to_world_pos(g.pos_vs);
  vec3 eye = frame.camera_pos.xyz;
  // Every reflector: a projection that misses one must not stop the others (ARCHITECTURE §9).
  // Consecutive reflectors on one plane (a tiled floor) share the mirror image and where the
  // camera sees it: computed once per plane, then only each rectangle is tested.
  vec4 plane = vec4(0.0);
  bool seen = false;  // `plane` holds a computed plane
  vec3 hit = vec3(0.0);
  bool crosses = false;  // the mirror image is visible through the plane (at `hit`)
  for (int k = 0; k < params.reflector_count; ++k) {
    PprReflector r = reflector(k);
    if (!seen || r.plane != plane) {
      plane = r.plane;
      seen = true;
      vec3 n = r.plane.xyz;
      float dist = dot(n, x) + r.plane.w;
      vec3 mirrored = x - 2.0 * dist * n;
      // The camera ray towards the mirror image crosses the plane at t in (0, 1); dist > 0: in
      // front of the mirror.
      float e = dot(n, eye) + r.plane.w;  // > 0: the technique orients planes towards the camera
      float t = e / (e - dot(n, mirrored) - r.plane.w);
      crosses = dist > 0.0 && t > 0.0 && t < 1.0;
      hit = eye + t * (mirrored - eye);
    }
    if (!crosses || uint(k + 1) == g.reflector) continue;  // behind the mirror, or on it
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
    // Each destination pixel stores the offset from its centre back to the source point that
    // lands exactly there: source = this pixel + J^-1 (centre - dest). A mirror flips a screen
    // axis (a floor turns screen-up into screen-down), so the destination's fraction cannot be
    // added to the source as it is: that biased the source by up to a pixel along the flipped
    // axis (the dark line at the wall/floor junction). Where the mirror magnifies (a near
    // object's reflection), one source covers several destination pixels: it is splatted over
    // its footprint (at most 5x5), or the skipped pixels would keep a source from the wall
    // behind it (the stripes in the spheres' reflections).
    mat2 jacobian;
    bool exact = mirror_jacobian(g, p, dest, r, jacobian);
    mat2 to_source = exact ? inverse(jacobian) : mat2(0.0);
    // The footprint's half extent per axis is h; a neighbour n pixels away has its centre more
    // than n - 0.5 from `dest`, so it can lie inside only when n < h + 0.5.
    vec2 h = 0.5 * (abs(jacobian[0]) + abs(jacobian[1]));
    ivec2 reach = exact ? ivec2(min(max(ceil(h - 0.5), vec2(0.0)), vec2(2.0))) : ivec2(0);
    for (int dy = -reach.y; dy <= reach.y; ++dy)
      for (int dx = -reach.x; dx <= reach.x; ++dx) {
        ivec2 d = q + ivec2(dx, dy);
        if (any(lessThan(d, ivec2(0))) || any(greaterThanEqual(d, size))) continue;
        vec2 move = to_source * (vec2(d) + 0.5 - dest);
        // Only the destination pixels whose centre lies in this source pixel's footprint.
        if ((dx != 0 || dy != 0) && any(greaterThan(abs(move), vec2(0.5)))) continue;
        if ((dx != 0 || dy != 0) && texelFetch(g_material, d, 0).x != uint(k + 1)) continue;
        vec2 source = vec2(p) + 0.5 + clamp(move, vec2(-1.0), vec2(1.0));
        imageAtomicMin(intermediate, d, ppr_pack(source - (vec2(d) + 0.5), u_fraction_bits));
      }
    // The rest of this plane's reflectors would land on the same destination pixel, which shows
    // this one: skip them (a tiled floor tests half its tiles on average, not all).
    crosses = false;
  }
}
