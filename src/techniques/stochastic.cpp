// `stochastic`: stochastic screen-space reflections as engines ship them (Diligent's document,
// AMD FidelityFX SSSR). Passes, each timed and each with a debug view:
//   classify   render/classification.h: which pixels trace (roughness threshold, rays per quad,
//              half resolution), and the list of tiles the trace runs on (indirect dispatch);
//   trace      shaders/techniques/stochastic_trace.comp: one GGX VNDF ray per traced pixel from
//              the spatio-temporal blue noise (core/blue_noise.h), GGX bias, Hi-Z; radiance,
//              hit vector, pdf; and the refraction of pixels behind glass, as the tracers';
//   spatial, temporal, bilateral   the denoiser (techniques/denoiser.h).
// Pixels rougher than the threshold get the composite's environment (confidence 0).
#include <algorithm>
#include <cmath>

#include "core/blue_noise.h"
#include "render/classification.h"
#include "render/gpu_scene.h"
#include "shared/stochastic.h"
#include "techniques/denoiser.h"
#include "techniques/stochastic.h"
#include "techniques/tracer.h"

namespace ssr {
namespace {

using P = shared::StochasticParams;

std::vector<ParamDesc> table() {
  std::vector<ParamDesc> t = {
      SSR_PARAM_FLOAT(P, roughness_threshold, 0.0, 1.0, 0.05, "",
                      "Pixels rougher than this trace no ray: the composite gives them the environment."),
      SSR_PARAM_CHOICE(P, rays_per_quad,
                       "Rays per 2x2 quad on pixels rougher than quad_roughness (the traced pixels rotate each "
                       "frame; the others reuse their neighbours' rays).",
                       "1", "2", "4"),
      SSR_PARAM_FLOAT(P, quad_roughness, 0.0, 1.0, 0.05, "",
                      "Pixels at or below this roughness trace a ray each (full resolution)."),
      SSR_PARAM_FLOAT(P, ggx_bias, 0.0, 1.0, 0.05, "",
                      "Pulls the GGX samples towards the lobe's centre: less noise, narrower (biased) reflections."),
      SSR_PARAM_BOOL(P, half_resolution,
                     "Trace one pixel of each 2x2 block (rotating each frame); the spatial stage runs on that "
                     "grid and the temporal stage upsamples with depth-aware weights (temporal off: the spatial "
                     "stage upsamples). The half grid rounds up: a 1-pixel-wide image traces its pixels."),
      SSR_PARAM_BOOL(P, previous_frame,
                     "Hits read the previous frame's final colour (reflections included): reflections of "
                     "reflections build up over frames."),
      with_auto(SSR_PARAM_INT(P, max_iterations, 1, 4096, "iterations",
                              "Cap on Hi-Z cell visits per ray; auto: half the image diagonal in pixels.")),
      with_auto(SSR_PARAM_INT(P, glossy_iterations, 1, 4096, "iterations",
                              "Lower cap for rays from pixels rougher than glossy_roughness: their few long "
                              "rays set the trace's time and the denoiser blurs them; auto: max_iterations.")),
      SSR_PARAM_FLOAT(P, glossy_roughness, 0.0, 1.0, 0.05, "",
                      "Rays from pixels rougher than this stop at glossy_iterations."),
      SSR_PARAM_INT(P, max_level, 0, 15, "level", "Coarsest Hi-Z level the trace climbs to."),
      SSR_PARAM_FLOAT(P, thickness, 0.001, 50.0, 0.01, "world units",
                      "A ray point this far or less behind the depth buffer counts as a hit."),
      with_auto(SSR_PARAM_FLOAT(P, max_distance, 0.01, 10000.0, 0.5, "world units",
                                "Length of the traced ray; auto: the scene's bounding-box diagonal.")),
      SSR_PARAM_INT(P, seed, 0, 1000000, "", "Shifts the blue-noise pattern."),
  };
  for (const ParamDesc& d : denoise_options(offsetof(P, denoise), /*with_switch=*/false)) t.push_back(d);
  return t;
}
const std::vector<ParamDesc> kTable = table();

class StochasticTechnique final : public TechniqueWithParams<P> {
 public:
  StochasticTechnique() : TechniqueWithParams("stochastic", kTable) {}

