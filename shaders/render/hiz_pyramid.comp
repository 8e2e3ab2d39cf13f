// One level of the depth pyramid (src/render/hiz_pyramid.cpp): level 0 copies the depth
// buffer, level k+1 keeps the max (reversed-Z: the closest depth) of its level-k footprint in r
// and the min (the farthest) in g.
#include "shared/bindings.h"
#include "shared/hiz.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_HIZ) uniform sampler2D src_tex;  // the depth buffer, or the pyramid itself
layout(binding = IMG_OUT, rg32f) uniform writeonly image2D dst;  // the level being written
layout(location = 0) uniform int u_src_level;  // < 0: copy level 0 of src_tex (the depth buffer)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 dst_size = imageSize(dst);
  if (any(greaterThanEqual(p, dst_size))) return;
  if (u_src_level < 0) {
    imageStore(dst, p, vec4(texelFetch(src_tex, p, 0).rr, 0.0, 0.0));
    return;
  }
  // 2x2 source texels; the last texel of a row/column also takes an odd source's extra one
  // (3x2, 2x3, 3x3), so every source texel lands in some texel of this level.
  ivec2 src_size = textureSize(src_tex, u_src_level);
  ivec2 lo = 2 * p;
  ivec2 hi = mix(lo + 1, src_size - 1, equal(p, dst_size - 1));
  hi = min(hi, src_size - 1);  // a 1-texel source
  vec2 m = texelFetch(src_tex, lo, u_src_level).rg;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      vec2 s = texelFetch(src_tex, ivec2(x, y), u_src_level).rg;
      m = vec2(max(m.x, s.x), min(m.y, s.y));
    }
  imageStore(dst, p, vec4(m, 0.0, 0.0));
}
