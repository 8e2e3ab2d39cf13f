#include "eval/pass_floor.h"

#include <vector>

#include "core/errors.h"
#include "eval/results.h"
#include "eval/runner.h"
#include "gl/readback.h"
#include "shared/bindings.h"

namespace ssr {

namespace {

// Every shape the measurements compare (docs/RESULTS.md): 8x8 is what the techniques use.
constexpr PassFloorMode kModes[] = {
    {"cs8x8", 8, 8, true, "compute, 8x8 invocations a group (the techniques' passes)"},
    {"cs32x2", 32, 2, true, "compute, 32x2: as many groups as 8x8, another shape"},
    {"cs16x8", 16, 8, true, "compute, 16x8: half the groups"},
    {"cs16x16", 16, 16, true, "compute, 16x16: a quarter of the groups"},
    {"cs8x8-independent", 8, 8, false, "compute, 8x8, the passes of a chain independent (no barrier)"},
    {"fs", 0, 0, true, "fragment pass: a full-screen triangle into a colour attachment"},
};
constexpr PassFloorKind kKinds[] = {
    {"empty", nullptr, "returns at once: the launch alone"},
    {"store", "PF_STORE", "writes a constant"},
    {"copy", "PF_COPY", "one fetch, one write"},
    {"taps3x3", "PF_TAPS_RADIUS 1", "a 3x3 box of fetches"},
    {"taps5x5", "PF_TAPS_RADIUS 2", "a 5x5 box of fetches"},
};

template <class T>
std::string joined_names(std::span<const T> list) {
  std::string names;
  for (const T& e : list) names += (names.empty() ? "" : ", ") + std::string(e.name);
  return names;
}

template <class T>
const T& named(std::span<const T> list, const std::string& name, const char* what) {
  for (const T& e : list)
    if (name == e.name) return e;
  throw InputError("unknown " + std::string(what) + " '" + name + "' (one of " + joined_names(list) + ").");
}

constexpr GLbitfield kChainBarrier = GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;

}  // namespace

// What the passes need bound (a fragment pass also needs blending, scissor and depth test off),
// set once around a run instead of in every timed pass; the destructor puts back what it found,
// so tests sharing the context see no change.
class PassFloorBench::State {
 public:
  explicit State(const PassFloorBench& b) {
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    for (int i = 0; i < 3; ++i) enabled_[i] = glIsEnabled(kCaps[i]);
    for (GLenum cap : kCaps) glDisable(cap);
    glViewport(0, 0, b.width_, b.height_);
    glBindVertexArray(b.vao_.id());
  }
  ~State() {
    // An object deleted while bound lives until it is unbound: once the run bound its own, the
    // name is gone (a test's program deleted at its end), and binding it would be an error.
    const auto id = [](GLint name, GLboolean (*exists)(GLuint)) {
      return name != 0 && exists(static_cast<GLuint>(name)) ? static_cast<GLuint>(name) : 0u;
    };
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, id(fbo_, glIsFramebuffer));
    glBindVertexArray(id(vao_, glIsVertexArray));
    glUseProgram(id(program_, glIsProgram));
    for (int i = 0; i < 3; ++i)
      if (enabled_[i]) glEnable(kCaps[i]);
  }
  State(const State&) = delete;
  State& operator=(const State&) = delete;

 private:
  static constexpr GLenum kCaps[3] = {GL_BLEND, GL_SCISSOR_TEST, GL_DEPTH_TEST};
  GLint viewport_[4] = {}, fbo_ = 0, vao_ = 0, program_ = 0;
  GLboolean enabled_[3] = {};
};

std::span<const PassFloorMode> pass_floor_modes() { return kModes; }
std::span<const PassFloorKind> pass_floor_kinds() { return kKinds; }
const PassFloorMode& pass_floor_mode(const std::string& name) { return named(pass_floor_modes(), name, "pass mode"); }
const PassFloorKind& pass_floor_kind(const std::string& name) { return named(pass_floor_kinds(), name, "pass kind"); }
std::string pass_floor_mode_names() { return joined_names(pass_floor_modes()); }
std::string pass_floor_kind_names() { return joined_names(pass_floor_kinds()); }

void pass_floor_source(int x, int y, float out[4]) {
  out[0] = static_cast<float>(x % 64) / 64.0f;
  out[1] = static_cast<float>(y % 32) / 32.0f;
  out[2] = static_cast<float>((x + 3 * y) % 16) / 16.0f;
  out[3] = 1.0f;
}

