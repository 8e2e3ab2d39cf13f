#include "render/hiz_pyramid.h"

#include <algorithm>
#include <cassert>

#include "shared/bindings.h"

namespace ssr {

std::vector<std::pair<int, int>> hiz_level_sizes(int w, int h) {
  std::vector<std::pair<int, int>> sizes{{w, h}};
  while (w > 1 || h > 1) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    sizes.emplace_back(w, h);
  }
  return sizes;
}

void HizPyramid::load(const gl::ShaderSource& src) {
  program_ = gl::Program::compute(src, "render/hiz_pyramid.comp");
}

void HizPyramid::build(const gl::Texture2D& depth) {
  const int w = depth.width(), h = depth.height();
  if (!texture_ || texture_.width() != w || texture_.height() != h)
    texture_ = gl::Texture2D("hiz depth pyramid", GL_RG32F, w, h, /*levels=*/0);  // full chain
  const auto sizes = hiz_level_sizes(w, h);
  // GL's mip chain is the same chain: floor halving down to 1x1.
  assert(static_cast<int>(sizes.size()) == texture_.levels());
  glBindTextureUnit(TEX_HIZ, depth.id());
  for (int level = 0; level < texture_.levels(); ++level) {
    if (level == 1) glBindTextureUnit(TEX_HIZ, texture_.id());  // from now on, read the level below
    glProgramUniform1i(program_.id(), 0, level - 1);              // -1: copy the depth buffer
    glBindImageTexture(IMG_OUT, texture_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    const auto [lw, lh] = sizes[static_cast<std::size_t>(level)];
    program_.dispatch_2d(lw, lh);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the next level (and the trace) fetch this one
  }
  glBindTextureUnit(TEX_HIZ, texture_.id());  // for the trace (a 1x1 chain never rebound it)
}

}  // namespace ssr
