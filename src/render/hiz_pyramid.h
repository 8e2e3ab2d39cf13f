// The depth pyramid (a frame resource built for techniques that declare kReadHiz, e.g. `hiz`):
// level sizes (shared by the GL code and the tests) and the GL pass
// that builds it.
#pragma once
#include <utility>
#include <vector>

#include "gl/program.h"

namespace ssr {

// (width, height) of every level, level 0 = w x h, each next max(1, floor(prev / 2)), down to
// 1x1: the GL mip chain of a full-chain texture. A texel of level k+1 reduces source texels
// 2x..2x+1 (and 2x+2 for the last texel of an odd source), so no source row or column is lost.
std::vector<std::pair<int, int>> hiz_level_sizes(int w, int h);

// RG32F pyramid with a full mip chain: level 0 = the depth buffer (in both channels), level
// k+1 = the max (reversed-Z: closest; r) and the min (farthest; g) over each texel's level-k
// footprint. Up to HIZ_LEVELS_PER_DISPATCH levels per dispatch (the first also copies the depth
// buffer).
class HizPyramid {
 public:
  // Builds the program (shaders/render/hiz_pyramid.comp); throws on a compile error.
  void load(const gl::ShaderSource& src);
  // Rebuilds every level from a D32F/R32F depth texture (reallocating on a size change) and
  // leaves the pyramid bound at TEX_HIZ. Binds image units IMG_HIZ_LEVELS.. (shared/bindings.h).
  void build(const gl::Texture2D& depth);
  const gl::Texture2D& texture() const { return texture_; }

 private:
  gl::Program program_;
  gl::Texture2D texture_;
};

}  // namespace ssr
