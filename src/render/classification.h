// Tile classification: a frame service for tracers that trace only some pixels (`stochastic`;
// the speed issue measures it). One pass over the trace grid writes each pixel's class
// (shared/classification.h: no reflection, environment only, traced this frame, reused from
// neighbours) and appends every CLASSIFY_TILE^2 tile of the trace grid that holds a traced
// texel to a list whose header is the indirect dispatch's arguments: the trace then runs one
// work group per listed tile (glDispatchComputeIndirect) and nothing elsewhere.
#pragma once
#include <cstdint>

#include "gl/program.h"
#include "gl/timer.h"
#include "shared/classification.h"

namespace ssr {

class TileClassifier {
 public:
  void load(const gl::ShaderSource& src);
  // Classifies every pixel of a frame whose G-buffer is bound (FrameContext), writing `classes`
  // (R8, full resolution) and the tile list. `p.trace_size` and the frame offset are filled in
  // here from `divisor` and `frame_index`.
  void classify(const gl::Texture2D& classes, shared::ClassifyParams p, int frame_index, gl::PassTimer* timer);
  // Binds the tile list at SSBO_TILES and as the indirect dispatch buffer; the trace pass calls
  // dispatch() with a program whose local size is CLASSIFY_TILE x CLASSIFY_TILE.
  void bind() const;
  void dispatch() const;
  // Reads the header back (stalls; for tests and the speed report): tiles listed, rays cast.
  shared::TileListHeader read_header() const;
  // The trace grid of a w x h frame at `divisor` (1 or 2): ceil(size / divisor).
  static glm::ivec2 trace_size(int w, int h, int divisor);

 private:
  gl::Program program_;
  gl::Buffer params_;
  gl::Buffer tiles_;
  std::size_t tiles_capacity_ = 0;
};

}  // namespace ssr
