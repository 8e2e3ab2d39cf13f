// `ppr`: Pixel-Projected Reflections (Kim 2018, after Cichocki 2017), a compute path with no ray
// march at all. Projection pass: every pixel is mirrored across each planar reflector and, where
// the camera sees that image through the reflector, writes (imageAtomicMin) the packed offset
// back to itself into an r32ui intermediate image at the destination pixel. Resolve pass:
// decode, patch holes from neighbours, fetch the reflected colour; normal maps and roughness
// by the thesis's reprojection of the perturbed (or GGX-sampled) reflection vector.
#include <algorithm>
#include <stdexcept>
#include <iterator>
#include <string_view>

#include "scene/scene.h"
#include "shared/ppr.h"
#include "shared/ppr_packing.h"
#include "techniques/ray_options.h"
#include "techniques/technique.h"

namespace ssr {

// The fallback tracers (their files' factories), in the order of the `fallback` choice below.
std::unique_ptr<Technique> make_linear_technique();
std::unique_ptr<Technique> make_linear_binary_technique();
std::unique_ptr<Technique> make_dda_technique();
std::unique_ptr<Technique> make_hiz_technique();

namespace {

using Factory = std::unique_ptr<Technique> (*)();
constexpr Factory kFallbacks[] = {nullptr, make_linear_technique, make_linear_binary_technique, make_dda_technique,
                                  make_hiz_technique};

using P = shared::PprParams;
const ParamDesc kTable[] = {
    SSR_PARAM_CHOICE(P, hole_fill, "Fill pixels nothing projected onto from their neighbours' solutions.",
                     "none", "4-neighbour", "8-neighbour"),
    samples_row(offsetof(P, samples)),
    roughness_row(offsetof(P, roughness)),
    SSR_PARAM_BOOL(P, normal_maps, "Follow normal-mapped normals: reflection distance times the perturbed reflection vector, reprojected."),
    SSR_PARAM_BOOL(P, edge_fade, "Fade confidence towards the screen edges: clamp(1 - |u-0.5| - |v-0.5|, 0, 1)."),
    seed_row(offsetof(P, seed)),
    SSR_PARAM_CHOICE(P, fallback,
                     "Tracer (at its defaults) for the reflective pixels projection cannot serve: non-planar surfaces, "
                     "unfilled holes, rays past a source's outline, normal-mapped mirror pixels, glossy rays whose "
                     "approximated point lies off the surface, reflectors of roughness 0.35 and more; none is the "
                     "thesis's technique.",
                     "none", "linear", "linear-binary", "dda", "hiz"),
};

class PprTechnique final : public TechniqueWithParams<P> {
 public:
  PprTechnique() : TechniqueWithParams("ppr", kTable) {}

  void load(const gl::ShaderSource& src) override {
    src_ = src;
    fallback_loaded_ = false;  // rebuilt from the new shaders on the next run
    auto clear = gl::Program::compute(src, "techniques/ppr_clear.comp");
    auto project = gl::Program::compute(src, "techniques/ppr_project.comp");
    auto resolve = gl::Program::compute(src, "techniques/ppr_resolve.comp");
    clear_ = std::move(clear);
    project_ = std::move(project);
    resolve_ = std::move(resolve);
    resolve_debug_ = gl::Program();  // on first use
  }

  // With a fallback tracer, ppr also reads what it reads and its refraction of glass pixels
  // stands.
  TechniqueDecl declare() const override {
    TechniqueDecl d;
    d.reads = kReadGBuffer | kReadLit | kReadReflectors;
    d.debug_views = {ViewMode::Offsets, ViewMode::Holes};
    // Two intermediates used in turn: the resolve empties the one the next frame projects into.
    d.textures = {{"intermediate 0", GL_R32UI, 1, true}, {"intermediate 1", GL_R32UI, 1, true}};
    if (params_.fallback != 0) {
      const TechniqueDecl f = fallback_technique().declare();
      d.reads |= f.reads;
      d.writes_refraction = true;
      d.textures.push_back({"fallback", GL_RGBA16F});
    }
    d.planar_only = params_.fallback == 0;
    return d;
  }

