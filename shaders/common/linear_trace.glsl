// The `linear` trace (include-only); the pass (techniques/linear.comp) provides
// `params` (LinearParams) and includes common/ssr_common.glsl first.

TraceResult linear_trace(ivec2 pixel, vec3 origin, vec3 dir, float jitter) {
  float near_z = -frame.clip.x;
  int steps = min(params.max_steps, int(params.max_distance / params.step_size) + 1);
  bool backfaces = params.ray.backface_thickness != 0;
  vec3 prev = origin;
  // scene z - ray z at the previous sample (< 0: the ray was in front of the visible surface).
  // A hit needs the ray to cross from in front to behind: a ray that starts "behind" its own
  // surface because the depth buffer is quantised per pixel does not hit itself. A ray from a
  // planar reflector cannot hit its own plane (hittable): its origin counts as in front, so a
  // surface the first sample already entered (a wall rising from the floor) is hit, and a
  // sample seen on its own plane tells nothing (inside a wall's base, the floor in front of
  // the wall hides it: it must not count as behind, or the junction row misses the wall).
  uint own = origin_reflector(pixel, origin);
  float prev_gap = own == 0u ? 1.0 : 0.0;
  bool from_origin = true;  // `prev` is still the origin
  for (int i = 1; i <= steps; ++i) {
    vec3 pos = origin + dir * (params.step_size * float(i));
    if (pos.z > near_z) return trace_miss(float(i));  // crossed the near plane
    vec2 uv;
    float depth;
    if (!project_to_uv(pos, uv, depth) || !uv_on_screen(uv)) return trace_miss(float(i));
    if (!hittable(ivec2(uv * frame.viewport.xy), own)) continue;
    float gap = scene_view_z(uv) - pos.z;  // > 0: the sample is behind the visible surface
    // The first sample hits only a surface the ray crossed, behind the origin's depth (as in
    // linear_binary_trace.glsl).
    bool crossed = !from_origin || scene_view_z(uv) <= origin.z;
    if (prev_gap <= 0.0 && crossed && inside_surface(uv, pos.z, params.thickness, backfaces)) {
      vec3 hit = pos;
      if (params.depth_interp != 0 && !from_origin)
        hit = mix(prev, pos, clamp(prev_gap / (prev_gap - gap), 0.0, 1.0));
      vec2 hit_uv;
      if (!project_to_uv(hit, hit_uv, depth) || !uv_on_screen(hit_uv)) hit_uv = uv;
      return TraceResult(true, pixel_centre_uv(hit_uv), float(i), length(hit - origin));
    }
    prev = pos;
    prev_gap = gap;
    from_origin = false;
  }
  return trace_miss(float(steps));
}
