// The reflection denoiser (issue 14): spatial reconstruction with the ratio estimator (fireflies
// weighed down while a pixel's history is young: it reads last frame's history length), temporal
// accumulation with surface and parallax reprojection, cross-bilateral cleanup
// (shaders/denoise/*.comp, each its own timed pass). `stochastic` runs it on its one ray per
// pixel; the tracers (linear, linear-binary, dda, hiz) run it on their samples with
// `denoise=true`, so any tracer can be compared with and without it.
//
// Input contract: the trace writes, per trace texel (full resolution, or one pixel per 2x2 block
// at half resolution), premultiplied radiance (rgb * confidence, confidence) and the ray (view-
// space hit vector, pdf of its direction), and the class texture (render/classification.h) says
// which pixels traced. The denoiser's textures are a block of the technique's declared textures
// (TechniqueDecl::textures), so the frame allocates them and zeroes the history on reset().
#pragma once
#include <span>
#include <vector>

#include "core/params.h"
#include "render/technique_api.h"
#include "shared/denoise.h"

namespace ssr {

// The denoiser's parameter rows for a Params struct whose DenoiseParams sits at `offset`.
// `with_switch` adds the `denoise` on/off row (tracers); `stochastic` always denoises.
std::vector<ParamDesc> denoise_options(std::size_t offset, bool with_switch);

class Denoiser {
 public:
  // The denoiser's textures, in this order (indices into the block).
  enum Slot : int {
    kClass,          // R8 classes (render/classification.h), full resolution
    kTraceRadiance,  // RGBA16F premultiplied radiance, trace resolution
    kTraceRay,       // RGBA16F hit vector, pdf, trace resolution
    kSpatial,        // RGBA16F premultiplied radiance after stage 1 (spatial_divisor)
    kSpatialStats,   // RG16F variance, mean hit length (spatial_divisor)
    // Stage 2's output and next frame's history, two pairs used in turn (persistent): a frame
    // reads one pair and writes the other, so nothing is copied.
    kTemporalA,      // RGBA16F premultiplied radiance after stage 2
    kTemporalStatsA, // RG16F variance, frames accumulated
    kTemporalB,
    kTemporalStatsB,
    kSlotCount,
  };
  static std::vector<TextureDecl> textures(int trace_divisor, const shared::DenoiseParams& p);
  // Where the spatial stage runs: on the trace grid (2) when the trace is at half resolution and
  // the temporal stage is on, which then upsamples (a pass costs about its invocation count:
  // docs/RESULTS.md, "each pass's floor"); else at full resolution (1), upsampling itself.
  static int spatial_divisor(int trace_divisor, const shared::DenoiseParams& p) {
    return trace_divisor == 2 && p.temporal != 0 ? 2 : 1;
  }
  // The stage views (classes, raw, ray length, spatial, and with the temporal stage temporal,
  // history; variance from the last stage) and the texture each shows after the last run, offset
  // by `first` (where the block starts in the technique's textures).
  std::vector<StageView> stage_views(int first, const shared::DenoiseParams& p) const;
  // Forget the history: the next frame writes pair A (the frame zeroed both).
  void reset() {
    written_ = kTemporalB;
    written_serial_ = 0;
  }

  void load(const gl::ShaderSource& src);
  // Runs the enabled stages on the block `tex` (kSlotCount textures) and writes the frame's
  // reflection. The classes and the trace textures must be written for this frame.
  void run(const FrameContext& frame, std::span<gl::Texture2D* const> tex, const shared::DenoiseParams& p,
           int trace_divisor);

 private:
  gl::Program spatial_, temporal_, bilateral_;
  gl::Buffer ubo_;
  gl::Sampler bilinear_;
  // The pair the last run wrote (radiance; + 1: its stats) and its frame: a new frame reads it
  // and writes the other; a second run of the same frame writes it again from the same history.
  Slot written_ = kTemporalB;
  std::uint64_t written_serial_ = 0;
};

}  // namespace ssr
