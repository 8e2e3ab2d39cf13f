// The pass every screen-space tracer shares (ssr_tracer_pass). Before including it, a tracer declares
//   layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { XParams params; };
// (with `RayOptions ray` as a member of XParams) and defines
//   TraceResult trace_ray(ivec2 pixel, vec3 origin_vs, vec3 dir_vs, float jitter);
// This file samples the reflection rays (GGX VNDF for rough pixels), averages the hits, applies
// the shared fades and writes the reflection and debug images. Compiled with
// SSR_DENOISE_OUTPUT (the tracer's `denoise` option) it writes the denoiser's inputs instead
// (techniques/denoiser.h): premultiplied radiance at IMG_OUT and the first sample's ray (hit
// vector, pdf) at IMG_OUT2, with samples that change every frame.
//
// Compiled with SSR_PLAIN_RAY (the tracer's options are the plain ones, shared/ray_options.h)
// it sees those options as constants; tests define SSR_TEST_GENERAL_RAY to compare the two.
//
// Compiled with SSR_RAY_LIST (the tracers' `compact` option) it runs one lane per pixel of the
// classification's ray list (render/classification.h), which already wrote the outputs of every
// pixel without work; otherwise one lane per screen pixel.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_LIT) uniform sampler2D lit_tex;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_reflection;
layout(binding = IMG_OUT2, rgba16f) uniform writeonly image2D out_debug;  // steps, hit share, distance
#include "common/refraction.glsl"
#include "common/telemetry.glsl"
// Outside the #ifdef: an include expands once, before the preprocessor runs.
#include "shared/classification.h"
#ifdef SSR_RAY_LIST
layout(std430, binding = SSBO_RAYS) readonly buffer Rays {
  RayListHeader ray_header;
  uint rays[];
};
#endif
#ifdef SSR_DENOISE_OUTPUT
#include "common/denoise_common.glsl"
#endif

// The refraction of the pixel behind glass (common/refraction.glsl), zero elsewhere. Returns
// the ray's iterations (0 without a transparent surface).
float trace_refraction(ivec2 p) {
  vec3 origin, dir;
  if (!refraction_ray(p, origin, dir)) { imageStore(out_refraction, p, vec4(0.0)); return 0.0; }
  TraceResult t = trace_ray(p, origin, dir, pixel_jitter(p, 0, params.ray.seed));
  imageStore(out_refraction, p, t.hit ? vec4(textureLod(lit_tex, t.uv, 0.0).rgb, 1.0) : vec4(0.0));
  telemetry_ray(t.steps);
  return t.steps;
}

// The debug image at p: with SSR_DENOISE_OUTPUT it is the denoiser's input (always written),
// else the debug views' channels, written by the variant compiled with SSR_DEBUG_IMAGE only (a
// branch on a uniform kept what feeds them alive: linear-binary 0.77 ms against 0.61 without).
void store_debug(ivec2 p, vec4 v) {
#if defined(SSR_DENOISE_OUTPUT) || defined(SSR_DEBUG_IMAGE)
  imageStore(out_debug, p, v);
#endif
}

// The reflection of pixel p; returns the iterations of all its rays.
float reflect_pixel(ivec2 p) {
  GSample g = gbuffer_fetch(p);
  if (!is_reflective(g)) {
    imageStore(out_reflection, p, vec4(0.0));
    store_debug(p, vec4(0.0));
    return 0.0;
  }
#if defined(SSR_PLAIN_RAY) && !defined(SSR_TEST_GENERAL_RAY)
  RayOptions o = plain_ray(params.ray);  // constants: shared/ray_options.h says why
#else
  RayOptions o = params.ray;
#endif
  float rough = o.roughness >= 0.0 ? o.roughness : g.roughness;
  vec3 v = -normalize(g.pos_vs);
  bool mirror = rough < SSR_MIRROR_ROUGHNESS;
  int n = mirror ? 1 : clamp(o.samples, 1, 16);
  vec3 f0 = f0_of(g.albedo, g.metallic, g.reflectance);

  vec3 radiance = vec3(0.0);
  float weight = 0.0, steps = 0.0, hits = 0.0, dist = 0.0;
#ifdef SSR_DENOISE_OUTPUT
  uint seed = uint(o.seed) ^ pcg_hash(uint(frame.counts.z));  // new samples every frame
  vec4 first_ray = vec4(0.0);
#else
  uint seed = uint(o.seed);
#endif
  for (int s = 0; s < n; ++s) {
    vec3 dir = reflect(-v, g.n_vs);
    if (!mirror) {
      vec3 l = sample_reflection(g.n_vs, v, rough, sample_xi(uint(p.x), uint(p.y), uint(s), seed));
      if (dot(l, g.n_vs) > 0.0) dir = l;  // under the horizon: fall back to the mirror ray
    }
    TraceResult t = trace_ray(p, g.pos_vs, normalize(dir), pixel_jitter(p, s, int(seed)));
#ifdef SSR_DENOISE_OUTPUT
    if (s == 0)
      first_ray = vec4(normalize(dir) * (t.hit ? t.distance : RAY_MISS_LENGTH),
                       reflection_pdf(g.n_vs, v, normalize(dir), rough));
#endif
    steps += t.steps;
    telemetry_ray(t.steps);
    if (!t.hit) continue;
    float w = 1.0;
    if (o.edge_fade != 0) w *= edge_fade(t.uv);
    if (o.falloff_distance > 0.0)
      w *= 1.0 - smoothstep(0.5 * o.falloff_distance, o.falloff_distance, t.distance);
    if (o.blend == 1) {
      // Roberts: beta = metallic^3 * -ray.z (no reflections towards the camera) * fades.
      w *= g.metallic * g.metallic * g.metallic * clamp(-dir.z, 0.0, 1.0);
      if (o.fresnel != 0) {
        vec3 fr = fresnel_schlick(f0, dot(g.n_vs, v));
        w *= max(fr.r, max(fr.g, fr.b));
      }
    }
    radiance += textureLod(lit_tex, t.uv, 0.0).rgb * w;
    weight += w;
    hits += 1.0;
    dist += t.distance;
  }
  // rgb: the weighted mean of what the hits saw; a: the share of the lobe they cover.
  vec3 rgb = weight > 0.0 ? radiance / weight : vec3(0.0);
  float confidence = clamp(weight / float(n), 0.0, 1.0);
#ifdef SSR_DENOISE_OUTPUT
  imageStore(out_reflection, p, vec4(rgb * confidence, confidence));
  store_debug(p, first_ray);
#else
  imageStore(out_reflection, p, vec4(rgb, confidence));
  store_debug(p, vec4(steps / float(n), hits / float(n), hits > 0.0 ? dist / hits : 0.0, 1.0));
#endif
  return steps;
}

// The tracer pass: each tracer .comp defines trace_ray(), includes this, and its main() calls it.
void ssr_tracer_pass() {
#ifdef SSR_RAY_LIST
  uint i = gl_WorkGroupID.x * uint(RAY_LIST_GROUP) + gl_LocalInvocationIndex;
  bool inside = i < ray_header.count;
  ivec2 p = inside ? unpack_texel(rays[i]) : ivec2(0);
#else
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  bool inside = all(lessThan(p, ivec2(frame.viewport.xy)));
#endif
  float iterations = 0.0;
  if (inside) iterations = trace_refraction(p) + reflect_pixel(p);
  telemetry_lanes(p, inside, iterations);
}
