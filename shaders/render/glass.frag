// Transparent surfaces' G-buffer: view-space normal + index of refraction, and tint.
#include "common/frame.glsl"

layout(std140, binding = UBO_DRAW) uniform DrawBlock { DrawUniforms draw; };

in vec3 v_normal_vs;
in vec4 v_tangent_vs;
in vec2 v_uv;

layout(location = 0) out vec4 out_surface;
layout(location = 1) out vec4 out_tint;

void main() {
  float len = length(v_normal_vs);
  vec3 n = len > 1e-8 ? v_normal_vs / len : vec3(0.0, 0.0, 1.0);
  if (!gl_FrontFacing) n = -n;
  out_surface = vec4(n, max(draw.material.w, 1.0));  // ior >= 1 marks "glass here"
  out_tint = vec4(draw.albedo_metallic.rgb, 1.0);
}
