// Tile classification: a frame service for tracers that trace only some pixels (`stochastic`;
// the speed issue measures it). One pass over the trace grid writes each pixel's class
// (shared/classification.h: no reflection, environment only, traced this frame, reused from
// neighbours) and appends every CLASSIFY_TILE^2 tile of the trace grid that holds a traced
// texel (with list_glass, or a pixel behind glass: it refracts) to a list whose header is the
// indirect dispatch's arguments: the trace then runs one work group per listed tile
// (glDispatchComputeIndirect) and nothing elsewhere. It also lists
// the tracing texels themselves (the ray list, FidelityFX's): a trace over it runs one lane per
// ray, so pixels without work cost no lane at all, even where they share a tile with some.
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
  // (R8, full resolution), the tile list and, with `p.list_rays`, the ray list. `p.trace_size`
  // and the frame offset are filled in here from `divisor` and `frame_index`.
  void classify(const gl::Texture2D& classes, shared::ClassifyParams p, int frame_index, gl::PassTimer* timer);
  // For a screen-space tracer's own trace (full resolution, no class image): lists the pixels
  // `p` traces (and, with list_glass, those behind glass) and writes, for every other pixel,
  // what the tracer writes for a pixel without work: zeros in the images bound at IMG_OUT,
  // IMG_OUT2 and IMG_REFRACTION (shaders/common/ssr_main.glsl's outputs).
  // `debug`: the tracer writes its debug image this frame, so the unlisted pixels get theirs.
  void classify_for_tracer(int width, int height, shared::ClassifyParams p, bool debug, gl::PassTimer* timer);
  // Binds the tile list at SSBO_TILES and as the indirect dispatch buffer; the trace pass calls
  // dispatch() with a program whose local size is CLASSIFY_TILE x CLASSIFY_TILE.
  void bind() const;
  void dispatch() const;
  // Binds the ray list at SSBO_RAYS and dispatches a program of RAY_LIST_GROUP lanes a group
  // over it (glDispatchComputeIndirect).
  void dispatch_rays() const;
  // Reads the header back (stalls; for tests and the speed report): tiles listed, rays cast.
  shared::TileListHeader read_header() const;
  // The trace grid of a w x h frame at `divisor` (1 or 2): ceil(size / divisor).
  static glm::ivec2 trace_size(int w, int h, int divisor);

 private:
  // Sizes the lists for a w x h trace grid, uploads `p`, zeroes the headers, binds them all.
  void prepare(glm::ivec2 size, const shared::ClassifyParams& p);
  gl::Program program_;
  gl::Program tracer_program_, tracer_debug_program_;  // CLASSIFY_FOR_TRACER (and SSR_DEBUG_IMAGE)
  gl::Buffer params_;
  gl::Buffer tiles_, rays_;
  std::size_t tiles_capacity_ = 0, rays_capacity_ = 0;
};

}  // namespace ssr
