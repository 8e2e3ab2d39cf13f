// The PPR packing (shaders/shared/ppr_packing.h) compiled as GLSL gives the very bits the C++
// twin gives: ppr_pack, ppr_unpack, ppr_fraction_bits, ppr_is_empty over a buffer of inputs
// (Falcor's PackedFormatsTests pattern).
#include <gtest/gtest.h>


#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "gl/program.h"
#include "gl_test_env.h"
#include "shared/ppr_packing.h"

using namespace ssr;
namespace sh = ssr::shared;

namespace {

// std430 layouts of the test shader's buffers (vec2 first, then 4-byte scalars: no padding).
struct PprCase {
  glm::vec2 offset;
  std::uint32_t fraction_bits;
  std::uint32_t raw;  // any 32-bit value, for ppr_unpack / ppr_is_empty of arbitrary bits
  std::uint32_t width, height;
  std::uint32_t pad0 = 0, pad1 = 0;
};
struct PprResult {
  glm::vec2 unpacked;      // ppr_unpack(ppr_pack(offset, fb), fb)
  glm::vec2 unpacked_raw;  // ppr_unpack(raw, fb)
  std::uint32_t packed;    // ppr_pack(offset, fb)
  std::uint32_t fraction_bits;  // ppr_fraction_bits(width, height)
  std::uint32_t raw_empty;      // ppr_is_empty(raw)
  std::uint32_t orientation;    // ppr_orientation(packed)
};
static_assert(sizeof(PprCase) == 32 && sizeof(PprResult) == 32);

const char* kShader = R"glsl(#include "shared/ppr_packing.h"
layout(local_size_x = 64) in;
struct PprCase { vec2 offset; uint fraction_bits; uint raw; uint width; uint height; uint pad0; uint pad1; };
struct PprResult { vec2 unpacked; vec2 unpacked_raw; uint packed_value; uint fraction_bits; uint raw_empty; uint orientation; };
layout(std430, binding = 0) readonly buffer Cases { PprCase cases[]; };
layout(std430, binding = 1) writeonly buffer Results { PprResult results[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(cases.length())) return;
  PprCase c = cases[i];
  uint p = ppr_pack(c.offset, c.fraction_bits);
  results[i].unpacked = ppr_unpack(p, c.fraction_bits);
  results[i].unpacked_raw = ppr_unpack(c.raw, c.fraction_bits);
  results[i].packed_value = p;
  results[i].fraction_bits = ppr_fraction_bits(c.width, c.height);
  results[i].raw_empty = ppr_is_empty(c.raw) ? 1u : 0u;
  results[i].orientation = ppr_orientation(p);
}
)glsl";

PprResult cpu_result(const PprCase& c) {
  const std::uint32_t p = sh::ppr_pack(c.offset, c.fraction_bits);
  return PprResult{.unpacked = sh::ppr_unpack(p, c.fraction_bits),
                   .unpacked_raw = sh::ppr_unpack(c.raw, c.fraction_bits),
                   .packed = p,
                   .fraction_bits = sh::ppr_fraction_bits(c.width, c.height),
                   .raw_empty = sh::ppr_is_empty(c.raw) ? 1u : 0u,
                   .orientation = sh::ppr_orientation(p)};
}

std::vector<PprCase> make_cases() {
  std::vector<PprCase> cases;
  std::mt19937 rng(2018);
  std::uniform_int_distribution<std::uint32_t> any_bits;
  std::uniform_int_distribution<std::uint32_t> any_size(1, 40000);
  auto add = [&](glm::vec2 o, std::uint32_t fb) {
    const std::uint32_t raw = cases.size() % 17 == 0 ? sh::PPR_EMPTY : any_bits(rng);
    const std::uint32_t w = any_size(rng), h = cases.size() % 5 == 0 ? w : any_size(rng);
    cases.push_back(PprCase{.offset = o, .fraction_bits = fb, .raw = raw, .width = w, .height = h});
  };
  // The named sizes (and what ppr_fraction_bits says for them).
  for (const glm::uvec2 sz : {glm::uvec2(1920, 1080), glm::uvec2(3840, 2160), glm::uvec2(7680, 4320),
                              glm::uvec2(1, 1), glm::uvec2(0, 0), glm::uvec2(4096, 4096), glm::uvec2(4097, 3),
                              glm::uvec2(16384, 9), glm::uvec2(65535, 65535)}) {
    cases.push_back(PprCase{.offset = {0, 0}, .fraction_bits = 2, .raw = 0, .width = sz.x, .height = sz.y});
  }
  const float nan_free_big = 1e30f;
  for (std::uint32_t fb = 0; fb <= 14; ++fb) {
    const float s = std::ldexp(1.0f, -static_cast<int>(fb));
    const float top = std::ldexp(1.0f, 14 - static_cast<int>(fb));
    // Every orientation, ties, zero, negative fractions, clamps.
    for (const glm::vec2 o :
         {glm::vec2(0, 0), glm::vec2(-0.0f, -0.0f), glm::vec2(0, 5 * s), glm::vec2(5 * s, 0), glm::vec2(0, -5 * s),
          glm::vec2(-5 * s, 0), glm::vec2(2 * s, 2 * s), glm::vec2(-2 * s, 2 * s), glm::vec2(-3.25f, 0.5f),
          glm::vec2(0.5f, -3.25f), glm::vec2(-0.5f, -0.25f), glm::vec2(-4095.75f, 1.0f), glm::vec2(1.0f, -4095.75f),
          glm::vec2(7679.5f, -4319.5f), glm::vec2(-7679.0f, 4319.0f), glm::vec2(-4319.5f, -7679.5f),
          glm::vec2(3839.75f, 2159.75f), glm::vec2(-3839.75f, -2159.75f), glm::vec2(top - s, -top),
          glm::vec2(top, top * 3), glm::vec2(-nan_free_big, 0.5f * nan_free_big), glm::vec2(nan_free_big, -nan_free_big),
          glm::vec2(-3.125f, 0.375f), glm::vec2(0.125f, -1.0f / 3.0f)})
      add(o, fb);
    // Exact ties and their float neighbours: the rounding must agree to the last bit.
    for (int k = -40; k <= 40; ++k) {
      const float tie = (static_cast<float>(k) + 0.5f) * s;
      for (const float v : {tie, std::nextafter(tie, -1e9f), std::nextafter(tie, 1e9f)}) {
        add({v, 0.25f * v}, fb);
        add({0.5f * v, v}, fb);
        add({-v, 3.0f * s}, fb);
      }
    }
    // Random offsets in and a bit beyond the range, and on the step grid.
    std::uniform_real_distribution<float> in_range(-1.1f * top, 1.1f * top), near(-6.0f, 6.0f);
    std::uniform_int_distribution<int> grid(-(1 << 14), (1 << 14) - 1);
    for (int i = 0; i < 1500; ++i) {
      add({in_range(rng), in_range(rng)}, fb);
      add({near(rng), near(rng)}, fb);
      add({static_cast<float>(grid(rng)) * s, static_cast<float>(grid(rng)) * s}, fb);
    }
  }
  return cases;
}

