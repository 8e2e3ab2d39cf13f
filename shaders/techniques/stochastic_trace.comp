// `stochastic`, trace stage (src/techniques/stochastic.cpp): one work group per tile that the
// classification listed (glDispatchComputeIndirect), one GGX VNDF ray per traced texel with a
// blue-noise sample, traced through the Hi-Z pyramid. Writes, per trace texel, the premultiplied
// radiance (rgb * confidence, confidence) and the hit vector (view space, hit - origin; a miss
// stores the direction * RAY_MISS_LENGTH) with the sample's pdf: what the denoiser's ratio
// estimator needs. Texels that do not trace this frame are not written (the denoiser reads
// the class texture). Compiled with STOCHASTIC_REFRACTION (scenes with glass), pixels behind
// glass refract as the tracers' do (common/refraction.glsl): one exact ray each, at full
// resolution, not denoised; the classification lists their tiles and writes the refraction's
// zeros outside the listed pixels, the trace every pixel of its tiles.
#include "common/ssr_common.glsl"
#include "common/hiz_trace.glsl"
#include "common/refraction.glsl"
#include "common/blue_noise.glsl"
#include "common/denoise_common.glsl"
#include "common/telemetry.glsl"
#include "shared/stochastic.h"

layout(local_size_x = CLASSIFY_TILE, local_size_y = CLASSIFY_TILE) in;
layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { StochasticParams params; };
layout(std430, binding = SSBO_TILES) buffer Tiles {
  TileListHeader header;
  uint tiles[];
};
layout(binding = TEX_LIT) uniform sampler2D lit_tex;
layout(binding = TEX_CLASS) uniform sampler2D class_tex;
layout(binding = TEX_PREV_COLOR) uniform sampler2D prev_color_tex;
layout(binding = TEX_MOTION) uniform sampler2D motion_tex;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_radiance;
layout(binding = IMG_OUT2, rgba16f) uniform writeonly image2D out_ray;

shared uint group_rays;

// The radiance a hit at `uv` sees: the lit colour, or with previous_frame the last frame's
// final colour where the hit was then (motion vectors), which carries its reflections too.
// previous_frame is 0 here whenever there is no previous colour (StochasticTechnique::run).
vec3 hit_radiance(vec2 uv) {
  if (params.previous_frame != 0) {
    vec2 prev = uv + texelFetch(motion_tex, ivec2(uv * frame.viewport.xy), 0).xy * frame.viewport.zw;
    if (uv_on_screen(prev)) return textureLod(prev_color_tex, prev, 0.0).rgb;
  }
  return textureLod(lit_tex, uv, 0.0).rgb;
}

void main() {
  if (gl_LocalInvocationIndex == 0u) group_rays = 0u;
  barrier();
  uint tile = tiles[gl_WorkGroupID.x];
  ivec2 t = ivec2(tile & 0xffffu, tile >> 16u) * CLASSIFY_TILE + ivec2(gl_LocalInvocationID.xy);
  int d = params.half_resolution != 0 ? 2 : 1;
  ivec2 p = t * d + trace_offset(d, frame.counts.z);
  bool traces = all(lessThan(p, ivec2(frame.viewport.xy))) && pixel_class_at(class_tex, p) == CLASS_TRACED;
  float iterations = 0.0;
  if (traces) {
    GSample g = gbuffer_fetch(p);
    vec3 v = -normalize(g.pos_vs);
    vec2 xi = blue_noise_xi(p, frame.counts.z, params.seed);
    xi.x *= 1.0 - clamp(params.ggx_bias, 0.0, 1.0);  // towards the lobe's centre (less noise, some bias)
    // Mirrors (as the tracers' ssr_main) take the exact mirror ray; others a GGX VNDF sample,
    // the mirror ray where it falls under the horizon.
    vec3 l = g.roughness < SSR_MIRROR_ROUGHNESS ? reflect(-v, g.n_vs) : sample_reflection(g.n_vs, v, g.roughness, xi);
    if (dot(l, g.n_vs) <= 0.0) l = reflect(-v, g.n_vs);
    float pdf = reflection_pdf(g.n_vs, v, l, g.roughness);
    // Glossy rays stop sooner: the few that walk far (grazing ones) set the dispatch's time.
    int cap = g.roughness > params.glossy_roughness ? params.glossy_iterations : params.max_iterations;
    TraceResult r = hiz_trace(g.pos_vs, l, HizTrace(params.max_distance, cap, 0, params.max_level,
                                                     params.thickness, false, g.reflector));
    vec4 radiance = r.hit ? vec4(hit_radiance(r.uv), 1.0) : vec4(0.0);
    imageStore(out_radiance, t, radiance);
    imageStore(out_ray, t, vec4(l * (r.hit ? r.distance : RAY_MISS_LENGTH), pdf));
    atomicAdd(group_rays, 1u);
    iterations = r.steps;
    telemetry_ray(r.steps);
  }
  bool refracts = false;
#ifdef STOCHASTIC_REFRACTION
  // The refraction of every pixel this texel stands for (its 2x2 block at half resolution).
  for (int y = 0; y < d; ++y)
    for (int x = 0; x < d; ++x) {
      ivec2 q = t * d + ivec2(x, y);
      if (any(greaterThanEqual(q, ivec2(frame.viewport.xy)))) continue;
      vec3 origin, dir;
      vec4 refraction = vec4(0.0);
      if (refraction_ray(q, origin, dir)) {
        TraceResult r = hiz_trace(origin, dir, HizTrace(params.max_distance, params.max_iterations, 0,
                                                        params.max_level, params.thickness, false, 0u));
        if (r.hit) refraction = vec4(textureLod(lit_tex, r.uv, 0.0).rgb, 1.0);
        iterations += r.steps;
        refracts = true;
        telemetry_ray(r.steps);
      }
      imageStore(out_refraction, q, refraction);
    }
#endif
  // At half resolution an odd size's last blocks may have this frame's pixel outside the image
  // while refracting inside it: the lane reports at its block's pixel in the image.
  telemetry_lanes(min(p, ivec2(frame.viewport.xy) - 1), traces || refracts, iterations);
  barrier();
  if (gl_LocalInvocationIndex == 0u && group_rays > 0u) atomicAdd(header.rays, group_rays);
}
