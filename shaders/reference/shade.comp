// Ground truth shading: for each reflective pixel, average its ray samples. A hit is shaded with
// shade_surface (the lit pass's code) seen from the ray; an escaped ray sees the environment.
// Also the screen-space ideal: the lit colour at the hit's pixel where the hit is traceable, the
// environment where it is not (what a perfect screen-space tracer would return).
#include "common/lighting.glsl"
#include "shared/reference.h"

layout(local_size_x = 64) in;
layout(std430, binding = SSBO_REF_SAMPLES) readonly buffer Samples { ReferenceSample samples[]; };
layout(std430, binding = SSBO_REF_PIXELS) readonly buffer Pixels { ReferencePixel pixels[]; };
layout(std430, binding = SSBO_REF_MATERIALS) readonly buffer Materials { ReferenceMaterial materials[]; };
layout(binding = TEX_REF_MAP0) uniform sampler2D albedo_maps[REFERENCE_MAX_TEXTURES];
layout(binding = TEX_LIT) uniform sampler2D lit_tex;
layout(binding = IMG_REF_TRUTH, rgba16f) uniform writeonly image2D out_truth;
layout(binding = IMG_REF_IDEAL, rgba16f) uniform writeonly image2D out_ideal;
layout(location = 0) uniform int u_pixel_count;
layout(location = 1) uniform int u_bounces;  // segments a sample
// 1 for refraction: where the hit is not traceable the ideal has confidence 0 (a tracer that
// finds nothing leaves the unbent background), instead of the environment.
layout(location = 2) uniform int u_ideal_traceable_only;

// Sampler arrays may only be indexed by constant expressions in GLSL 4.50: one branch per slot.
vec3 texture_map(int slot, vec2 uv, float lod_uv) {
  vec3 c = vec3(1.0);
#define SSR_MAP_CASE(i) \
  if (slot == i) c = textureLod(albedo_maps[i], uv, lod_uv + log2(float(textureSize(albedo_maps[i], 0).x))).rgb;
  SSR_MAP_CASE(0) SSR_MAP_CASE(1) SSR_MAP_CASE(2) SSR_MAP_CASE(3)
  SSR_MAP_CASE(4) SSR_MAP_CASE(5) SSR_MAP_CASE(6) SSR_MAP_CASE(7)
#if REFERENCE_MAX_TEXTURES != 8
#error "one SSR_MAP_CASE per slot: texture_map() must list REFERENCE_MAX_TEXTURES cases"
#endif
  return c;
}

Surface surface_of(ReferenceSample s) {
  ReferenceMaterial mat = materials[int(s.position.w)];
  Surface surf;
  surf.pos_ws = s.position.xyz;
  surf.n_ws = s.normal.xyz;
  surf.albedo = mat.albedo_metallic.rgb;
  int slot = int(mat.params.z);
  if (slot >= 0) surf.albedo *= texture_map(slot, s.hit_pixel.zw, s.normal.w);
  // The normal map, as the G-buffer pass applies it (so that the truth of a normal-mapped
  // surface seen in a mirror is shaded like the surface seen directly).
  int normal_slot = int(mat.params.w);
  if (normal_slot >= 0) {
    vec3 n = surf.n_ws;
    vec3 t = s.tangent.xyz - n * dot(n, s.tangent.xyz);
    float tl = length(t);
    if (tl > 1e-8) {
      t /= tl;
      vec3 b = cross(n, t) * (s.tangent.w < 0.0 ? -1.0 : 1.0);
      vec3 m = texture_map(normal_slot, s.hit_pixel.zw, s.normal.w) * 2.0 - 1.0;
      m.xy *= mat.emission.w;
      vec3 pn = t * m.x + b * m.y + n * max(m.z, 0.0);
      float pl = length(pn);
      if (pl > 1e-6) surf.n_ws = pn / pl;
    }
  }
  surf.metallic = mat.albedo_metallic.a;
  surf.roughness = mat.params.x;
  surf.reflectance = mat.params.y;
  surf.emission = mat.emission.rgb;
  return surf;
}

// Radiance arriving along one sample's first segment: its segments from the last back, each
// hit shaded as the lit pass would, plus the composite's specular weight times what the next
// segment brought (the multi-bounce truth; one segment is the single-bounce truth).
vec3 sample_radiance(int first) {
  vec3 radiance = vec3(0.0);
  for (int b = u_bounces - 1; b >= 0; --b) {
    ReferenceSample s = samples[first + b];
    int m = int(s.position.w);
    vec3 dir = s.direction.xyz;
    if (m == -2) {
      radiance = vec3(0.0);
    } else if (m == -1) {
      radiance = environment_radiance(dir);
    } else {
      Surface surf = surface_of(s);
      vec3 next = radiance;
      radiance = shade_surface(surf, -dir);
      if (b + 1 < u_bounces && int(samples[first + b + 1].position.w) != -2)
        radiance += specular_weight(f0_of(surf.albedo, surf.metallic, surf.reflectance),
                                    dot(surf.n_ws, -dir), surf.roughness) * next;
    }
  }
  return radiance;
}

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= u_pixel_count) return;
  ivec4 px = pixels[i].data;
  vec3 truth = vec3(0.0), ideal = vec3(0.0);
  for (int k = 0; k < px.w; ++k) {
    int first = (px.z + k) * u_bounces;
    ReferenceSample s = samples[first];
    truth += sample_radiance(first);
    ideal += s.direction.w > 0.5 ? texelFetch(lit_tex, ivec2(s.hit_pixel.xy), 0).rgb
                                 : environment_radiance(s.direction.xyz);
  }
  float inv = px.w > 0 ? 1.0 / float(px.w) : 0.0;
  float a = px.w > 0 ? 1.0 : 0.0;
  imageStore(out_truth, px.xy, vec4(truth * inv, a));
  if (u_ideal_traceable_only == 1) {
    bool found = samples[px.z * u_bounces].direction.w > 0.5;
    imageStore(out_ideal, px.xy, found ? vec4(ideal * inv, 1.0) : vec4(0.0));
  } else {
    imageStore(out_ideal, px.xy, vec4(ideal * inv, a));
  }
}
