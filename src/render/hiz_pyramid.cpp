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
  const int levels = texture_.levels();
  assert(static_cast<int>(sizes.size()) == levels);
  const GLuint prog = program_.id();
  glUseProgram(prog);
  // Each dispatch reads level s and writes s+1 and s+2 (hiz_pyramid.comp); the first reads the
  // depth buffer as level 0 and writes level 0 too. A 1x1 chain: its one level is both the copy
  // and the "reduction" of a 1x1 footprint.
  glBindImageTexture(IMG_REFRACTION, texture_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
  const auto size = [&](int level) { return sizes[static_cast<std::size_t>(level)]; };
  int s = 0;
  do {
    const bool first = s == 0;
    const int l1 = std::min(s + 1, levels - 1);
    const bool two = s + 2 < levels;
    const int l2 = two ? s + 2 : l1;
    glBindTextureUnit(TEX_HIZ, first ? depth.id() : texture_.id());
    glProgramUniform1i(prog, 0, s);
    glProgramUniform1i(prog, 1, first ? 1 : 0);
    glProgramUniform1i(prog, 2, two ? 1 : 0);
    glProgramUniform2i(prog, 3, size(s).first, size(s).second);
    glProgramUniform2i(prog, 4, size(l1).first, size(l1).second);
    glProgramUniform2i(prog, 5, size(l2).first, size(l2).second);
    glBindImageTexture(IMG_OUT, texture_.id(), l1, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    glBindImageTexture(IMG_OUT2, texture_.id(), l2, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    // A group: 4x4 texels of level s+2 (and the 8x8 of s+1 under them), or 8x8 of s+1 alone.
    const int per = two ? 4 : 8;
    const auto [gw, gh] = size(two ? l2 : l1);
    glDispatchCompute(static_cast<GLuint>((gw + per - 1) / per), static_cast<GLuint>((gh + per - 1) / per), 1);
    // The next dispatch (and the trace) fetch these levels.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    s += two ? 2 : 1;
  } while (s + 1 < levels);
  glBindTextureUnit(TEX_HIZ, texture_.id());  // for the trace
}

}  // namespace ssr
