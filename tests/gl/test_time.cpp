// Time: motion vectors against analytic values, history (the previous frame's targets) and the
// frame's rules for it (resets, non-finite values, resources built only when declared).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "gl_test_env.h"
#include "render/renderer.h"
#include "scene/animation.h"
#include "scene/builtin_scenes.h"
#include "techniques/assignments.h"
#include "scene_builders.h"
#include "techniques/technique.h"
#include "registry/registry.h"

using namespace ssr;
using test::add_mesh;
using test::camera;
using test::material;
using test::point_light;

namespace {

constexpr int kW = 96, kH = 64;

// A diffuse back wall (z = -5, x in [-6, 6], y in [0, 2]: sky above it) on a floor, with a
// box standing in front. Seen horizontally from (0, 1, 0).
Scene wall_scene() {
  Scene s;
  s.name = "time-test";
  s.materials = {material({0.7f, 0.7f, 0.7f}, 0.8f, 0.0f, 0.0f), material({0.8f, 0.2f, 0.1f}, 0.8f, 0.0f, 0.0f),
                 material({0.3f, 0.5f, 0.8f}, 0.8f, 0.0f, 0.0f)};
  add_mesh(s, meshgen::plane({12.0f, 10.0f}), "floor", 0, glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -2.5f}));
  add_mesh(s, meshgen::plane({12.0f, 2.0f}), "wall", 2,
           glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, -5.0f}) *
               glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), {1.0f, 0.0f, 0.0f}));
  add_mesh(s, meshgen::box({0.6f, 0.6f, 0.6f}), "box", 1, glm::translate(glm::mat4(1.0f), {-0.4f, 0.3f, -3.0f}));
  s.lights = {point_light({0.0f, 3.0f, -1.0f}, 20.0f)};
  s.cameras = {camera("default", {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, -5.0f}, 60.0f)};
  validate(s);
  return s;
}

// The motion vector the G-buffer should hold at (x, y_top) for a point at reversed-Z depth `d`
// (0: sky), given this frame's and the previous frame's matrices, and the point's motion
// `world_prev` (this frame's world point -> where it was).
template <class F>
glm::vec2 expected_motion(const CameraMatrices& now, const CameraMatrices& before, int x, int y_top,
                          float d, F world_prev) {
  const int y = kH - 1 - y_top;  // GL rows go up
  const glm::vec2 px(x + 0.5f, y + 0.5f);
  const glm::vec2 ndc = px / glm::vec2(kW, kH) * 2.0f - 1.0f;
  const glm::mat4 vp = now.proj * now.view, prev_vp = before.proj * before.view;
  glm::vec4 prev_clip;
  if (d > 0.0f) {
    const glm::vec4 w = glm::inverse(vp) * glm::vec4(ndc, d, 1.0f);
    prev_clip = prev_vp * glm::vec4(world_prev(glm::vec3(w) / w.w), 1.0f);
  } else {  // the sky: a direction, moved by the rotation only
    const glm::vec4 v = glm::inverse(now.proj) * glm::vec4(ndc, 0.5f, 1.0f);
    const glm::vec3 dir = glm::mat3(glm::inverse(now.view)) * glm::normalize(glm::vec3(v) / v.w);
    prev_clip = prev_vp * glm::vec4(dir, 0.0f);
  }
  const glm::vec2 prev_px = (glm::vec2(prev_clip) / prev_clip.w * 0.5f + 0.5f) * glm::vec2(kW, kH);
  return prev_px - px;
}

// Renders two consecutive frames (cameras a then b, times ta then tb) with `none` and returns
// the largest |motion - expected| over the frame, and the motion image.
template <class F>
double motion_error(const Scene& s, const Camera& a, const Camera& b, float ta, float tb, F world_prev,
                    RgbaImageF* motion_out = nullptr) {
  Renderer r(s, kW, kH);
  auto none = create_technique("none");
  none->load(r.shaders());
  r.render(FrameRequest(a, {0, ta}), *none, ViewMode::Final, nullptr);
  r.render(FrameRequest(b, {1, tb}), *none, ViewMode::Final, nullptr);
  const RgbaImageF motion = r.read_texture(r.motion());
  const std::vector<float> depth = r.read_depth();
  const std::vector<std::uint16_t> material = r.read_material();
  const CameraMatrices ma = camera_matrices(a, kW, kH), mb = camera_matrices(b, kW, kH);
  double worst = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kW + x;
      const glm::vec2 want = expected_motion(mb, ma, x, y, depth[i], [&](glm::vec3 p) {
        return world_prev(p, static_cast<int>(material[i * 4 + 3]));
      });
      const glm::vec2 got(motion.pixels[i * 4], motion.pixels[i * 4 + 1]);
      worst = std::max(worst, static_cast<double>(glm::length(got - want)));
    }
  if (motion_out) *motion_out = motion;
  test::expect_no_gl_errors();
  return worst;
}

}  // namespace

