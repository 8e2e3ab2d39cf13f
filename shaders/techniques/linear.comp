// `linear`: brute-force view-space march (see src/techniques/linear.cpp).
#include "common/gbuffer.glsl"
#include "shared/linear.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { LinearParams params; };
layout(binding = TEX_LIT) uniform sampler2D lit_tex;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_reflection;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  GSample g = gbuffer_fetch(p);
  if (!is_reflective(g)) { imageStore(out_reflection, p, vec4(0.0)); return; }

  vec3 origin = g.pos_vs;
  vec3 dir = reflect(normalize(origin), g.n_vs);
  float near_z = -frame.clip.x;
  int steps = min(params.max_steps, int(params.max_distance / params.step_size) + 1);

  vec3 prev = origin;
  // scene z - ray z at the previous sample (< 0: the ray was in front of the visible surface).
  // A hit needs the ray to cross from in front to behind: a ray that starts "behind" its own
  // surface because the depth buffer is quantised per pixel does not hit itself.
  float prev_gap = 1.0;
  vec4 result = vec4(0.0);
  for (int i = 1; i <= steps; ++i) {
    vec3 pos = origin + dir * (params.step_size * float(i));
    if (pos.z > near_z) break;  // crossed the near plane: nothing on screen there
    vec2 uv;
    float depth;
    if (!project_to_uv(pos, uv, depth) || !uv_on_screen(uv)) break;
    float gap = scene_view_z(uv) - pos.z;  // > 0: the sample is behind the visible surface
    if (gap > 0.0 && gap < params.thickness && prev_gap <= 0.0) {
      vec3 hit = pos;
      if (params.depth_interp != 0) {
        float t = prev_gap / (prev_gap - gap);  // where (scene z - ray z) crosses 0
        hit = mix(prev, pos, clamp(t, 0.0, 1.0));
      }
      vec2 hit_uv;
      float hit_depth;
      if (!project_to_uv(hit, hit_uv, hit_depth) || !uv_on_screen(hit_uv)) hit_uv = uv;
      result = vec4(textureLod(lit_tex, hit_uv, 0.0).rgb, 1.0);
      break;
    }
    prev = pos;
    prev_gap = gap;
  }
  imageStore(out_reflection, p, result);
}
