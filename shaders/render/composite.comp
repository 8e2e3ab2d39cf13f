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
layout(binding = TEX_GLASS_DEPTH) uniform sampler2D glass_depth;
layout(binding = TEX_GLASS_SURFACE) uniform sampler2D glass_surface;
layout(binding = TEX_GLASS_TINT) uniform sampler2D glass_tint;
layout(binding = TEX_REFRACTION) uniform sampler2D refraction_tex;

// A transparent surface over `behind`: tinted refraction (where the technique found one, else
// the unbent background) plus the environment's Fresnel reflection.
vec3 over_glass(ivec2 p, vec4 surface) {
  vec3 pos = view_position(pixel_to_uv(p), texelFetch(glass_depth, p, 0).r);
  vec3 n = normalize(surface.xyz);
  vec3 v = -normalize(pos);
  float f0 = pow((surface.w - 1.0) / (surface.w + 1.0), 2.0);
  float f = fresnel_schlick(vec3(f0), abs(dot(n, v))).r;
  vec4 refr = texelFetch(refraction_tex, p, 0);
  vec3 through = mix(texelFetch(lit_tex, p, 0).rgb, refr.rgb, clamp(refr.a, 0.0, 1.0));
  vec3 env = environment_radiance(view_to_world_dir(reflect(-v, n)));
  return (1.0 - f) * texelFetch(glass_tint, p, 0).rgb * through + f * env;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  vec3 color = texelFetch(lit_tex, p, 0).rgb;
  GSample g = gbuffer_fetch(p);
  if (!is_background(g.depth)) {
    vec3 v = -normalize(g.pos_vs);
    vec3 r_ws = view_to_world_dir(reflect(-v, g.n_vs));
    vec3 env = environment_radiance(r_ws);
    vec4 refl = is_reflective(g) ? texelFetch(reflection_tex, p, 0) : vec4(0.0);
    vec3 weight = specular_weight(f0_of(g.albedo, g.metallic, g.reflectance), dot(g.n_vs, v), g.roughness);
    color = u_blend == 1 ? mix(color, refl.rgb, clamp(refl.a, 0.0, 1.0))
                         : color + weight * mix(env, refl.rgb, clamp(refl.a, 0.0, 1.0));
  }
  vec4 glass = texelFetch(glass_surface, p, 0);
  if (glass.w >= 1.0) color = over_glass(p, glass);
  imageStore(out_color, p, vec4(color, 1.0));
}