// The camera moves 0.1 right: every wall pixel (5 units away) moved f * 0.1 / 5 pixels, f the
// focal length in pixels; the general check covers the floor, the box and the sky as well.
TEST(Motion, TranslatingCamera) {
  const Scene s = wall_scene();
  Camera a = s.cameras[0], b = a;
  b.position.x += 0.1f;
  b.target.x += 0.1f;
  RgbaImageF motion;
  const double worst = motion_error(s, a, b, 0, 0, [](glm::vec3 p, int) { return p; }, &motion);
  // Measured 0.0020 px on llvmpipe (RG16F rounding of ~1.1 px values).
  EXPECT_LT(worst, 0.01);
  // The wall straight ahead (pixel row 26 from the top: below the wall's top edge at row 21,
  // above the box).
  const float f = 0.5f * kH / std::tan(glm::radians(30.0f));
  const float* m = test::texel(motion, kW / 2, 26);
  EXPECT_NEAR(m[0], f * 0.1f / 5.0f, 0.01f);
  EXPECT_NEAR(m[1], 0.0f, 0.01f);
}

// A yaw of 2 degrees: a pure rotation moves every pixel (sky or surface) by the same function of
// its direction; at the image centre, f * tan(2 deg) horizontally.
TEST(Motion, RotatingCamera) {
  const Scene s = wall_scene();
  Camera a = s.cameras[0], b = a;
  const glm::mat4 yaw = glm::rotate(glm::mat4(1.0f), glm::radians(2.0f), {0.0f, 1.0f, 0.0f});
  b.target = b.position + glm::vec3(yaw * glm::vec4(a.target - a.position, 0.0f));
  RgbaImageF motion;
  const double worst = motion_error(s, a, b, 0, 0, [](glm::vec3 p, int) { return p; }, &motion);
  EXPECT_LT(worst, 0.01);  // measured 0.0020 px
  const float f = 0.5f * kH / std::tan(glm::radians(30.0f));
  // Turning left (+yaw about +y), what was at the centre is now right of it: it was left.
  const float* centre = test::texel(motion, kW / 2, kH / 2);
  EXPECT_NEAR(std::abs(centre[0]), f * std::tan(glm::radians(2.0f)), 0.05f);
  const float* sky = test::texel(motion, kW / 2, 2);  // top rows: above the wall
  EXPECT_LT(std::abs(sky[0] - centre[0]), 0.5f);
}

// The box slides along +x (an object motion); the camera stands still: only the box's pixels
// move, by its projected displacement.
TEST(Motion, MovingObject) {
  Scene s = wall_scene();
  ObjectMotion slide;
  slide.kind = ObjectMotion::Kind::Keyframes;
  slide.meshes = {2};
  TransformKey k0, k1;
  k1.time = 1.0f;
  k1.translate = {1.0f, 0.0f, 0.0f};
  slide.keys = {k0, k1};
  s.animation.objects = {slide};
  s.animation.duration = 1.0f;
  const float ta = 0.3f, tb = 0.4f;
  const glm::mat4 back = mesh_transform(s, 2, ta) * glm::inverse(mesh_transform(s, 2, tb));
  RgbaImageF motion;
  const double worst = motion_error(s, s.cameras[0], s.cameras[0], ta, tb, [&](glm::vec3 p, int object) {
    return object == 2 ? glm::vec3(back * glm::vec4(p, 1.0f)) : p;
  }, &motion);
  EXPECT_LT(worst, 0.01);  // measured 0.0010 px
  std::size_t moving = 0, still = 0;
  for (std::size_t i = 0; i < motion.pixels.size(); i += 4)
    (std::abs(motion.pixels[i]) > 0.1f ? moving : still)++;
  EXPECT_GT(moving, 100u);  // the box covers a few hundred pixels
  EXPECT_GT(still, moving);
}