PassFloorBench::PassFloorBench(const gl::ShaderSource& shaders, int width, int height)
    : shaders_(shaders), width_(width), height_(height), vao_("pass floor") {
  std::vector<float> src(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      pass_floor_source(x, y, &src[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4]);
  const float zero[4] = {0, 0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    textures_[i] = gl::Texture2D(i == 2 ? "pass floor source" : "pass floor target", GL_RGBA16F, width, height);
    glClearTexImage(textures_[i].id(), 0, GL_RGBA, GL_FLOAT, zero);
  }
  for (int i = 0; i < 2; ++i) {
    fbos_[i] = gl::Framebuffer("pass floor target");
    glNamedFramebufferTexture(fbos_[i].id(), GL_COLOR_ATTACHMENT0, textures_[i].id(), 0);
  }
  glTextureSubImage2D(textures_[2].id(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, src.data());
}

const gl::Program& PassFloorBench::program(const PassFloorMode& mode, const PassFloorKind& kind) {
  const std::string key = std::string(mode.name) + "/" + kind.name;
  if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  // "empty" compiles the store body and skips it at run time.
  std::vector<std::string> defines = {kind.define ? kind.define : "PF_STORE"};
  gl::Program p;
  if (mode.local_x == 0) {
    p = gl::Program::graphics(shaders_, "eval/pass_floor.vert", "eval/pass_floor.frag", defines);
  } else {
    defines.push_back("PF_LOCAL_X " + std::to_string(mode.local_x));
    defines.push_back("PF_LOCAL_Y " + std::to_string(mode.local_y));
    p = gl::Program::compute(shaders_, "eval/pass_floor.comp", defines);
  }
  glProgramUniform1i(p.id(), 0, kind.define ? 0 : 1);  // pf_skip
  return cache_.emplace(key, std::move(p)).first->second;
}

std::array<int, 2> PassFloorBench::group_size(const PassFloorMode& mode, const PassFloorKind& kind) {
  const gl::Program& p = program(mode, kind);
  if (mode.local_x == 0) return {0, 0};
  GLint size[3] = {0, 0, 0};
  glGetProgramiv(p.id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
  return {size[0], size[1]};
}

// Pass `index` of a chain (State bound): dependent passes take turns between targets 0 and 1
// (pass 0 reads the source); independent ones all read the source.
void PassFloorBench::issue(const PassFloorMode& mode, const gl::Program& program, int index) {
  const int in = !mode.dependent || index == 0 ? 2 : index % 2, out = (index + 1) % 2;
  glBindTextureUnit(TEX_STAGE_IN, textures_[in].id());
  glUseProgram(program.id());
  if (mode.local_x == 0) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos_[out].id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  } else {
    glBindImageTexture(IMG_OUT, textures_[out].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    program.dispatch_2d(width_, height_);
    if (mode.dependent) glMemoryBarrier(kChainBarrier);
  }
}

RgbaImageF PassFloorBench::run_once(const PassFloorMode& mode, const PassFloorKind& kind, int passes) {
  const gl::Program& p = program(mode, kind);
  const float zero[4] = {0, 0, 0, 0};
  for (int i = 0; i < 2; ++i) glClearTexImage(textures_[i].id(), 0, GL_RGBA, GL_FLOAT, zero);
  {
    State state(*this);
    for (int i = 0; i < passes; ++i) issue(mode, p, i);
  }
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  RgbaImageF im;
  im.width = width_;
  im.height = height_;
  im.pixels = gl::read_texture<float>(textures_[passes % 2], GL_RGBA, GL_FLOAT, 4);
  return im;
}

double PassFloorBench::time_ms(const PassFloorMode& mode, const PassFloorKind& kind, int chain, int frames,
                               gl::PassTimer::Clock clock) {
  const gl::Program& p = program(mode, kind);
  State state(*this);
  gl::PassTimer timer(clock);
  const auto frame = [&] {
    timer.begin_frame();
    timer.begin("chain");
    for (int i = 0; i < chain; ++i) issue(mode, p, i);
    timer.end();
    timer.end_frame();
  };
  warm_up({10, frames, clock}, true, frame);
  timer.flush();
  timer.completed().clear();  // the warm-up's frames
  for (int f = 0; f < frames; ++f) frame();
  timer.flush();
  std::vector<double> ms;
  for (const gl::FrameTimes& frame : timer.completed()) ms.push_back(gl::outer_ms(frame));
  return time_stats(std::move(ms)).median;
}

}  // namespace ssr
