#include "eval/runner.h"

#include <algorithm>
#include <chrono>
#include <map>

#include "core/cli_common.h"
#include "reference/reference.h"
#include "shared/bindings.h"
#include "shared/tonemap.h"
#include "techniques/assignments.h"
#include "techniques/screen_pass.h"
#include "registry/registry.h"

namespace ssr {

RgbaImageF display_values(const RgbaImageF& hdr, float exposure) {
  RgbaImageF out{hdr.width, hdr.height, std::vector<float>(hdr.pixels.size())};
  for (std::size_t i = 0; i < hdr.pixels.size(); i += 4) {
    const glm::vec3 v = shared::display_transform(
        glm::vec3(hdr.pixels[i], hdr.pixels[i + 1], hdr.pixels[i + 2]), exposure);
    // A non-finite input stays non-finite, so the metrics count it instead of hiding it.
    for (int c = 0; c < 3; ++c)
      out.pixels[i + static_cast<std::size_t>(c)] =
          std::isfinite(hdr.pixels[i + static_cast<std::size_t>(c)]) ? v[c] : hdr.pixels[i + static_cast<std::size_t>(c)];
    out.pixels[i + 3] = 1.0f;
  }
  return out;
}

// The composited image (ViewMode::Final) or the reflected radiance (ViewMode::Reflected) of
// what the frame's reflection target holds now, as display values.
RgbaImageF ScoredFrame::display_of(ViewMode view) {
  renderer_.redisplay(view);
  const RgbaImageF hdr = view == ViewMode::Final ? renderer_.read_texture(renderer_.color())
                                                 : renderer_.read_linear();
  return display_values(hdr, renderer_.settings.exposure);
}

namespace {
// Copies the reference's screen-space ideal into the frame's reflection and refraction targets,
// so that it goes through the same composite as every technique.
void put_ideal(Renderer& r, const ReferenceOutputs& out) {
  glCopyImageSubData(out.ideal->id(), GL_TEXTURE_2D, 0, 0, 0, 0, r.reflection().id(), GL_TEXTURE_2D, 0,
                     0, 0, 0, r.width(), r.height(), 1);
  glCopyImageSubData(out.ideal_refraction->id(), GL_TEXTURE_2D, 0, 0, 0, 0, r.refraction().id(),
                     GL_TEXTURE_2D, 0, 0, 0, 0, r.width(), r.height(), 1);
  r.outputs_written();
}
}  // namespace

ScoredFrame::ScoredFrame(Renderer& renderer, const FrameRequest& frame, Technique& reference)
    : renderer_(renderer), reference_(reference), frame_(frame) {
  renderer_.render(frame_, reference, ViewMode::Final, nullptr);
  truth_ = display_of(ViewMode::Final);
  truth_reflected_ = display_of(ViewMode::Reflected);
  const ReferenceOutputs out = reference_outputs(reference);
  if (!out.ideal || !out.classes)
    throw std::logic_error("ScoredFrame needs the reference technique");
  rays_ = out.rays;
  put_ideal(renderer_, out);
  ideal_ = display_of(ViewMode::Final);
  ideal_reflected_ = display_of(ViewMode::Reflected);

  labels_.width = renderer_.width();
  labels_.height = renderer_.height();
  labels_.classes = *out.classes;
  labels_.reflectors = static_cast<int>(renderer_.scene().reflectors.size());
  const std::vector<std::uint16_t> material = renderer_.read_material();
  const RgbaImageF normal_rough = renderer_.read_texture(renderer_.gbuffer().normal_roughness);
  const RgbaImageF glass = renderer_.read_texture(renderer_.gbuffer().glass_surface);
  const std::size_t n = labels_.classes.size();
  labels_.glass.resize(n);
  labels_.reflector.resize(n);
  labels_.roughness.resize(n);
  normal_mapped_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    labels_.reflector[i] = material[i * 4];
    labels_.roughness[i] = std::clamp(normal_rough.pixels[i * 4 + 3], 0.0f, 1.0f);
    normal_mapped_[i] = (material[i * 4 + 2] & MATERIAL_FLAG_NORMAL_MAPPED) != 0;
    labels_.glass[i] = glass.pixels[i * 4 + 3] >= 1.0f;
  }
  inherent_psnr_ = psnr_from_rmse(rmse_where(ideal_, truth_, labels_.classes, [](PixelClass c) {
    return c != PixelClass::NotReflective;
  }));
}

