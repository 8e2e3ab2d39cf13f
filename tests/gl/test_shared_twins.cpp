// The shared headers with functions, compiled as GLSL, agree with their C++ twins over a buffer
// of inputs: sampling.h (hash and random numbers bit for bit; the GGX VNDF sample, the basis and
// the reflection within float rounding), tonemap.h (the display transform) and colormap.h (the
// heat map, hue and category colours the views and the legends draw with); classification.h's
// and telemetry.h's integer helpers bit for bit; roughness_bands.h's rounding of the bounds.
// ppr_packing.h has its own bit-exact test (test_ppr_packing.cpp).
#include <gtest/gtest.h>


#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "gl/program.h"
#include "gl_test_env.h"
#include "shared/sampling.h"
#include "shared/tonemap.h"
#include "shared/classification.h"
#include "shared/colormap.h"
#include "shared/telemetry.h"
#include "shared/roughness_bands.h"

using namespace ssr;
namespace sh = ssr::shared;

namespace {

struct TwinCase {
  glm::vec4 n;         // xyz: a unit normal; w: an angle in [-pi, pi] (hue)
  glm::vec4 v;         // xyz: a unit view direction; w: roughness
  glm::vec4 radiance;  // xyz: HDR radiance; w: exposure (stops)
  glm::uvec4 ids;      // x, y, index, seed
};
struct TwinResult {
  glm::uvec4 hashes;   // pcg_hash(ids.x), uint_to_unit bits of ids.y, sample_xi bits (2)
  glm::vec4 basis[3];  // basis_from_normal(n) columns
  glm::vec4 vndf;      // sample_ggx_vndf(local view, alpha, xi)
  glm::vec4 reflection;  // sample_reflection(n, v, roughness, xi)
  glm::vec4 tonemap;   // tonemap_aces(radiance)
  glm::vec4 srgb;      // linear_to_srgb(tonemap)
  glm::vec4 display;   // display_transform(radiance, exposure)
  glm::vec4 heat;      // heat(v.w * 1.5 - 0.25): both clamps and the ramp
  glm::vec4 hue;       // hue(n.w): n.w an angle in [-pi, pi]
  glm::vec4 tile;      // tile_class_colour(ids.z % 5 - 1)
  glm::vec4 mask;      // mask_colour(ids.w & 1, ids.w & 2)
};
static_assert(sizeof(TwinCase) == 64 && sizeof(TwinResult) == 208);

const char* kShader = R"glsl(#include "shared/sampling.h"
#include "shared/tonemap.h"
#include "shared/colormap.h"
layout(local_size_x = 64) in;
struct TwinCase { vec4 n; vec4 v; vec4 radiance; uvec4 ids; };
struct TwinResult { uvec4 hashes; vec4 basis[3]; vec4 vndf; vec4 reflection; vec4 tonemap; vec4 srgb; vec4 display;
                    vec4 heat; vec4 hue; vec4 tile; vec4 mask; };
layout(std430, binding = 0) readonly buffer Cases { TwinCase cases[]; };
layout(std430, binding = 1) writeonly buffer Results { TwinResult results[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(cases.length())) return;
  TwinCase c = cases[i];
  vec2 xi = sample_xi(c.ids.x, c.ids.y, c.ids.z, c.ids.w);
  results[i].hashes = uvec4(pcg_hash(c.ids.x), floatBitsToUint(uint_to_unit(c.ids.y)), floatBitsToUint(xi));
  mat3 b = basis_from_normal(c.n.xyz);
  for (int k = 0; k < 3; ++k) results[i].basis[k] = vec4(b[k], 0.0);
  float alpha = max(c.v.w * c.v.w, 1e-4);
  vec3 ve = normalize(vec3(c.v.xy, max(abs(c.v.z), 1e-3)));
  results[i].vndf = vec4(sample_ggx_vndf(ve, alpha, xi), 0.0);
  results[i].reflection = vec4(sample_reflection(c.n.xyz, c.v.xyz, c.v.w, xi), 0.0);
  vec3 t = tonemap_aces(c.radiance.xyz * exp2(c.radiance.w));
  results[i].tonemap = vec4(t, 0.0);
  results[i].srgb = vec4(linear_to_srgb(t), 0.0);
  results[i].display = vec4(display_transform(c.radiance.xyz, c.radiance.w), 0.0);
  results[i].heat = vec4(heat(c.v.w * 1.5 - 0.25), 0.0);
  results[i].hue = vec4(hue(c.n.w), 0.0);
  results[i].tile = vec4(tile_class_colour(int(c.ids.z % 5u) - 1), 0.0);
  results[i].mask = vec4(mask_colour((c.ids.w & 1u) != 0u, (c.ids.w & 2u) != 0u), 0.0);
}
)glsl";

