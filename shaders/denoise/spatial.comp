// Denoiser stage 1, spatial reconstruction (src/techniques/denoiser.h): each pixel reuses the
// rays of its neighbours with the ratio estimator (Stachowiak 2015; Diligent's
// SSR_ComputeSpatialReconstruction):
//   L(p) = sum_q L_q f_p(l_q) cos / pdf_q  /  sum_q f_p(l_q) cos / pdf_q
// where l_q is the direction from p to q's hit point: the BRDF is p's own, the pdf the one q's
// sample was drawn with, so each pixel keeps its own lobe. The radius grows with roughness;
// mirror pixels only fill from neighbours where they have no ray (half resolution, quads). With
// the stage off it is the upsample alone: the nearest rays that stand for this pixel. With
// `firefly`, glossy pixels weigh each ray by 1 / (1 + luminance) too (Karis), less as their
// history grows: cleaner first frames and less flicker (docs/RESULTS.md).
// Writes premultiplied radiance and (luminance variance, mean hit length): per pixel, or with
// pass.trace.w = 2 per trace texel, at this frame's traced pixel of its block (the temporal stage
// then upsamples: a quarter of the invocations, Denoiser::spatial_divisor).
#include "common/brdf.glsl"
#include "common/gbuffer.glsl"
#include "common/denoise_common.glsl"
#include "shared/denoise.h"
#include "shared/roughness_bands.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = UBO_PASS) uniform PassBlock { DenoisePass pass; };
layout(binding = TEX_CLASS) uniform sampler2D class_tex;
layout(binding = TEX_TRACE_RADIANCE) uniform sampler2D radiance_tex;
layout(binding = TEX_TRACE_RAY) uniform sampler2D ray_tex;
layout(binding = TEX_HISTORY_STATS) uniform sampler2D history_stats;  // last frame's (variance, frames)
layout(binding = TEX_MOTION) uniform sampler2D motion_tex;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_radiance;
layout(binding = IMG_OUT2, rg16f) uniform writeonly image2D out_stats;

struct Accum {
  vec4 radiance;  // sum of w * (L c, c)
  float weight;   // sum of w
  float m1, m2;   // sums of w * luminance, w * luminance^2
  float length, length_weight;
};

// Adds the ray of the trace texel that covers pixel q (if it traced this frame) to p's sums.
// `brdf`: weight by the ratio estimator (glossy p); else by geometry and `kernel` only.
void add_ray(inout Accum a, GSample g, vec3 v, ivec2 q, float kernel, bool brdf, float firefly) {
  ivec2 size = ivec2(frame.viewport.xy);
  int d = pass.trace.x;
  ivec2 t = q / d;
  ivec2 o = t * d + pass.trace.yz;  // the pixel the texel's ray started from
  if (any(lessThan(o, ivec2(0))) || any(greaterThanEqual(o, size))) return;
  if (pixel_class_at(class_tex, o) != CLASS_TRACED) return;
  GSample go = gbuffer_fetch(o);
  float w = kernel * geometric_weight(g.pos_vs, g.n_vs, g.roughness, go.pos_vs, go.n_vs, go.roughness);
  vec4 ray = texelFetch(ray_tex, t, 0);
  vec4 radiance = texelFetch(radiance_tex, t, 0);
  if (brdf) {
    vec3 l = normalize(go.pos_vs + ray.xyz - g.pos_vs);
    w *= brdf_cos(g.n_vs, v, l, g.roughness) / max(ray.w, 1e-6);
  }
  float lum = luminance(radiance.rgb);
  // Fireflies (a rare ray that found a small bright source) would spread over the whole disk:
  // weigh rays down by their luminance (Karis). Not on sharp lobes, whose neighbours' rays
  // differ for real (edges in the reflection), not by chance.
  w /= 1.0 + lum * firefly;
  if (!(w > 0.0)) return;
  a.radiance += w * radiance;
  a.weight += w;
  a.m1 += w * lum;
  a.m2 += w * lum * lum;
  if (radiance.a > 0.0) {
    a.length += w * length(ray.xyz);
    a.length_weight += w;
  }
}

// How strongly the rays are weighed down by luminance at pixel p: fully on rough lobes, not on
// sharp ones, and less as the pixel's history grows (the accumulation averages fireflies out;
// a weighting that stayed kept cornell's highlights dim: docs/RESULTS.md).
float firefly_strength(ivec2 p, GSample g) {
  if (pass.params.firefly == 0) return 0.0;
  float s = clamp((g.roughness - 0.1) / 0.2, 0.0, 1.0);
  if (pass.params.temporal != 0) {
    ivec2 prev = ivec2(floor(vec2(p) + 0.5 + texelFetch(motion_tex, p, 0).xy));
    if (all(greaterThanEqual(prev, ivec2(0))) && all(lessThan(prev, ivec2(frame.viewport.xy))))
      s /= 1.0 + texelFetch(history_stats, prev, 0).g;
  }
  return s;
}

