// The common shape of a screen-space tracer: a Params struct P that starts with the shared
// RayOptions, one compute shader built on shaders/common/ssr_main.glsl, one dispatch (over the
// classification's ray list, or every pixel), optionally followed by the denoiser.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>

#include "render/classification.h"
#include "techniques/denoiser.h"
#include "techniques/ray_options.h"
#include "techniques/technique.h"

namespace ssr {

// What "auto" parameters are resolved from, each frame.
struct AutoContext {
  float scene_diagonal = 0;  // world units: the diagonal of the scene's bounding box
  float image_diagonal = 0;  // pixels
  static AutoContext of(const FrameContext& f) {
    return {f.scene_diagonal, static_cast<float>(std::hypot(double(f.width), double(f.height)))};
  }
  // The tracers' "auto" ray length: the scene's bounding-box diagonal.
  float max_distance() const { return std::max(scene_diagonal, 0.01f); }
  // The Hi-Z traces' "auto" cap on cell visits (hiz, stochastic): half the image diagonal.
  int hiz_iterations() const { return std::clamp(static_cast<int>(std::ceil(0.5f * image_diagonal)), 1, 4096); }
};

template <class P>
class TracerTechnique : public TechniqueWithParams<P> {
 public:
  // `resolve` replaces the technique's own "auto" values in a copy of its parameters.
  using Resolver = std::function<void(P&, const AutoContext&)>;
  TracerTechnique(std::string name, std::span<const ParamDesc> table, std::string shader, Resolver resolve = {})
      : TechniqueWithParams<P>(std::move(name), table), shader_(std::move(shader)), resolve_(std::move(resolve)) {}

  // The variant the current parameters run compiles here (so a compile error surfaces now); the
  // others, the classifier and the denoiser on first use.
  void load(const gl::ShaderSource& src) override {
    const Variant v{this->params_.ray.compact != 0, this->params_.ray.denoise.enabled != 0, false,
                    shared::is_plain_ray(resolved_ray(this->params_.ray))};
    gl::Program p = compile(src, v);
    src_ = src;
    for (gl::Program& program : programs_) program = gl::Program();
    programs_[v.index()] = std::move(p);
    classifier_loaded_ = denoiser_loaded_ = false;
  }

  // The shared ray options' "auto" resolved. The edge fade's auto is on with the Roberts blend
  // only (the standard composite already falls back to the environment at low confidence;
  // fading there only loses reflections).
  static shared::RayOptions resolved_ray(shared::RayOptions r) {
    if (r.edge_fade < 0) r.edge_fade = r.blend == 1 ? 1 : 0;
    return r;
  }

  // The parameters as this frame runs them: every "auto" resolved.
  P resolved(const AutoContext& ctx) const {
    P p = this->params_;
    p.ray = resolved_ray(p.ray);
    if (resolve_) resolve_(p, ctx);
    return p;
  }

