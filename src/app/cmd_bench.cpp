// `ssrlab bench`: scenes x techniques x parameter sweeps x sizes. Warm-up, then N frames with
// every pass timed; the floor pass; the error of every variant against the reference; JSON, CSV
// and SVG plots (error vs time, time vs resolution, time vs the swept parameter).
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <set>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "core/cli_common.h"
#include "core/errors.h"
#include "gl/context.h"
#include "core/files.h"
#include "core/revision.h"
#include "registry/variants.h"
#include "eval/results.h"
#include "eval/runner.h"
#include "eval/svg_plot.h"
#include "scene/scene_io.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

namespace fs = std::filesystem;

namespace ssr {
namespace {

struct BenchOptions {
  std::string scenes;                 // comma-separated
  std::vector<std::string> scene_list;  // --scene, repeatable (for names with options and commas)
  std::optional<std::string> techniques;  // not given: every technique but reference and planar
  std::vector<std::string> presets;
  std::vector<std::string> sets;
  std::vector<std::string> sweeps;
  std::string sizes = "1280x720";
  int frames = 20;
  int warmup = 5;
  std::string json, csv, plot;
  std::string gl = "auto";
  std::string shader_dir;  // empty: the embedded shaders
  FrameOptions frame;      // --exposure, --reflective-f0
};

constexpr std::size_t kMaxListed = 64;  // scenes, and sizes, per bench

std::string size_name(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

void progress(std::size_t done, std::size_t total, const std::string& what) {
  if (!isatty(STDOUT_FILENO)) return;
  const int width = 30;
  const int filled = total ? static_cast<int>(width * done / total) : width;
  std::printf("\r[%s%s] %zu/%zu %-50.50s", std::string(static_cast<std::size_t>(filled), '#').c_str(),
              std::string(static_cast<std::size_t>(width - filled), ' ').c_str(), done, total, what.c_str());
  if (done == total) std::printf("\n");
  std::fflush(stdout);
}

// The plots beside --plot are named after it, the plot's kind, the scene and the size. A scene's
// name comes from its file, so anything but letters, digits, '.', '-' and '_' becomes '_'.
std::string plot_path(const std::string& plot, const std::string& kind, const std::string& scene,
                      const std::string& size = "") {
  const fs::path base(plot);
  std::string slug = scene;
  for (char& ch : slug)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-' && ch != '_') ch = '_';
  return (base.parent_path() / base.stem()).string() + "-" + kind + "-" + slug + (size.empty() ? "" : "-" + size) + ".svg";
}

// Which plots bench writes beside --plot, and where: one error-vs-time plot per run (the first
// run's is the --plot file itself), a time-vs-parameter plot per run when a variant sweeps, and a
// time-vs-resolution plot per scene when several sizes run. Planned before the runs (every path
// checked) and followed after them.
enum class PlotKind { Pareto, Sweep, Resolution };
struct PlotPlan {
  std::string plot;  // --plot
  bool swept = false;
  bool several_sizes = false;

  // No value: this plot is not written. `size` and `first_run` matter to the per-run plots only.
  std::optional<std::string> path(PlotKind kind, const std::string& scene, const std::string& size = "",
                                  bool first_run = false) const {
    switch (kind) {
      case PlotKind::Pareto: return first_run ? plot : plot_path(plot, "pareto", scene, size);
      case PlotKind::Sweep: return swept ? std::optional(plot_path(plot, "sweep", scene, size)) : std::nullopt;
      case PlotKind::Resolution: return several_sizes ? std::optional(plot_path(plot, "resolution", scene)) : std::nullopt;
    }
    return std::nullopt;
  }
};

void write_plots(const PlotPlan& plan, const std::vector<RunResults>& runs,
                 const std::vector<Variant>& variants, const std::string& clock) {
  std::vector<std::string> written;
  auto write = [&](const std::string& path, const PlotSpec& spec) {
    write_text_file_atomic(path, svg_plot(spec));
    written.push_back(path);
  };
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const RunResults& run = runs[r];
    const std::string where = run.scene + " " + size_name(run.width, run.height);
    // Error vs time: one curve per technique across its sweep; presets as labelled points.
    PlotSpec pareto{"Tracing error vs time, " + where, "time (ms, " + clock + ", log)",
                    "PSNR traceable (dB, higher is better)", true, false, {}};
    std::map<std::string, std::size_t> series_of;
    for (std::size_t i = 0; i < run.results.size(); ++i) {
      const TechniqueResult& t = run.results[i];
      const std::string name = t.preset.empty() ? t.technique : "preset " + t.preset;
      if (!series_of.count(name)) {
        series_of[name] = pareto.series.size();
        pareto.series.push_back({name, {}, {}, t.preset.empty()});
      }
      PlotSeries& s = pareto.series[series_of[name]];
      if (!t.error.psnr_traceable) continue;  // nothing traceable: no point to plot
      s.points.push_back({t.time_ms.median, *t.error.psnr_traceable});
      s.labels.push_back(t.preset.empty() ? t.label.substr(t.technique.size()) : t.preset);
    }
    // Each technique's curve is its Pareto front (sorted by time, each point better than every
    // faster one); the variants it dominates are drawn as unlabelled markers beside it.
    std::vector<PlotSeries> fronts;
    for (const PlotSeries& s : pareto.series) {
      std::vector<std::size_t> idx(s.points.size());
      for (std::size_t k = 0; k < idx.size(); ++k) idx[k] = k;
      std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return s.points[a].first < s.points[b].first; });
      PlotSeries front{s.name, {}, {}, s.lines}, rest{s.name + " (dominated)", {}, {}, false};
      double best = -1e300;
      for (auto k : idx) {
        PlotSeries& to = s.points[k].second > best ? front : rest;
        best = std::max(best, s.points[k].second);
        to.points.push_back(s.points[k]);
        to.labels.push_back(&to == &front ? s.labels[k] : "");
      }
      fronts.push_back(front);
      if (!rest.points.empty()) fronts.push_back(rest);
    }
    pareto.series = fronts;
    const std::string size = size_name(run.width, run.height);
    write(*plan.path(PlotKind::Pareto, run.scene, size, r == 0), pareto);
    // Time vs the swept parameter, per technique with a sweep.
    const std::optional<std::string> sweep_path = plan.path(PlotKind::Sweep, run.scene, size);
    if (!sweep_path) continue;
    // Against the first swept key: a series for each combination of the other swept keys' values.
    // A key whose values are not all numbers (auto, true/false, a choice) is placed by the order
    // of its values, each point labelled with its value.
    PlotSpec sweep{"Time vs swept parameter, " + where, "parameter value", "time (ms, " + clock + ")", false, false, {}};
    const auto param = [](const TechniqueResult& t, const std::string& key) {
      for (const auto& [k, v] : t.params)
        if (k == key) return v;
      return std::string();
    };
    struct Axis {
      std::vector<std::string> values;  // in order of appearance
      bool numeric = true;              // every value a number (param_value_json's typing)
    };
    std::map<std::string, Axis> axes;  // per x key
    for (std::size_t i = 0; i < run.results.size(); ++i) {
      if (variants[i].swept_keys.empty()) continue;
      Axis& axis = axes[variants[i].swept_keys.front()];
      const std::string v = param(run.results[i], variants[i].swept_keys.front());
      if (std::find(axis.values.begin(), axis.values.end(), v) != axis.values.end()) continue;
      axis.values.push_back(v);
      axis.numeric = axis.numeric && param_value_json(v).is_number();
    }
    for (std::size_t i = 0; i < run.results.size(); ++i) {
      const std::vector<std::string>& keys = variants[i].swept_keys;
      if (keys.empty()) continue;
      const TechniqueResult& t = run.results[i];
      std::string name = keys.front();
      for (std::size_t k = 1; k < keys.size(); ++k) name += (k == 1 ? " at " : ", ") + keys[k] + "=" + param(t, keys[k]);
      auto it = std::find_if(sweep.series.begin(), sweep.series.end(), [&](const PlotSeries& s) { return s.name == name; });
      if (it == sweep.series.end()) { sweep.series.push_back({name, {}, {}, true}); it = sweep.series.end() - 1; }
      const Axis& axis = axes[keys.front()];
      const std::string v = param(t, keys.front());
      const double x = axis.numeric ? param_value_json(v).get<double>()
                                    : static_cast<double>(std::find(axis.values.begin(), axis.values.end(), v) - axis.values.begin());
      it->points.push_back({x, t.time_ms.median});
      if (!axis.numeric) it->labels.push_back(v);
    }
    write(*sweep_path, sweep);
  }
  // Time vs resolution: per scene, per technique (first variant of each), when several sizes ran.
  std::map<std::string, PlotSpec> by_scene;
  for (const RunResults& run : runs) {
    PlotSpec& spec = by_scene[run.scene];
    spec.title = "Time vs resolution, " + run.scene;
    spec.x_label = "megapixels (log)";
    spec.y_label = "time (ms, " + clock + ", log)";
    spec.log_x = spec.log_y = true;
    std::map<std::string, bool> seen;
    for (const TechniqueResult& t : run.results) {
      const std::string name = t.preset.empty() ? t.technique : "preset " + t.preset;
      if (seen[name]) continue;
      seen[name] = true;
      auto it = std::find_if(spec.series.begin(), spec.series.end(), [&](const PlotSeries& s) { return s.name == name; });
      if (it == spec.series.end()) { spec.series.push_back({name, {}, {}, true}); it = spec.series.end() - 1; }
      it->points.push_back({run.width * double(run.height) / 1e6, t.time_ms.median});
      it->labels.push_back(size_name(run.width, run.height));
    }
  }
  for (auto& [scene, spec] : by_scene) {
    const std::optional<std::string> path = plan.path(PlotKind::Resolution, scene);
    bool several = false;  // not when every size but one was skipped
    for (const PlotSeries& s : spec.series) several |= s.points.size() > 1;
    if (path && several) write(*path, spec);
  }
  for (const std::string& p : written) std::printf("plot: %s\n", p.c_str());
}

