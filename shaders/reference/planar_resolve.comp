// `planar` resolve: pixels of one planar reflector take the colour their reflected ray sees in the
// mirrored camera's lit image (rendered with the geometry behind the mirror clipped away).
#include "common/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_PLANAR_MIRROR_LIT) uniform sampler2D mirror_lit;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_reflection;
layout(location = 0) uniform mat4 u_mirror_view_proj;
layout(location = 1) uniform uint u_reflector;  // 1-based id in the G-buffer

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  GSample g = gbuffer_fetch(p);
  if (is_background(g.depth) || g.reflector != u_reflector) return;
  vec4 c = u_mirror_view_proj * vec4(view_to_world_pos(g.pos_vs), 1.0);
  if (c.w <= 1e-6) { imageStore(out_reflection, p, vec4(0.0)); return; }
  vec2 uv = c.xy / c.w * 0.5 + 0.5;
  // The mirrored camera's pixel grid is this one's, flipped: nearest texel = the same ray.
  ivec2 q = clamp(ivec2(floor(uv * frame.viewport.xy)), ivec2(0), ivec2(frame.viewport.xy) - 1);
  imageStore(out_reflection, p, vec4(texelFetch(mirror_lit, q, 0).rgb, 1.0));
}
