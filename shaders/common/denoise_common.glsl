// What the stochastic trace and the denoiser stages share: the class texture, the sample pdf,
// the ratio estimator's weight and the geometric similarity of two pixels. Include after
// common/gbuffer.glsl and common/brdf.glsl.
#include "shared/classification.h"

// Where a miss's ray ends (view-space units): far enough to stand for "at infinity" when a
// neighbour turns it into a direction, small enough for RGBA16F.
const float RAY_MISS_LENGTH = 1000.0;

uint pixel_class_at(sampler2D classes, ivec2 p) { return uint(texelFetch(classes, p, 0).r * CLASS_LEVELS + 0.5); }

// Half resolution: the traced pixels form a grid (texel t at pixel 2t + offset, the same corner
// of every 2x2 block). Pixel p lies between texels t0 + (0..1, 0..1): returns t0 (-1 at the top
// and left edges: no texel there) and `b`, p's place between them (0 or 0.5 per axis).
ivec2 half_grid_texel(ivec2 p, ivec2 offset, out vec2 b) {
  vec2 f = vec2(p - offset) * 0.5;
  ivec2 t0 = ivec2(floor(f));
  b = f - vec2(t0);
  return t0;
}

// The bilinear weight of texel t0 + (i, j) at `b` (half_grid_texel).
float half_grid_weight(vec2 b, int i, int j) { return (i == 0 ? 1.0 - b.x : b.x) * (j == 0 ? 1.0 - b.y : b.y); }

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// GGX Smith G1 for direction w (n.w = n_w), alpha = roughness^2.
float g1_ggx(float n_w, float alpha) {
  float a2 = alpha * alpha;
  return 2.0 * n_w / max(n_w + sqrt(a2 + (1.0 - a2) * n_w * n_w), 1e-7);
}

// The pdf (solid angle) of reflection direction l drawn by sample_reflection() (GGX VNDF):
// G1(v) D(h) / (4 n.v). Clamped to what RGBA16F holds (mirrors: a huge number, not infinity).
float reflection_pdf(vec3 n, vec3 v, vec3 l, float roughness) {
  float alpha = max(roughness * roughness, 1e-4);
  vec3 h = normalize(v + l);
  float n_v = max(dot(n, v), 1e-4);
  float pdf = g1_ggx(n_v, alpha) * d_ggx(max(dot(n, h), 0.0), alpha) / (4.0 * n_v);
  return clamp(pdf, 1e-6, 60000.0);
}

// The ratio estimator's numerator weight (Stachowiak 2015): BRDF * cos for this pixel's view
// and lobe towards l; divided by the sample's pdf by the caller. Fresnel is left to the
// composite (it weights the whole reflection), as are constant factors (they cancel).
float brdf_cos(vec3 n, vec3 v, vec3 l, float roughness) {
  float n_l = dot(n, l);
  if (n_l <= 0.0) return 0.0;
  float alpha = max(roughness * roughness, 1e-4);
  vec3 h = normalize(v + l);
  return d_ggx(max(dot(n, h), 0.0), alpha) * v_smith_ggx(max(dot(n, v), 1e-4), n_l, alpha) * n_l;
}

// How much pixel q (position pos_q, normal n_q, roughness r_q) may stand in for pixel p: near
// p's tangent plane (relative to p's distance), facing the same way, equally rough.
float geometric_weight(vec3 pos_p, vec3 n_p, float r_p, vec3 pos_q, vec3 n_q, float r_q) {
  float plane = abs(dot(n_p, pos_q - pos_p)) / (0.01 * abs(pos_p.z) + 1e-4);
  float facing = pow(max(dot(n_p, n_q), 0.0), 32.0);
  return exp(-plane) * facing * exp(-abs(r_p - r_q) * 10.0);
}
