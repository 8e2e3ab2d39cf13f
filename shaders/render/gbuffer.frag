// G-buffer fill: view-space normal + roughness, albedo + metallic, material ids, flags and the
// object (mesh) id, motion vectors.
#include "common/frame.glsl"
#include "common/brdf.glsl"
#include "common/motion.glsl"

layout(std140, binding = UBO_DRAW) uniform DrawBlock { DrawUniforms draw; };
layout(binding = TEX_ALBEDO_MAP) uniform sampler2D albedo_map;
layout(binding = TEX_NORMAL_MAP) uniform sampler2D normal_map;

in vec3 v_normal_vs;
in vec4 v_tangent_vs;
in vec2 v_uv;
in vec4 v_clip;
in vec4 v_prev_clip;

layout(location = 0) out vec4 out_normal_roughness;
layout(location = 1) out vec4 out_albedo_metallic;
layout(location = 2) out uvec4 out_material;
layout(location = 3) out vec4 out_emission;
layout(location = 4) out vec2 out_motion;

void main() {
  vec3 n = v_normal_vs;
  float len = length(n);
  n = len > 1e-8 ? n / len : vec3(0.0, 0.0, 1.0);
  if (!gl_FrontFacing) n = -n;  // two-sided: a wall seen from behind still has a sane normal
  if (draw.ids.z != 0) {
    vec3 t = v_tangent_vs.xyz - n * dot(n, v_tangent_vs.xyz);
    float tl = length(t);
    if (tl > 1e-8) {
      t /= tl;
      vec3 b = cross(n, t) * (v_tangent_vs.w < 0.0 ? -1.0 : 1.0);
      vec3 m = texture(normal_map, v_uv).xyz * 2.0 - 1.0;
      m.xy *= draw.material.z;
      vec3 pn = t * m.x + b * m.y + n * max(m.z, 0.0);
      float pl = length(pn);
      if (pl > 1e-6) n = pn / pl;
    }
  }
  vec3 albedo = draw.albedo_metallic.rgb;
  if (draw.ids.y != 0) albedo *= texture(albedo_map, v_uv).rgb;  // sRGB texture: decoded by GL
  float metallic = draw.albedo_metallic.a;
  float reflectance = draw.material.y;
  vec3 f0 = f0_of(albedo, metallic, reflectance);
  uint flags = 0u;
  if (draw.ids.x > 0 || max(f0.r, max(f0.g, f0.b)) >= frame.settings.z)
    flags |= MATERIAL_FLAG_REFLECTIVE;
  if (draw.ids.w != 0) flags |= MATERIAL_FLAG_TRANSPARENT;
  if (draw.ids.z != 0) flags |= MATERIAL_FLAG_NORMAL_MAPPED;
  out_emission = vec4(draw.emission.rgb, 0.0);
  out_motion = motion_pixels(v_clip, v_prev_clip);
  out_normal_roughness = vec4(n, draw.material.x);
  out_albedo_metallic = vec4(albedo, metallic);
  out_material = uvec4(uint(draw.ids.x), uint(round(clamp(reflectance, 0.0, 1.0) * 255.0)), flags,
                      uint(draw.object.x));
}
