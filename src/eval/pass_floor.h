// The pass-floor microbenchmark (`ssrlab-passfloor`, docs/RESULTS.md "What one screen pass
// costs"): what a full-screen pass costs by itself on a device, as a compute dispatch in
// several work-group shapes or as a fragment pass, for kinds of pixel work from none to a 5x5
// box of fetches, alone and in chains of dependent passes. It tells a pass's launch cost from
// its work, which the techniques' own timings cannot.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "core/image.h"
#include "gl/program.h"
#include "gl/timer.h"

namespace ssr {

// How a pass is issued.
struct PassFloorMode {
  const char* name;
  int local_x, local_y;  // compute work-group size (0 for a fragment pass)
  bool barrier;          // chained passes depend on each other (memory barrier between them);
                         // false: each reads the source, none waits for another
  const char* description;
};
// What each pixel does.
struct PassFloorKind {
  const char* name;
  const char* define;  // selects the body in shaders/eval/pass_floor.glsl; null: "empty"
  const char* description;
};

std::span<const PassFloorMode> pass_floor_modes();
std::span<const PassFloorKind> pass_floor_kinds();
// The entry named `name`; throws InputError naming the choices otherwise.
const PassFloorMode& pass_floor_mode(const std::string& name);
const PassFloorKind& pass_floor_kind(const std::string& name);

class PassFloorBench {
 public:
  // RGBA16F source and two targets of w x h; the source holds pass_floor_source(). Needs a
  // current GL 4.5 context.
  PassFloorBench(const gl::ShaderSource& shaders, int width, int height);
  // One pass of `kind` issued as `mode`, source -> target; returns the target in GL's row order
  // (row 0 at the bottom, as pass_floor_source()).
  RgbaImageF run_once(const PassFloorMode& mode, const PassFloorKind& kind);
  // Median time of `chain` passes in a row, over `frames` frames after a warm-up (10 frames and
  // at least 0.3 s: the clock of an idle GPU is still low after a few). `clock` Gpu: GL
  // timestamps around the chain; Cpu: a wall clock around the chain and glFinish (llvmpipe).
  double time_ms(const PassFloorMode& mode, const PassFloorKind& kind, int chain, int frames,
                 gl::PassTimer::Clock clock);

 private:
  void issue(const PassFloorMode& mode, const gl::Program& program, int index);
  const gl::Program& program(const PassFloorMode& mode, const PassFloorKind& kind);

  gl::ShaderSource shaders_;
  int width_, height_;
  gl::Texture2D textures_[3];  // [0], [1]: chained passes ping-pong; [2]: the source
  gl::Framebuffer fbos_[3];
  gl::VertexArray vao_;
  std::vector<std::pair<std::string, gl::Program>> cache_;
};

// The source's texel (x, y) (y = 0 the bottom row, as GL stores it): values a half float holds
// exactly, different in every channel.
void pass_floor_source(int x, int y, float out[4]);

}  // namespace ssr