  void load(const gl::ShaderSource& src) override {
    auto trace = gl::Program::compute(src, "techniques/stochastic_trace.comp");
    classifier_.load(src);
    denoiser_.load(src);
    trace_ = std::move(trace);
    src_ = src;
    trace_refraction_ = gl::Program();  // on the first frame with glass (as the tracers' variants)
    if (!blue_noise_) {
      const BlueNoise& bn = default_blue_noise();
      blue_noise_ = gl::Texture2D("stochastic blue noise", GL_R8, bn.size, bn.size * bn.slices);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTextureSubImage2D(blue_noise_.id(), 0, 0, 0, bn.size, bn.size * bn.slices, GL_RED, GL_UNSIGNED_BYTE,
                          bn.texels.data());
    }
  }

  TechniqueDecl declare() const override {
    TechniqueDecl d;
    d.reads = kReadGBuffer | kReadLit | kReadGlass | kReadHiz | kReadMotion | kReadPrevDepth | kReadPrevNormal;
    d.writes_refraction = true;  // pixels behind glass refract, as the tracers' do (run())
    if (params_.previous_frame) d.reads |= kReadPrevColor;
    d.textures = Denoiser::textures(divisor(), params_.denoise);
    d.stage_views = denoiser_.stage_views(0, params_.denoise);
    for (const StageView& v : d.stage_views) d.debug_views.push_back(v.view);
    d.debug_views.insert(d.debug_views.end(), {ViewMode::Iterations, ViewMode::IdleLanes});
    d.telemetry = true;
    d.varies_per_frame = true;  // blue noise turns every frame; the history accumulates
    return d;
  }

  void run(const FrameContext& in) override {
    P p = params_;
    const AutoContext autos = AutoContext::of(in);  // "auto" as `hiz` resolves it
    if (p.max_distance == 0.0f) p.max_distance = autos.max_distance();
    if (p.max_iterations == 0) p.max_iterations = autos.hiz_iterations();
    p.glossy_iterations = p.glossy_iterations == 0 ? p.max_iterations : std::min(p.glossy_iterations, p.max_iterations);
    record_run(p);
    // No previous colour to read (first frame, a reset, a cut): hits read the lit colour. The
    // frame's own "continues" flag is not enough: a reset zeroes the colour mid-sequence.
    p.previous_frame = p.previous_frame && in.previous_color ? 1 : 0;
    const auto tex = std::span<gl::Texture2D* const>(in.textures);
    // Pixels behind glass refract (as the tracers' do). Only glass pixels read the refraction
    // image, so a scene without glass runs the trace without that code.
    const bool glass = in.gpu_scene.has_transparent();
    if (glass && !trace_refraction_)
      trace_refraction_ = gl::Program::compute(src_, "techniques/stochastic_trace.comp", {"STOCHASTIC_REFRACTION"});
    const shared::ClassifyParams c{.roughness_threshold = p.roughness_threshold,
                                   .quad_roughness = p.quad_roughness,
                                   .rays_per_quad = 1 << p.rays_per_quad,  // the choice 0, 1, 2 is 1, 2, 4 rays
                                   .divisor = divisor(),
                                   .trace_size = {},
                                   .list_glass = glass ? 1 : 0,  // their tiles are listed: the trace refracts
                                   .list_rays = 0};  // the trace runs over the tile list
    classifier_.classify(*tex[Denoiser::kClass], c, in.time.index, in.timer);
    {
      gl::ScopedPass pass(in.timer, "trace");
      bind_params(&p);
      glBindTextureUnit(TEX_CLASS, tex[Denoiser::kClass]->id());
      glBindTextureUnit(TEX_BLUE_NOISE, blue_noise_.id());
      glBindImageTexture(IMG_OUT, tex[Denoiser::kTraceRadiance]->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      glBindImageTexture(IMG_OUT2, tex[Denoiser::kTraceRay]->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      glUseProgram((glass ? trace_refraction_ : trace_).id());
      classifier_.dispatch();
      glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    }
    denoiser_.run(in, tex, p.denoise, divisor());
    in.rebind();
  }

  void reset() override { denoiser_.reset(); }

  // Tiles listed and reflection rays cast by the last frame (stalls): the tests read them.
  shared::TileListHeader last_counts() const { return classifier_.read_header(); }

 private:
  int divisor() const { return params_.half_resolution ? 2 : 1; }

  TileClassifier classifier_;
  Denoiser denoiser_;
  gl::ShaderSource src_;
  gl::Program trace_, trace_refraction_;
  gl::Texture2D blue_noise_;
};

}  // namespace

std::unique_ptr<Technique> make_stochastic_technique() { return std::make_unique<StochasticTechnique>(); }

shared::TileListHeader stochastic_tile_counts(const Technique& stochastic) {
  return dynamic_cast<const StochasticTechnique&>(stochastic).last_counts();
}

}  // namespace ssr