InherentFigures ScoredFrame::inherent() const {
  ReferenceImages r;
  r.truth = &truth_;
  r.ideal = &ideal_;
  return compute_inherent(labels_, r);
}

ReferenceImages ScoredFrame::references(int samples) {
  ReferenceImages r{&truth_, &ideal_, &truth_reflected_, &ideal_reflected_, nullptr};
  if (samples <= 0) return r;
  auto it = ideal_at_samples_.find(samples);
  if (it == ideal_at_samples_.end()) {
    // Another seed, so that its samples are independent of the converged ideal's.
    rerun_reference(samples, 7919);
    put_ideal(renderer_, reference_outputs(*last_rerun_));
    it = ideal_at_samples_.emplace(samples, display_of(ViewMode::Final)).first;
  }
  r.ideal_at_samples = &it->second;
  return r;
}

void set_up_with_seed(Technique& truth, Technique& ref, long shift, int samples) {
  ParamSet from = truth.params(), to = ref.params();
  to.copy_values_from(from);
  if (samples > 0) to.set(static_cast<std::size_t>(to.find("samples")), samples);
  const std::size_t seed = static_cast<std::size_t>(to.find("seed"));
  to.set(seed, static_cast<double>((static_cast<long>(from.get(seed)) + shift) % 1000000));
}

void ScoredFrame::rerun_reference(int samples, long shift) {
  // One second reference serves every rerun, set up anew each time: its program is compiled once
  // and its BVH built once a scene (the viewer's truth-noise reference does the same).
  if (!last_rerun_) {
    last_rerun_ = create_technique(truth_name());
    last_rerun_->load(renderer_.shaders());
  }
  set_up_with_seed(reference_, *last_rerun_, shift, samples);
  renderer_.render(frame_, *last_rerun_, ViewMode::Final, nullptr);
}

std::optional<TruthNoise> ScoredFrame::truth_noise() {
  if (truth_noise_) return *truth_noise_;
  const ParamSet p = reference_.params();
  const auto value = [&](const char* key) { return p.get(static_cast<std::size_t>(p.find(key))); };
  const double mirror_roughness = value("mirror_roughness");
  bool sampled = value("bounces") > 1;
  for (std::size_t i = 0; i < labels_.classes.size() && !sampled; ++i)
    sampled = labels_.classes[i] != PixelClass::NotReflective && !labels_.glass[i] &&
              labels_.roughness[i] >= mirror_roughness;
  if (!sampled) return *(truth_noise_ = std::optional<TruthNoise>());
  rerun_reference(static_cast<int>(value("samples")), kTruthNoiseSeedShift);
  const RgbaImageF other = display_of(ViewMode::Final);
  other_truth_reflected_ = display_of(ViewMode::Reflected);
  const auto noise = [&](auto keep) { return noise_floor_psnr(rmse_where(truth_, other, labels_.classes, keep)); };
  TruthNoise n;
  n.psnr = noise([](PixelClass c) { return c != PixelClass::NotReflective; });
  n.psnr_traceable = noise([](PixelClass c) { return c == PixelClass::Traceable; });
  return *(truth_noise_ = std::optional<TruthNoise>(n));
}

const RgbaImageF* ScoredFrame::other_truth_reflected() {
  return truth_noise() ? &other_truth_reflected_ : nullptr;
}

int technique_samples(Technique& t) {
  ParamSet p = t.params();
  const int i = p.find("samples");
  return i < 0 ? 0 : static_cast<int>(p.get(static_cast<std::size_t>(i)));
}

