// Helpers shared by the GL tests.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gl/context.h"
#include "render/renderer.h"

namespace ssr::test {

extern gl::HeadlessContext* g_context;

// Fails the current test with the GL errors recorded since the last call.
inline void expect_no_gl_errors() {
  for (const std::string& e : gl::take_gl_errors()) ADD_FAILURE() << "GL error: " << e;
}

inline std::size_t count_nonfinite(const RgbaImageF& im) {
  std::size_t n = 0;
  for (float v : im.pixels) n += !std::isfinite(v);
  return n;
}

// Texel (x, y) with y = 0 the top row.
inline const float* texel(const RgbaImageF& im, int x, int y) {
  return &im.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(im.width) +
                     static_cast<std::size_t>(x)) * 4];
}

}  // namespace ssr::test
