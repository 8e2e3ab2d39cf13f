// Per-pass timings. On a GPU: GL_TIME_ELAPSED queries in a ring, read a few frames late so the
// CPU never waits. On llvmpipe (whose timer queries return garbage) a CPU clock around glFinish,
// labelled "cpu" wherever it is reported.
#pragma once
#include <string>
#include <vector>

#include "gl/objects.h"

namespace ssr::gl {

struct PassTime {
  std::string name;
  double ms = 0;
};
using FrameTimes = std::vector<PassTime>;

class PassTimer {
 public:
  enum class Clock { Gpu, Cpu };
  explicit PassTimer(Clock clock, int ring = 4);
  Clock clock() const { return clock_; }
  const char* clock_name() const { return clock_ == Clock::Gpu ? "gpu" : "cpu"; }

  void begin_frame();  // collects the oldest frame in the ring once its queries are ready
  void begin(const std::string& pass);
  void end();
  void end_frame();
  // Waits for every frame still in flight and moves it to completed().
  void flush();

  // Completed frames, oldest first; the caller may clear it.
  std::vector<FrameTimes>& completed() { return completed_; }

 private:
  struct Slot {
    std::vector<std::string> names;
    std::vector<Query> queries;
    std::vector<double> cpu_ms;
    bool pending = false;
  };
  void collect(Slot& slot);

  Clock clock_;
  std::vector<Slot> ring_;
  int current_ = -1;
  int open_ = -1;  // index of the pass being timed in the current slot
  double cpu_start_ = 0;
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
