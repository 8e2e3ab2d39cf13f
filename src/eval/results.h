// Result records of `ssrlab compare` and `ssrlab bench`, and their writers (ARCHITECTURE §6, §7):
// results JSON, bench JSON, CSV, and a text table for the terminal.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/breakdown.h"
#include "eval/metrics.h"
#include "render/telemetry.h"

namespace ssr {

struct TimeStats {
  double median = 0, min = 0, max = 0;
};

// Median (mean of the two middle values for even counts), min and max; all 0 for no samples.
TimeStats time_stats(std::vector<double> samples);

struct PassTiming {
  std::string name;
  double ms = 0;  // median over the frames
};

struct DeviceInfo {
  std::string renderer, version, clock;  // clock: "gpu" or "cpu"
};

struct TechniqueResult {
  std::string technique;
  std::string preset;  // "" when none
  std::string label;   // what tables and plots call it, e.g. "linear max_steps=64" ("" = technique)
  // key -> value as text, in table order. In JSON, values that parse as numbers become numbers,
  // true/false become booleans, anything else stays a string.
  std::vector<std::pair<std::string, std::string>> params;
  // The values it ran with, "auto" resolved and a cap that another parameter lowers applied
  // (Technique::ran_params): what ran at this scene and size, where `params` is what was asked.
  std::vector<std::pair<std::string, std::string>> ran_params;
  TimeStats time_ms;                // the technique's passes only
  std::vector<PassTiming> passes;   // every pass of the frame
  double floor_ms = 0;              // the floor pass (ARCHITECTURE §6)
  ErrorMetrics error;
  Breakdown breakdown;              // per region and class (empty: not scored)
  std::optional<IterationStats> telemetry;  // one instrumented frame; none: the technique does not iterate
  // Its image changes frame to frame on a still camera (TechniqueDecl::varies_per_frame: history,
  // new samples): the figures are of its first frame, before any history.
  bool varies_per_frame = false;
};

// The truth's own sampling noise (rough pixels, several bounces): as PSNR, what the noise-free
// truth would score against the truth a run used; a technique's figure near it is limited by the
// truth, not by the technique (raise reference.samples). None where the truth samples nothing.
struct TruthNoise {
  std::optional<double> psnr;            // over every scored pixel
  std::optional<double> psnr_traceable;  // over the traceable ones (trace dB's pixels)
};

struct RunResults {  // one scene at one size
  std::string scene;
  int width = 0, height = 0;
  std::optional<double> inherent_psnr;  // ideal vs truth, once per scene (null: nothing reflects)
  std::vector<TechniqueResult> results;
  InherentFigures inherent;  // ideal vs truth per class
  std::optional<OracleAgreement> oracles;  // planar vs reference, when planar ran
  // The reference's parameters ("reference.samples" ...), as its technique's are: the truth a
  // run was scored against (--set reference.* changes it).
  std::vector<std::pair<std::string, std::string>> reference_params;
  // The frame settings ("frame.exposure", "frame.reflective_f0"): the exposure moves every
  // figure (errors are on display values), reflective_f0 which pixels are scored.
  std::vector<std::pair<std::string, std::string>> frame_settings;
  std::optional<TruthNoise> truth_noise;
};

// time_ms.median / floor_ms; 0 when floor_ms is not positive.
double time_over_floor(const TechniqueResult& r);

// A param value as JSON: integer, floating-point number, boolean, or string.
nlohmann::json param_value_json(const std::string& text);
// {key: value} of a parameter list, each value typed by param_value_json.
nlohmann::json params_json(const std::vector<std::pair<std::string, std::string>>& params);

// The results JSON of ARCHITECTURE §7 (one scene at one size).
nlohmann::json to_json(const DeviceInfo& device, const std::string& revision,
                       const RunResults& run);

// {device, revision, runs:[<each run as to_json without device/revision>]}.
nlohmann::json bench_json(const DeviceInfo& device, const std::string& revision,
                          const std::vector<RunResults>& runs);

// One header line, then one line per technique result (RFC 4180 quoting, "\n" line ends).
std::string results_csv(const std::vector<RunResults>& runs);

// A fixed-width text table of one run for the terminal; `clock` labels the time column. Per
// technique: the pooled figures and the planar / other split of the traceable PSNR against the
// ideal and the correct coverage.
std::string results_table(const RunResults& run, const std::string& clock);

// Every region x class of every technique of a run, one block per technique (--breakdown);
// `regions` (names as Region::name() gives them) keeps only those rows, empty keeps all.
std::string breakdown_table(const RunResults& run, const std::vector<std::string>& regions = {});

// A figure that may be absent: null when it is (and, as nlohmann writes them, when not finite).
nlohmann::json optional_json(const std::optional<double>& v);
// A text table: columns padded to their widest cell, the first left-aligned, the others
// right-aligned, a rule under the header; every row has the header's cell count.
std::string format_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
// A dB figure for tables and messages: two decimals, "-" for an empty set.
std::string db_text(const std::optional<double>& v);
// {"renderer", "version", "clock"}.
nlohmann::json device_json(const DeviceInfo& d);
// The "error" object of one result (pooled figures).
nlohmann::json error_json(const ErrorMetrics& e);
// {"psnr", "psnr_traceable"}, or null where the truth samples nothing.
nlohmann::json truth_noise_json(const std::optional<TruthNoise>& n);
// The "telemetry" object of one result: {"rays", "iterations": {mean, p50, p95, max},
// "idle_lanes"}; null without telemetry.
nlohmann::json telemetry_json(const std::optional<IterationStats>& t);
// The "regions" object of one result (README: results JSON).
nlohmann::json breakdown_json(const Breakdown& b);

// Writes `text` to path + ".tmp<pid>", then renames it onto `path`. On failure removes the
// temporary file and throws RuntimeError (one sentence).
void write_text_file_atomic(const std::filesystem::path& path, const std::string& text);

}  // namespace ssr
