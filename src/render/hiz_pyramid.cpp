#include "render/hiz_pyramid.h"

#include <algorithm>
#include <cassert>

#include "shared/bindings.h"
#include "shared/hiz.h"

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
  const auto size = [&](int level) { return sizes[static_cast<std::size_t>(level)]; };
  // Each dispatch reads level s and writes s+1..s+n (hiz_pyramid.comp); the first reads the depth
  // buffer as level 0 and writes level 0 too. A 1x1 chain: its one level is both the copy and
  // the "reduction" of a 1x1 footprint.
  int s = 0;
  do {
    const bool first = s == 0;
    const int n = std::max(1, std::min(HIZ_LEVELS_PER_DISPATCH, levels - 1 - s));
    const int last = std::min(s + n, levels - 1);  // level s+n; the 1x1 chain's only level
    glBindTextureUnit(TEX_HIZ, first ? depth.id() : texture_.id());
    glProgramUniform1i(prog, 0, s);
    glProgramUniform1i(prog, 1, first ? 1 : 0);
    glProgramUniform1i(prog, 2, n);
    for (int j = 0; j <= HIZ_LEVELS_PER_DISPATCH; ++j) {
      // Units past level s+n get the last level written: bound, never stored to.
      const int level = std::min(s + j, last);
      glProgramUniform2i(prog, 3 + j, size(level).first, size(level).second);
      glBindImageTexture(IMG_HIZ_LEVELS + j, texture_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    }
    // A group per texel of level s+n (its footprint: 2^n x 2^n texels of level s, or up to the
    // level's end in an axis's last group).
    const auto [gw, gh] = size(last);
    glDispatchCompute(static_cast<GLuint>(gw), static_cast<GLuint>(gh), 1);
    // The next dispatch (and the trace) fetch these levels.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    s += n;
  } while (s + 1 < levels);
  glBindTextureUnit(TEX_HIZ, texture_.id());  // for the trace
}

}  // namespace ssr
