// Denoiser stage 2, temporal accumulation (src/techniques/denoiser.h; Diligent's
// SSR_ComputeTemporalAccumulation after EA's hybrid ray tracing talk). Two places where this
// pixel's reflection was last frame:
//   surface:  where the reflecting surface was (the motion vectors), right for rough lobes and
//             for still reflections;
//   parallax: where the reflected point's virtual image was (the point the mean hit length puts
//             behind the mirror, through last frame's camera), right for sharp reflections under
//             a moving camera.
// Each is checked against the surface last frame there (normal, roughness; depth for the
// surface one); of the valid ones the one closer to this frame's 3x3 neighbourhood wins. Its
// history is clipped to the neighbourhood's mean +- clip_gamma * sigma (widened to hold this
// frame's value) and blended with weight
// 1 / n (n = frames accumulated, at most `history`). Nothing valid: the history restarts.
// At half resolution the spatial stage ran on the trace grid (pass.trace.w = 2): this stage
// upsamples its output first (depth-aware), and takes the neighbourhood on that grid (3x3 texels
// around the nearest: steadier than the 2x2 a pixel blends from, docs/RESULTS.md).
// Writes premultiplied radiance and (variance, frames accumulated).
#include "common/brdf.glsl"
#include "common/gbuffer.glsl"
#include "common/denoise_common.glsl"
#include "shared/denoise.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = UBO_PASS) uniform PassBlock { DenoisePass pass; };
layout(binding = TEX_CLASS) uniform sampler2D class_tex;
// The spatial stage's output: per pixel, or per trace texel (pass.trace.w = 2).
layout(binding = TEX_STAGE_IN) uniform sampler2D current_tex;     // premultiplied radiance
layout(binding = TEX_STAGE_STATS) uniform sampler2D current_stats;  // variance, mean hit length
layout(binding = TEX_HISTORY) uniform sampler2D history_tex;     // bilinear
layout(binding = TEX_HISTORY_STATS) uniform sampler2D history_stats;  // variance, frames
layout(binding = TEX_MOTION) uniform sampler2D motion_tex;
layout(binding = TEX_PREV_DEPTH) uniform sampler2D prev_depth_tex;
layout(binding = TEX_PREV_NORMAL_ROUGHNESS) uniform sampler2D prev_normal_tex;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_radiance;
layout(binding = IMG_OUT2, rg16f) uniform writeonly image2D out_stats;

#include "common/temporal_accumulate.glsl"

// Adds the spatial stage's texel t of the half-resolution grid, weighed by `kernel` and by how
// alike its pixel (this frame's traced pixel of block t) is to this one, if it holds a result.
void add_texel(inout vec4 radiance, inout vec2 stats, inout float weight, GSample g, ivec2 t, float kernel) {
  if (!(kernel > 0.0) || any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, textureSize(current_tex, 0)))) return;
  ivec2 q = t * 2 + pass.trace.yz;
  if (any(greaterThanEqual(q, ivec2(frame.viewport.xy)))) return;
  uint c = pixel_class_at(class_tex, q);
  if (c != CLASS_TRACED && c != CLASS_REUSED) return;  // no result there (zeros)
  GSample gq = gbuffer_fetch(q);
  float w = kernel * geometric_weight(g.pos_vs, g.n_vs, g.roughness, gq.pos_vs, gq.n_vs, gq.roughness);
  if (!(w > 0.0)) return;
  radiance += w * texelFetch(current_tex, t, 0);
  stats += w * texelFetch(current_stats, t, 0).rg;
  weight += w;
}

// Pixel p's value from the half-resolution grid: the 2 or 4 texels around it bilinearly (its own
// where it traced), each weighed by its pixel's likeness (a depth-aware upsample); none alike (a
// thin surface between them): the 3x3 around by likeness alone, as the spatial stage fills a
// pixel that has no ray at full resolution. `nearest`: the texel the neighbourhood centres on.
void upsample(ivec2 p, GSample g, out vec4 radiance, out vec2 stats, out ivec2 nearest) {
  radiance = vec4(0.0);
  stats = vec2(0.0);
  float weight = 0.0;
  vec2 b;
  ivec2 t0 = half_grid_texel(p, pass.trace.yz, b);
  nearest = clamp(t0 + ivec2(greaterThan(b, vec2(0.0))), ivec2(0), textureSize(current_tex, 0) - 1);  // ties up
  uint c = pixel_class_at(class_tex, p);
  if (c != CLASS_TRACED && c != CLASS_REUSED) return;  // rougher than the threshold: no reflection traced
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      add_texel(radiance, stats, weight, g, t0 + ivec2(i, j), half_grid_weight(b, i, j));
  if (weight == 0.0)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) add_texel(radiance, stats, weight, g, nearest + ivec2(x, y), 0.5);
  if (weight > 0.0) {
    radiance /= weight;
    stats /= weight;
  }
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  GSample g = gbuffer_fetch(p);
  if (!is_reflective(g)) {
    imageStore(out_radiance, p, vec4(0.0));
    imageStore(out_stats, p, vec4(0.0));
    return;
  }
  vec4 current, mean, sigma;
  vec2 current_stats_value;
  ivec2 centre = p;
  if (pass.trace.w == 2) {
    upsample(p, g, current, current_stats_value, centre);
  } else {
    current = texelFetch(current_tex, p, 0);
    current_stats_value = texelFetch(current_stats, p, 0).rg;
  }
  temporal_neighbourhood(centre, mean, sigma);
  vec4 result;
  vec2 stats;
  temporal_accumulate(p, g, current, current_stats_value, mean, sigma, result, stats);
  imageStore(out_radiance, p, result);
  imageStore(out_stats, p, vec4(stats, 0.0, 0.0));
}
