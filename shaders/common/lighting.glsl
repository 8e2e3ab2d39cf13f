// Direct + ambient lighting of a surface point: the one copy of the lit pass's shading, used by
// the lighting pass and (later) by the reference to shade ray hits seen from the ray.
#include "common/brdf.glsl"
#include "common/environment.glsl"

layout(std430, binding = SSBO_LIGHTS) readonly buffer LightBlock { GpuLight lights[]; };

struct Surface {
  vec3 pos_ws;
  vec3 n_ws;
  vec3 albedo;
  float metallic;
  float roughness;
  float reflectance;
  vec3 emission;
};

// Radiance leaving `s` towards `v_ws` (unit, from the surface to the viewer): lights, ambient,
// emission. No reflections: those are the techniques' work.
vec3 shade_surface(Surface s, vec3 v_ws) {
  vec3 n = s.n_ws;
  float n_v = max(dot(n, v_ws), 1e-4);
  // Point lights on a perfect mirror would be a Dirac: keep a tiny lobe for direct light.
  float alpha = max(s.roughness * s.roughness, 0.02);
  vec3 f0 = f0_of(s.albedo, s.metallic, s.reflectance);
  vec3 diffuse_color = s.albedo * (1.0 - s.metallic);
  vec3 result = s.emission + diffuse_color * environment_diffuse(n) * frame.settings.x;
  for (int i = 0; i < frame.counts.x; ++i) {
    GpuLight light = lights[i];
    vec3 l;
    vec3 radiance;
    if (light.position_type.w < 0.5) {
      vec3 to_light = light.position_type.xyz - s.pos_ws;
      float d2 = max(dot(to_light, to_light), 1e-4);
      l = to_light * inversesqrt(d2);
      float x = d2 / (light.color_range.w * light.color_range.w);
      float window = clamp(1.0 - x * x, 0.0, 1.0);
      radiance = light.color_range.rgb * window * window / d2;
    } else {
      l = -light.position_type.xyz;
      radiance = light.color_range.rgb;
    }
    float n_l = dot(n, l);
    if (n_l <= 0.0) continue;
    vec3 h = normalize(l + v_ws);
    float n_h = max(dot(n, h), 0.0);
    vec3 f = fresnel_schlick(f0, max(dot(v_ws, h), 0.0));
    vec3 spec = d_ggx(n_h, alpha) * v_smith_ggx(n_v, n_l, alpha) * f;
    vec3 diff = (1.0 - f) * diffuse_color / PI;
    result += (diff + spec) * radiance * n_l;
  }
  return result;
}