  void run(const FrameContext& in) override {
    const Scene& scene = in.scene;
    // The reflectors, oriented towards this frame's camera; edge-on ones are left out.
    const glm::vec3 eye = in.camera.position;
    std::vector<shared::PprReflector> refl;
    for (const Reflector& r : scene.reflectors) {
      glm::vec3 n = r.normal();
      float d = -glm::dot(n, r.center);
      const float side = glm::dot(n, eye) + d;
      if (std::abs(side) < 1e-6f * (1.0f + glm::length(eye))) n = glm::vec3(0.0f);  // edge-on: inert
      if (side < 0) {
        n = -n;
        d = -d;
      }
      refl.push_back({glm::vec4(n, d), glm::vec4(r.center, 1.0f), glm::vec4(r.tangent, r.half_extents.x),
                      glm::vec4(r.bitangent, r.half_extents.y)});
    }
    // Each reflector knows where its run of coplanar neighbours ends (the projection tests a
    // plane once and asks the destination pixel which of them it shows).
    for (std::size_t i = refl.size(); i-- > 0;)
      refl[i].center.w = i + 1 < refl.size() && refl[i + 1].plane == refl[i].plane ? refl[i + 1].center.w
                                                                                  : static_cast<float>(i + 1);
    static_assert(Scene::kMaxReflectors <= PPR_MAX_REFLECTORS, "ppr_project.comp's shared copy holds them all");
    params_.reflector_count = static_cast<int>(refl.size());
    if (refl.empty()) refl.push_back({});  // a buffer must have storage
    const std::size_t bytes = refl.size() * sizeof(refl[0]);
    if (bytes > reflectors_bytes_) {
      reflectors_ = gl::make_buffer("ppr reflectors", static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
      reflectors_bytes_ = bytes;
    }
    glNamedBufferSubData(reflectors_.id(), 0, static_cast<GLsizeiptr>(bytes), refl.data());
    gl::Texture2D& intermediate = *in.textures[parity_];
    gl::Texture2D& next = *in.textures[1 - parity_];
    parity_ = 1 - parity_;
    const GLuint bits = shared::ppr_fraction_bits(static_cast<GLuint>(in.width), static_cast<GLuint>(in.height));

    // The hybrid: the fallback tracer first (over the whole frame, for now), into its own image.
    if (params_.fallback != 0) {
      Technique& fallback = fallback_technique();
      if (!fallback_loaded_) {
        fallback.load(src_);
        fallback_loaded_ = true;
      }
      FrameContext f = in;
      f.reflection = in.textures[2];
      f.debug = nullptr;  // the resolve writes ppr's own debug views over every pixel
      f.textures.clear();
      fallback.run(f);
      glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      glBindTextureUnit(TEX_PPR_FALLBACK, in.textures[2]->id());
    }

    bind_params();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_PPR_REFLECTORS, reflectors_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, UBO_PPR_REFLECTORS, reflectors_.id());  // the first one (projection)
    glBindImageTexture(IMG_PPR_INTERMEDIATE, intermediate.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    if (!emptied_) {  // first frame, or the frame zeroed the textures (reset)
      gl::ScopedPass pass(in.timer, "ppr clear");
      clear_.dispatch_2d(in.width, in.height);
      glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    {
      gl::ScopedPass pass(in.timer, "ppr project");
      glProgramUniform1ui(project_.id(), 0, bits);
      project_.dispatch_2d(in.width, in.height);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
      gl::ScopedPass pass(in.timer, "ppr resolve");
      glBindTextureUnit(TEX_PPR_PROJECTED, intermediate.id());
      glBindImageTexture(IMG_PPR_INTERMEDIATE, next.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
      // The offsets and holes views' image only when read (techniques/technique_api.h).
      if (in.debug && !resolve_debug_)
        resolve_debug_ = gl::Program::compute(src_, "techniques/ppr_resolve.comp", {"SSR_DEBUG_IMAGE"});
      const gl::Program& resolve = in.debug ? resolve_debug_ : resolve_;
      glProgramUniform1ui(resolve.id(), 0, bits);
      glProgramUniform1i(resolve.id(), 1, params_.fallback != 0 ? 1 : 0);
      glBindImageTexture(IMG_OUT, in.reflection->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      resolve.dispatch_2d(in.width, in.height);
      glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    emptied_ = true;
  }

  // The frame zeroed the intermediates (0 is a valid offset, not PPR_EMPTY).
  void reset() override { emptied_ = false; }

 private:
  gl::Program clear_, project_, resolve_, resolve_debug_;
  // The fallback tracer at its defaults, created when the parameter names it (no GL needed).
  Technique& fallback_technique() const {
    // The choice's name, from the table row that describes it.
    const auto row = std::find_if(std::begin(kTable), std::end(kTable),
                                  [](const ParamDesc& d) { return std::string_view(d.name) == "fallback"; });
    const std::string name = row->choices[static_cast<std::size_t>(params_.fallback)];
    if (!fallback_ || fallback_->name() != name) {
      fallback_ = kFallbacks[params_.fallback]();
      if (fallback_->name() != name) throw std::logic_error("ppr: kFallbacks is not in the fallback choices' order");
      fallback_loaded_ = false;
    }
    return *fallback_;
  }

  gl::ShaderSource src_;
  int parity_ = 0;        // the intermediate this frame projects into
  bool emptied_ = false;  // it holds PPR_EMPTY everywhere (the last resolve emptied it)
  mutable std::unique_ptr<Technique> fallback_;
  mutable bool fallback_loaded_ = false;
  gl::Buffer reflectors_;
  std::size_t reflectors_bytes_ = 0;
};

}  // namespace

std::unique_ptr<Technique> make_ppr_technique() { return std::make_unique<PprTechnique>(); }

}  // namespace ssr
