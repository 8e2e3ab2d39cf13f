// The pass-floor microbenchmark (eval/pass_floor.h, `ssrlab passfloor`) compares like with like:
// every mode (compute group shapes, fragment) writes every pixel of every kind the same, chains
// feed each pass the one before (or the source, when independent), the compute modes run the
// group sizes they are named for, and a run restores the context state it changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "core/errors.h"
#include "eval/pass_floor.h"
#include "gl_test_env.h"

using namespace ssr;

namespace {

constexpr int kW = 37, kH = 23;  // odd sides: the compute groups overhang the image on both axes

// An RGBA image in GL rows (y = 0 at the bottom), as the passes address it.
using Texels = std::vector<float>;
float* px(Texels& im, int x, int y) { return &im[(static_cast<std::size_t>(y) * kW + static_cast<std::size_t>(x)) * 4]; }

Texels source() {
  Texels im(static_cast<std::size_t>(kW * kH * 4));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) pass_floor_source(x, y, px(im, x, y));
  return im;
}

// One pass of kind `k` on `in` (the shader's arithmetic in float), stored as RGBA16F stores it.
Texels apply(const PassFloorKind& k, Texels in) {
  const std::string name = k.name;
  Texels out(in.size(), 0.0f);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      float* o = px(out, x, y);
      if (name == "empty") continue;  // nothing written: the target as cleared
      if (name == "store") {
        const float c[4] = {0.25f, 0.5f, 0.75f, 1.0f};
        std::copy(c, c + 4, o);
      } else if (name == "copy") {
        std::copy(px(in, x, y), px(in, x, y) + 4, o);
      } else {
        const int r = name == "taps3x3" ? 1 : 2;
        for (int dy = -r; dy <= r; ++dy)
          for (int dx = -r; dx <= r; ++dx) {
            const float* s = px(in, std::clamp(x + dx, 0, kW - 1), std::clamp(y + dy, 0, kH - 1));
            for (int c = 0; c < 4; ++c) o[c] += s[c] * (1.0f + 0.125f * static_cast<float>(dx + 2 * dy));
          }
        for (int c = 0; c < 4; ++c) o[c] /= static_cast<float>((2 * r + 1) * (2 * r + 1));
      }
      for (int c = 0; c < 4; ++c) o[c] = glm::unpackHalf1x16(glm::packHalf1x16(o[c]));
    }
  return out;
}

// Pixels (channels) of `got` (top row first) further than `tolerance` from `want` (GL rows);
// the first one described in `where`.
int count_wrong(const RgbaImageF& got, Texels want, float tolerance, std::string& where) {
  int wrong = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 4; ++c) {
        const float g = got.at(x, kH - 1 - y)[c], w = px(want, x, y)[c];
        if (std::abs(g - w) <= tolerance) continue;
        if (wrong++ == 0) {
          std::ostringstream s;
          s << "first at (" << x << ", " << y << ") channel " << c << ": " << g << " against " << w;
          where = s.str();
        }
      }
  return wrong;
}

}  // namespace

TEST(PassFloor, EveryModeWritesWhatItsKindSays) {
  PassFloorBench bench(gl::ShaderSource(), kW, kH);
  ASSERT_GE(pass_floor_modes().size(), 2u);
  for (const PassFloorMode& m : pass_floor_modes())
    for (const PassFloorKind& k : pass_floor_kinds()) {
      const RgbaImageF out = bench.run_once(m, k);
      ASSERT_EQ(out.pixels.size(), static_cast<std::size_t>(kW * kH * 4));
      std::string where;
      // One pass: the GPU's float arithmetic and one rounding to half against the same here.
      EXPECT_EQ(count_wrong(out, apply(k, source()), 1.0f / 1024.0f, where), 0) << m.name << " / " << k.name << ": " << where;
    }
  test::expect_no_gl_errors();
}

TEST(PassFloor, ChainsFeedEachPassTheOneBeforeOrTheSource) {
  PassFloorBench bench(gl::ShaderSource(), kW, kH);
  const PassFloorKind& taps = pass_floor_kind("taps3x3");
  Texels once = apply(taps, source()), thrice = apply(taps, apply(taps, once));
  for (const PassFloorMode& m : pass_floor_modes()) {
    std::string where;
    // Three roundings to half, each up to 2^-11 of values below 2: 2^-9 covers them.
    EXPECT_EQ(count_wrong(bench.run_once(m, taps, 3), m.dependent ? thrice : once, 1.0f / 512.0f, where), 0)
        << m.name << (m.dependent ? " (dependent)" : " (independent)") << ": " << where;
  }
  test::expect_no_gl_errors();
}

TEST(PassFloor, ComputeModesRunTheirGroupSizes) {
  PassFloorBench bench(gl::ShaderSource(), kW, kH);
  for (const PassFloorMode& m : pass_floor_modes()) {
    const std::array<int, 2> size = bench.group_size(m, pass_floor_kind("copy"));
    EXPECT_EQ(size[0], m.local_x) << m.name;
    EXPECT_EQ(size[1], m.local_y) << m.name;
  }
}

TEST(PassFloor, LeavesTheContextAsItFoundIt) {
  GLuint vao = 0, fbo = 0;
  glCreateVertexArrays(1, &vao);
  glCreateFramebuffers(1, &fbo);
  GLuint tex = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &tex);
  glTextureStorage2D(tex, 1, GL_RGBA8, 8, 8);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, tex, 0);
  glBindVertexArray(vao);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
  glViewport(1, 2, 5, 6);
  glEnable(GL_BLEND);
  {
    PassFloorBench bench(gl::ShaderSource(), kW, kH);
    for (const PassFloorMode& m : pass_floor_modes()) {
      bench.run_once(m, pass_floor_kind("copy"), 2);
      bench.time_ms(m, pass_floor_kind("store"), 1, 1, gl::PassTimer::Clock::Cpu);
    }
  }
  GLint viewport[4], bound_vao = 0, bound_fbo = 0;
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &bound_vao);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound_fbo);
  EXPECT_EQ(viewport[0], 1);
  EXPECT_EQ(viewport[1], 2);
  EXPECT_EQ(viewport[2], 5);
  EXPECT_EQ(viewport[3], 6);
  EXPECT_EQ(static_cast<GLuint>(bound_vao), vao);
  EXPECT_EQ(static_cast<GLuint>(bound_fbo), fbo);
  EXPECT_TRUE(glIsEnabled(GL_BLEND));
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  glDeleteFramebuffers(1, &fbo);
  glDeleteTextures(1, &tex);
  glDeleteVertexArrays(1, &vao);
  test::expect_no_gl_errors();
}

TEST(PassFloor, UnknownNamesAreInputErrors) {
  EXPECT_THROW(pass_floor_mode("cs7x7"), InputError);
  EXPECT_THROW(pass_floor_kind("taps9x9"), InputError);
}
