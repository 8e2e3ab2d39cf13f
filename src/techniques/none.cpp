// `none`: no reflection work at all. Confidence 0 everywhere, so the composite shows the
// environment: the baseline every other technique is measured against.
#include "techniques/technique.h"

namespace ssr {
namespace {

struct NoParams {};

class NoneTechnique final : public TechniqueWithParams<NoParams> {
 public:
  NoneTechnique() : TechniqueWithParams("none", {}) {}
  void load(const gl::ShaderSource& src) override {
    program_ = gl::Program::compute(src, "techniques/none.comp");
  }
  TechniqueDecl declare() const override {
    TechniqueDecl d;
    d.reads = kReadGBuffer;
    return d;
  }
  void run(const FrameContext& in) override {
    gl::ScopedPass pass(in.timer, "none");
    glBindImageTexture(IMG_OUT, in.reflection->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    program_.dispatch_2d(in.width, in.height);  // out-of-range invocations: imageStore ignores them
  }

 private:
  gl::Program program_;
};

}  // namespace

std::unique_ptr<Technique> make_none_technique() { return std::make_unique<NoneTechnique>(); }

}  // namespace ssr
