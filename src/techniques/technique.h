// The technique interface and registry.
//
// A technique reads the frame's inputs (G-buffer, lit colour, frame uniforms) and writes one
// RGBA16F reflection texture: rgb = reflected radiance, a = confidence in [0,1]. It never
// allocates its inputs; it says what it needs and the renderer provides it.
//
// Adding a technique: one src/techniques/<name>.cpp (Params table + run), its shaders under
// shaders/techniques/, and one line in registry.cpp.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gl/program.h"
#include "gl/timer.h"
#include "render/targets.h"
#include "shared/bindings.h"
#include "techniques/params.h"

namespace ssr {

struct Scene;
class Renderer;

// Everything a technique may read for one frame.
struct TechniqueInputs {
  const Renderer& renderer;   // camera, matrices, scene upload; bind_frame_inputs() to restore
  const GBuffer& gbuffer;
  const gl::Texture2D& lit;   // RGBA16F lit colour without reflections (bilinear filtering on)
  GLuint frame_ubo;           // FrameUniforms, bound at UBO_FRAME
  int width, height;
  const Scene& scene;
  gl::PassTimer* timer;       // may be null
  float scene_diagonal;       // world units: the scene's bounding-box diagonal ("auto" lengths)
};

class Technique {
 public:
  virtual ~Technique() = default;
  virtual const std::string& name() const = 0;
  // The technique's parameters; valid for the technique's lifetime. Needs no GL context.
  virtual ParamSet params() = 0;
  // (Re)builds GL programs from `src`. Throws RuntimeError with file:line on a compile error,
  // leaving the previous programs in place.
  virtual void load(const gl::ShaderSource& src) = 0;
  // Writes `reflection` (same size as the frame). Called with the frame's inputs bound, and
  // the debug image (steps, hit share, distance) bound at IMG_OUT2.
  virtual void run(const TechniqueInputs& in, gl::Texture2D& reflection) = 0;

  // What the renderer must provide or do around run().
  virtual bool needs_backfaces() const { return false; }  // back-face depth at TEX_BACK_DEPTH
  // The outputs besides the reflection that the technique writes; the frame clears the others
  // before run(), so that no technique reads or shows another's stale image.
  virtual bool writes_debug() const { return false; }       // steps, hit share, distance (IMG_OUT2)
  virtual bool writes_refraction() const { return false; }  // glass pixels' refraction (IMG_REFRACTION)
  virtual int composite_blend() const { return 0; }       // 0 standard, 1 Roberts (mix(lit, refl, a))
  // Handles planar reflector pixels only (ppr without a fallback, the planar oracle): the
  // breakdown reports every other pixel as not handled instead of scoring what it leaves there.
  virtual bool planar_only() const { return false; }
};

struct TechniqueInfo {
  std::string name;
  std::string description;  // one line for `ssrlab techniques`
  std::function<std::unique_ptr<Technique>()> create;  // no GL needed
};

// Every technique, in the order `ssrlab techniques` lists them.
const std::vector<TechniqueInfo>& technique_registry();
// The named technique's entry; throws InputError listing the known names.
const TechniqueInfo& technique_info(const std::string& name);
// Creates the named technique; throws InputError listing the known names.
std::unique_ptr<Technique> create_technique(const std::string& name);

// The common shape of a technique: a Params struct P with defaults and its table.
template <class P>
class TechniqueWithParams : public Technique {
 public:
  TechniqueWithParams(std::string name, std::span<const ParamDesc> table)
      : name_(std::move(name)), table_(table) {}
  const std::string& name() const override { return name_; }
  ParamSet params() override { return ParamSet(name_, table_, &params_, &kDefaults); }

 protected:
  // Uploads `values` (default: params_) to the technique UBO and binds it at UBO_TECHNIQUE.
  void bind_params(const P* values = nullptr) {
    if (!ubo_) ubo_ = gl::make_buffer(name_ + " params", sizeof(P));
    glNamedBufferSubData(ubo_.id(), 0, sizeof(P), values ? values : &params_);
    glBindBufferBase(GL_UNIFORM_BUFFER, UBO_TECHNIQUE, ubo_.id());
  }
  P params_{};

 private:
  static inline const P kDefaults{};
  std::string name_;
  std::span<const ParamDesc> table_;
  gl::Buffer ubo_;
};

}  // namespace ssr
