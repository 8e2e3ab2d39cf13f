#include "techniques/denoiser.h"

#include "render/classification.h"
#include "shared/bindings.h"
#include "shared/classification.h"

namespace ssr {

std::vector<ParamDesc> denoise_options(std::size_t offset, bool with_switch) {
  using D = shared::DenoiseParams;
  auto at = [offset](ParamDesc d, std::size_t field) {
    d.offset = offset + field;
    d.group = "denoiser";
    return d;
  };
  std::vector<ParamDesc> t;
  if (with_switch)
    t.push_back(at({"denoise", ParamType::Bool, 0, 0, 1, 1, "",
                    "Run the denoiser (spatial, temporal, bilateral stages) on the traced samples."},
                   offsetof(D, enabled)));
  t.push_back(at({"spatial", ParamType::Bool, 0, 0, 1, 1, "",
                  "Denoiser stage 1: reuse neighbours' rays with the ratio estimator (off: upsample only)."},
                 offsetof(D, spatial)));
  t.push_back(at({"spatial_samples", ParamType::Int, 0, 1, 32, 1, "rays",
                  "Neighbours' rays each pixel reuses, besides its own."}, offsetof(D, spatial_samples)));
  t.push_back(at({"spatial_radius", ParamType::Float, 0, 0, 32, 0.5, "pixels",
                  "Reuse radius at roughness 0.5 and above; it shrinks linearly to 0 at roughness 0."},
                 offsetof(D, spatial_radius)));
  t.push_back(at({"firefly", ParamType::Bool, 0, 0, 1, 1, "",
                  "Stage 1 weighs each ray by 1 / (1 + its luminance) (Karis) on pixels rougher than 0.1 "
                  "(fully from 0.3), divided by 1 + the pixel's history length: a bright outlier no longer "
                  "spreads over the reuse disk in the first frames, and the weighting weakens as the "
                  "accumulation takes over."},
                 offsetof(D, firefly)));
  t.push_back(at({"temporal", ParamType::Bool, 0, 0, 1, 1, "",
                  "Denoiser stage 2: accumulate over frames (motion and hit-parallax reprojection)."},
                 offsetof(D, temporal)));
  t.push_back(at({"history", ParamType::Int, 0, 1, 256, 1, "frames",
                  "Most frames the accumulation averages (blend weight 1/n up to this n)."}, offsetof(D, history)));
  t.push_back(at({"clip_gamma", ParamType::Float, 0, 0.1, 8, 0.05, "sigma",
                  "History clipped to the 3x3 neighbourhood's mean +- gamma standard deviations: "
                  "lower ghosts less and flickers more."}, offsetof(D, clip_gamma)));
  t.push_back(at({"variance_stability", ParamType::Float, 0, 0, 1, 0.05, "",
                  "Share of the variance estimate taken from history (Diligent's variance stability factor)."},
                 offsetof(D, variance_stability)));
  t.push_back(at({"bilateral", ParamType::Bool, 0, 0, 1, 1, "",
                  "Denoiser stage 3: cross-bilateral cleanup guided by variance, depth, normal, roughness."},
                 offsetof(D, bilateral)));
  t.push_back(at({"bilateral_radius", ParamType::Int, 0, 0, 8, 1, "pixels",
                  "Half width of the bilateral window ((2r+1)^2 taps)."}, offsetof(D, bilateral_radius)));
  t.push_back(at({"bilateral_sigma", ParamType::Float, 0, 0.5, 8, 0.1, "pixels",
                  "Spatial sigma for fully noisy pixels (relative noise 1); less noise, a smaller sigma."},
                 offsetof(D, bilateral_sigma)));
  t.push_back(at({"young_sigma", ParamType::Float, 0, 0, 8, 0.1, "pixels",
                  "Stage 3's sigma is at least this over the frames of history on sampled lobes (roughness "
                  "0.01 and up): a pixel new on screen, disoccluded or after a cut holds one noisy sample, "
                  "near mirrors included, and gets a wide blur that fades as its history grows, to "
                  "young_sigma / history at most (none from 0.3 px). Needs the temporal and bilateral stages; "
                  "bilateral_radius bounds the window; 0: off."},
                 offsetof(D, young_sigma)));
  return t;
}

std::vector<TextureDecl> Denoiser::textures(int trace_divisor, const shared::DenoiseParams& p) {
  const int spatial = spatial_divisor(trace_divisor, p);
  return {
      {"classes", GL_R8, 1, false},
      {"trace radiance", GL_RGBA16F, trace_divisor, false},
      {"trace ray", GL_RGBA16F, trace_divisor, false},
      {"spatial", GL_RGBA16F, spatial, false},
      {"spatial stats", GL_RG16F, spatial, false},
      {"temporal A", GL_RGBA16F, 1, true},
      {"temporal stats A", GL_RG16F, 1, true},
      {"temporal B", GL_RGBA16F, 1, true},
      {"temporal stats B", GL_RG16F, 1, true},
  };
}

std::vector<StageView> Denoiser::stage_views(int first, const shared::DenoiseParams& p) const {
  std::vector<StageView> v = {{ViewMode::Classes, first + kClass},
                              {ViewMode::Raw, first + kTraceRadiance},
                              {ViewMode::RayLength, first + kSpatialStats},
                              {ViewMode::Spatial, first + kSpatial}};
  const int t = written_;
  if (p.temporal) {
    v.push_back({ViewMode::Temporal, first + t});
    v.push_back({ViewMode::History, first + t + 1});
  }
  v.push_back({ViewMode::Variance, first + (p.temporal ? t + 1 : kSpatialStats)});
  return v;
}

void Denoiser::load(const gl::ShaderSource& src) {
  spatial_ = gl::Program::compute(src, "denoise/spatial.comp");
  if (!bilinear_) {
    // The history is read at reprojected positions between texel centres.
    bilinear_ = gl::Sampler("denoiser history (bilinear)", 0);
    glSamplerParameteri(bilinear_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(bilinear_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(bilinear_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(bilinear_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  temporal_ = gl::Program::compute(src, "denoise/temporal.comp");
  bilateral_ = gl::Program::compute(src, "denoise/bilateral.comp");
}

namespace {
void bind_out(GLuint unit, const gl::Texture2D& t) {
  glBindImageTexture(unit, t.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, t.format());
}

constexpr GLbitfield kStageBarrier = GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
}  // namespace

void Denoiser::run(const FrameContext& frame, std::span<gl::Texture2D* const> tex, const shared::DenoiseParams& p,
                   int trace_divisor) {
  const auto& t = [&](Slot s) -> const gl::Texture2D& { return *tex[static_cast<std::size_t>(s)]; };
  const int spatial_div = spatial_divisor(trace_divisor, p);
  const glm::ivec2 o = shared::trace_offset(trace_divisor, frame.time.index);
  const shared::DenoisePass pass{p, {trace_divisor, o.x, o.y, spatial_div}};
  if (!ubo_) ubo_ = gl::make_buffer("denoiser pass", sizeof(shared::DenoisePass));
  glNamedBufferSubData(ubo_.id(), 0, sizeof(pass), &pass);
  glBindBufferBase(GL_UNIFORM_BUFFER, UBO_PASS, ubo_.id());
  glBindTextureUnit(TEX_CLASS, t(kClass).id());
  glBindTextureUnit(TEX_TRACE_RADIANCE, t(kTraceRadiance).id());
  glBindTextureUnit(TEX_TRACE_RAY, t(kTraceRay).id());
  // Last frame wrote one pair (zeroed by the frame after a reset): read it, write the other.
  const auto other = [](Slot s) { return s == kTemporalA ? kTemporalB : kTemporalA; };
  const Slot out = frame.serial == written_serial_ ? written_ : other(written_), in = other(out);
  const auto next = [](Slot s) { return static_cast<Slot>(s + 1); };
  // Last frame's (variance, frames): the spatial stage's firefly weight and the temporal stage.
  glBindTextureUnit(TEX_HISTORY_STATS, t(next(in)).id());
  {
    gl::ScopedPass timed(frame.timer, p.spatial ? "spatial" : "upsample");
    bind_out(IMG_OUT, t(kSpatial));
    bind_out(IMG_OUT2, t(kSpatialStats));
    spatial_.dispatch_2d(t(kSpatial).width(), t(kSpatial).height());  // a texel each (textures(): spatial_divisor)
    glMemoryBarrier(kStageBarrier);
  }
  const gl::Texture2D* radiance = &t(kSpatial);
  const gl::Texture2D* stats = &t(kSpatialStats);
  if (p.temporal) {
    gl::ScopedPass timed(frame.timer, "temporal");
    glBindTextureUnit(TEX_STAGE_IN, radiance->id());
    glBindTextureUnit(TEX_STAGE_STATS, stats->id());
    glBindTextureUnit(TEX_HISTORY, t(in).id());
    glBindSampler(TEX_HISTORY, bilinear_.id());
    glBindSampler(TEX_HISTORY_STATS, bilinear_.id());
    bind_out(IMG_OUT, t(out));
    bind_out(IMG_OUT2, t(next(out)));
    temporal_.dispatch_2d(frame.width, frame.height);
    glMemoryBarrier(kStageBarrier);
    glBindSampler(TEX_HISTORY, 0);
    glBindSampler(TEX_HISTORY_STATS, 0);
    written_ = out;
    written_serial_ = frame.serial;
    radiance = &t(out);
    stats = &t(next(out));
  }
  {
    gl::ScopedPass timed(frame.timer, p.bilateral ? "bilateral" : "resolve");
    glBindTextureUnit(TEX_STAGE_IN, radiance->id());
    glBindTextureUnit(TEX_STAGE_STATS, stats->id());
    bind_out(IMG_OUT, *frame.reflection);
    bilateral_.dispatch_2d(frame.width, frame.height);
    glMemoryBarrier(kStageBarrier);
  }
}

}  // namespace ssr
