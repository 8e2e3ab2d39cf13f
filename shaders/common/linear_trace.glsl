// The `linear` trace (include-only); the pass (techniques/linear.comp) provides
// `params` (LinearParams) and includes common/ssr_common.glsl first.

TraceResult linear_trace(ivec2 pixel, vec3 origin, vec3 dir, float jitter) {
  float near_z = -frame.clip.x;
  int steps = min(params.max_steps, int(params.max_distance / params.step_size) + 1);
  bool backfaces = params.ray.backface_thickness != 0;
  vec3 prev = origin;
  // scene z - ray z at the previous sample (< 0: the ray was in front of the visible surface).
  // A hit needs the ray to cross from in front to behind: a ray that starts "behind" its own
  // surface because the depth buffer is quantised per pixel does not hit itself.
  float prev_gap = 1.0;
  uint own = origin_reflector(pixel, origin);
  for (int i = 1; i <= steps; ++i) {
    vec3 pos = origin + dir * (params.step_size * float(i));
    if (pos.z > near_z) return trace_miss(float(i));  // crossed the near plane
    vec2 uv;
    float depth;
    if (!project_to_uv(pos, uv, depth) || !uv_on_screen(uv)) return trace_miss(float(i));
    float gap = scene_view_z(uv) - pos.z;  // > 0: the sample is behind the visible surface
    if (prev_gap <= 0.0 && inside_surface(uv, pos.z, params.thickness, backfaces) &&
        hittable(ivec2(uv * frame.viewport.xy), own)) {
      vec3 hit = pos;
      if (params.depth_interp != 0) hit = mix(prev, pos, clamp(prev_gap / (prev_gap - gap), 0.0, 1.0));
      vec2 hit_uv;
      if (!project_to_uv(hit, hit_uv, depth) || !uv_on_screen(hit_uv)) hit_uv = uv;
      return TraceResult(true, hit_uv, float(i), length(hit - origin));
    }
    prev = pos;
    prev_gap = gap;
  }
  return trace_miss(float(steps));
}
