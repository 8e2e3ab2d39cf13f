#include "eval/sequence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/cli_common.h"
#include "core/errors.h"
#include "eval/results.h"
#include "eval/svg_plot.h"
#include "eval/temporal.h"
#include "scene/animation.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

namespace ssr {

CameraPath sequence_path(const Scene& scene, const std::string& name) {
  const Animation& a = scene.animation;
  if (name == kStillPath || (name.empty() && a.paths.empty())) {
    const Camera& c = scene.cameras.front();
    return CameraPath{kStillPath, "the default camera, standing still", {CameraKey{0.0f, c.position, c.target, c.fov_y_deg, false}}};
  }
  if (name.empty()) return a.paths[static_cast<std::size_t>(std::max(a.default_path, 0))];
  for (const CameraPath& p : a.paths)
    if (p.name == name) return p;
  std::string names;  // the scene's paths, and this command's own
  for (const CameraPath& p : a.paths) names += p.name + ", ";
  throw InputError("scene '" + scene.name + "' has no camera path '" + name + "' (paths: " + names + kStillPath +
                   " for the default camera standing still).");
}

namespace {

TemporalFrame read_temporal(const Renderer& r) {
  TemporalFrame f;
  f.width = r.width();
  f.height = r.height();
  const RgbaImageF motion = r.read_texture(r.motion());
  const std::vector<std::uint16_t> material = r.read_material();
  const std::vector<float> depth = r.read_depth();
  const std::size_t n = depth.size();
  f.motion.resize(n);
  f.object.resize(n);
  f.reflective = scored_pixels(material, depth, r.read_texture(r.gbuffer().glass_surface));
  for (std::size_t i = 0; i < n; ++i) {
    f.motion[i] = {motion.pixels[i * 4], motion.pixels[i * 4 + 1]};
    f.object[i] = depth[i] > 0.0f ? static_cast<std::uint32_t>(material[i * 4 + 3]) + 1u : 0u;
  }
  return f;
}

// Squared error sums of display values (RGB) for the ghosting groups; `moving` is the part of
// `elsewhere` whose true reflection changed since the truth frame before (kMovingReflection).
struct GhostSums {
  double recent = 0, elsewhere = 0, moving = 0;
  std::size_t recent_px = 0, elsewhere_px = 0, moving_px = 0;
};

// A settled pixel whose true reflected radiance changed by more than this (display value, in
// some channel) since the truth frame before, at its reprojected position: a reflection moving
// over a surface that stays, where a history that lags leaves a trail (gallery's slide: the
// green sphere's reflection on the mirror floor). Also where the truth's own noise moves it
// (README: ghosting).
constexpr float kMovingReflection = 0.1f;

// Per pixel of this frame: whether its true reflection moved (kMovingReflection) since the truth
// frame before, at the pixel it reprojects to. Once per truth frame, for every technique.
std::vector<bool> moved_reflections(const std::vector<int>& previous, const RgbaImageF& now, const RgbaImageF& before) {
  std::vector<bool> out(previous.size(), false);
  for (std::size_t p = 0; p < previous.size(); ++p) {
    if (previous[p] < 0) continue;
    const std::size_t q = static_cast<std::size_t>(previous[p]);
    float change = 0;
    for (std::size_t c = 0; c < 3; ++c) change = std::max(change, std::abs(now.pixels[p * 4 + c] - before.pixels[q * 4 + c]));
    out[p] = change > kMovingReflection;
  }
  return out;
}

std::optional<double> psnr_of(double sum, std::size_t px) {
  if (px == 0) return std::nullopt;
  return psnr_from_rmse(std::sqrt(sum / (3.0 * static_cast<double>(px))));
}

struct TechniqueRun {
  std::unique_ptr<Technique> technique;
  RgbaImageF reflected_before;  // its reflected radiance on the previous truth frame
  std::vector<float> excess;    // every pair's pixels
  std::vector<std::pair<std::string, std::vector<float>>> region_excess;  // the same by region
  GhostSums ghost;
  ChangeTotals change;          // technique and truth change over every pair
  ChangeMoments moments;        // the same pairs against two truths (SequenceSpec::second_truth)
};

}  // namespace

SequenceResults run_sequence(Renderer& renderer, const std::vector<Variant>& variants, Technique& reference,
                             const SequenceSpec& spec,
                             const std::function<void(const SequenceImages&)>& on_frame) {
  const Scene& scene = renderer.scene();
  const CameraPath path = sequence_path(scene, spec.path);
  SequenceResults out;
  out.scene = scene.name;
  out.path = path.name;
  out.width = renderer.width();
  out.height = renderer.height();
  out.fps = spec.fps;
  out.truth_every = spec.truth_every;
  out.second_truth = spec.second_truth;
  out.reference_params = param_list(reference);
  out.frame_settings = param_list(frame_settings_params(renderer.settings));

  std::vector<TechniqueRun> runs;
  for (const Variant& v : variants) {
    TechniqueRun run;
    run.technique = create_technique(v.technique);
    apply_assignments(*run.technique, v.assignments);
    run.technique->load(renderer.shaders());
    runs.push_back(std::move(run));
  }

  TemporalFrame before;
  std::vector<int> ages;
  RgbaImageF truth_reflected_before;
  RgbaImageF other_truth_before;  // the last truth frame's second truth (another seed), if rendered
  bool truth_before = false;
  float time_before = 0;
  for (int i = 0; i < spec.frames; ++i) {
    const float t = static_cast<float>(i) / spec.fps;
    const bool cut = i > 0 && cut_between(path, time_before, t);
    const FrameRequest request(camera_at(path, t, scene.cameras.front()), FrameTime{i, t, cut});
    renderer.render_inputs(request, nullptr);
    const TemporalFrame now = read_temporal(renderer);
    const std::vector<int> previous = i > 0 ? reproject(now, before) : std::vector<int>(now.motion.size(), -1);
    ages = update_ages(previous, now, before, ages, cut, kGhostingFrames);

    const int k = spec.truth_every;
    const bool truth = i % k == 0 || (k > 1 && i % k == 1);
    std::optional<ScoredFrame> scored;
    if (truth) scored.emplace(renderer, request, reference);
    const bool pair = truth && truth_before && i > 0 && !cut;
    // Before any technique, as they render the truth again with another seed: the truth's noise
    // on frame 0 and in the first pair's change, and with second_truth on every truth frame
    // (null where the truth samples nothing).
    if (i == 0) out.truth_noise = scored->truth_noise();
    const RgbaImageF* other = truth && (i <= 1 || spec.second_truth) ? scored->other_truth_reflected() : nullptr;
    const RgbaImageF& truth_now = truth ? scored->truth_reflected() : truth_reflected_before;
    if (i == 1 && pair && other && !other_truth_before.pixels.empty()) {
      out.first_pair_noise_change = noise_in_change(previous, now, before, truth_now, truth_reflected_before, *other,
                                                    other_truth_before);
      const ChangeTotals t =
          change_totals(previous, now, before, truth_now, truth_reflected_before, truth_now, truth_reflected_before);
      if (t.pixels) out.first_pair_truth_change = t.truth / static_cast<double>(t.pixels);
    }
    // A frame whose truth samples nothing has no second truth: it is deterministic, so its truth
    // serves as both.
    const bool second_pair = spec.second_truth && pair;
    const RgbaImageF& other_now = other ? *other : truth_now;
    const RgbaImageF& other_before = other_truth_before.pixels.empty() ? truth_reflected_before : other_truth_before;
    const std::vector<bool> moving =
        pair ? moved_reflections(previous, scored->truth_reflected(), truth_reflected_before) : std::vector<bool>();

    SequenceFrame frame{i, t, cut, truth, {}};
    std::vector<RgbaImageF> finals(runs.size());
    for (std::size_t v = 0; v < runs.size(); ++v) {
      TechniqueRun& run = runs[v];
      SequenceTechniqueFrame r;
      r.technique = variants[v].technique;
      r.label = variants[v].label();
      if (truth) {
        ScoredFrame::Score s = scored->score(*run.technique);
        r.nonfinite = s.error.nonfinite;
        r.error = s.error;
        r.breakdown = std::move(s.breakdown);
        const std::vector<PixelClass>& cls = scored->classes();
        for (std::size_t p = 0; p < cls.size(); ++p) {
          if (cls[p] == PixelClass::NotReflective) continue;
          double e = 0;
          for (std::size_t c = 0; c < 3; ++c) {
            const double d = s.display.pixels[p * 4 + c] - scored->truth().pixels[p * 4 + c];
            e += std::isfinite(d) ? d * d : 1.0;
          }
          if (ages[p] < kGhostingFrames) {
            run.ghost.recent += e;
            ++run.ghost.recent_px;
          } else {
            run.ghost.elsewhere += e;
            ++run.ghost.elsewhere_px;
            if (!moving.empty() && moving[p]) {
              run.ghost.moving += e;
              ++run.ghost.moving_px;
            }
          }
        }
        if (pair) {
          const std::vector<float> map = excess_change_map(previous, now, before, s.reflected, run.reflected_before,
                                                           scored->truth_reflected(), truth_reflected_before,
                                                           &run.change);
          if (second_pair)
            add_change_moments(previous, now, before, s.reflected, run.reflected_before, truth_now,
                               truth_reflected_before, other_now, other_before, run.moments);
          double sum = 0;
          std::size_t n = 0;
          for (float e : map)
            if (e >= 0.0f) sum += e, ++n, run.excess.push_back(e);
          if (n) r.instability = sum / static_cast<double>(n);
          for (const Region& region : frame_regions(scored->labels())) {
            const std::string name = region.name();
            auto it = std::find_if(run.region_excess.begin(), run.region_excess.end(),
                                   [&](const auto& kv) { return kv.first == name; });
            if (it == run.region_excess.end()) it = run.region_excess.insert(run.region_excess.end(), {name, {}});
            for (std::size_t p = 0; p < map.size(); ++p)
              if (map[p] >= 0.0f && region.contains(scored->labels(), p)) it->second.push_back(map[p]);
          }
        }
        run.reflected_before = std::move(s.reflected);
        finals[v] = std::move(s.display);
      } else {
        renderer.render(request, *run.technique, ViewMode::Final, nullptr);
        const RgbaImageF color = renderer.read_texture(renderer.color());
        r.nonfinite = count_nonfinite(renderer.read_texture(renderer.reflection()).pixels) + count_nonfinite(color.pixels);
        if (on_frame) finals[v] = display_values(color, renderer.settings.exposure);
      }
      frame.results.push_back(std::move(r));
    }
    if (on_frame) {
      SequenceImages images{frame, {}, truth ? &scored->truth() : nullptr, truth ? &scored->classes() : nullptr};
      for (const RgbaImageF& f : finals) images.technique.push_back(&f);
      on_frame(images);
    }
    out.frames.push_back(std::move(frame));
    if (truth) {
      truth_reflected_before = scored->truth_reflected();
      other_truth_before = other ? *other : RgbaImageF{};
    }
    truth_before = truth;
    before = now;
    time_before = t;
  }

  for (std::size_t v = 0; v < runs.size(); ++v) {
    TechniqueRun& run = runs[v];
    SequenceSummary s;
    s.technique = variants[v].technique;
    s.label = variants[v].label();
    s.preset = variants[v].preset;
    s.params = param_list(*run.technique);
    s.ran_params = param_list(run.technique->ran_params());
    const auto stats = [](std::vector<float>& v, SequenceSummary::RegionInstability& out) {
      out.pixels = v.size();
      if (v.empty()) return;
      double sum = 0;
      for (float e : v) sum += e;
      out.mean = sum / static_cast<double>(v.size());
      std::sort(v.begin(), v.end());
      out.p95 = v[std::min(v.size() - 1, v.size() * 95 / 100)];
    };
    SequenceSummary::RegionInstability pooled;
    stats(run.excess, pooled);
    s.instability_mean = pooled.mean;
    s.instability_p95 = pooled.p95;
    s.instability_pixels = pooled.pixels;
    for (auto& [name, values] : run.region_excess) {
      SequenceSummary::RegionInstability ri;
      ri.region = name;
      stats(values, ri);
      s.instability_regions.push_back(ri);
    }
    if (run.change.pixels) {
      const double n = static_cast<double>(run.change.pixels);
      s.change_mean = run.change.technique / n;
      s.truth_change_mean = run.change.truth / n;
      if (run.change.truth > 0) s.change_ratio = run.change.technique / run.change.truth;
    }
    if (spec.second_truth) {
      s.noise_free_change_ratio = noise_free_change_ratio(run.moments);
      s.rms_change_ratio = rms_change_ratio(run.moments);
    }
    s.disoccluded_psnr = psnr_of(run.ghost.recent, run.ghost.recent_px);
    s.elsewhere_psnr = psnr_of(run.ghost.elsewhere, run.ghost.elsewhere_px);
    s.disoccluded_pixels = run.ghost.recent_px;
    s.moving_psnr = psnr_of(run.ghost.moving, run.ghost.moving_px);
    s.moving_pixels = run.ghost.moving_px;
    for (const SequenceFrame& f : out.frames) {
      const SequenceTechniqueFrame& r = f.results[v];
      s.nonfinite += r.nonfinite;
      if (!f.truth) continue;
      s.convergence.push_back(r.error ? r.error->psnr : std::nullopt);
      s.convergence_frames.push_back(f.index);
    }
    out.summary.push_back(std::move(s));
  }
  return out;
}

nlohmann::json sequence_json(const DeviceInfo& device, const std::string& revision, const SequenceResults& r) {
  nlohmann::json frames = nlohmann::json::array();
  for (const SequenceFrame& f : r.frames) {
    nlohmann::json results = nlohmann::json::array();
    for (const SequenceTechniqueFrame& t : f.results) {
      nlohmann::json j{{"technique", t.technique}, {"label", t.label}, {"nonfinite", t.nonfinite},
                       {"error", t.error ? error_json(*t.error) : nlohmann::json(nullptr)},
                       {"regions", t.breakdown ? breakdown_json(*t.breakdown) : nlohmann::json(nullptr)},
                       {"instability", optional_json(t.instability)}};
      results.push_back(std::move(j));
    }
    frames.push_back({{"index", f.index}, {"time", f.time}, {"cut", f.cut}, {"truth", f.truth}, {"results", results}});
  }
  nlohmann::json summary = nlohmann::json::array();
  for (const SequenceSummary& s : r.summary) {
    nlohmann::json convergence = nlohmann::json::array();
    for (const auto& p : s.convergence) convergence.push_back(optional_json(p));
    nlohmann::json regions = nlohmann::json::object();
    for (const auto& ri : s.instability_regions)
      regions[ri.region] = {{"mean", optional_json(ri.mean)}, {"p95", optional_json(ri.p95)}, {"pixels", ri.pixels}};
    nlohmann::json params = params_json(s.params);
    summary.push_back({{"technique", s.technique},
                       {"label", s.label},
                       {"preset", s.preset},
                       {"params", std::move(params)},
                       {"ran_params", params_json(s.ran_params)},
                       {"instability", {{"mean", optional_json(s.instability_mean)}, {"p95", optional_json(s.instability_p95)}, {"pixels", s.instability_pixels}, {"regions", regions},
                                       {"change_mean", optional_json(s.change_mean)}, {"truth_change_mean", optional_json(s.truth_change_mean)},
                                       {"change_ratio", optional_json(s.change_ratio)},
                                       {"noise_free_change_ratio", optional_json(s.noise_free_change_ratio)},
                                       {"rms_change_ratio", optional_json(s.rms_change_ratio)}}},
                       {"ghosting", {{"disoccluded_psnr", optional_json(s.disoccluded_psnr)}, {"elsewhere_psnr", optional_json(s.elsewhere_psnr)}, {"disoccluded_pixels", s.disoccluded_pixels},
                                     {"moving_psnr", optional_json(s.moving_psnr)}, {"moving_pixels", s.moving_pixels}}},
                       {"convergence", convergence},
                       {"convergence_frames", s.convergence_frames},
                       {"nonfinite", s.nonfinite}});
  }
  nlohmann::json truth_noise = truth_noise_json(r.truth_noise);
  if (r.truth_noise) {
    truth_noise["first_pair_change_mean"] = optional_json(r.first_pair_truth_change);
    truth_noise["first_pair_noise_change_mean"] = optional_json(r.first_pair_noise_change);
  }
  return {{"device", device_json(device)},
          {"revision", revision},
          {"scene", r.scene},
          {"path", r.path},
          {"width", r.width},
          {"height", r.height},
          {"fps", r.fps},
          {"truth_every", r.truth_every},
          {"second_truth", r.second_truth},
          {"reference", params_json(r.reference_params)},
          {"truth_noise", truth_noise},
          {"frame", params_json(r.frame_settings)},
          {"frames", frames},
          {"summary", summary}};
}

std::string sequence_table(const SequenceResults& r) {
  auto num = [](const std::optional<double>& v, const char* f) {
    char b[32];
    if (!v) return std::string("-");
    std::snprintf(b, sizeof b, f, *v);
    return std::string(b);
  };
  std::vector<std::vector<std::string>> rows;
  for (const SequenceSummary& s : r.summary) {
    double sum = 0;
    int n = 0;
    for (const auto& p : s.convergence)
      if (p && std::isfinite(*p)) sum += *p, ++n;
    rows.push_back({s.label, num(n ? std::optional<double>(sum / n) : std::nullopt, "%.2f dB"), num(s.instability_mean, "%.5f"),
                    num(s.instability_p95, "%.5f"), num(s.change_ratio, "%.2f"), num(s.disoccluded_psnr, "%.2f dB"),
                    num(s.elsewhere_psnr, "%.2f dB"), num(s.moving_psnr, "%.2f dB")});
    if (r.second_truth) rows.back().insert(rows.back().begin() + 5, num(s.noise_free_change_ratio, "%.2f"));
  }
  std::vector<std::string> header{"technique", "mean PSNR", "flicker mean", "flicker p95", "x truth", "disocc. PSNR",
                                  "elsewhere", "moving refl."};
  if (r.second_truth) header.insert(header.begin() + 5, "x truth, no noise");
  std::string out = format_table(header, rows);
  if (r.second_truth)
    out += "x truth, no noise: the technique's root-mean-square change over the truth's without its noise (two "
           "truths of every truth frame).\n";
  if (!r.first_pair_noise_change || !r.first_pair_truth_change) return out;
  const double noise = *r.first_pair_noise_change, change = *r.first_pair_truth_change;
  out += "truth noise: from frame 0 to 1 the truth changes by " + num(change, "%.5f") +
         " a pixel; its noise alone would change it by " + num(noise, "%.5f") +
         " (a second truth with another seed; noise floor " + db_text(r.truth_noise->psnr) + " dB).\n";
  if (noise > 0 && noise >= 0.5 * change)
    out += r.second_truth ? "the truth's change is mostly noise: flicker up to that size is not seen and 'x truth' "
                            "flatters every technique; 'x truth, no noise' does not.\n"
                          : "the truth's change is mostly noise: flicker up to that size is not seen and 'x truth' "
                            "flatters every technique (raise reference.samples, or --second-truth).\n";
  return out;
}

std::string sequence_svg(const SequenceResults& r) {
  PlotSpec error{"PSNR per frame (" + r.scene + ", path " + r.path + ")", "frame", "PSNR vs truth (dB)", false, false, {}, 800, 420};
  PlotSpec flicker{"Flicker beyond the truth's (mean excess change per frame)", "frame", "excess change (display units)",
                   false, false, {}, 800, 420};
  for (std::size_t v = 0; v < r.summary.size(); ++v) {
    PlotSeries e{r.summary[v].label, {}, {}, true}, f{r.summary[v].label, {}, {}, true};
    for (const SequenceFrame& fr : r.frames) {
      const SequenceTechniqueFrame& t = fr.results[v];
      if (t.error && t.error->psnr) e.points.emplace_back(fr.index, *t.error->psnr);
      if (t.instability) f.points.emplace_back(fr.index, *t.instability);
    }
    error.series.push_back(std::move(e));
    flicker.series.push_back(std::move(f));
  }
  // Two documents stacked as nested <svg> elements of one.
  auto body = [](const std::string& doc) { return doc.substr(doc.find("<svg")); };
  std::string top = body(svg_plot(error)), bottom = body(svg_plot(flicker));
  bottom.insert(4, " y=\"420\"");
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"840\">\n" +
         top + bottom + "</svg>\n";
}

}  // namespace ssr
