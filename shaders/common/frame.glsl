// The frame uniform block and camera helpers: projection, reconstruction from reversed-Z depth.
#include "shared/bindings.h"
#include "shared/frame.h"

layout(std140, binding = UBO_FRAME) uniform FrameBlock { FrameUniforms frame; };

// Pixel centre (integer pixel) -> uv in [0,1].
vec2 pixel_to_uv(ivec2 p) { return (vec2(p) + 0.5) * frame.viewport.zw; }

// View-space position from uv and reversed-Z depth, through the inverse projection.
vec3 view_position(vec2 uv, float depth) {
  vec4 p = frame.inv_proj * vec4(uv * 2.0 - 1.0, depth, 1.0);
  return p.xyz / p.w;
}

// View-space z (negative in front of the camera) of a reversed-Z depth value; depth 0 -> far.
float view_z_from_depth(float depth) {
  // proj[2][2] = A = n/(f-n), proj[3][2] = B = n f/(f-n), clip.w = -z  =>  depth = B / -z - A
  float a = frame.proj[2][2], b = frame.proj[3][2];
  return -b / max(depth + a, 1e-30);
}

// Clip coordinates to uv and depth; false at or behind the camera plane (w <= 0), where
// dividing by w would flip or blow up.
bool clip_to_uv(vec4 c, out vec2 uv, out float depth) {
  if (c.w <= 1e-6) { uv = vec2(-1.0); depth = 0.0; return false; }
  uv = c.xy / c.w * 0.5 + 0.5;
  depth = c.z / c.w;
  return true;
}

// Roberts's edge fade: 1 at the screen's centre, 0 on its diamond towards the edges.
float edge_fade(vec2 uv) { return clamp(1.0 - abs(uv.x - 0.5) - abs(uv.y - 0.5), 0.0, 1.0); }

// Projects a view-space point (this frame's camera).
bool project_to_uv(vec3 p, out vec2 uv, out float depth) { return clip_to_uv(frame.proj * vec4(p, 1.0), uv, depth); }

bool uv_on_screen(vec2 uv) { return all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0))); }

vec3 view_to_world_dir(vec3 d) { return mat3(frame.inv_view) * d; }
vec3 view_to_world_pos(vec3 p) { return (frame.inv_view * vec4(p, 1.0)).xyz; }
