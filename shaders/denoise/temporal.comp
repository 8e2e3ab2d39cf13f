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
// Writes premultiplied radiance and (variance, frames accumulated).
#include "common/brdf.glsl"
#include "common/gbuffer.glsl"
#include "common/denoise_common.glsl"
#include "shared/denoise.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = UBO_PASS) uniform PassBlock { DenoisePass pass; };
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

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  GSample g = gbuffer_fetch(p);
  if (!is_reflective(g)) {
    imageStore(out_radiance, p, vec4(0.0));
    imageStore(out_stats, p, vec4(0.0));
    return;
  }
  vec4 result;
  vec2 stats;
  temporal_accumulate(p, g, texelFetch(current_tex, p, 0), texelFetch(current_stats, p, 0).rg, result, stats);
  imageStore(out_radiance, p, result);
  imageStore(out_stats, p, vec4(stats, 0.0, 0.0));
}
