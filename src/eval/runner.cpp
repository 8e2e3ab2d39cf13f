#include "eval/runner.h"

#include <algorithm>
#include <map>

#include "core/cli_common.h"
#include "reference/reference.h"
#include "shared/bindings.h"
#include "shared/tonemap.h"

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

RgbaImageF ScoredFrame::final_display() {
  renderer_.composite_and_display(ViewMode::Final, nullptr);
  return display_values(renderer_.read_texture(renderer_.color()), renderer_.settings.exposure);
}

ScoredFrame::ScoredFrame(Renderer& renderer, const Camera& camera, Technique& reference)
    : renderer_(renderer) {
  renderer_.render_inputs(camera, nullptr);
  renderer_.run_technique(reference, nullptr);
  truth_ = final_display();
  const ReferenceOutputs out = reference_outputs(reference);
  if (!out.ideal || !out.classes)
    throw std::logic_error("ScoredFrame needs the reference technique");
  classes_ = *out.classes;
  rays_ = out.rays;
  // The ideal goes through the same composite: copy it into the frame's reflection target.
  glCopyImageSubData(out.ideal->id(), GL_TEXTURE_2D, 0, 0, 0, 0, renderer_.reflection().id(),
                     GL_TEXTURE_2D, 0, 0, 0, 0, renderer_.width(), renderer_.height(), 1);
  ideal_ = final_display();
  std::vector<PixelClass> all = classes_;
  inherent_psnr_ = psnr_from_rmse(rmse_where(ideal_, truth_, all, [](PixelClass c) {
    return c != PixelClass::NotReflective;
  }));
}

ScoredFrame::Score ScoredFrame::score(Technique& t) {
  renderer_.run_technique(t, nullptr);
  Score s;
  s.reflection = renderer_.read_texture(renderer_.reflection());
  s.display = final_display();
  std::vector<float> confidence(s.reflection.pixels.size() / 4);
  for (std::size_t i = 0; i < confidence.size(); ++i) confidence[i] = s.reflection.pixels[i * 4 + 3];
  s.error = compute_metrics(s.display, truth_, ideal_, classes_, confidence);
  // Non-finite values anywhere in the technique's output count, not only where metrics look.
  s.error.nonfinite = count_nonfinite(s.reflection.pixels) +
                      count_nonfinite(renderer_.read_texture(renderer_.color()).pixels);
  return s;
}

namespace {
bool is_frame_pass(const std::string& name) {
  return name == "gbuffer" || name == "lighting" || name == "composite" || name == "display";
}
}  // namespace

Timing time_frames(Renderer& renderer, const Camera& camera, Technique& t, const TimingOptions& o) {
  gl::PassTimer timer(o.clock);
  for (int f = 0; f < o.warmup + o.frames; ++f) {
    timer.begin_frame();
    renderer.render_inputs(camera, &timer);
    renderer.run_technique(t, &timer);
    renderer.composite_and_display(ViewMode::Final, &timer);
    timer.end_frame();
  }
  timer.flush();
  std::vector<gl::FrameTimes>& frames = timer.completed();
  frames.erase(frames.begin(), frames.begin() + std::min<std::ptrdiff_t>(o.warmup, static_cast<std::ptrdiff_t>(frames.size())));
  std::vector<double> totals;
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> per_pass;
  for (const gl::FrameTimes& frame : frames) {
    double technique_ms = 0;
    std::map<std::string, double> sums;  // a pass name may repeat within a frame
    for (const gl::PassTime& p : frame) {
      if (!sums.count(p.name) && !per_pass.count(p.name)) order.push_back(p.name);
      sums[p.name] += p.ms;
      if (!is_frame_pass(p.name)) technique_ms += p.ms;
    }
    for (auto& [name, ms] : sums) per_pass[name].push_back(ms);
    totals.push_back(technique_ms);
  }
  Timing out;
  out.technique = time_stats(totals);
  for (const std::string& name : order) out.passes.push_back({name, time_stats(per_pass[name]).median});
  return out;
}

FloorPass::FloorPass(const gl::ShaderSource& shaders)
    : program_(gl::Program::compute(shaders, "eval/floor.comp")) {}

double FloorPass::time(Renderer& renderer, const TimingOptions& o) {
  gl::PassTimer timer(o.clock);
  for (int f = 0; f < o.warmup + o.frames; ++f) {
    timer.begin_frame();
    renderer.bind_frame_inputs();
    {
      gl::ScopedPass pass(&timer, "floor");
      glBindImageTexture(IMG_OUT, renderer.reflection().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      program_.dispatch_2d(renderer.width(), renderer.height());
    }
    timer.end_frame();
  }
  timer.flush();
  std::vector<double> ms;
  const auto& frames = timer.completed();
  for (std::size_t f = static_cast<std::size_t>(std::max(o.warmup, 0)); f < frames.size(); ++f)
    ms.push_back(frames[f].empty() ? 0.0 : frames[f][0].ms);
  return time_stats(ms).median;
}

EvaluatedVariant evaluate_variant(Renderer& renderer, ScoredFrame& frame, const Camera& camera,
                                  const Variant& variant, const TimingOptions& timing, double floor_ms) {
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
  ev.result.time_ms = tm.technique;
  ev.result.passes = tm.passes;
  ev.result.floor_ms = floor_ms;
  ev.result.error = ev.score.error;
  return ev;
}

std::vector<std::pair<std::string, std::string>> param_list(Technique& t) {
  std::vector<std::pair<std::string, std::string>> out;
  ParamSet p = t.params();
  for (std::size_t i = 0; i < p.size(); ++i) out.emplace_back(p.key(i), p.to_string(i));
  return out;
}

}  // namespace ssr
