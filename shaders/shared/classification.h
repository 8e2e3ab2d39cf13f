// The tile classification (render/classification.h), a frame service for tracers that trace a
// subset of pixels through an indirect dispatch: which pixels get a ray this frame, the list of
// trace tiles that hold at least one, and the list of the texels themselves (the ray list).
#pragma once
#include "shared/interop.h"

#define CLASS_NONE 0u         // not reflective: no reflection work
#define CLASS_ENVIRONMENT 1u  // rougher than the threshold: the composite's environment only
#define CLASS_TRACED 2u       // traces its own ray this frame
#define CLASS_REUSED 3u       // reflective, no ray of its own this frame: neighbours' rays fill it
#define CLASS_LEVELS 3.0      // the class texture (R8) stores class / CLASS_LEVELS
#define CLASSIFY_TILE 8       // a tile is CLASSIFY_TILE^2 trace texels: one trace work group
#define RAY_LIST_GROUP 64     // lanes of a work group that traces the ray list

SSR_SHARED_BEGIN

struct ClassifyParams {
  float roughness_threshold;  // rougher pixels: CLASS_ENVIRONMENT
  float quad_roughness;       // pixels at or below trace every frame (full resolution)
  int rays_per_quad;          // 1, 2 or 4: rays per 2x2 quad above quad_roughness
  int divisor;                // 1: a trace texel per pixel; 2: per 2x2 block (half resolution)
  ivec4 trace_size;           // xy: the trace grid's size; zw: this frame's pixel of a 2x2 block
  int list_glass SSR_DEFAULT(0);  // 1: pixels behind a transparent surface join the lists (they refract)
  int list_rays SSR_DEFAULT(1);   // 1: the ray list is built too (a tracer's `compact`); 0: the tile list alone
  int pad1 SSR_DEFAULT(0);
  int pad2 SSR_DEFAULT(0);
};

// The trace grid's texel t stands for pixel t * divisor + offset (offset: the frame's pixel of
// each 2x2 block, cycling through all four over four frames; (0, 0) at full resolution).
SSR_FN ivec2 quad_offset(int frame_index) {
  int k = frame_index & 3;  // diagonal first, so two frames already cover both diagonals
  return ivec2(k == 1 || k == 2 ? 1 : 0, k == 1 || k == 3 ? 1 : 0);
}

// That offset for a trace grid of `divisor` (1, 2).
SSR_FN ivec2 trace_offset(int divisor, int frame_index) {
  return divisor == 2 ? quad_offset(frame_index) : ivec2(0);
}

// Is pixel p one of the quad's `rays` (1, 2, 4) traced pixels this frame? The choice rotates
// with the frame so every pixel gets rays over four frames.
SSR_FN bool quad_traces(ivec2 p, int frame_index, int rays) {
  ivec2 o = quad_offset(frame_index);
  ivec2 q = ivec2(p.x & 1, p.y & 1);
  if (rays >= 4) return true;
  if (rays >= 2) return (q.x ^ q.y) == (o.x ^ o.y);  // the frame's diagonal
  return q.x == o.x && q.y == o.y;
}

// The trace tiles: an indirect dispatch's arguments, then one packed tile per work group.
struct TileListHeader {
  uint groups_x;  // tiles listed (the dispatch's x); y and z stay 1
  uint groups_y;
  uint groups_z;
  uint rays;      // reflection rays the trace cast (it counts them; refraction rays not)
};

// The ray list: an indirect dispatch's arguments (RAY_LIST_GROUP lanes a group), then one
// packed trace texel (x | y << 16) per lane, a tile's texels next to each other.
struct RayListHeader {
  uint groups_x;  // ceil(count / RAY_LIST_GROUP)
  uint groups_y;
  uint groups_z;
  uint count;     // texels listed
};

SSR_FN uint pack_texel(ivec2 t) { return uint(t.x) | (uint(t.y) << 16u); }
SSR_FN ivec2 unpack_texel(uint v) { return ivec2(int(v & 0xffffu), int(v >> 16u)); }

SSR_SHARED_END