namespace {

struct ProbeParams {
  float gain = 1.0f;
};
const ParamDesc kProbeTable[] = {SSR_PARAM_FLOAT(ProbeParams, gain, 0, 10, 0.1, "", "A parameter to change.")};

// A technique that reads every history resource and keeps a persistent texture: it records
// what the frame gives it and writes no reflection.
class HistoryProbe final : public TechniqueWithParams<ProbeParams> {
 public:
  HistoryProbe() : TechniqueWithParams("history-probe", kProbeTable) {}
  void load(const gl::ShaderSource&) override {}
  TechniqueDecl declare() const override {
    TechniqueDecl d;
    d.reads = kReadGBuffer | kReadLit | kReadMotion | kReadHistory;
    d.textures = {{"accumulator", GL_RGBA16F, 1, true}, {"scratch", GL_RGBA16F, 2, false}};
    return d;
  }
  void run(const FrameContext& f) override {
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(f.reflection->id(), 0, GL_RGBA, GL_FLOAT, zero);
    history_valid = f.history_valid;
    accumulator = f.textures[0];
    scratch_size = {f.textures[1]->width(), f.textures[1]->height()};
  }
  void reset() override { ++resets; }

  int resets = 0;
  bool history_valid = false;
  gl::Texture2D* accumulator = nullptr;
  glm::ivec2 scratch_size{0};
};

// Infinity where the sizes differ or a difference is not finite (std::max would pass a NaN over).
double max_abs_diff(const RgbaImageF& a, const RgbaImageF& b) {
  if (a.pixels.size() != b.pixels.size()) return std::numeric_limits<double>::infinity();
  double m = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const double d = std::abs(static_cast<double>(a.pixels[i]) - b.pixels[i]);
    if (!std::isfinite(d)) return std::numeric_limits<double>::infinity();
    m = std::max(m, d);
  }
  return m;
}

}  // namespace

TEST(History, StillCameraReprojectsToTheIdentity) {
  const Scene s = wall_scene();
  Renderer r(s, kW, kH);
  HistoryProbe probe;
  r.render(FrameRequest(s.cameras[0], {0, 0.0f}), probe, ViewMode::Final, nullptr);
  EXPECT_FALSE(probe.history_valid);  // no previous frame
  r.render(FrameRequest(s.cameras[0], {1, 0.04f}), probe, ViewMode::Final, nullptr);
  EXPECT_TRUE(probe.history_valid);
  ASSERT_NE(r.prev_lit(), nullptr);
  const RgbaImageF motion = r.read_texture(r.motion());
  for (std::size_t i = 0; i < motion.pixels.size(); i += 4) {
    ASSERT_EQ(motion.pixels[i], 0.0f);
    ASSERT_EQ(motion.pixels[i + 1], 0.0f);
  }
  EXPECT_EQ(max_abs_diff(r.read_texture(*r.prev_lit()), r.read_texture(r.lit())), 0.0);
  EXPECT_EQ(max_abs_diff(r.read_texture(*r.prev_normal_roughness()), r.read_texture(r.gbuffer().normal_roughness)), 0.0);
  EXPECT_EQ(probe.scratch_size, glm::ivec2((kW + 1) / 2, (kH + 1) / 2));  // divisor 2: half size
}

