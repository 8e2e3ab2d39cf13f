// The reflection denoiser (issue 14): spatial reconstruction with the ratio estimator, temporal
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
    kSpatial,        // RGBA16F premultiplied radiance after stage 1
    kSpatialStats,   // RG16F variance, mean hit length
    kTemporal,       // RGBA16F after stage 2
    kTemporalStats,  // RG16F variance, frames accumulated
    kHistory,        // persistent copies of the two above, for the next frame
    kHistoryStats,
    kSlotCount,
  };
  static std::vector<TextureDecl> textures(int trace_divisor);
  // The stage views (classes, raw, ray length, spatial, and with the temporal stage temporal,
  // history; variance from the last stage) and the texture each shows, offset by `first`
  // (where the block starts in the technique's textures).
  static std::vector<StageView> stage_views(int first, const shared::DenoiseParams& p);

  void load(const gl::ShaderSource& src);
  // Runs the enabled stages on the block `tex` (kSlotCount textures) and writes the frame's
  // reflection. The classes and the trace textures must be written for this frame.
  void run(const FrameContext& frame, std::span<gl::Texture2D* const> tex, const shared::DenoiseParams& p,
           int trace_divisor);

 private:
  gl::Program spatial_, temporal_, bilateral_;
  gl::Buffer ubo_;
};

}  // namespace ssr
