// `none`: no reflection work at all. Confidence 0 everywhere, so the composite shows the
// environment: the baseline every other technique is measured against.
#include "techniques/technique.h"

namespace ssr {
namespace {

struct NoParams {};

class NoneTechnique final : public TechniqueWithParams<NoParams> {
 public:
  NoneTechnique() : TechniqueWithParams("none", {}) {}
  void load(const gl::ShaderSource&) override {}
  void run(const TechniqueInputs& in, gl::Texture2D& reflection) override {
    gl::ScopedPass pass(in.timer, "none");
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(reflection.id(), 0, GL_RGBA, GL_FLOAT, zero);
  }
};

}  // namespace

std::unique_ptr<Technique> make_none_technique() { return std::make_unique<NoneTechnique>(); }

}  // namespace ssr
