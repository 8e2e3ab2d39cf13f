// Shading model: Lambert diffuse + GGX/Smith specular, Schlick Fresnel; split-sum weights.
const float PI = 3.14159265358979;

vec3 f0_of(vec3 albedo, float metallic, float reflectance) {
  return mix(vec3(0.16 * reflectance * reflectance), albedo, metallic);
}

vec3 fresnel_schlick(vec3 f0, float cos_theta) {
  float f = pow(1.0 - clamp(cos_theta, 0.0, 1.0), 5.0);
  return f0 + (1.0 - f0) * f;
}

float d_ggx(float n_h, float alpha) {
  float a2 = alpha * alpha;
  float d = n_h * n_h * (a2 - 1.0) + 1.0;
  return a2 / (PI * d * d);
}

// Height-correlated Smith visibility V = G / (4 n.l n.v).
float v_smith_ggx(float n_v, float n_l, float alpha) {
  float a2 = alpha * alpha;
  float gv = n_l * sqrt(n_v * n_v * (1.0 - a2) + a2);
  float gl = n_v * sqrt(n_l * n_l * (1.0 - a2) + a2);
  return 0.5 / max(gv + gl, 1e-7);
}

// Split-sum environment BRDF (F0 * A + B), Karis' analytic fit; the composite weights every
// technique's reflection with it.
vec3 specular_weight(vec3 f0, float n_v, float roughness) {
  const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
  const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
  vec4 r = roughness * c0 + c1;
  float a004 = min(r.x * r.x, exp2(-9.28 * clamp(n_v, 0.0, 1.0))) * r.x + r.y;
  vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
  return f0 * ab.x + ab.y;
}