  void run(const FrameContext& in) override {
    const P p = resolved(AutoContext::of(in));
    this->record_run(p);
    const bool compact = p.ray.compact != 0, denoise = p.ray.denoise.enabled != 0;
    // The denoiser's inputs take the debug image's place: no debug variant of that one.
    const bool debug = in.debug != nullptr && !denoise;
    const gl::Program& program = program_for({compact, denoise, debug, shared::is_plain_ray(p.ray)});
    if ((compact || denoise) && !classifier_loaded_) {
      classifier_.load(src_);
      classifier_loaded_ = true;
    }
    // Every reflective pixel traces (and every pixel behind glass refracts): the classification
    // at threshold 1, one ray a pixel; the ray list only for a compact trace.
    const shared::ClassifyParams every_pixel{.roughness_threshold = 1.0f, .quad_roughness = 1.0f, .rays_per_quad = 4,
                                             .divisor = 1, .trace_size = {}, .list_glass = 1,
                                             .list_rays = compact ? 1 : 0};
    auto trace = [&] {
      gl::ScopedPass pass(in.timer, this->name());
      this->bind_params(&p);
      if (compact) classifier_.dispatch_rays(); else program.dispatch_2d(in.width, in.height);
    };
    if (!denoise) {
      glBindImageTexture(IMG_OUT, in.reflection->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      if (compact) classifier_.classify_for_tracer(in.width, in.height, every_pixel, debug, in.timer);
      glUseProgram(program.id());
      trace();
      return;
    }
    // With the denoiser: the trace writes the denoiser's inputs (the classes say which pixels
    // hold some), the denoiser the reflection.
    if (!denoiser_loaded_) {
      denoiser_.load(src_);
      denoiser_loaded_ = true;
    }
    const auto tex = std::span<gl::Texture2D* const>(in.textures);
    classifier_.classify(*tex[Denoiser::kClass], every_pixel, in.time.index, in.timer);
    glBindImageTexture(IMG_OUT, tex[Denoiser::kTraceRadiance]->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(IMG_OUT2, tex[Denoiser::kTraceRay]->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glUseProgram(program.id());
    trace();
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    denoiser_.run(in, tex, p.ray.denoise, 1);
    in.rebind();
  }

  void reset() override { denoiser_.reset(); }

  // Every tracer reads the G-buffer, the lit colour and the glass surfaces (it refracts), and
  // fills the steps/hits/distance debug views; `extra_reads` adds its own (the Hi-Z pyramid).
  TechniqueDecl declare() const override {
    TechniqueDecl d;
    d.reads = kReadGBuffer | kReadLit | kReadGlass | extra_reads_;
    if (this->params_.ray.backface_thickness != 0) d.reads |= kReadBackDepth;
    d.writes_refraction = true;
    d.debug_views = {ViewMode::Steps, ViewMode::Hits, ViewMode::Distance, ViewMode::Iterations, ViewMode::IdleLanes};
    d.blend = this->params_.ray.blend;
    d.telemetry = true;
    if (this->params_.ray.denoise.enabled) {
      // Its second image holds the rays then: the stage views replace the step views.
      d.reads |= kReadMotion | kReadPrevDepth | kReadPrevNormal;
      d.textures = Denoiser::textures(1, this->params_.ray.denoise);
      d.varies_per_frame = true;  // new samples every frame, accumulated
      d.stage_views = denoiser_.stage_views(0, this->params_.ray.denoise);
      d.debug_views.clear();
      for (const StageView& v : d.stage_views) d.debug_views.push_back(v.view);
      d.debug_views.insert(d.debug_views.end(), {ViewMode::Iterations, ViewMode::IdleLanes});
    }
    return d;
  }

 protected:
  std::uint32_t extra_reads_ = 0;

 private:
  // A compiled variant of the tracer's shader, each flag a define of ssr_main.glsl.
  struct Variant {
    bool compact;  // SSR_RAY_LIST: over the classification's ray list
    bool denoise;  // SSR_DENOISE_OUTPUT: writes the denoiser's inputs
    bool debug;    // SSR_DEBUG_IMAGE: writes the debug image
    bool plain;    // SSR_PLAIN_RAY: the plain ray options as constants (shared/ray_options.h)
    std::size_t index() const { return (compact ? 1 : 0) + (denoise ? 2 : 0) + (debug ? 4 : 0) + (plain ? 8 : 0); }
  };
  gl::Program compile(const gl::ShaderSource& src, Variant v) const {
    std::vector<std::string> defines;
    if (v.compact) defines.push_back("SSR_RAY_LIST");
    if (v.denoise) defines.push_back("SSR_DENOISE_OUTPUT");
    if (v.debug) defines.push_back("SSR_DEBUG_IMAGE");
    if (v.plain) defines.push_back("SSR_PLAIN_RAY");
    return gl::Program::compute(src, shader_, defines);
  }
  const gl::Program& program_for(Variant v) {
    gl::Program& p = programs_[v.index()];
    if (!p) p = compile(src_, v);
    return p;
  }

  std::string shader_;
  Resolver resolve_;
  gl::ShaderSource src_;
  // By Variant::index(): every flag on or off.
  std::array<gl::Program, 16> programs_;
  bool classifier_loaded_ = false, denoiser_loaded_ = false;
  TileClassifier classifier_;
  Denoiser denoiser_;
};

}  // namespace ssr