TwinResult cpu_result(const TwinCase& c) {
  TwinResult r{};
  const glm::vec2 xi = sh::sample_xi(c.ids.x, c.ids.y, c.ids.z, c.ids.w);
  auto bits = [](float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
  };
  r.hashes = {sh::pcg_hash(c.ids.x), bits(sh::uint_to_unit(c.ids.y)), bits(xi.x), bits(xi.y)};
  const glm::mat3 b = sh::basis_from_normal(glm::vec3(c.n));
  for (int k = 0; k < 3; ++k) r.basis[k] = glm::vec4(b[k], 0.0f);
  const float alpha = std::max(c.v.w * c.v.w, 1e-4f);
  const glm::vec3 ve = glm::normalize(glm::vec3(c.v.x, c.v.y, std::max(std::abs(c.v.z), 1e-3f)));
  r.vndf = glm::vec4(sh::sample_ggx_vndf(ve, alpha, xi), 0.0f);
  r.reflection = glm::vec4(sh::sample_reflection(glm::vec3(c.n), glm::vec3(c.v), c.v.w, xi), 0.0f);
  const glm::vec3 t = sh::tonemap_aces(glm::vec3(c.radiance) * std::exp2(c.radiance.w));
  r.tonemap = glm::vec4(t, 0.0f);
  r.srgb = glm::vec4(sh::linear_to_srgb(t), 0.0f);
  r.display = glm::vec4(sh::display_transform(glm::vec3(c.radiance), c.radiance.w), 0.0f);
  r.heat = glm::vec4(sh::heat(c.v.w * 1.5f - 0.25f), 0.0f);
  r.hue = glm::vec4(sh::hue(c.n.w), 0.0f);
  r.tile = glm::vec4(sh::tile_class_colour(static_cast<int>(c.ids.z % 5u) - 1), 0.0f);
  r.mask = glm::vec4(sh::mask_colour((c.ids.w & 1u) != 0u, (c.ids.w & 2u) != 0u), 0.0f);
  return r;
}

std::vector<TwinCase> make_cases() {
  std::mt19937 rng(1973);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), unit(0.0f, 1.0f), stops(-4.0f, 4.0f);
  std::uniform_int_distribution<std::uint32_t> any;
  auto unit_vec = [&] {
    glm::vec3 d;
    do d = {u(rng), u(rng), u(rng)}; while (glm::dot(d, d) < 1e-4f || glm::dot(d, d) > 1.0f);
    return glm::normalize(d);
  };
  std::vector<TwinCase> cases;
  // The corners: axis normals (the basis's branch), grazing views, roughness 0 and 1, black and
  // very bright radiance, the largest ids.
  const glm::vec3 axes[] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  for (const glm::vec3& a : axes)
    for (const float r : {0.0f, 0.01f, 0.5f, 1.0f})
      cases.push_back({glm::vec4(a, 0), glm::vec4(glm::normalize(a + glm::vec3(0.3f, -0.2f, 0.1f)), r),
                       glm::vec4(0.0f, 1.0f, 1e4f, 0.0f), glm::uvec4(0, 0xffffffffu, 7, 0x80000000u)});
  for (int i = 0; i < 4000; ++i) {
    const glm::vec3 n = unit_vec();
    glm::vec3 v = unit_vec();
    if (glm::dot(v, n) < 0.0f) v = -v;  // views from the surface's side, some grazing
    const float rough = i % 7 == 0 ? 0.0f : unit(rng);
    const glm::vec3 rad(unit(rng) * 8.0f, unit(rng) * unit(rng), i % 11 == 0 ? 0.0f : unit(rng) * 100.0f);
    cases.push_back({glm::vec4(n, u(rng) * 3.14159265f), glm::vec4(v, rough), glm::vec4(rad, stops(rng)),
                     glm::uvec4(any(rng) % 8192u, any(rng) % 8192u, any(rng) % 64u, any(rng))});
  }
  return cases;
}

float max_diff(glm::vec4 a, glm::vec4 b) {
  const glm::vec4 d = glm::abs(a - b);
  return std::max(std::max(d.x, d.y), std::max(d.z, d.w));
}

}  // namespace