ScoredFrame::Score ScoredFrame::score(Technique& t) {
  // The noise floor's reference run (if a new sample count) overwrites the reflection target:
  // it runs first.
  const ReferenceImages refs = references(technique_samples(t));
  renderer_.render(frame_, t, ViewMode::Final, nullptr);
  Score s;
  s.reflection = renderer_.read_texture(renderer_.reflection());
  s.display = display_of(ViewMode::Final);
  s.reflected = display_of(ViewMode::Reflected);
  // Glass pixels show the refraction: their claim is the refraction's confidence.
  const RgbaImageF refraction = renderer_.read_texture(renderer_.refraction());
  s.confidence.resize(s.reflection.pixels.size() / 4);
  for (std::size_t i = 0; i < s.confidence.size(); ++i)
    s.confidence[i] = (labels_.is_glass(i) ? refraction : s.reflection).pixels[i * 4 + 3];
  s.error = compute_metrics(s.display, truth_, ideal_, labels_.classes, s.confidence);
  // Non-finite values anywhere in the technique's output count, not only where metrics look.
  s.error.nonfinite = count_nonfinite(s.reflection.pixels) + count_nonfinite(refraction.pixels) +
                      count_nonfinite(renderer_.read_texture(renderer_.color()).pixels);
  s.breakdown = compute_breakdown(labels_, {&s.display, &s.reflected, &s.confidence}, refs,
                                  t.declare().planar_only);
  return s;
}

std::vector<HitClass> ScoredFrame::hit_classes_of(const Score& s, const Technique& t) {
  return hit_classes(labels_, {&s.display, &s.reflected, &s.confidence}, references(0),
                     t.declare().planar_only);
}

namespace {
// A GPU idle for a while (the reference was computed on the CPU) runs at a low clock for the
// first frames after: warm-up frames go on for at least this long (on the GPU clock only; the
// H200 timed a floor pass 0.076 ms instead of 0.028 after 10 warm-up frames).
constexpr double kGpuWarmupSeconds = 0.3;
}  // namespace

void warm_up(const TimingOptions& o, bool clock, const std::function<void()>& frame) {
  const auto start = std::chrono::steady_clock::now();
  const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  for (int f = 0; f < o.warmup; ++f) frame();
  if (clock && o.clock == gl::PassTimer::Clock::Gpu) {
    glFinish();
    while (seconds() < kGpuWarmupSeconds) {
      frame();
      glFinish();
    }
  }
}

namespace {
// Renders the warm-up (warm_clock: long enough for the GPU's clock), then o.frames timed frames
// of a still camera, one after another from frame index `next` on (history carries, as in an
// application; `next` is left at the index after the last); returns the timed frames' timings.
std::vector<gl::FrameTimes> timed_frames(Renderer& renderer, const Camera& camera, Technique& t,
                                         const TimingOptions& o, int max_depth, bool warm_clock, int& next) {
  const auto render = [&](gl::PassTimer* timer) {
    renderer.render(FrameRequest(camera, FrameTime{next++, 0.0f}), t, ViewMode::Final, timer);
  };
  warm_up(o, warm_clock, [&] { render(nullptr); });
  gl::PassTimer timer(o.clock, 4, max_depth);
  for (int f = 0; f < o.frames; ++f) {
    timer.begin_frame();
    render(&timer);
    timer.end_frame();
  }
  timer.flush();
  return std::move(timer.completed());
}

std::vector<double> technique_times(const std::vector<gl::FrameTimes>& frames) {
  std::vector<double> out;
  for (const gl::FrameTimes& frame : frames) out.push_back(technique_ms(frame));
  return out;
}
}  // namespace

Timing time_frames(Renderer& renderer, const Camera& camera, Technique& t, const TimingOptions& o) {
  int next = 1;  // the span run continues the pass run's frames: the same steady history
  const std::vector<gl::FrameTimes> frames = timed_frames(renderer, camera, t, o, gl::PassTimer::kAllDepths, true, next);
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> per_pass;
  for (const gl::FrameTimes& frame : frames) {
    std::map<std::string, double> sums;  // a pass name may repeat within a frame
    double inside = 0;
    for (const gl::PassTime& p : frame) {
      if (p.depth == 0 && p.name == kTechniqueSpan) continue;  // the technique's time, below
      if (!sums.count(p.name) && !per_pass.count(p.name)) order.push_back(p.name);
      sums[p.name] += p.ms;
      if (p.depth == 1) inside += p.ms;
    }
    // What the span holds besides its passes: untimed work (clears, copies) and gaps.
    sums[kBetweenPasses] = std::max(technique_ms(frame) - inside, 0.0);
    for (auto& [name, ms] : sums) per_pass[name].push_back(ms);
  }
  order.push_back(kBetweenPasses);
  Timing out;
  for (const std::string& name : order) out.passes.push_back({name, time_stats(per_pass[name]).median});
  // A query between passes costs the GPU time of its own; the CPU clock has no such cost (and
  // another run on llvmpipe would double the tests' time for nothing).
  out.technique = time_stats(technique_times(
      o.clock == gl::PassTimer::Clock::Gpu ? timed_frames(renderer, camera, t, o, /*max_depth=*/1, /*warm_clock=*/false, next) : frames));
  return out;
}

