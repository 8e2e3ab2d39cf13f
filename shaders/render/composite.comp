// Composite: final = lit + specular(F0, n.v, roughness) * mix(env, reflection.rgb, reflection.a).
// Every technique reaches the image only through the reflection texture, so they are compared
// on exactly the same work.
#include "common/gbuffer.glsl"
#include "common/brdf.glsl"
#include "common/environment.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_LIT) uniform sampler2D lit_tex;
layout(binding = TEX_REFLECTION) uniform sampler2D reflection_tex;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_color;
layout(location = 0) uniform int u_blend;  // 0 standard, 1 Roberts: mix(lit, reflection, a)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  vec3 lit = texelFetch(lit_tex, p, 0).rgb;
  GSample g = gbuffer_fetch(p);
  if (is_background(g.depth)) {
    imageStore(out_color, p, vec4(lit, 1.0));
    return;
  }
  vec3 v = -normalize(g.pos_vs);
  vec3 r_ws = view_to_world_dir(reflect(-v, g.n_vs));
  vec3 env = environment_radiance(r_ws);
  vec4 refl = is_reflective(g) ? texelFetch(reflection_tex, p, 0) : vec4(0.0);
  vec3 weight = specular_weight(f0_of(g.albedo, g.metallic, g.reflectance), dot(g.n_vs, v), g.roughness);
  vec3 color = u_blend == 1 ? mix(lit, refl.rgb, clamp(refl.a, 0.0, 1.0))
                            : lit + weight * mix(env, refl.rgb, clamp(refl.a, 0.0, 1.0));
  imageStore(out_color, p, vec4(color, 1.0));
}