// The camera steps right and forward: the previous frame's lit colour, fetched (bilinear) at
// each pixel's motion vector, is this frame's lit colour wherever the surface was visible then.
TEST(History, MovedCameraReprojectsThePreviousColour) {
  const Scene s = wall_scene();
  Renderer r(s, kW, kH);
  HistoryProbe probe;
  Camera a = s.cameras[0], b = a;
  b.position += glm::vec3(0.08f, 0.0f, -0.1f);
  b.target += glm::vec3(0.08f, 0.0f, -0.1f);
  r.render(FrameRequest(a, {0, 0.0f}), probe, ViewMode::Final, nullptr);
  r.render(FrameRequest(b, {1, 0.04f}), probe, ViewMode::Final, nullptr);
  const RgbaImageF prev = r.read_texture(*r.prev_lit()), lit = r.read_texture(r.lit());
  const RgbaImageF motion = r.read_texture(r.motion());
  // Bilinear fetch of `prev` at GL pixel coordinates (x, y up), as a shader's texture() would.
  auto fetch = [&](glm::vec2 p, int c) {
    const glm::vec2 q = p - 0.5f;
    const int x0 = static_cast<int>(std::floor(q.x)), y0 = static_cast<int>(std::floor(q.y));
    const glm::vec2 f = q - glm::vec2(x0, y0);
    auto at = [&](int x, int y) {
      x = std::clamp(x, 0, kW - 1);
      y = std::clamp(y, 0, kH - 1);
      return prev.pixels[(static_cast<std::size_t>(kH - 1 - y) * kW + x) * 4 + static_cast<std::size_t>(c)];
    };
    return (at(x0, y0) * (1 - f.x) + at(x0 + 1, y0) * f.x) * (1 - f.y) +
           (at(x0, y0 + 1) * (1 - f.x) + at(x0 + 1, y0 + 1) * f.x) * f.y;
  };
  std::vector<double> errors;
  double identity_sum = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * kW + x) * 4;
      const glm::vec2 p(x + 0.5f, kH - 1 - y + 0.5f);
      const glm::vec2 q = p + glm::vec2(motion.pixels[i], motion.pixels[i + 1]);
      if (q.x < 1 || q.y < 1 || q.x > kW - 1 || q.y > kH - 1) continue;  // came from off screen
      double e = 0, e0 = 0;
      for (int c = 0; c < 3; ++c) {
        e = std::max(e, static_cast<double>(std::abs(fetch(q, c) - lit.pixels[i + static_cast<std::size_t>(c)])));
        e0 = std::max(e0, static_cast<double>(std::abs(prev.pixels[i + static_cast<std::size_t>(c)] - lit.pixels[i + static_cast<std::size_t>(c)])));
      }
      errors.push_back(e);
      identity_sum += e0;
    }
  ASSERT_GT(errors.size(), static_cast<std::size_t>(kW * kH * 8 / 10));
  std::sort(errors.begin(), errors.end());
  double sum = 0;
  for (double e : errors) sum += e;
  const double mean = sum / static_cast<double>(errors.size());
  const double p90 = errors[errors.size() * 9 / 10];
  // Measured on llvmpipe: mean 0.0027, p90 0.0002 (the error sits on the few pixels along
  // edges, where bilinear fetches mix surfaces); without the motion vectors: mean 0.0082.
  EXPECT_LT(mean, 0.006);
  EXPECT_LT(p90, 0.002);
  EXPECT_LT(mean, 0.5 * identity_sum / static_cast<double>(errors.size()));
}

TEST(History, ResetOnCutResizeSkipParameterAndLightingChanges) {
  const Scene s = wall_scene();
  Renderer r(s, kW, kH);
  HistoryProbe probe;
  const Camera& c = s.cameras[0];
  auto frame = [&](int index, bool cut = false) {
    r.render(FrameRequest(c, {index, 0.04f * static_cast<float>(index), cut}), probe, ViewMode::Final, nullptr);
  };
  frame(0);
  EXPECT_EQ(probe.resets, 1);  // first run
  frame(1);
  frame(2);
  EXPECT_EQ(probe.resets, 1);  // consecutive frames carry history
  r.render(FrameRequest(c, {2, 0.08f}), probe, ViewMode::Final, nullptr);
  EXPECT_EQ(probe.resets, 1);  // the same frame again (another technique's turn): no reset
  frame(3, /*cut=*/true);
  EXPECT_EQ(probe.resets, 2);
  EXPECT_FALSE(probe.history_valid);
  frame(5);  // skipped a frame
  EXPECT_EQ(probe.resets, 3);
  frame(6);
  EXPECT_EQ(probe.resets, 3);
  ParamSet p = probe.params();
  p.set(0, 2.0);
  frame(7);
  EXPECT_EQ(probe.resets, 4);  // parameter change
  r.resize(kW + 2, kH);
  frame(8);
  EXPECT_EQ(probe.resets, 5);  // resize
  r.set_lighting(s.lights, s.environment, 0.5f);
  frame(9);
  EXPECT_EQ(probe.resets, 6);  // the scene changed
  EXPECT_FALSE(probe.history_valid);
  frame(10);
  EXPECT_EQ(probe.resets, 6);
  EXPECT_TRUE(probe.history_valid);
}

