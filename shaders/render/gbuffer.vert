// G-buffer geometry: world-space vertices (meshes are baked in world space, then moved by their
// animation transform) to clip space, and the previous frame's clip position for motion vectors.
#include "common/frame.glsl"

layout(std140, binding = UBO_DRAW) uniform DrawBlock { DrawUniforms draw; };

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_tangent;

out vec3 v_normal_vs;
out vec4 v_tangent_vs;
out vec2 v_uv;
out vec4 v_clip;
out vec4 v_prev_clip;

void main() {
  vec4 world = draw.model * vec4(in_position, 1.0);
  mat3 normal_world = mat3(draw.normal_model);
  v_normal_vs = mat3(frame.view) * (normal_world * in_normal);
  v_tangent_vs = vec4(mat3(frame.view) * (mat3(draw.model) * in_tangent.xyz), in_tangent.w);
  v_uv = in_uv;
  gl_Position = frame.view_proj * world;
  v_clip = gl_Position;
  v_prev_clip = frame.prev_view_proj * (draw.prev_model * vec4(in_position, 1.0));
  // Planar mirror renders clip what lies behind the mirror; (0,0,0,1) keeps everything.
  gl_ClipDistance[0] = dot(frame.clip_plane, world);
}
