// What a missed ray sees: a procedural sky (zenith/horizon/ground gradient) or a constant.
#include "common/frame.glsl"

vec3 environment_radiance(vec3 dir_ws) {
  if (frame.env_zenith.w > 0.5) return frame.env_constant.rgb;
  float y = clamp(dir_ws.y / max(length(dir_ws), 1e-20), -1.0, 1.0);
  if (y >= 0.0) return mix(frame.env_horizon.rgb, frame.env_zenith.rgb, sqrt(y));
  return mix(frame.env_horizon.rgb, frame.env_ground.rgb, sqrt(min(-y * 4.0, 1.0)));
}

// Cosine-weighted irradiance / PI of the environment around a normal (for ambient light).
vec3 environment_diffuse(vec3 n_ws) {
  if (frame.env_zenith.w > 0.5) return frame.env_constant.rgb;
  vec3 sky = mix(frame.env_horizon.rgb, frame.env_zenith.rgb, 0.6);
  return mix(frame.env_ground.rgb, sky, clamp(n_ws.y * 0.5 + 0.5, 0.0, 1.0));
}
