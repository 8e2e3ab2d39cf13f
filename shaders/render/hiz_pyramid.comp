// Up to five levels of the depth pyramid per dispatch (src/render/hiz_pyramid.cpp): level m+1
// keeps the max (reversed-Z: the closest depth) of its level-m footprint in r and the min (the
// farthest) in g. The dispatch reads level k and writes k+1..k+n (n <= HIZ_LEVELS_PER_DISPATCH),
// the first from texture fetches, the others from shared memory. The first dispatch reads the
// depth buffer as level 0 and also writes level 0 (the copy), so a 1080p chain of 11 levels
// takes 2 dispatches (each dispatch mostly waited for the one before: small levels are latency).
//
// A group owns one texel of level k+n and its footprint at every finer level. Only the last
// texel of a level takes an odd source's extra row/column, and the last texels of all levels
// are ancestors of each other, so a group's footprint is a 2^j-aligned square of level k+n-j
// except in the last group of an axis, whose footprint runs to the level's end (< 2^(j+1)).
#include "shared/bindings.h"
#include "shared/hiz.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = TEX_HIZ) uniform sampler2D src_tex;  // the depth buffer, or the pyramid itself
// Unit IMG_HIZ_LEVELS + j: level k+j (j = 0: the copy of the depth buffer, first dispatch only).
layout(binding = IMG_HIZ_LEVELS, rg32f) uniform writeonly image2D level_img[HIZ_LEVELS_PER_DISPATCH + 1];
layout(location = 0) uniform int u_src_level;  // k: the level read (0 with u_copy: the depth buffer)
layout(location = 1) uniform bool u_copy;      // the source is the depth buffer: copy it to level 0
layout(location = 2) uniform int u_levels;     // n: levels written, k+1..k+n
layout(location = 3) uniform ivec2 u_size[HIZ_LEVELS_PER_DISPATCH + 1];  // [j]: level k+j's size

// Ping-pong between two tiles of up to 31x31 texels (a last group's level k+1 footprint).
const int TILE = 32;
shared vec2 tile[2][TILE * TILE];

void store_level(int j, ivec2 p, vec2 m) {
  // Constant indices into the image array: every GL accepts those.
  switch (j) {
    case 0: imageStore(level_img[0], p, vec4(m, 0.0, 0.0)); break;
    case 1: imageStore(level_img[1], p, vec4(m, 0.0, 0.0)); break;
    case 2: imageStore(level_img[2], p, vec4(m, 0.0, 0.0)); break;
    case 3: imageStore(level_img[3], p, vec4(m, 0.0, 0.0)); break;
    case 4: imageStore(level_img[4], p, vec4(m, 0.0, 0.0)); break;
    default: imageStore(level_img[5], p, vec4(m, 0.0, 0.0)); break;
  }
}

// The last texel of a level also takes an odd source's extra one (3x2, 2x3, 3x3), so every
// source texel lands in some texel.
ivec2 footprint_hi(ivec2 p, ivec2 dst_size, ivec2 src_size) {
  return min(mix(2 * p + 1, src_size - 1, equal(p, dst_size - 1)), src_size - 1);
}

// The group's first texel of level k+j and its texel count there (per axis).
void group_range(int j, out ivec2 lo, out ivec2 count) {
  ivec2 g = ivec2(gl_WorkGroupID.xy);
  int span = 1 << (u_levels - j);  // level k+j texels per level k+n texel
  lo = g * span;
  ivec2 last = u_size[u_levels] - 1;
  count = mix(ivec2(span), u_size[j] - lo, equal(g, last));
}

void main() {
  const int tid = int(gl_LocalInvocationIndex), threads = int(gl_WorkGroupSize.x * gl_WorkGroupSize.y);
  ivec2 lo, count;
  group_range(1, lo, count);
  // Level k+1 from the source.
  for (int i = tid; i < count.x * count.y; i += threads) {
    ivec2 q = ivec2(i % count.x, i / count.x), p = lo + q;
    ivec2 s_lo = 2 * p, s_hi = footprint_hi(p, u_size[1], u_size[0]);
    vec2 m = vec2(-1e30, 1e30);
    if (u_copy && all(equal(s_hi, s_lo + 1))) {
      // A 2x2 footprint of the depth buffer in one gather (at the texels' shared corner: exactly
      // those four), in the order (0,1) (1,1) (1,0) (0,0).
      vec4 d = textureGather(src_tex, vec2(s_lo + 1) / vec2(u_size[0]), 0);
      store_level(0, s_lo, d.ww);
      store_level(0, s_lo + ivec2(1, 0), d.zz);
      store_level(0, s_lo + ivec2(0, 1), d.xx);
      store_level(0, s_lo + ivec2(1, 1), d.yy);
      m = vec2(max(max(d.x, d.y), max(d.z, d.w)), min(min(d.x, d.y), min(d.z, d.w)));
    } else {
      for (int y = s_lo.y; y <= s_hi.y; ++y)
        for (int x = s_lo.x; x <= s_hi.x; ++x) {
          vec2 s = u_copy ? texelFetch(src_tex, ivec2(x, y), 0).rr : texelFetch(src_tex, ivec2(x, y), u_src_level).rg;
          if (u_copy) store_level(0, ivec2(x, y), s);
          m = vec2(max(m.x, s.x), min(m.y, s.y));
        }
    }
    tile[0][q.y * TILE + q.x] = m;
    store_level(1, p, m);
  }
  // Levels k+2..k+n from the level before, in shared memory.
  for (int j = 2; j <= u_levels; ++j) {
    barrier();
    ivec2 src_lo = lo;
    group_range(j, lo, count);
    int from = j & 1, to = from ^ 1;  // level k+1 is in tile[0]
    for (int i = tid; i < count.x * count.y; i += threads) {
      ivec2 q = ivec2(i % count.x, i / count.x), p = lo + q;
      ivec2 s_lo = 2 * p - src_lo, s_hi = footprint_hi(p, u_size[j], u_size[j - 1]) - src_lo;
      vec2 m = vec2(-1e30, 1e30);
      for (int y = s_lo.y; y <= s_hi.y; ++y)
        for (int x = s_lo.x; x <= s_hi.x; ++x) {
          vec2 s = tile[from][y * TILE + x];
          m = vec2(max(m.x, s.x), min(m.y, s.y));
        }
      tile[to][q.y * TILE + q.x] = m;
      store_level(j, p, m);
    }
  }
}
