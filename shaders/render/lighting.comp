// Lit pass: direct lights + ambient environment for every G-buffer pixel; background = sky.
// Background pixels also get their motion vector here (the G-buffer draws no geometry there).
#include "common/gbuffer.glsl"
#include "common/lighting.glsl"
#include "common/motion.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_lit;
layout(binding = TEX_EMISSION) uniform sampler2D g_emission;
layout(binding = IMG_MOTION, rg16f) uniform writeonly image2D out_motion;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  GSample g = gbuffer_fetch(p);
  vec3 view_dir_ws = view_to_world_dir(normalize(view_position(pixel_to_uv(p), 0.5)));
  if (is_background(g.depth)) {
    imageStore(out_lit, p, vec4(environment_radiance(view_dir_ws), 1.0));
    // The sky is at infinity: only the camera's rotation moves it (w = 0 drops translation).
    vec4 dir = vec4(view_dir_ws, 0.0);
    imageStore(out_motion, p, vec4(motion_pixels(frame.view_proj * dir, frame.prev_view_proj * dir), 0.0, 0.0));
    return;
  }
  Surface s;
  s.pos_ws = view_to_world_pos(g.pos_vs);
  s.n_ws = view_to_world_dir(g.n_vs);
  s.albedo = g.albedo;
  s.metallic = g.metallic;
  s.roughness = g.roughness;
  s.reflectance = g.reflectance;
  s.emission = texelFetch(g_emission, p, 0).rgb;
  imageStore(out_lit, p, vec4(shade_surface(s, -view_dir_ws), 1.0));
}
