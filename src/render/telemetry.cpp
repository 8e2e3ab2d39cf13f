#include "render/telemetry.h"

#include <algorithm>

#include "shared/bindings.h"

namespace ssr {

namespace {
constexpr std::size_t kHeaderBytes = sizeof(shared::TelemetryHeader);
constexpr std::size_t kHistogramBytes = TELEMETRY_BINS * sizeof(std::uint32_t);
}  // namespace

void TelemetryBuffer::begin(int width, int height) {
  const std::size_t bytes = kHeaderBytes + kHistogramBytes + std::size_t(width) * std::size_t(height) * 4;
  if (bytes > capacity_) {
    buffer_ = gl::make_buffer("telemetry", static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    capacity_ = bytes;
  }
  width_ = width;
  height_ = height;
  const std::uint32_t zero = 0;
  glClearNamedBufferData(buffer_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  const std::uint32_t w = static_cast<std::uint32_t>(width);
  glNamedBufferSubData(buffer_.id(), offsetof(shared::TelemetryHeader, width), sizeof(w), &w);
  bind();
}

void TelemetryBuffer::bind_for(int width, int height) {
  if (!buffer_ || width != width_ || height != height_) begin(width, height);
  bind();
}

void TelemetryBuffer::bind() const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_TELEMETRY, buffer_.id()); }

TelemetryFrame TelemetryBuffer::read() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  TelemetryFrame f;
  f.histogram.resize(TELEMETRY_BINS);
  f.pixels.resize(std::size_t(width_) * std::size_t(height_));
  glGetNamedBufferSubData(buffer_.id(), 0, kHeaderBytes, &f.header);
  glGetNamedBufferSubData(buffer_.id(), kHeaderBytes, kHistogramBytes, f.histogram.data());
  glGetNamedBufferSubData(buffer_.id(), kHeaderBytes + kHistogramBytes,
                          static_cast<GLsizeiptr>(f.pixels.size() * 4), f.pixels.data());
  return f;
}

std::optional<IterationStats> TelemetryFrame::stats() const {
  IterationStats s;
  double sum = 0;
  for (std::size_t i = 0; i < histogram.size(); ++i) {
    s.rays += histogram[i];
    sum += double(i) * histogram[i];
    if (histogram[i] > 0) s.max = static_cast<int>(i);
  }
  if (s.rays == 0) return std::nullopt;
  s.mean = sum / double(s.rays);
  auto percentile = [&](double q) {
    const double want = q * double(s.rays);
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < histogram.size(); ++i) {
      seen += histogram[i];
      if (double(seen) >= want) return static_cast<int>(i);
    }
    return s.max;
  };
  s.p50 = percentile(0.5);
  s.p95 = percentile(0.95);
  const auto wide = [](std::uint32_t lo, std::uint32_t hi) { return (std::uint64_t(hi) << 32) | lo; };
  const std::uint64_t slots = wide(header.slots_lo, header.slots_hi);
  if (slots > 0) s.idle_lanes = 1.0 - double(wide(header.busy_lo, header.busy_hi)) / double(slots);
  return s;
}

}  // namespace ssr
