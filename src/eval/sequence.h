// `ssrlab sequence`: a camera path rendered frame after frame, each technique keeping its history,
// scored against each frame's truth (every K-th frame and the one after it), with temporal
// metrics: flicker beyond the truth's, error on recently disoccluded pixels, error per frame.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "registry/variants.h"
#include "eval/breakdown.h"
#include "eval/metrics.h"
#include "eval/runner.h"

namespace ssr {

struct SequenceSpec {
  std::string path;      // the scene's camera path; "still" = its default camera, not moving
  int frames = 1;
  int truth_every = 1;   // truth at frames 0, K, 2K, ... and the frame after each (flicker pairs)
  float fps = 30.0f;     // frame i is at time i / fps
  // Every truth frame rendered a second time with another seed, for the flicker ratio without
  // the truth's noise (SequenceSummary::noise_free_change_ratio).
  bool second_truth = false;
};

// A built-in path every scene has: the default camera standing still (convergence).
inline const char* kStillPath = "still";

struct SequenceTechniqueFrame {
  std::string technique, label;
  std::size_t nonfinite = 0;          // non-finite values in its outputs this frame
  std::optional<ErrorMetrics> error;  // truth frames only
  std::optional<Breakdown> breakdown;
  std::optional<double> instability;  // mean excess change vs the previous frame (pairs only)
};

struct SequenceFrame {
  int index = 0;
  float time = 0;
  bool cut = false;
  bool truth = false;
  std::vector<SequenceTechniqueFrame> results;
};

struct SequenceSummary {
  std::string technique, label, preset;
  std::vector<std::pair<std::string, std::string>> params;  // every parameter's value, "auto" included
  std::vector<std::pair<std::string, std::string>> ran_params;  // as the last frame ran them ("auto" resolved)
  std::optional<double> instability_mean, instability_p95;  // over every pair's pixels
  std::size_t instability_pixels = 0;
  struct RegionInstability {
    std::string region;
    std::optional<double> mean, p95;
    std::size_t pixels = 0;
  };
  std::vector<RegionInstability> instability_regions;  // breakdown.h's regions, report order
  // Mean change per pixel between frame pairs of the technique and of the truth (same pixels),
  // and their ratio: the technique moves `change_ratio` times as much as the scene does.
  std::optional<double> change_mean, truth_change_mean, change_ratio;
  // With SequenceSpec::second_truth: the technique's root-mean-square change over the truth's
  // without its noise (temporal.h noise_free_change_ratio), on the same pixels.
  std::optional<double> noise_free_change_ratio;
  // The same against the truth's change with its noise (rms_change_ratio): the step from
  // change_ratio to this is the norm's, from this to noise_free_change_ratio the noise's.
  std::optional<double> rms_change_ratio;
  std::optional<double> disoccluded_psnr, elsewhere_psnr;   // final image vs truth
  std::size_t disoccluded_pixels = 0;
  // The part of `elsewhere` whose true reflection moved since the truth frame before (trails).
  std::optional<double> moving_psnr;
  std::size_t moving_pixels = 0;
  std::vector<std::optional<double>> convergence;           // PSNR per truth frame (null: nothing reflects)
  std::vector<int> convergence_frames;                      // the frame index of each
  std::size_t nonfinite = 0;                                // over every frame
};

struct SequenceResults {
  std::string scene, path;
  int width = 0, height = 0;
  float fps = 0;
  int truth_every = 1;
  bool second_truth = false;
  std::vector<std::pair<std::string, std::string>> reference_params;  // the truth's (reference.*)
  std::vector<std::pair<std::string, std::string>> frame_settings;    // frame.exposure, frame.reflective_f0
  // The truth's own noise (ScoredFrame::truth_noise) on frame 0, and on the pair of frames 0 and 1
  // the truth's mean change and the part of it that is noise (temporal.h noise_in_change): where
  // that part is most of the change, flicker of that size is hidden in the truth's.
  std::optional<TruthNoise> truth_noise;
  std::optional<double> first_pair_truth_change, first_pair_noise_change;
  std::vector<SequenceFrame> frames;
  std::vector<SequenceSummary> summary;
};

// What a frame shows, for videos and PNG frames: per technique its final image, and the truth
// (when this is a truth frame), as display values.
struct SequenceImages {
  const SequenceFrame& frame;
  std::vector<const RgbaImageF*> technique;  // per variant
  const RgbaImageF* truth = nullptr;         // null on frames without truth
  const std::vector<PixelClass>* classes = nullptr;
};

// The camera path a sequence follows: the scene's path of that name, or kStillPath. Throws
// InputError naming the known paths.
CameraPath sequence_path(const Scene& scene, const std::string& name);

// Pixels a history needs to count as settled: younger pixels are "recently disoccluded".
constexpr int kGhostingFrames = 4;

// Renders the sequence. `on_frame` (may be empty) receives each frame's images.
SequenceResults run_sequence(Renderer& renderer, const std::vector<Variant>& variants, Technique& reference,
                             const SequenceSpec& spec,
                             const std::function<void(const SequenceImages&)>& on_frame);

nlohmann::json sequence_json(const DeviceInfo& device, const std::string& revision, const SequenceResults& r);
// The summary as a text table, with a line on the truth's noise where it was estimated.
std::string sequence_table(const SequenceResults& r);
// Two plots in one SVG: PSNR per frame, and flicker (mean excess change) per frame.
std::string sequence_svg(const SequenceResults& r);

}  // namespace ssr
