// G-buffer geometry: world-space vertices (meshes are baked in world space) to clip space.
#include "common/frame.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_tangent;

out vec3 v_normal_vs;
out vec4 v_tangent_vs;
out vec2 v_uv;

void main() {
  v_normal_vs = mat3(frame.view) * in_normal;
  v_tangent_vs = vec4(mat3(frame.view) * in_tangent.xyz, in_tangent.w);
  v_uv = in_uv;
  gl_Position = frame.view_proj * vec4(in_position, 1.0);
  // Planar mirror renders clip what lies behind the mirror; (0,0,0,1) keeps everything.
  gl_ClipDistance[0] = dot(frame.clip_plane, vec4(in_position, 1.0));
}