// History never carries a non-finite value: NaN written into the previous-frame targets and into
// a technique's persistent texture is gone after the reset that a cut causes.
TEST(History, InjectedNanIsGoneAfterAReset) {
  const Scene s = wall_scene();
  Renderer r(s, kW, kH);
  HistoryProbe probe;
  r.render(FrameRequest(s.cameras[0], {0, 0.0f}), probe, ViewMode::Final, nullptr);
  r.render(FrameRequest(s.cameras[0], {1, 0.04f}), probe, ViewMode::Final, nullptr);
  const float nan4[4] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::quiet_NaN(),
                         std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::quiet_NaN()};
  ASSERT_NE(probe.accumulator, nullptr);
  for (const gl::Texture2D* t : {r.prev_lit(), r.prev_normal_roughness(), static_cast<const gl::Texture2D*>(probe.accumulator)})
    glClearTexImage(t->id(), 0, GL_RGBA, GL_FLOAT, nan4);
  ASSERT_GT(test::count_nonfinite(r.read_texture(*probe.accumulator)), 0u);
  r.render(FrameRequest(s.cameras[0], {2, 0.08f, /*cut=*/true}), probe, ViewMode::Final, nullptr);
  EXPECT_EQ(test::count_nonfinite(r.read_texture(*probe.accumulator)), 0u);
  EXPECT_EQ(test::count_nonfinite(r.read_texture(*r.prev_lit())), 0u);
  EXPECT_EQ(test::count_nonfinite(r.read_texture(*r.prev_normal_roughness())), 0u);
  EXPECT_EQ(test::count_nonfinite(r.read_texture(r.color())), 0u);
  test::expect_no_gl_errors();
}

// The frame builds back faces, the depth pyramid and history only for techniques that declare
// them.
TEST(Frame, OptionalResourcesOnlyWhenDeclared) {
  const Scene s = wall_scene();
  Renderer r(s, kW, kH);
  auto passes_of = [&](Technique& t, int index) {
    gl::PassTimer timer(gl::PassTimer::Clock::Cpu);
    timer.begin_frame();
    r.render(FrameRequest(s.cameras[0], {index, 0.0f}), t, ViewMode::Final, &timer);
    timer.end_frame();
    timer.flush();
    std::vector<std::string> names;
    for (const gl::PassTime& p : timer.completed().back()) names.push_back(p.name);
    return names;
  };
  auto has = [](const std::vector<std::string>& v, const char* n) { return std::find(v.begin(), v.end(), n) != v.end(); };
  auto linear = create_technique("linear");
  linear->load(r.shaders());
  ParamSet lp = linear->params();
  lp.set(static_cast<std::size_t>(lp.find("backface_thickness")), 0.0);
  auto names = passes_of(*linear, 0);
  EXPECT_FALSE(has(names, "hiz pyramid"));
  EXPECT_FALSE(has(names, "backfaces"));
  EXPECT_EQ(r.prev_lit(), nullptr);
  lp.set(static_cast<std::size_t>(lp.find("backface_thickness")), 1.0);
  names = passes_of(*linear, 1);
  EXPECT_TRUE(has(names, "backfaces"));
  auto hiz = create_technique("hiz");
  hiz->load(r.shaders());
  names = passes_of(*hiz, 2);
  EXPECT_TRUE(has(names, "hiz pyramid"));
  EXPECT_EQ(r.prev_lit(), nullptr);
  // A second technique on the same frame (the viewer's B) builds what it reads inside its own
  // span too: it found A's pyramid built and its time left it out.
  auto hiz_b = create_technique("hiz");
  hiz_b->load(r.shaders());
  names = passes_of(*hiz_b, 2);
  EXPECT_TRUE(has(names, "hiz pyramid"));
  EXPECT_FALSE(has(names, "gbuffer")) << "the inputs are drawn once a frame";
  HistoryProbe probe;
  passes_of(probe, 3);
  EXPECT_NE(r.prev_lit(), nullptr);
}

