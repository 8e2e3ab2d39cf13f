// The floor pass (ARCHITECTURE §6): reads every input a screen-space technique reads at its own pixel
// (depth, normal + roughness, material, lit colour) and writes the reflection once. Its time is
// what the memory traffic alone costs; technique / floor says how far a pass is from that limit.
#include "common/gbuffer.glsl"
#include "common/screen_rows.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_LIT) uniform sampler2D lit_tex;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_reflection;

void floor_pixel(ivec2 p) {
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  GSample g = gbuffer_fetch(p);
  vec3 lit = texelFetch(lit_tex, p, 0).rgb;
  // Every read feeds the output, so no compiler can drop one.
  float keep = (g.depth + g.roughness + float(g.flags)) * 1e-30;
  imageStore(out_reflection, p, vec4(lit + g.n_vs * keep, is_reflective(g) ? 0.0 : keep));
}

void main() {
  for (int r = 0; r < SSR_ROWS; ++r) floor_pixel(screen_pixel(r));
}
