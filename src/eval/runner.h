// Scoring and timing techniques on one frame: the engine of `ssrlab compare` and `ssrlab bench`.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/variants.h"
#include "eval/metrics.h"
#include "eval/results.h"
#include "gl/timer.h"
#include "render/renderer.h"
#include "techniques/technique.h"

namespace ssr {

// Display values (tone-mapped, sRGB-encoded, in [0,1]) of a linear HDR image, computed with the
// same shared/tonemap.h code as the display pass.
RgbaImageF display_values(const RgbaImageF& hdr, float exposure);

// One frame of one scene with its ground truth: the reference runs once, then any number of
// techniques are scored against it on exactly the same G-buffer and lit colour.
class ScoredFrame {
 public:
  // Renders the frame's inputs for `camera` and runs `reference` (a "reference" technique).
  ScoredFrame(Renderer& renderer, const Camera& camera, Technique& reference);

  struct Score {
    ErrorMetrics error;
    RgbaImageF display;     // the technique's final image, display values
    RgbaImageF reflection;  // its reflection texture (rgb, confidence)
  };
  // Runs `t` on this frame's inputs and scores it.
  Score score(Technique& t);

  const RgbaImageF& truth() const { return truth_; }      // reference final image, display values
  const RgbaImageF& ideal() const { return ideal_; }      // screen-space ideal, display values
  const std::vector<PixelClass>& classes() const { return classes_; }
  double inherent_psnr() const { return inherent_psnr_; }
  std::size_t reference_rays() const { return rays_; }

 private:
  RgbaImageF final_display();
  Renderer& renderer_;
  RgbaImageF truth_, ideal_;
  std::vector<PixelClass> classes_;
  double inherent_psnr_ = 0;
  std::size_t rays_ = 0;
};

struct TimingOptions {
  int warmup = 3;
  int frames = 10;
  gl::PassTimer::Clock clock = gl::PassTimer::Clock::Gpu;
};

struct Timing {
  TimeStats technique;             // the technique's passes, summed per frame
  std::vector<PassTiming> passes;  // median of every pass of the frame
};

// Renders warmup + frames whole frames (inputs, technique, composite) and times every pass.
Timing time_frames(Renderer& renderer, const Camera& camera, Technique& t, const TimingOptions& o);

// The floor pass (DESIGN §6): reads a technique's inputs, writes its output once.
class FloorPass {
 public:
  explicit FloorPass(const gl::ShaderSource& shaders);
  // Median time over `o.frames` runs (after `o.warmup`) on the renderer's current inputs.
  double time(Renderer& renderer, const TimingOptions& o);

 private:
  gl::Program program_;
};

// Creates the variant's technique, scores it on `frame` and times it: one row of results.
struct EvaluatedVariant {
  TechniqueResult result;
  ScoredFrame::Score score;
};
EvaluatedVariant evaluate_variant(Renderer& renderer, ScoredFrame& frame, const Camera& camera,
                                  const Variant& variant, const TimingOptions& timing, double floor_ms);

// The parameters of a technique as key -> text, in table order (for results).
std::vector<std::pair<std::string, std::string>> param_list(Technique& t);

}  // namespace ssr
