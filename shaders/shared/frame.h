// Per-frame and per-draw uniform layouts (std140 in GLSL; identical C++ structs).
#pragma once
#include "shared/interop.h"

SSR_SHARED_BEGIN

struct FrameUniforms {
  mat4 view;           // world -> view (right-handed, camera looks down -Z)
  mat4 proj;           // view -> clip, reversed-Z (near -> depth 1, far -> depth 0)
  mat4 inv_view;
  mat4 inv_proj;
  mat4 view_proj;
  vec4 viewport;       // width, height, 1/width, 1/height (pixels)
  vec4 camera_pos;     // world position, w = 1
  vec4 clip;           // near, far, tan(fov_y / 2), aspect
  vec4 env_zenith;     // linear radiance (intensity applied), w = environment type (0 sky, 1 constant)
  vec4 env_horizon;
  vec4 env_ground;
  vec4 env_constant;
  vec4 settings;       // x ambient scale, y exposure (stops), z reflective F0 threshold, w unused
  ivec4 counts;        // x lights, y reflectors, z frame index (FrameTime::index), w unused
  vec4 clip_plane;     // world-space plane (n, d): geometry with dot(n, p) + d < 0 is clipped
  mat4 prev_view_proj; // the previous frame's view_proj (= view_proj when history is not valid)
  vec4 time;           // x seconds, y seconds since the previous frame, z 1 when the history
                       // (previous-frame resources) is valid, w unused
  mat4 prev_view;      // the previous frame's view (= view when history is not valid): its
                       // view-space normals (TEX_PREV_NORMAL_ROUGHNESS) are in this frame
};

// Motion vectors (TEX_MOTION, RG16F): in pixels, the offset from a pixel's centre to where its
// surface point was in the previous frame: previous position = pixel centre + motion (GL pixel
// convention, +y up). Camera and object motion; the background moves with the camera's rotation.

struct DrawUniforms {
  vec4 albedo_metallic;   // linear rgb, metallic
  vec4 material;          // roughness, reflectance, normal strength, ior
  vec4 emission;          // linear rgb, w unused
  ivec4 ids;              // x reflector id, y has albedo map, z has normal map, w transparent
  ivec4 object;           // x mesh index (the G-buffer's object id), yzw unused
  mat4 model;             // the mesh's animation transform at this frame (identity when static)
  mat4 prev_model;        // ... at the previous frame (motion vectors)
  mat4 normal_model;      // inverse transpose of model (normals and tangents)
};

struct GpuLight {
  vec4 position_type;     // world xyz (point) / travel direction (directional); w 0 point, 1 dir
  vec4 color_range;       // linear rgb * intensity, range (point)
};

SSR_SHARED_END