int run_bench(const BenchOptions& o) {
  if (o.json.empty() && o.csv.empty() && o.plot.empty())
    throw InputError("bench needs at least one of --json, --csv, --plot.");
  if (!o.plot.empty() && files::lower_extension(o.plot) != ".svg") throw InputError("--plot must name a .svg file.");
  if (o.frames < 1 || o.frames > 10000) throw InputError("--frames must be in [1, 10000].");
  if (o.warmup < 0 || o.warmup > 1000) throw InputError("--warmup must be in [0, 1000].");
  std::vector<std::pair<int, int>> sizes;
  for (const std::string& s : split_list(o.sizes, "size")) {
    sizes.push_back(parse_size(s));
    if (std::count(sizes.begin(), sizes.end(), sizes.back()) > 1)  // "1080p,1920x1080"
      throw InputError("size list names " + std::to_string(sizes.back().first) + "x" +
                       std::to_string(sizes.back().second) + " twice.");
  }
  std::vector<std::string> scene_names = o.scene_list;
  if (!o.scenes.empty())
    for (const std::string& s : split_list(o.scenes, "scene")) scene_names.push_back(s);
  if (scene_names.empty()) scene_names.push_back("gallery");
  // --scene X and --scenes X, or two paths to one file: two runs a reader takes for two scenes.
  std::vector<std::string> identities;
  for (const std::string& spec : scene_names) {
    std::error_code ec;
    const fs::path file = fs::weakly_canonical(spec, ec);
    identities.push_back(!ec && fs::is_regular_file(file, ec) ? file.string() : spec);
    if (std::count(identities.begin(), identities.end(), identities.back()) > 1)
      throw InputError("scene '" + spec + "' is given twice.");
  }
  require_output_files({{"--json", o.json}, {"--csv", o.csv}, {"--plot", o.plot}}, scene_names);
  // Every scene is loaded up front, and each size is a full run: bound both lists.
  for (const auto& [what, n] : {std::pair{"sizes", sizes.size()}, {"scenes", scene_names.size()}})
    if (n > kMaxListed)
      throw InputError("bench was given " + std::to_string(n) + " " + what + ", more than the " +
                       std::to_string(kMaxListed) + " supported.");
  std::vector<Scene> scenes;
  for (const std::string& s : scene_names) scenes.push_back(load_scene(s));
  const std::vector<std::string> names = technique_names(o.techniques, oracle_names());
  const std::vector<Variant> variants = build_variants(names, o.sets, o.sweeps, o.presets);
  const FrameSettings settings = frame_settings(o.frame);  // the table's ranges, before any GL
  auto reference = create_technique(truth_name());
  apply_assignments(*reference, sets_for(truth_name(), o.sets));
  const gl::ShaderSource shaders = gl::ShaderSource::from_option(o.shader_dir);
  const PlotPlan plot_plan{o.plot,
                           std::any_of(variants.begin(), variants.end(), [](const Variant& v) { return !v.swept_keys.empty(); }),
                           sizes.size() > 1};
  if (!o.plot.empty()) {
    // Every plot write_plots() may write beside --plot, checked against the other outputs now:
    // not after the runs, with half the files written.
    // Two scenes whose names give one file name (two files named alike, "a b" and "a_b") would
    // overwrite each other's plots.
    std::vector<std::pair<std::string, std::string>> outputs = {{"--json", o.json}, {"--csv", o.csv}, {"--plot", o.plot}};
    std::map<std::string, std::size_t> planned;  // plot path -> the scene it belongs to
    std::size_t scene_index = 0;
    auto plan = [&](const std::string& what, const std::optional<std::string>& path) {
      if (!path || *path == o.plot) return;  // not written, or the --plot file itself
      const auto [it, added] = planned.emplace(*path, scene_index);
      if (added) outputs.emplace_back("--plot's " + what + " plot", *path);
      else if (it->second != scene_index)
        throw InputError("scenes '" + scene_names[it->second] + "' and '" + scene_names[scene_index] +
                         "' would write the same plot '" + *path + "' (their names give one file name).");
    };
    for (scene_index = 0; scene_index < scenes.size(); ++scene_index) {
      const std::string& scene = scenes[scene_index].name;
      for (std::size_t j = 0; j < sizes.size(); ++j) {
        const std::string size = size_name(sizes[j].first, sizes[j].second);
        plan("pareto", plot_plan.path(PlotKind::Pareto, scene, size, scene_index + j == 0));
        plan("sweep", plot_plan.path(PlotKind::Sweep, scene, size));
      }
      plan("resolution", plot_plan.path(PlotKind::Resolution, scene));
    }
    require_output_files(outputs, scene_names);
  }

  auto ctx = open_gl(o.gl, sizes);
  const gl::ContextInfo& gi = ctx->info();
  const std::string clock = gi.software ? "cpu" : "gpu";
  const TimingOptions timing{o.warmup, o.frames, gi.software ? gl::PassTimer::Clock::Cpu : gl::PassTimer::Clock::Gpu};
  std::vector<RunResults> runs;
  const std::size_t total = scenes.size() * sizes.size() * variants.size();
  std::size_t done = 0;
  for (const Scene& scene : scenes) {
    std::unique_ptr<Renderer> renderer;
    for (auto [w, h] : sizes) {
      try {
        if (!renderer) renderer = std::make_unique<Renderer>(scene, w, h, shaders);
        renderer->resize(w, h);
        renderer->settings = settings;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "ssrlab: skipping %s at %dx%d: %s\n", scene.name.c_str(), w, h, e.what());
        done += variants.size();
        continue;
      }
      reference->load(renderer->shaders());
      const Camera& camera = scene.cameras.front();
      progress(done, total, scene.name + " " + size_name(w, h) + " reference");
      auto frame = std::make_unique<ScoredFrame>(*renderer, camera, *reference);
      RunResults run{scene.name, w, h, frame->inherent_psnr(), {}, frame->inherent(), std::nullopt, param_list(*reference),
                     param_list(frame_settings_params(renderer->settings)),
                     frame->truth_noise()};  // with the reference's run, before any timing
      for (const Variant& v : variants) {
        progress(done, total, scene.name + " " + size_name(w, h) + " " + v.label());
        EvaluatedVariant ev = evaluate_variant(*renderer, *frame, camera, v, timing);
        run.results.push_back(ev.result);
        if (technique_info(v.technique).oracle && !run.oracles) run.oracles = oracle_agreement(*frame, ev.score);
        ++done;
      }
      time_floor(*renderer, camera, timing, run);  // after the variants (runner.h says why)
      progress(done, total, "");
      std::printf("%s", results_table(run, clock).c_str());
      runs.push_back(std::move(run));
      renderer->resize(1, 1);  // free the big targets before the next size
    }
  }
  if (runs.empty()) throw RuntimeError("every scene and size was skipped; nothing was written.");
  // Shaders loaded from a directory are not the build's: the revision says so.
  const std::string revision = build_revision() + (o.shader_dir.empty() ? "" : " (shaders from " + o.shader_dir + ")");
  if (!o.json.empty()) write_text_file_atomic(o.json, bench_json({gi.renderer, gi.version, clock}, revision, runs).dump(2) + "\n");
  if (!o.csv.empty()) write_text_file_atomic(o.csv, results_csv(runs));
  if (!o.plot.empty() && !runs.empty()) write_plots(plot_plan, runs, variants, clock);
  std::printf("device: %s | %s | clock %s | revision %s\n", gi.renderer.c_str(), gi.version.c_str(), clock.c_str(), revision.c_str());
  return 0;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* c = app.add_subcommand("bench", "Time and score techniques over scenes, sweeps and sizes.");
  c->add_option("--scenes", o->scenes, "Comma-separated scenes (default gallery).");
  c->add_option("--scene", o->scene_list, "One scene, options allowed: gallery:reflectors=4,normal_map=tiles (repeatable).");
  c->add_option("--techniques", o->techniques, "Comma-separated techniques (default: all screen-space ones).");
  c->add_option("--preset", o->presets, "Add a named preset as its own variant (repeatable).");
  c->add_option("--set", o->sets, "Parameter assignment technique.key=value (repeatable; reference.* too).");
  c->add_option("--sweep", o->sweeps, "technique.key=v1,v2,... (repeatable; sweeps of one technique multiply).");
  c->add_option("--sizes", o->sizes, "Comma-separated sizes: WxH or " + size_names() + ".")->capture_default_str();
  c->add_option("--frames", o->frames, "Timed frames per variant.")->capture_default_str();
  c->add_option("--warmup", o->warmup, "Untimed frames before timing (on a GPU, more until 0.3 s have passed: the clock comes up).")->capture_default_str();
  c->add_option("--json", o->json, "Results JSON.");
  c->add_option("--csv", o->csv, "Results CSV.");
  c->add_option("--plot", o->plot, "Error-vs-time SVG; sweep and resolution plots go beside it.");
  add_frame_options(c, &o->frame);
  c->add_option("--gl", o->gl, "GL path: " + gl::backend_names() + ".")->capture_default_str();
  c->add_option("--shaders", o->shader_dir,
                "Load shaders from this directory instead of the embedded copy (to time another revision's).");
  return {c, [o] { return run_bench(*o); }};
}

}  // namespace ssr