// Tolerances for the float functions: the GLSL compiler may contract a*b+c into fma and use its
// own sqrt/sin/cos/pow; measured on llvmpipe (LLVM 15), 4020 cases: basis 1.2e-7, vndf 1.6e-5,
// reflection 5.2e-6, tonemap 2.4e-7, srgb 3.6e-7, display 3.6e-7, heat 6e-8, hue 0. The bounds (6x and more) leave
// room for a GPU's transcendentals.
TEST(SharedTwins, SamplingTonemapAndColormapGlslMatchCpp) {
  const gl::Program prog = test::compile_test_shader("twins", kShader);
  const std::vector<TwinCase> cases = make_cases();
  const std::vector<TwinResult> gpu = test::run_twin_shader<TwinResult>(prog, cases);

  std::size_t bad_bits = 0;
  float basis = 0, vndf = 0, refl = 0, tonemap = 0, srgb = 0, display = 0, heat = 0, hue = 0, swatches = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const TwinResult c = cpu_result(cases[i]);
    const TwinResult& g = gpu[i];
    if (g.hashes != c.hashes && ++bad_bits <= 5)
      ADD_FAILURE() << "case " << i << ": hash/xi bits differ: gpu " << g.hashes.x << " " << g.hashes.y << " "
                    << g.hashes.z << " " << g.hashes.w << ", cpu " << c.hashes.x << " " << c.hashes.y << " "
                    << c.hashes.z << " " << c.hashes.w;
    for (int k = 0; k < 3; ++k) basis = std::max(basis, max_diff(g.basis[k], c.basis[k]));
    vndf = std::max(vndf, max_diff(g.vndf, c.vndf));
    refl = std::max(refl, max_diff(g.reflection, c.reflection));
    tonemap = std::max(tonemap, max_diff(g.tonemap, c.tonemap));
    srgb = std::max(srgb, max_diff(g.srgb, c.srgb));
    display = std::max(display, max_diff(g.display, c.display));
    heat = std::max(heat, max_diff(g.heat, c.heat));
    hue = std::max(hue, max_diff(g.hue, c.hue));
    swatches = std::max({swatches, max_diff(g.tile, c.tile), max_diff(g.mask, c.mask)});
  }
  std::printf("shared twins: %zu cases; max |gpu - cpu|: basis %.2g, vndf %.2g, reflection %.2g, tonemap %.2g, "
              "srgb %.2g, display %.2g, heat %.2g, hue %.2g, swatches %.2g\n", cases.size(), basis, vndf, refl, tonemap,
              srgb, display, heat, hue, swatches);
  EXPECT_EQ(bad_bits, 0u);
  EXPECT_LE(basis, 1e-5f);
  EXPECT_LE(vndf, 1e-4f);
  EXPECT_LE(refl, 1e-4f);
  EXPECT_LE(tonemap, 1e-5f);
  EXPECT_LE(srgb, 1e-4f);
  EXPECT_LE(heat, 1e-5f);
  EXPECT_LE(hue, 1e-4f);
  EXPECT_EQ(swatches, 0.0f);  // constants chosen by branches: exact
  EXPECT_LE(display, 1e-4f);
  test::expect_no_gl_errors();
}

// The integer helpers of classification.h (the quad rotation, the ray list's texel packing) and
// telemetry.h (the per-pixel word) agree bit for bit; the idle share's float exactly.
struct IntCase {
  glm::ivec4 p;   // pixel x, y, frame index, rays per quad (1, 2, 4)
  glm::vec4 idle; // x: an idle share (some outside [0, 1]); y: iterations (as a float)
};
struct IntResult {
  glm::ivec4 quad;    // quad_offset(frame).xy, quad_traces(p, frame, rays), 0
  glm::uvec4 texel;   // pack_texel(p.xy), unpack_texel(..).xy, telemetry_pack(iterations, idle)
  glm::vec4 word;     // telemetry_iterations(word) (as float), telemetry_idle(word)
};
static_assert(sizeof(IntCase) == 32 && sizeof(IntResult) == 48);

