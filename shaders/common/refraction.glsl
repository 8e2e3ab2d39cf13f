// The refraction ray of a pixel behind glass (2012 blog): the transparent surface in front of it
// refracts the view ray with refract() instead of reflect(), and the ray is traced against the
// opaque depth buffer, which holds what lies behind the glass. One ray, a single interface
// (thin-surface model). Shared by the tracers (common/ssr_main.glsl) and `stochastic`; include
// after common/ssr_common.glsl. The pass stores the hit's lit colour at IMG_REFRACTION.
layout(binding = TEX_GLASS_DEPTH) uniform sampler2D g_glass_depth;
layout(binding = TEX_GLASS_SURFACE) uniform sampler2D g_glass_surface;
layout(binding = IMG_REFRACTION, rgba16f) uniform writeonly image2D out_refraction;

// False where no transparent surface lies in front of pixel p; else the ray's view-space origin
// (on the glass) and unit direction.
bool refraction_ray(ivec2 p, out vec3 origin, out vec3 dir) {
  vec4 surface = texelFetch(g_glass_surface, p, 0);
  origin = vec3(0.0);
  dir = vec3(0.0);
  if (surface.w < 1.0) return false;
  origin = view_position(pixel_to_uv(p), texelFetch(g_glass_depth, p, 0).r);
  vec3 n = normalize(surface.xyz);
  vec3 d = normalize(origin);
  dir = refract(d, n, 1.0 / surface.w);
  if (dot(dir, dir) < 1e-6) dir = reflect(d, n);  // total internal reflection
  dir = normalize(dir);
  return true;
}