// The technique is timed as one span (what bench reports) with its own passes nested inside;
// a timer limited to depth 1 records the outermost passes alone (no query between the
// technique's passes).
TEST(Frame, TechniqueIsOneSpanAroundItsPasses) {
  const Scene s = wall_scene();
  Renderer r(s, kW, kH);
  auto hiz = create_technique("hiz");
  hiz->load(r.shaders());
  auto frame_times = [&](int max_depth, int index) {
    gl::PassTimer timer(gl::PassTimer::Clock::Cpu, 4, max_depth);
    timer.begin_frame();
    r.render(FrameRequest(s.cameras[0], {index, 0.0f}), *hiz, ViewMode::Final, &timer);
    timer.end_frame();
    timer.flush();
    return timer.completed().back();
  };
  const gl::FrameTimes all = frame_times(gl::PassTimer::kAllDepths, 0);
  std::vector<std::string> outer, inner;
  double inner_ms = 0;
  for (const gl::PassTime& p : all) {
    (p.depth == 0 ? outer : inner).push_back(p.name);
    if (p.depth == 1) inner_ms += p.ms;
    EXPECT_LE(p.depth, 1) << p.name;
  }
  EXPECT_EQ(outer, (std::vector<std::string>{"gbuffer", "lighting", kTechniqueSpan, "composite", "display"}));
  EXPECT_NE(std::find(inner.begin(), inner.end(), "hiz pyramid"), inner.end());
  EXPECT_GE(inner.size(), 2u);  // the pyramid and the trace
  // The CPU clock stamps the span before its first pass and after its last one.
  EXPECT_GE(technique_ms(all), inner_ms);
  const gl::FrameTimes top = frame_times(1, 1);
  std::vector<std::string> top_names;
  for (const gl::PassTime& p : top) top_names.push_back(p.name);
  EXPECT_EQ(top_names, outer);
  EXPECT_GT(technique_ms(top), 0.0);
}

// ---- A technique's history across what the viewer does between frames ----------------------

namespace {

// Renders frame `index` of a still camera on cornell for `t` and returns the view's linear values.
RgbaImageF still_frame(Renderer& r, const Scene& s, Technique& t, int index, ViewMode view = ViewMode::Final) {
  r.render(FrameRequest(s.cameras[0], {index, index / 30.0f}), t, view, nullptr);
  return r.read_linear();
}

std::unique_ptr<Technique> stochastic(const Renderer& r, std::vector<std::string> sets) {
  auto t = create_technique("stochastic");
  apply_assignments(*t, sets);
  t->load(r.shaders());
  return t;
}

}  // namespace

// The previous colour follows a resize made while previous_frame was off: it was kept at the old
// size (its state reallocated only on a resize seen with the option on), so the hits read a
// stretched corner of it. Against a technique switched on at the same frame, which starts fresh.
TEST(History, PreviousColourFollowsAResizeMadeWhileItWasOff) {
  const Scene s = make_builtin_scene("cornell");
  Renderer r(s, kW, kH);
  auto toggled = stochastic(r, {"stochastic.previous_frame=true"});
  still_frame(r, s, *toggled, 0);
  still_frame(r, s, *toggled, 1);
  apply_assignments(*toggled, {"stochastic.previous_frame=false"});
  still_frame(r, s, *toggled, 2);
  r.resize(kW - 20, kH - 14);
  still_frame(r, s, *toggled, 3);
  apply_assignments(*toggled, {"stochastic.previous_frame=true"});
  auto fresh = stochastic(r, {"stochastic.previous_frame=true"});
  for (int f = 4; f < 8; ++f) {
    const RgbaImageF a = still_frame(r, s, *toggled, f);
    const RgbaImageF b = still_frame(r, s, *fresh, f);
    EXPECT_EQ(max_abs_diff(a, b), 0.0) << "frame " << f;
  }
  test::expect_no_gl_errors();
}

