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
  for (int i = 1; i <= n; ++i) {
    vec3 pos = origin + dir * (step * float(i));
    if (pos.z > near_z) return trace_miss(float(i));
    vec2 uv;
    float depth;
    if (!project_to_uv(pos, uv, depth) || !uv_on_screen(uv)) return trace_miss(float(i));
    // Not sample_inside: uv is at hand. The material is fetched only for an inside sample of a
    // ray from a reflector, in a branch of its own.
    bool inside = inside_surface(uv, pos.z, params.thickness, backfaces);
    if (inside && own != 0u) inside = hittable(ivec2(uv * frame.viewport.xy), own);
    // The first sample hits only a surface the ray crossed, behind the origin's depth: not one
    // in front of the origin that a thickness of many metres swallows (hard-depth-range's ball
    // 1 cm from the eye); the ray then stays inside it, as from any other origin.
    if (inside && !prev_inside && i == 1 && !(scene_view_z(uv) <= origin.z)) {
      prev = pos;
      prev_inside = true;
      continue;
    }
    if (inside && !prev_inside) {
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
    prev = pos;
    prev_inside = inside;
  }
  return trace_miss(float(n));
}
