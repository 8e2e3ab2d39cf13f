// Denoiser stage 3, cross-bilateral cleanup (src/techniques/denoiser.h; Diligent's
// SSR_ComputeBilateralCleanup): a (2r+1)^2 Gaussian whose spatial sigma grows with the pixel's
// relative noise (sqrt(variance) / luminance, from the earlier stages) and with roughness (none
// on mirrors), and is wider where the history is young; its range weights come from the
// G-buffer, not the noisy colour: depth (distance from the pixel's tangent plane), normal and
// roughness (after SVGF). With the stage off (or r = 0) it only resolves. Writes the
// technique's reflection: rgb (un-premultiplied), confidence.
#include "common/brdf.glsl"
#include "common/gbuffer.glsl"
#include "common/denoise_common.glsl"
#include "shared/denoise.h"
#include "shared/sampling.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = UBO_PASS) uniform PassBlock { DenoisePass pass; };
layout(binding = TEX_STAGE_IN) uniform sampler2D radiance_tex;  // premultiplied
layout(binding = TEX_STAGE_STATS) uniform sampler2D stats_tex;  // variance in r
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_reflection;

vec4 resolve(vec4 premultiplied) {
  return premultiplied.a > 1e-4 ? vec4(premultiplied.rgb / premultiplied.a, min(premultiplied.a, 1.0)) : vec4(0.0);
}

// How far a neighbour's normal keeps its reflection inside a GGX lobe of this roughness: the
// lobe's half vectors spread about alpha = roughness^2 around the normal (taken as at least 0.02
// rad, a chosen floor: flat surfaces blur, a sphere's few degrees a pixel do not), so a normal
// turned by angle a weighs exp(-(a / alpha)^2), with a^2 ~ 2 (1 - cos a).
// `strength` in [0, 1] scales the exponent (0: every neighbour counts in full).
float lobe_weight(vec3 n_p, vec3 n_q, float roughness, float strength) {
  float width = max(roughness * roughness, 0.02);
  return exp(-2.0 * strength * max(1.0 - dot(n_p, n_q), 0.0) / (width * width));
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (any(greaterThanEqual(p, size))) return;
  vec4 centre = texelFetch(radiance_tex, p, 0);
  if (!reflective_at(p)) {  // before the rest of the G-buffer (gbuffer.glsl)
    imageStore(out_reflection, p, resolve(centre));
    return;
  }
  GSample g = gbuffer_fetch(p);
  int r = pass.params.bilateral != 0 ? clamp(pass.params.bilateral_radius, 0, 8) : 0;
  vec2 stats = texelFetch(stats_tex, p, 0).rg;
  float noise = clamp(sqrt(stats.r) / max(luminance(centre.rgb), 1e-3), 0.0, 1.0);
  float sigma = mix(0.5, max(pass.params.bilateral_sigma, 0.5), noise) * clamp(g.roughness / 0.2, 0.0, 1.0);
  // A pixel with little history (new on screen, disoccluded, the frames after a cut) shows one or
  // a few samples that the accumulation has not averaged yet, however sharp its lobe: near
  // mirrors (corridor's floor, roughness 0.05, whose sigma above is under 0.3) sparkle where they
  // mirror lights. Its sigma is at least young_sigma / frames, as NRD's history fix blurs young
  // pixels (docs/RESULTS.md: corridor's pan). Exact mirrors (shared/sampling.h) have no noise.
  // Where that widens the blur, a neighbour counts only as far as its normal keeps the
  // reflection inside this pixel's lobe (lobe_weight): a flat floor blurs, a chrome sphere's
  // sharp reflection does not. Its strength fades with log2(young sigma / own sigma), from full at
  // 4x down to none where the two meet, so as the history grows the sharpening lets go as
  // gradually as the blur narrows (switched off at once, a glossy sphere's checker jumped when
  // the blur stopped widening: Denoiser.YoungHistoryBlurFadesWithoutAStepOnACurvedSurface).
  float lobe = 0.0;
  if (pass.params.temporal != 0 && g.roughness >= SSR_MIRROR_ROUGHNESS) {
    float s = pass.params.young_sigma / max(stats.g, 1.0);  // stats.g: frames of history
    lobe = s > sigma ? clamp(0.5 * log2(s / sigma), 0.0, 1.0) : 0.0;  // sigma >= 0.025 here
    sigma = max(sigma, s);
  }
  if (r == 0 || sigma < 0.3) {
    imageStore(out_reflection, p, resolve(centre));
    return;
  }
  vec4 sum = centre;
  float weight = 1.0;
  float inv_two_sigma2 = 1.0 / (2.0 * sigma * sigma);
  for (int y = -r; y <= r; ++y)
    for (int x = -r; x <= r; ++x) {
      ivec2 q = p + ivec2(x, y);
      if ((x == 0 && y == 0) || any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      GSample gq = gbuffer_fetch(q);
      if (!is_reflective(gq)) continue;
      float w = exp(-float(x * x + y * y) * inv_two_sigma2) *
                geometric_weight(g.pos_vs, g.n_vs, g.roughness, gq.pos_vs, gq.n_vs, gq.roughness);
      if (lobe > 0.0) w *= lobe_weight(g.n_vs, gq.n_vs, g.roughness, lobe);
      sum += w * texelFetch(radiance_tex, q, 0);
      weight += w;
    }
  imageStore(out_reflection, p, resolve(sum / weight));
}