// Switching previous_frame on mid-sequence resets the technique, which zeroes its previous
// colour; the frame itself goes on, so the shader's "continues" flag said the zeros were last
// frame's image and every hit read black. With nothing kept yet, hits read the lit colour: the
// frame is the one previous_frame=false renders.
TEST(History, PreviousFrameSwitchedOnMidSequenceReadsTheLitColour) {
  const Scene s = make_builtin_scene("cornell");
  Renderer r(s, kW, kH);
  auto toggled = stochastic(r, {});
  for (int f = 0; f < 3; ++f) still_frame(r, s, *toggled, f);
  apply_assignments(*toggled, {"stochastic.previous_frame=true"});
  auto without = stochastic(r, {});
  const RgbaImageF a = still_frame(r, s, *toggled, 3, ViewMode::Reflection);
  const RgbaImageF b = still_frame(r, s, *without, 3, ViewMode::Reflection);
  EXPECT_EQ(max_abs_diff(a, b), 0.0);
  test::expect_no_gl_errors();
}

// One frame rendered twice (the viewer showing another view of it, a window shot) runs the
// technique twice: the second run must not accumulate the frame into its history again, and
// the stage views show what the run wrote, also on the frame after a reset.
TEST(History, ASecondRenderOfAFrameLeavesTheHistoryAsOne) {
  const Scene s = make_builtin_scene("cornell");
  Renderer r(s, kW, kH);
  auto once = stochastic(r, {"stochastic.previous_frame=true"});
  auto twice = stochastic(r, {"stochastic.previous_frame=true"});
  for (int f = 0; f < 6; ++f) {
    const RgbaImageF a = still_frame(r, s, *once, f);
    still_frame(r, s, *twice, f, ViewMode::History);
    still_frame(r, s, *twice, f, ViewMode::Temporal);
    const RgbaImageF b = still_frame(r, s, *twice, f);
    EXPECT_EQ(max_abs_diff(a, b), 0.0) << "frame " << f;
  }
  // A parameter change after an odd number of frames: the temporal view named the pair the
  // reset had just zeroed (black), not the one the frame wrote.
  for (Technique* t : {once.get(), twice.get()}) apply_assignments(*t, {"stochastic.history=20"});
  still_frame(r, s, *once, 6);  // both reset here; `twice` twice over
  auto fresh = stochastic(r, {"stochastic.previous_frame=true", "stochastic.history=20"});
  for (ViewMode v : {ViewMode::Temporal, ViewMode::History}) {
    const RgbaImageF a = still_frame(r, s, *once, 6, v);
    const RgbaImageF b = still_frame(r, s, *fresh, 6, v);
    EXPECT_EQ(max_abs_diff(a, b), 0.0) << view_info(v).name;
    double sum = 0;
    for (float x : a.pixels) sum += x;
    EXPECT_GT(sum, 0.0) << view_info(v).name << " is black";
  }
  test::expect_no_gl_errors();
}

// The exposure is the display's alone: changing it keeps the frame and every history (it reset
// them all, so moving the viewer's slider threw away the convergence), and the new exposure
// shows at once, on the same frame too.
TEST(Frame, ExposureKeepsTheHistoryAndShowsAtOnce) {
  const Scene s = wall_scene();
  Renderer r(s, kW, kH);
  HistoryProbe probe;
  const Camera& c = s.cameras[0];
  r.render(FrameRequest(c, {0, 0.0f}), probe, ViewMode::Final, nullptr);
  r.render(FrameRequest(c, {1, 0.04f}), probe, ViewMode::Final, nullptr);
  const RgbaImageF before = r.read_linear();
  const RgbaImage8 before8 = r.read_display();
  r.settings.exposure = 2.0f;
  r.render(FrameRequest(c, {1, 0.04f}), probe, ViewMode::Final, nullptr);  // the same frame
  EXPECT_EQ(max_abs_diff(before, r.read_linear()), 0.0) << "the linear values do not take the exposure";
  EXPECT_NE(before8.pixels, r.read_display().pixels) << "the display does";
  r.render(FrameRequest(c, {2, 0.08f}), probe, ViewMode::Final, nullptr);
  EXPECT_EQ(probe.resets, 1);
  EXPECT_TRUE(probe.history_valid);
  r.settings.reflective_f0 = 0.5f;  // a setting the frame's inputs depend on still restarts it
  r.render(FrameRequest(c, {3, 0.12f}), probe, ViewMode::Final, nullptr);
  EXPECT_EQ(probe.resets, 2);
  test::expect_no_gl_errors();
}
