// The pass-floor microbenchmark (`ssrlab passfloor`, docs/RESULTS.md "What one screen pass
// costs"): what a full-screen pass costs by itself on a device, as a compute dispatch in
// several work-group shapes or as a fragment pass, for kinds of pixel work from none to a 5x5
// box of fetches, alone and in chains of passes. It separates what a pass's launches cost from
// what its work costs, which the techniques' own timings cannot.
#pragma once
#include <array>
#include <map>
#include <span>
#include <string>

#include "core/image.h"
#include "gl/program.h"
#include "gl/timer.h"

namespace ssr {

// How a pass is issued.
struct PassFloorMode {
  const char* name;
  int local_x, local_y;  // compute work-group size (0 for a fragment pass)
  bool dependent;        // each pass of a chain reads the one before (compute: a memory barrier
                         // after each; fragment: GL orders a draw after the one that wrote its
                         // texture); false: each reads the source and none waits for another
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
// Every mode's (kind's) name, comma-separated, for help texts.
std::string pass_floor_mode_names();
std::string pass_floor_kind_names();

class PassFloorBench {
 public:
  // RGBA16F source and two targets of w x h; the source holds pass_floor_source(). Needs a
  // current GL 4.5 context. A run restores the viewport, framebuffer, vertex array, program and
  // the tests it turns off; it leaves its texture and image units bound (every pass binds its own).
  PassFloorBench(const gl::ShaderSource& shaders, int width, int height);
  // A chain of `passes` passes of `kind` issued as `mode` (the targets cleared first); returns
  // the last pass's target, top row first.
  RgbaImageF run_once(const PassFloorMode& mode, const PassFloorKind& kind, int passes = 1);
  // The work-group size the compiled compute program has ({0, 0} for a fragment mode).
  std::array<int, 2> group_size(const PassFloorMode& mode, const PassFloorKind& kind);
  // Median time of `chain` passes in a row, over `frames` frames after bench's warm-up (10
  // frames, and on the GPU at least 0.3 s: runner.h warm_up). `clock` Gpu: GL timestamps around
  // the chain; Cpu: a wall clock around the chain and glFinish (llvmpipe).
  double time_ms(const PassFloorMode& mode, const PassFloorKind& kind, int chain, int frames,
                 gl::PassTimer::Clock clock);

 private:
  class State;  // binds what the passes need and restores what it found
  void issue(const PassFloorMode& mode, const gl::Program& program, int index);
  const gl::Program& program(const PassFloorMode& mode, const PassFloorKind& kind);

  gl::ShaderSource shaders_;
  int width_, height_;
  gl::Texture2D textures_[3];  // [0], [1]: the targets, in turn in a chain; [2]: the source
  gl::Framebuffer fbos_[2];    // the targets as colour attachments (fragment mode)
  gl::VertexArray vao_;
  std::map<std::string, gl::Program> cache_;  // "mode/kind"
};

// The source's texel (x, y), y = 0 the bottom row (as GL addresses it): values a half float
// holds exactly, different in every channel.
void pass_floor_source(int x, int y, float out[4]);

}  // namespace ssr
