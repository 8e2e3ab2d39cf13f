// Up to five levels of the depth pyramid per dispatch (src/render/hiz_pyramid.cpp): level m+1
// keeps the max (reversed-Z: the closest depth) of its level-m footprint in r and the min (the
// farthest) in g. The dispatch reads level k and writes k+1..k+n (n <= HIZ_LEVELS_PER_DISPATCH).
// The first dispatch reads the depth buffer as level 0 and also writes level 0 (the copy), so a
// 1080p chain of 11 levels takes 2 dispatches (each dispatch mostly waited for the one before:
// small levels are latency).
//
// A group owns one texel of level k+n and its footprint at every finer level. An invocation
// reduces level k+2's texels (k+1 when n = 1) from the source in registers: an inner one's
// footprint is 2x2 texels of level k+1 and 4x4 of level k, fetched together (four gathers from
// the depth buffer). Levels k+3..k+n follow in shared memory. Only the last texel of a level
// takes an odd source's extra row/column, and the last texels of all levels are ancestors of
// each other, so a group's footprint is a 2^j-aligned square of level k+n-j except in the last
// group of an axis, whose footprint runs to the level's end (< 2^(j+1)).
#include "shared/bindings.h"
#include "shared/hiz.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_HIZ) uniform sampler2D src_tex;  // the depth buffer, or the pyramid itself
// Unit IMG_HIZ_LEVELS + j: level k+j (j = 0: the copy of the depth buffer, first dispatch only).
layout(binding = IMG_HIZ_LEVELS, rg32f) uniform writeonly image2D level_img[HIZ_LEVELS_PER_DISPATCH + 1];
layout(location = 0) uniform int u_src_level;  // k: the level read (0 with u_copy: the depth buffer)
layout(location = 1) uniform bool u_copy;      // the source is the depth buffer: copy it to level 0
layout(location = 2) uniform int u_levels;     // n: levels written, k+1..k+n
layout(location = 3) uniform ivec2 u_size[HIZ_LEVELS_PER_DISPATCH + 1];  // [j]: level k+j's size

// Ping-pong between two tiles of up to 15x15 texels (a last group's level k+2 footprint).
const int TILE = 16;
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

vec2 reduce(vec2 a, vec2 b) { return vec2(max(a.x, b.x), min(a.y, b.y)); }

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

vec2 fetch_source(ivec2 p) {
  return u_copy ? texelFetch(src_tex, p, 0).rr : texelFetch(src_tex, p, u_src_level).rg;
}

// Level k+1's texel p from the source (any footprint; level k's copy on the first dispatch).
vec2 reduce_source(ivec2 p) {
  ivec2 s_lo = 2 * p, s_hi = footprint_hi(p, u_size[1], u_size[0]);
  vec2 m = vec2(-1e30, 1e30);
  for (int y = s_lo.y; y <= s_hi.y; ++y)
    for (int x = s_lo.x; x <= s_hi.x; ++x) {
      vec2 s = fetch_source(ivec2(x, y));
      if (u_copy) store_level(0, ivec2(x, y), s);
      m = reduce(m, s);
    }
  store_level(1, p, m);
  return m;
}

// A 2x2 block of the depth buffer in one gather (at the texels' shared corner: exactly those
// four, in the order (0,1) (1,1) (1,0) (0,0)), copied to level 0 and reduced.
vec2 gather_copy(ivec2 s_lo) {
  vec4 d = textureGather(src_tex, vec2(s_lo + 1) / vec2(u_size[0]), 0);
  store_level(0, s_lo, d.ww);
  store_level(0, s_lo + ivec2(1, 0), d.zz);
  store_level(0, s_lo + ivec2(0, 1), d.xx);
  store_level(0, s_lo + ivec2(1, 1), d.yy);
  return vec2(max(max(d.x, d.y), max(d.z, d.w)), min(min(d.x, d.y), min(d.z, d.w)));
}

// Level k+2's texel p from the source through level k+1.
vec2 reduce_two(ivec2 p) {
  if (u_copy && all(lessThan(p, u_size[2] - 1))) {
    // An inner texel: 2x2 level-1 texels of 2x2 depth texels each, the four gathers issued together.
    ivec2 s = 4 * p;
    vec2 a = gather_copy(s), b = gather_copy(s + ivec2(2, 0));
    vec2 c = gather_copy(s + ivec2(0, 2)), d = gather_copy(s + ivec2(2, 2));
    ivec2 q = 2 * p;
    store_level(1, q, a);
    store_level(1, q + ivec2(1, 0), b);
    store_level(1, q + ivec2(0, 1), c);
    store_level(1, q + ivec2(1, 1), d);
    return reduce(reduce(a, b), reduce(c, d));
  }
  ivec2 q_lo = 2 * p, q_hi = footprint_hi(p, u_size[2], u_size[1]);
  vec2 m = vec2(-1e30, 1e30);
  for (int y = q_lo.y; y <= q_hi.y; ++y)
    for (int x = q_lo.x; x <= q_hi.x; ++x) m = reduce(m, reduce_source(ivec2(x, y)));
  return m;
}

void main() {
  const int tid = int(gl_LocalInvocationIndex), threads = int(gl_WorkGroupSize.x * gl_WorkGroupSize.y);
  // Levels k+1..k+r in registers, r = 2 (1 for a one-level dispatch).
  const int r = min(u_levels, 2);
  ivec2 lo, count;
  group_range(r, lo, count);
  for (int i = tid; i < count.x * count.y; i += threads) {
    ivec2 q = ivec2(i % count.x, i / count.x), p = lo + q;
    vec2 m = r == 2 ? reduce_two(p) : reduce_source(p);
    if (r == 2) store_level(2, p, m);
    tile[0][q.y * TILE + q.x] = m;
  }
  // Levels k+3..k+n from the level before, in shared memory.
  for (int j = r + 1; j <= u_levels; ++j) {
    barrier();
    ivec2 src_lo = lo;
    group_range(j, lo, count);
    int from = (j - r) & 1 ^ 1, to = from ^ 1;  // level k+r is in tile[0]
    for (int i = tid; i < count.x * count.y; i += threads) {
      ivec2 q = ivec2(i % count.x, i / count.x), p = lo + q;
      ivec2 s_lo = 2 * p - src_lo, s_hi = footprint_hi(p, u_size[j], u_size[j - 1]) - src_lo;
      vec2 m = vec2(-1e30, 1e30);
      for (int y = s_lo.y; y <= s_hi.y; ++y)
        for (int x = s_lo.x; x <= s_hi.x; ++x) m = reduce(m, tile[from][y * TILE + x]);
      tile[to][q.y * TILE + q.x] = m;
      store_level(j, p, m);
    }
  }
}