TEST(SharedTwins, ClassificationAndTelemetryHelpersGlslMatchCpp) {
  const char* shader = R"glsl(#include "shared/classification.h"
#include "shared/telemetry.h"
layout(local_size_x = 64) in;
struct IntCase { ivec4 p; vec4 idle; };
struct IntResult { ivec4 quad; uvec4 texel; vec4 word; };
layout(std430, binding = 0) readonly buffer Cases { IntCase cases[]; };
layout(std430, binding = 1) writeonly buffer Results { IntResult results[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(cases.length())) return;
  IntCase c = cases[i];
  results[i].quad = ivec4(quad_offset(c.p.z), quad_traces(c.p.xy, c.p.z, c.p.w) ? 1 : 0, 0);
  uint t = pack_texel(c.p.xy);
  uint w = telemetry_pack(uint(c.idle.y), c.idle.x);
  results[i].texel = uvec4(t, uvec2(unpack_texel(t)), w);
  results[i].word = vec4(float(telemetry_iterations(w)), telemetry_idle(w), 0.0, 0.0);
}
)glsl";
  const gl::Program prog = test::compile_test_shader("int_twins", shader);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(0, 16383), frame(0, 1 << 20), rays_pick(0, 2), iters(0, 100000);
  std::uniform_real_distribution<float> idle(-0.5f, 1.5f);
  std::vector<IntCase> cases;
  for (int i = 0; i < 4096; ++i)
    cases.push_back({glm::ivec4(coord(rng), coord(rng), i < 64 ? i : frame(rng), 1 << rays_pick(rng)),
                     glm::vec4(i % 9 == 0 ? 1.0f : idle(rng), static_cast<float>(iters(rng)), 0, 0)});
  const std::vector<IntResult> gpu = test::run_twin_shader<IntResult>(prog, cases);
  std::size_t bad = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const IntCase& c = cases[i];
    const glm::ivec2 o = sh::quad_offset(c.p.z);
    const std::uint32_t t = sh::pack_texel(glm::ivec2(c.p.x, c.p.y));
    const std::uint32_t w = sh::telemetry_pack(static_cast<std::uint32_t>(c.idle.y), c.idle.x);
    const IntResult cpu{glm::ivec4(o, sh::quad_traces(glm::ivec2(c.p.x, c.p.y), c.p.z, c.p.w) ? 1 : 0, 0),
                        glm::uvec4(t, glm::uvec2(sh::unpack_texel(t)), w),
                        glm::vec4(static_cast<float>(sh::telemetry_iterations(w)), sh::telemetry_idle(w), 0, 0)};
    if ((gpu[i].quad != cpu.quad || gpu[i].texel != cpu.texel || gpu[i].word != cpu.word) && ++bad <= 5)
      ADD_FAILURE() << "case " << i << " (pixel " << c.p.x << "," << c.p.y << " frame " << c.p.z << " rays " << c.p.w
                    << "): gpu and cpu differ";
    // The round trips hold: the texel comes back, the iterations saturate at 16 bits.
    EXPECT_EQ(glm::ivec2(sh::unpack_texel(t)), glm::ivec2(c.p.x, c.p.y));
    EXPECT_EQ(sh::telemetry_iterations(w), std::min(static_cast<std::uint32_t>(c.idle.y), 65535u));
  }
  EXPECT_EQ(bad, 0u);
}

// roughness_bands.h's rounding to the G-buffer's half float, which the verdicts' bands and the
// spatial stage's "lobe wide enough to reuse by the BRDF" test both apply to the mirror bound:
// the bounds bit for bit, so both place a material at exactly 0.05 on the same side of it (as
// stored, 0.05 is below 0.05). Elsewhere the two may differ by one half-float step: GL leaves
// the rounding of halfway cases to the implementation (llvmpipe rounds 0.5 + 2^-12 down, glm
// up); 0.05 and 0.4 are not halfway cases.
TEST(SharedTwins, StoredRoughnessGlslMatchesCpp) {
  const char* shader = R"glsl(#include "shared/roughness_bands.h"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Cases { vec4 cases[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(cases.length())) return;
  results[i] = vec4(as_stored_roughness(cases[i].x), as_stored_roughness(MIRROR_BAND_BELOW),
                    as_stored_roughness(ROUGH_BAND_ABOVE), 0.0);
}
)glsl";
  const gl::Program prog = test::compile_test_shader("roughness_twins", shader);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec4> cases;
  for (int i = 0; i < 4096; ++i) cases.emplace_back(i < 2 ? static_cast<float>(i) : unit(rng), 0, 0, 0);
  const std::vector<glm::vec4> gpu = test::run_twin_shader<glm::vec4>(prog, cases);
  const float mirror = sh::as_stored_roughness(MIRROR_BAND_BELOW), rough = sh::as_stored_roughness(ROUGH_BAND_ABOVE);
  std::size_t bad = 0, exact = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const float cpu = sh::as_stored_roughness(cases[i].x);
    const float step = std::max(std::abs(cpu) / 1024.0f, 1e-7f);  // a half's step near cpu (10-bit mantissa)
    exact += gpu[i].x == cpu;
    if ((gpu[i].y != mirror || gpu[i].z != rough || std::abs(gpu[i].x - cpu) > step) && ++bad <= 5)
      ADD_FAILURE() << "roughness " << cases[i].x << ": gpu " << gpu[i].x << " " << gpu[i].y << " " << gpu[i].z
                    << ", cpu " << cpu << " " << mirror << " " << rough;
  }
  std::printf("stored roughness: %zu of %zu random values bit for bit\n", exact, cases.size());
  EXPECT_EQ(bad, 0u);
  EXPECT_LT(mirror, static_cast<float>(MIRROR_BAND_BELOW));  // why the rounding is needed
  EXPECT_GE(sh::as_stored_roughness(0.05f), mirror);         // an authored 0.05 is glossy
  EXPECT_LT(sh::as_stored_roughness(0.0499f), mirror);       // the next half below is a mirror
}
