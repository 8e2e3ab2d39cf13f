// Random numbers and GGX importance sampling, shared by GLSL (techniques) and C++ (the reference).
// Written in the common subset of GLSL and GLM so both sides run the very same arithmetic.
//
// Fixes the seeds' defects (ARCHITECTURE §9): samples come from the distribution of *visible*
// normals (Heitz 2018), so no microfacet faces away from the viewer, and every random number is
// in [0, 1) and every divisor clamped, so nothing divides by zero at xi -> 1.
#pragma once
#include "shared/interop.h"

// Below this perceptual roughness a technique traces a lobe as its one exact mirror ray: no
// sample, no noise. The tracers, `stochastic`, PPR's resolve and the denoiser read it here (the
// reference's own threshold is its parameter mirror_roughness, by default the same).
#define SSR_MIRROR_ROUGHNESS 0.01

SSR_SHARED_BEGIN

// PCG hash (Jarzynski & Olano 2020): a good 32-bit mix, identical in C++ and GLSL.
SSR_FN uint pcg_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// A uniform number in [0, 1): 24 random bits, so 1.0 is never reached.
SSR_FN float uint_to_unit(uint v) { return float(v >> 8u) * (1.0f / 16777216.0f); }

// Two uniform numbers in [0, 1) for sample `index` of pixel (x, y) under `seed`.
SSR_FN vec2 sample_xi(uint x, uint y, uint index, uint seed) {
  uint h = pcg_hash(x ^ pcg_hash(y ^ pcg_hash(index ^ pcg_hash(seed))));
  return vec2(uint_to_unit(h), uint_to_unit(pcg_hash(h)));
}

// Orthonormal basis with `n` as the third column (Duff et al. 2017, no branch on a threshold).
SSR_FN mat3 basis_from_normal(vec3 n) {
  float s = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (s + n.z);
  float b = n.x * n.y * a;
  return mat3(vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x), vec3(b, s + n.y * n.y * a, -n.y), n);
}

// A microfacet normal from the GGX distribution of visible normals (Heitz 2018), in the local
// frame where the macro normal is +Z. ve: unit view direction with ve.z > 0; xi in [0, 1).
SSR_FN vec3 sample_ggx_vndf(vec3 ve, float alpha, vec2 xi) {
  vec3 vh = normalize(vec3(alpha * ve.x, alpha * ve.y, ve.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lensq > 1e-12f ? vec3(-vh.y, vh.x, 0.0f) * inversesqrt(lensq) : vec3(1.0f, 0.0f, 0.0f);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(xi.x);
  float phi = 6.28318530718f * xi.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * sqrt(max(1.0f - p1 * p1, 0.0f)) + s * p2;
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(1.0f - p1 * p1 - p2 * p2, 0.0f)) * vh;
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(nh.z, 1e-6f)));
}

// A reflection direction for view v (unit, from the surface towards the eye) around normal n,
// importance sampled from GGX VNDF with perceptual roughness r (alpha = r * r). With r = 0 this
// is the mirror direction. The result may point under the surface for rough lobes: callers
// check dot(l, n) > 0 and drop such samples.
SSR_FN vec3 sample_reflection(vec3 n, vec3 v, float roughness, vec2 xi) {
  float alpha = max(roughness * roughness, 1e-4f);
  mat3 tbn = basis_from_normal(n);
  vec3 ve = transpose(tbn) * v;
  ve = normalize(vec3(ve.x, ve.y, max(ve.z, 1e-4f)));  // grazing or back-facing views stay finite
  vec3 h = tbn * sample_ggx_vndf(ve, alpha, xi);
  return reflect(-v, h);
}

SSR_SHARED_END
