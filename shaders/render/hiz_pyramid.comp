// Two levels of the depth pyramid per dispatch (src/render/hiz_pyramid.cpp): level k+1 keeps
// the max (reversed-Z: the closest depth) of its level-k footprint in r and the min (the
// farthest) in g; level k+2 the same over level k+1, from shared memory. The first dispatch reads
// the depth buffer as level 0 and also writes level 0 (the copy), so a 1080p chain of 11 levels
// takes 5 dispatches instead of 11 (each level's dispatch mostly waited for the one before).
#include "shared/bindings.h"
#include "shared/hiz.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_HIZ) uniform sampler2D src_tex;  // the depth buffer, or the pyramid itself
layout(binding = IMG_OUT, rg32f) uniform writeonly image2D dst1;   // level k+1
layout(binding = IMG_OUT2, rg32f) uniform writeonly image2D dst2;  // level k+2 (when u_two)
layout(binding = IMG_REFRACTION, rg32f) uniform writeonly image2D dst0;  // level 0 (when u_copy)
layout(location = 0) uniform int u_src_level;  // k: the level read (0 with u_copy: the depth buffer)
layout(location = 1) uniform bool u_copy;      // the source is the depth buffer: copy it to level 0
layout(location = 2) uniform bool u_two;       // level k+2 exists: write it too
layout(location = 3) uniform ivec2 u_src_size; // level k's size
layout(location = 4) uniform ivec2 u_size1;    // level k+1's size
layout(location = 5) uniform ivec2 u_size2;    // level k+2's size

// A group writes level k+2 texels 4g..4g+3 (per axis) and the level k+1 texels their footprints
// cover: 8g..8g+7, and 8g+8 where the last texel of an odd level takes three.
const int TILE = 9;
shared vec2 tile[TILE * TILE];

// Texels lo..hi of the source reduced to one: 2x2, and the last texel of a row/column also takes
// an odd source's extra one (3x2, 2x3, 3x3), so every source texel lands in some texel.
ivec2 footprint_hi(ivec2 p, ivec2 dst_size, ivec2 src_size) {
  return min(mix(2 * p + 1, src_size - 1, equal(p, dst_size - 1)), src_size - 1);
}

vec2 reduce_source(ivec2 p) {
  ivec2 lo = 2 * p, hi = footprint_hi(p, u_size1, u_src_size);
  vec2 m = vec2(-1e30, 1e30);
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      vec2 s = u_copy ? texelFetch(src_tex, ivec2(x, y), 0).rr : texelFetch(src_tex, ivec2(x, y), u_src_level).rg;
      if (u_copy) imageStore(dst0, ivec2(x, y), vec4(s, 0.0, 0.0));
      m = vec2(max(m.x, s.x), min(m.y, s.y));
    }
  return m;
}

void main() {
  ivec2 base = ivec2(gl_WorkGroupID.xy) * 8;  // the group's first level k+1 texel
  for (int i = int(gl_LocalInvocationIndex); i < TILE * TILE; i += 64) {
    ivec2 p = base + ivec2(i % TILE, i / TILE);
    if (any(greaterThanEqual(p, u_size1))) continue;
    vec2 m = reduce_source(p);
    tile[i] = m;
    imageStore(dst1, p, vec4(m, 0.0, 0.0));  // 8g+8 twice, by two groups: the same value
  }
  if (!u_two) return;
  barrier();
  ivec2 l = ivec2(gl_LocalInvocationID.xy);
  ivec2 q = ivec2(gl_WorkGroupID.xy) * 4 + l;
  if (any(greaterThanEqual(l, ivec2(4))) || any(greaterThanEqual(q, u_size2))) return;
  ivec2 lo = 2 * q, hi = footprint_hi(q, u_size2, u_size1);
  vec2 m = vec2(-1e30, 1e30);
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      vec2 s = tile[(y - base.y) * TILE + (x - base.x)];
      m = vec2(max(m.x, s.x), min(m.y, s.y));
    }
  imageStore(dst2, q, vec4(m, 0.0, 0.0));
}
