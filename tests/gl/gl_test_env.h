// Helpers shared by the GL tests.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gl/context.h"
#include "eval/metrics.h"
#include "render/renderer.h"

namespace ssr::test {

extern gl::HeadlessContext* g_context;

// Fails the current test with the GL errors recorded since the last call.
inline void expect_no_gl_errors() {
  for (const std::string& e : gl::take_gl_errors()) ADD_FAILURE() << "GL error: " << e;
}

inline std::size_t count_nonfinite(const RgbaImageF& im) { return ssr::count_nonfinite(im.pixels); }

// Texel (x, y) with y = 0 the top row.
inline const float* texel(const RgbaImageF& im, int x, int y) {
  return &im.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(im.width) +
                     static_cast<std::size_t>(x)) * 4];
}

// Pixels of planar reflectors (G-buffer reflector id > 0), row 0 = top like read-back images.
inline std::vector<bool> planar_mask(const Renderer& r) {
  const int w = r.width(), h = r.height();
  std::vector<std::uint8_t> m(static_cast<std::size_t>(w) * h * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(r.gbuffer().material.id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE,
                    static_cast<GLsizei>(m.size()), m.data());
  std::vector<bool> out(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      out[static_cast<std::size_t>(h - 1 - y) * w + x] = m[(static_cast<std::size_t>(y) * w + x) * 4] > 0;
  return out;
}

}  // namespace ssr::test
