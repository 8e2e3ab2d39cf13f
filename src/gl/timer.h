// Per-pass timings. On a GPU: a GL_TIMESTAMP query at each pass's start and end, in a ring read
// a few frames late so the CPU never waits. On llvmpipe (whose timer queries return garbage) a
// CPU clock around glFinish, labelled "cpu" wherever it is reported.
//
// Passes nest (timestamps, unlike GL_TIME_ELAPSED queries, may overlap): the renderer times the
// technique as one span with its passes inside. A timer built with max_depth = 1 records the
// outermost spans alone, so the technique's time carries no query between its passes.
#pragma once
#include <string>
#include <vector>

#include "gl/objects.h"

namespace ssr::gl {

struct PassTime {
  std::string name;
  double ms = 0;
  int depth = 0;  // 0: outermost; n: inside n spans
};
using FrameTimes = std::vector<PassTime>;

// The sum over the outermost passes of a frame: each moment of it counted once.
double outer_ms(const FrameTimes& frame);

class PassTimer {
 public:
  enum class Clock { Gpu, Cpu };
  static constexpr int kAllDepths = 1 << 20;
  explicit PassTimer(Clock clock, int ring = 4, int max_depth = kAllDepths);
  Clock clock() const { return clock_; }
  const char* clock_name() const { return clock_ == Clock::Gpu ? "gpu" : "cpu"; }

  void begin_frame();  // collects the oldest frame in the ring once its queries are ready
  void begin(const std::string& pass);
  void end();
  void end_frame();
  // Waits for every frame still in flight and moves it to completed().
  void flush();

  // Completed frames, oldest first, passes in the order they began; the caller may clear it.
  std::vector<FrameTimes>& completed() { return completed_; }

 private:
  struct Slot {
    FrameTimes passes;
    std::vector<Query> queries;  // two per pass: start, end
    std::vector<double> cpu_ms;  // the CPU clock's stamps, in the same slots
    bool pending = false;
  };
  void collect(Slot& slot);
  void stamp(Slot& s, std::size_t slot);

  Clock clock_;
  int max_depth_;
  std::vector<Slot> ring_;
  int current_ = -1;
  std::vector<int> open_;  // the open passes, innermost last (-1: deeper than max_depth, not timed)
  std::vector<FrameTimes> completed_;
};

// Times one pass for its scope: `ScopedPass p(timer, "lighting");` (timer may be null).
class ScopedPass {
 public:
  ScopedPass(PassTimer* t, const std::string& name) : t_(t) { if (t_) t_->begin(name); }
  ~ScopedPass() { if (t_) t_->end(); }
  ScopedPass(const ScopedPass&) = delete;
  ScopedPass& operator=(const ScopedPass&) = delete;

 private:
  PassTimer* t_;
};

}  // namespace ssr::gl