bool same(glm::vec2 a, glm::vec2 b) { return a.x == b.x && a.y == b.y; }

}  // namespace

TEST(PprPackingGl, GlslMatchesCppBitForBit) {
  const gl::Program prog = test::compile_test_shader("ppr_packing", kShader);
  const std::vector<PprCase> cases = make_cases();
  const std::vector<PprResult> gpu = test::run_twin_shader<PprResult>(prog, cases);

  int bad_pack = 0, bad_unpack = 0, bad_raw = 0, bad_fb = 0, bad_empty = 0, bad_orient = 0, empties = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const PprCase& c = cases[i];
    const PprResult cpu = cpu_result(c);
    const PprResult& g = gpu[i];
    const bool ok = g.packed == cpu.packed && same(g.unpacked, cpu.unpacked) &&
                    same(g.unpacked_raw, cpu.unpacked_raw) && g.fraction_bits == cpu.fraction_bits &&
                    g.raw_empty == cpu.raw_empty && g.orientation == cpu.orientation;
    bad_pack += g.packed != cpu.packed;
    bad_unpack += !same(g.unpacked, cpu.unpacked);
    bad_raw += !same(g.unpacked_raw, cpu.unpacked_raw);
    bad_fb += g.fraction_bits != cpu.fraction_bits;
    bad_empty += g.raw_empty != cpu.raw_empty;
    bad_orient += g.orientation != cpu.orientation;
    empties += cpu.raw_empty;
    if (!ok && bad_pack + bad_unpack + bad_raw + bad_fb + bad_empty + bad_orient <= 10)
      ADD_FAILURE() << "case " << i << ": offset (" << c.offset.x << ", " << c.offset.y << ") fb " << c.fraction_bits
                    << " raw 0x" << std::hex << c.raw << " size " << std::dec << c.width << "x" << c.height
                    << "\n  packed   gpu 0x" << std::hex << g.packed << " cpu 0x" << cpu.packed << std::dec
                    << "\n  unpacked gpu (" << g.unpacked.x << ", " << g.unpacked.y << ") cpu (" << cpu.unpacked.x
                    << ", " << cpu.unpacked.y << ")"
                    << "\n  raw      gpu (" << g.unpacked_raw.x << ", " << g.unpacked_raw.y << ") cpu ("
                    << cpu.unpacked_raw.x << ", " << cpu.unpacked_raw.y << ")"
                    << "\n  fraction bits gpu " << g.fraction_bits << " cpu " << cpu.fraction_bits << ", empty gpu "
                    << g.raw_empty << " cpu " << cpu.raw_empty << ", orientation gpu " << g.orientation << " cpu "
                    << cpu.orientation;
  }
  std::printf("ppr packing: %zu cases (%d raw PPR_EMPTY), mismatches: pack %d, unpack %d, unpack(raw) %d, "
              "fraction_bits %d, is_empty %d, orientation %d\n",
              cases.size(), empties, bad_pack, bad_unpack, bad_raw, bad_fb, bad_empty, bad_orient);
  EXPECT_EQ(bad_pack, 0);
  EXPECT_EQ(bad_unpack, 0);
  EXPECT_EQ(bad_raw, 0);
  EXPECT_EQ(bad_fb, 0);
  EXPECT_EQ(bad_empty, 0);
  EXPECT_EQ(bad_orient, 0);
  EXPECT_GT(empties, 0);
  test::expect_no_gl_errors();
}
