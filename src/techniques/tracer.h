// The common shape of a screen-space tracer: a Params struct P that starts with the shared
// RayOptions, one compute shader built on shaders/common/ssr_main.glsl, one dispatch.
#pragma once
#include <string>

#include "techniques/ray_options.h"
#include "techniques/technique.h"

namespace ssr {

template <class P>
class TracerTechnique : public TechniqueWithParams<P> {
 public:
  TracerTechnique(std::string name, std::span<const ParamDesc> table, std::string shader)
      : TechniqueWithParams<P>(std::move(name), table), shader_(std::move(shader)) {}

  void load(const gl::ShaderSource& src) override { program_ = gl::Program::compute(src, shader_); }

  void run(const TechniqueInputs& in, gl::Texture2D& reflection) override {
    gl::ScopedPass pass(in.timer, this->name());
    prepare(in);
    this->bind_params();
    glBindImageTexture(IMG_OUT, reflection.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    program_.dispatch_2d(in.width, in.height);
  }

  bool needs_backfaces() const override { return this->params_.ray.backface_thickness != 0; }
  bool writes_debug() const override { return true; }
  bool writes_refraction() const override { return true; }
  int composite_blend() const override { return this->params_.ray.blend; }

 protected:
  // Work before the trace (e.g. building a depth pyramid); timed with the technique.
  virtual void prepare(const TechniqueInputs&) {}

 private:
  std::string shader_;
  gl::Program program_;
};

}  // namespace ssr