// A Vogel (golden-angle) disk: sample i of n at radius r, turned by `angle`.
vec2 vogel(int i, int n, float r, float angle) {
  float rho = r * sqrt((float(i) + 0.5) / float(n));
  float theta = float(i) * 2.39996323 + angle;
  return rho * vec2(cos(theta), sin(theta));
}

void main() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);  // the output texel
  if (any(greaterThanEqual(id, imageSize(out_radiance)))) return;
  ivec2 p = pass.trace.w == 2 ? id * 2 + pass.trace.yz : id;  // the pixel it is for
  // Not reflective, not traced, or (the grid's last texels of an odd size) outside the image.
  uint c = all(lessThan(p, ivec2(frame.viewport.xy))) ? pixel_class_at(class_tex, p) : CLASS_NONE;
  if (c != CLASS_TRACED && c != CLASS_REUSED) {
    imageStore(out_radiance, id, vec4(0.0));
    imageStore(out_stats, id, vec4(0.0));
    return;
  }
  GSample g = gbuffer_fetch(p);
  vec3 v = -normalize(g.pos_vs);
  // The ratio estimator's BRDF weights only on lobes wider than the band bound as stored: a lobe
  // authored at 0.05 (corridor's floor, pedestal's chrome; glossy to the verdicts) keeps its own
  // ray as traced, because at alpha 0.0025 the half-float normals swing the weight by orders of
  // magnitude and a silhouette ray under the stored normal's horizon weighs 0 (as glossy, 3 of
  // 536 sphere pixels in Denoiser.YoungHistoryBlurKeepsACurvedMirrorSharp went wrong).
  bool glossy = g.roughness > as_stored_roughness(MIRROR_BAND_BELOW);
  Accum a = Accum(vec4(0.0), 0.0, 0.0, 0.0, 0.0, 0.0);
  // Its own ray, if any; else the nearest rays around it (the upsample).
  float firefly = firefly_strength(p, g);
  int d = pass.trace.x;
  bool own = c == CLASS_TRACED && (d == 1 || p == (p / d) * d + pass.trace.yz);
  if (d == 2 && !own) {
    // Half resolution: the traced pixels form a grid (one per 2x2 block, the same corner in
    // every block), so a pixel between them takes the 2 or 4 around it, bilinearly, each
    // weighed by its geometric likeness too (a depth-aware bilinear upsample).
    vec2 b;
    ivec2 t0 = half_grid_texel(p, pass.trace.yz, b);
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        float k = half_grid_weight(b, i, j);
        ivec2 t = t0 + ivec2(i, j);
        if (k > 0.0 && all(greaterThanEqual(t, ivec2(0)))) add_ray(a, g, v, t * 2 + pass.trace.yz, k, glossy, firefly);
      }
  } else {
    add_ray(a, g, v, p, 1.0, glossy, firefly);
  }
  // No ray of its own or from the grid (an edge, a reused quad pixel): the 3x3 around it.
  if ((d == 1 && !own) || a.weight == 0.0)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x)
        if (x != 0 || y != 0) add_ray(a, g, v, p + ivec2(x, y) * d, 0.5, glossy, firefly);
  float radius = pass.params.spatial_radius * clamp(g.roughness * 2.0, 0.0, 1.0);
  if (pass.params.spatial != 0 && glossy && radius >= 1.0) {
    // A per-pixel, per-frame turn of the disk: neighbouring pixels pick different neighbours.
    float angle = 6.28318530718 * fract(0.754877669 * float(p.x) + 0.569840296 * float(p.y) +
                                         0.61803398875 * float(frame.counts.z));
    int n = clamp(pass.params.spatial_samples, 1, 32);
    for (int i = 0; i < n; ++i) add_ray(a, g, v, p + ivec2(round(vogel(i, n, radius, angle))), 1.0, true, firefly);
  }
  vec4 radiance = a.weight > 0.0 ? a.radiance / a.weight : vec4(0.0);
  float mean = a.weight > 0.0 ? a.m1 / a.weight : 0.0;
  float variance = a.weight > 0.0 ? max(a.m2 / a.weight - mean * mean, 0.0) : 0.0;
  float ray_length = a.length_weight > 0.0 ? a.length / a.length_weight : 0.0;
  imageStore(out_radiance, id, radiance);
  imageStore(out_stats, id, vec4(variance, ray_length, 0.0, 0.0));
}
