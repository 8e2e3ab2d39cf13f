// Scoring and timing techniques on one frame: the engine of `ssrlab compare` and `ssrlab bench`.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "registry/variants.h"
#include "eval/breakdown.h"
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
  // Renders `frame` and runs `reference` (a "reference" technique) on it.
  ScoredFrame(Renderer& renderer, const FrameRequest& frame, Technique& reference);

  struct Score {
    ErrorMetrics error;     // pooled figures (ARCHITECTURE §7's `error`)
    Breakdown breakdown;    // per region and class
    RgbaImageF display;     // the technique's final image, display values
    RgbaImageF reflected;   // its reflected radiance before the specular weight, display values
    RgbaImageF reflection;  // its reflection texture (rgb, confidence)
    std::vector<float> confidence;
  };
  // Runs `t` on this frame's inputs and scores it.
  Score score(Technique& t);

  const RgbaImageF& truth() const { return truth_; }      // reference final image, display values
  const RgbaImageF& ideal() const { return ideal_; }      // screen-space ideal, display values
  const RgbaImageF& truth_reflected() const { return truth_reflected_; }
  const RgbaImageF& ideal_reflected() const { return ideal_reflected_; }
  const std::vector<PixelClass>& classes() const { return labels_.classes; }
  const PixelLabels& labels() const { return labels_; }
  // The G-buffer's normal-map flag per pixel (row 0 = top): the oracles skip those pixels.
  const std::vector<bool>& normal_mapped() const { return normal_mapped_; }
  std::optional<double> inherent_psnr() const { return inherent_psnr_; }
  InherentFigures inherent() const;
  std::size_t reference_rays() const { return rays_; }
  // The truth's sampling noise (results.h TruthNoise): a second reference run with another seed;
  // half the mean squared difference of the two truths is the noise variance one carries. Run on
  // the first call; none when the truth samples nothing (every scored pixel a mirror, one bounce).
  std::optional<TruthNoise> truth_noise();
  // That second truth's reflected radiance (display values), or null where the truth samples
  // nothing: `sequence` compares the truth's change between frames under the two seeds.
  const RgbaImageF* other_truth_reflected();
  // The references as the breakdown takes them; `samples` > 0 adds the noise floor of a
  // technique tracing that many rays per rough pixel (one more reference run per new count).
  ReferenceImages references(int samples);
  // The hit classes of a score (for the `hit-classes` view).
  std::vector<HitClass> hit_classes_of(const Score& s, const Technique& t);

 private:
  RgbaImageF display_of(ViewMode view);
  // Renders the reference again with `samples` rays a rough pixel and its seed moved by `shift`
  // (independent samples): its truth in the renderer's targets, its outputs in last_rerun_.
  void rerun_reference(int samples, long shift);
  std::unique_ptr<Technique> last_rerun_;  // the reference every rerun uses
  Renderer& renderer_;
  Technique& reference_;
  FrameRequest frame_;
  RgbaImageF truth_, ideal_, truth_reflected_, ideal_reflected_;
  PixelLabels labels_;
  std::vector<bool> normal_mapped_;
  std::map<int, RgbaImageF> ideal_at_samples_;  // composited ideal at N samples a rough pixel
  std::optional<double> inherent_psnr_;
  std::size_t rays_ = 0;
  std::optional<std::optional<TruthNoise>> truth_noise_;  // computed once
  RgbaImageF other_truth_reflected_;                      // truth_noise()'s second truth
};

// The rays per rough pixel of a technique (its `samples` parameter), 0 when it has none.
int technique_samples(Technique& t);

// How far the second truth's seed lies from the truth's (the truth's own noise: compare, bench,
// sequence and the viewer), apart from the noise floor's run (7919): independent samples.
inline constexpr long kTruthNoiseSeedShift = 2 * 7919;

// Sets the reference `ref` up as `truth` (the same parameters) with its seed moved by `shift` and,
// where `samples` > 0, that many rays a rough pixel.
void set_up_with_seed(Technique& truth, Technique& ref, long shift, int samples = 0);

struct TimingOptions {
  int warmup = 3;
  int frames = 10;
  gl::PassTimer::Clock clock = gl::PassTimer::Clock::Gpu;
};

// Runs the warm-up: o.warmup calls of `frame`, and on the GPU clock, with `clock` set, more until
// 0.3 s have passed (a GPU idle for a while runs at a low clock for the first frames after).
void warm_up(const TimingOptions& o, bool clock, const std::function<void()>& frame);

// The pass that Timing::passes names for the technique span's time outside its timed passes.
inline constexpr const char* kBetweenPasses = "between passes";

struct Timing {
  TimeStats technique;             // the technique's span (renderer.h kTechniqueSpan)
  std::vector<PassTiming> passes;  // median of every pass of the frame (the span's inside too)
};

// Renders warm-up and timed whole frames (inputs, technique, composite) and times every pass.
// On the GPU it renders them twice: once with a timestamp around each pass (the passes), once
// with the outermost spans alone (the technique's time, no query between its passes).
Timing time_frames(Renderer& renderer, const Camera& camera, Technique& t, const TimingOptions& o);

// Times the floor pass (ARCHITECTURE §6: reads a technique's inputs, writes its output once) as
// a technique of its own, in whole frames like every variant, and sets every result's floor_ms.
// Call it after the variants: straight after a long reference (64 samples on rough scenes) the
// H200 timed it at 2.4x (0.065-0.076 ms against 0.028). Timed alone, frame after frame of one
// short pass, it also came out at 2.5x now and then at 4K (0.16 ms against 0.065): an idle GPU.
void time_floor(Renderer& renderer, const Camera& camera, const TimingOptions& o, RunResults& run);

// One frame of the variant with its shaders instrumented (SSR_TELEMETRY): per-ray iterations
// and idle lanes (render/telemetry.h). None for a technique that records no telemetry.
std::optional<IterationStats> measure_telemetry(Renderer& renderer, const Camera& camera, const Variant& variant);

// Creates the variant's technique, scores it on `frame` and times it: one row of results
// (with its telemetry).
struct EvaluatedVariant {
  TechniqueResult result;
  ScoredFrame::Score score;
};
EvaluatedVariant evaluate_variant(Renderer& renderer, ScoredFrame& frame, const Camera& camera,
                                  const Variant& variant, const TimingOptions& timing);

// `planar` (its score on `frame`) against the reference: mirror, non-normal-mapped reflector
// pixels (ARCHITECTURE §5: the two oracles check each other).
OracleAgreement oracle_agreement(const ScoredFrame& frame, const ScoredFrame::Score& planar);

// The pixels every pooled figure covers in the renderer's current G-buffer (row 0 = top): those
// that do reflection work and those behind glass, which show the technique's refraction (the
// reference's classes, ErrorMetrics::reflective).
std::vector<bool> scored_pixels(const Renderer& r);
// The same from read-back material, depth and glass surfaces (RGBA, ior in w).
std::vector<bool> scored_pixels(const std::vector<std::uint16_t>& material, const std::vector<float>& depth,
                                const RgbaImageF& glass_surface);
// The pixels that do reflection work, from read-back material (4 values a pixel) and depth.
std::vector<bool> reflective_pixels(const std::vector<std::uint16_t>& material, const std::vector<float>& depth);

// The parameters of a technique (or of any table: the frame settings) as key -> text, in table
// order (for results).
std::vector<std::pair<std::string, std::string>> param_list(const ParamSet& p);
inline std::vector<std::pair<std::string, std::string>> param_list(Technique& t) { return param_list(t.params()); }

}  // namespace ssr
