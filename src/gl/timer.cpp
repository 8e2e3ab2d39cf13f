#include "gl/timer.h"

#include <cassert>
#include <chrono>

namespace ssr::gl {

namespace {
double now_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}
}  // namespace

PassTimer::PassTimer(Clock clock, int ring) : clock_(clock), ring_(static_cast<std::size_t>(ring)) {}

void PassTimer::collect(Slot& slot) {
  if (!slot.pending) return;
  FrameTimes frame;
  for (std::size_t i = 0; i < slot.names.size(); ++i) {
    double ms = 0;
    if (clock_ == Clock::Gpu) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(slot.queries[i].id(), GL_QUERY_RESULT, &ns);  // waits if not ready
      ms = static_cast<double>(ns) * 1e-6;
    } else {
      ms = slot.cpu_ms[i];
    }
    frame.push_back({slot.names[i], ms});
  }
  completed_.push_back(std::move(frame));
  slot.names.clear();
  slot.cpu_ms.clear();
  slot.pending = false;
}

void PassTimer::begin_frame() {
  current_ = (current_ + 1) % static_cast<int>(ring_.size());
  collect(ring_[static_cast<std::size_t>(current_)]);
}

void PassTimer::begin(const std::string& pass) {
  assert(current_ >= 0 && open_ < 0 && "PassTimer: begin_frame first; passes do not nest");
  Slot& s = ring_[static_cast<std::size_t>(current_)];
  open_ = static_cast<int>(s.names.size());
  s.names.push_back(pass);
  if (clock_ == Clock::Gpu) {
    if (s.queries.size() < s.names.size()) s.queries.emplace_back("pass timer", GL_TIME_ELAPSED);
    glBeginQuery(GL_TIME_ELAPSED, s.queries[static_cast<std::size_t>(open_)].id());
  } else {
    glFinish();
    cpu_start_ = now_ms();
  }
}

void PassTimer::end() {
  assert(open_ >= 0);
  Slot& s = ring_[static_cast<std::size_t>(current_)];
  if (clock_ == Clock::Gpu) {
    glEndQuery(GL_TIME_ELAPSED);
  } else {
    glFinish();
    s.cpu_ms.push_back(now_ms() - cpu_start_);
  }
  open_ = -1;
}

void PassTimer::end_frame() {
  if (current_ >= 0) ring_[static_cast<std::size_t>(current_)].pending = true;
}

void PassTimer::flush() {
  // Oldest first: walk the ring starting after the current slot.
  const int n = static_cast<int>(ring_.size());
  for (int k = 1; k <= n; ++k) collect(ring_[static_cast<std::size_t>((current_ + k + n) % n)]);
}

}  // namespace ssr::gl
