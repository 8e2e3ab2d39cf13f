// The `linear-binary` trace (include-only); the pass (techniques/linear_binary.comp) provides
// `params` (LinearBinaryParams) and includes common/ssr_common.glsl first.

// Inside a surface the ray may hit, seen at p's projection? (false off screen or behind the
// camera plane, and on the origin's own reflector)
bool sample_inside(vec3 p, bool backfaces, uint own, out vec2 uv) {
  float depth;
  if (!project_to_uv(p, uv, depth) || !uv_on_screen(uv)) return false;
  return inside_surface(uv, p.z, params.thickness, backfaces) && hittable(ivec2(uv * frame.viewport.xy), own);
}

TraceResult linear_binary_trace(ivec2 pixel, vec3 origin, vec3 dir, float jitter) {
  float near_z = -frame.clip.x;
  bool backfaces = params.ray.backface_thickness != 0;
  int n = max(params.linear_steps, 1);
  float step = params.max_distance / float(n);
  vec3 prev = origin;
  // A hit needs an outside sample first: no hit on the origin surface. A ray from a planar
  // reflector cannot hit its own plane (hittable), so there the origin counts as outside and a
  // surface the first sample already entered (a wall rising from the floor) is hit.
  uint own = origin_reflector(pixel, origin);
  bool prev_inside = own == 0u;
  int i = 1;
  // The inner loop is the plain march; the rules for rays from a reflector run only at an
  // outside-to-inside step, after it, and resume the march. Same images as testing them in the
  // march (gallery, corridor, ripples, 8 tiles, hard-depth-range; one difference in principle:
  // an own-plane sample after one inside another surface no longer ends that surface, and none
  // of those scenes has one); the march stays as tight as without them: gallery 1080p 0.86 ->
  // 0.77 ms, corridor 0.43 -> 0.36 (H200; 0.58 / 0.35 without the rules, whose cost is the
  // driver's code generation: docs/RESULTS.md).
  for (;;) {
    bool found = false;  // (not derived from i after the loop: that measured 0.02 ms slower)
    vec2 uv;
    vec3 pos;
    for (; i <= n; ++i) {
      pos = origin + dir * (step * float(i));
      if (pos.z > near_z) return trace_miss(float(i));
      float depth;
      if (!project_to_uv(pos, uv, depth) || !uv_on_screen(uv)) return trace_miss(float(i));
      bool inside = inside_surface(uv, pos.z, params.thickness, backfaces);
      if (inside && !prev_inside) {
        found = true;
        break;
      }
      prev = pos;
      prev_inside = inside;
    }
    if (!found) return trace_miss(float(n));
    // The origin's own plane is not a surface to hit: the ray is outside there. The first sample
    // hits only a surface the ray crossed, behind the origin's depth: not one in front of the
    // origin that a thickness of many metres swallows (hard-depth-range's ball 1 cm from the
    // eye); the ray then stays inside it, as from any other origin.
    bool own_plane = own != 0u && !hittable(ivec2(uv * frame.viewport.xy), own);
    bool in_front = own != 0u && i == 1 && !(scene_view_z(uv) <= origin.z);
    if (own_plane || in_front) {
      prev = pos;
      prev_inside = !own_plane;
      ++i;
      continue;
    }
    // Bisection between the last outside sample (a) and the first inside one (b).
    vec3 a = prev, b = pos;
    vec2 b_uv = uv;
    for (int k = 0; k < params.binary_steps; ++k) {
      vec3 mid = 0.5 * (a + b);
      vec2 mid_uv;
      if (sample_inside(mid, backfaces, own, mid_uv)) {
        b = mid;
        b_uv = mid_uv;
      } else {
        a = mid;
      }
    }
    return TraceResult(true, pixel_centre_uv(b_uv), float(i + params.binary_steps), length(b - origin));
  }
}