void time_floor(Renderer& renderer, const Camera& camera, const TimingOptions& o, RunResults& run) {
  // A technique, so that it is timed in the same frames as the variants. Two pixel rows per
  // invocation: the same traffic in 0.022 ms instead of 0.028 at 1080p and 0.066 instead of
  // 0.086 at 4K (H200; 4 and 8 rows and other group shapes were slower), so one row per
  // invocation was not the floor. The techniques' own passes were slower that way (RESULTS.md).
  ScreenPassTechnique floor("floor", "eval/floor.comp", kReadGBuffer | kReadLit, {"SSR_ROWS 2"});
  floor.load(renderer.shaders());
  const double ms = time_frames(renderer, camera, floor, o).technique.median;
  for (TechniqueResult& r : run.results) r.floor_ms = ms;
}

EvaluatedVariant evaluate_variant(Renderer& renderer, ScoredFrame& frame, const Camera& camera,
                                  const Variant& variant, const TimingOptions& timing) {
  auto t = create_technique(variant.technique);
  apply_assignments(*t, variant.assignments);
  t->load(renderer.shaders());
  EvaluatedVariant ev;
  // Timing first: it re-renders the inputs, which scoring then reuses untouched.
  const Timing tm = time_frames(renderer, camera, *t, timing);
  ev.score = frame.score(*t);
  ev.result.technique = variant.technique;
  ev.result.preset = variant.preset;
  ev.result.label = variant.label();
  ev.result.params = param_list(*t);
  ev.result.ran_params = param_list(t->ran_params());
  ev.result.varies_per_frame = t->declare().varies_per_frame;
  ev.result.time_ms = tm.technique;
  ev.result.passes = tm.passes;
  ev.result.error = ev.score.error;
  ev.result.breakdown = ev.score.breakdown;
  ev.result.telemetry = measure_telemetry(renderer, camera, variant);  // none if it does not iterate
  return ev;
}

std::optional<IterationStats> measure_telemetry(Renderer& renderer, const Camera& camera, const Variant& variant) {
  auto t = create_technique(variant.technique);
  apply_assignments(*t, variant.assignments);
  if (!t->declare().telemetry) return std::nullopt;
  t->load(renderer.shaders().with_defines({"SSR_TELEMETRY"}));
  renderer.telemetry().begin(renderer.width(), renderer.height());
  renderer.render(FrameRequest(camera, FrameTime{1, 0.0f}), *t, ViewMode::Final, nullptr);
  return renderer.telemetry().read().stats();
}

OracleAgreement oracle_agreement(const ScoredFrame& frame, const ScoredFrame::Score& planar) {
  std::vector<bool> eligible(frame.normal_mapped().size());
  for (std::size_t i = 0; i < eligible.size(); ++i) eligible[i] = !frame.normal_mapped()[i];
  return compare_oracles(frame.labels(), planar.reflected, frame.truth_reflected(), eligible);
}

std::vector<bool> scored_pixels(const Renderer& r) {
  return scored_pixels(r.read_material(), r.read_depth(), r.read_texture(r.gbuffer().glass_surface));
}

std::vector<bool> scored_pixels(const std::vector<std::uint16_t>& material, const std::vector<float>& depth,
                                const RgbaImageF& glass_surface) {
  std::vector<bool> out = reflective_pixels(material, depth);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = out[i] || glass_surface.pixels[i * 4 + 3] >= 1.0f;
  return out;
}

std::vector<bool> reflective_pixels(const std::vector<std::uint16_t>& material, const std::vector<float>& depth) {
  std::vector<bool> out(depth.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = depth[i] > 0.0f && (material[i * 4 + 2] & MATERIAL_FLAG_REFLECTIVE) != 0;
  return out;
}

std::vector<std::pair<std::string, std::string>> param_list(const ParamSet& p) {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < p.size(); ++i) out.emplace_back(p.key(i), p.to_string(i));
  return out;
}

}  // namespace ssr
