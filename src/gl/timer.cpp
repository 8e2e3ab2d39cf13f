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

double outer_ms(const FrameTimes& frame) {
  double ms = 0;
  for (const PassTime& p : frame)
    if (p.depth == 0) ms += p.ms;
  return ms;
}

PassTimer::PassTimer(Clock clock, int ring, int max_depth)
    : clock_(clock), max_depth_(max_depth), ring_(static_cast<std::size_t>(ring)) {}

void PassTimer::collect(Slot& slot) {
  if (!slot.pending) return;
  for (std::size_t i = 0; i < slot.passes.size(); ++i) {
    if (clock_ == Clock::Gpu) {
      GLuint64 start = 0, end = 0;
      glGetQueryObjectui64v(slot.queries[2 * i].id(), GL_QUERY_RESULT, &start);  // waits if not ready
      glGetQueryObjectui64v(slot.queries[2 * i + 1].id(), GL_QUERY_RESULT, &end);
      slot.passes[i].ms = end > start ? static_cast<double>(end - start) * 1e-6 : 0.0;
    } else {
      slot.passes[i].ms = slot.cpu_ms[2 * i + 1] - slot.cpu_ms[2 * i];
    }
  }
  completed_.push_back(std::move(slot.passes));
  slot.passes.clear();
  slot.cpu_ms.clear();
  slot.pending = false;
}

void PassTimer::begin_frame() {
  assert(open_.empty() && "PassTimer: a pass is still open");
  current_ = (current_ + 1) % static_cast<int>(ring_.size());
  collect(ring_[static_cast<std::size_t>(current_)]);
}

void PassTimer::stamp(Slot& s, std::size_t slot) {
  if (clock_ == Clock::Gpu) {
    while (s.queries.size() <= slot) s.queries.emplace_back("pass timestamp", GL_TIMESTAMP);
    glQueryCounter(s.queries[slot].id(), GL_TIMESTAMP);
  } else {
    glFinish();
    if (s.cpu_ms.size() <= slot) s.cpu_ms.resize(slot + 1);
    s.cpu_ms[slot] = now_ms();
  }
}

void PassTimer::begin(const std::string& pass) {
  assert(current_ >= 0 && "PassTimer: begin_frame first");
  const int depth = static_cast<int>(open_.size());
  if (depth >= max_depth_) {
    open_.push_back(-1);
    return;
  }
  Slot& s = ring_[static_cast<std::size_t>(current_)];
  const int index = static_cast<int>(s.passes.size());
  s.passes.push_back({pass, 0.0, depth});
  open_.push_back(index);
  stamp(s, 2 * static_cast<std::size_t>(index));
}

void PassTimer::end() {
  assert(!open_.empty());
  const int index = open_.back();
  open_.pop_back();
  if (index < 0) return;
  Slot& s = ring_[static_cast<std::size_t>(current_)];
  stamp(s, 2 * static_cast<std::size_t>(index) + 1);
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
