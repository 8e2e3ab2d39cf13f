// A technique that is one compute pass over the screen writing the reflection, with no
// parameters: `none` (techniques/none.cpp) and the floor pass the speed figures divide by
// (eval/runner.cpp). The pass is timed under the technique's name.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "shared/bindings.h"
#include "techniques/technique.h"

namespace ssr {

struct NoParams {};

class ScreenPassTechnique final : public TechniqueWithParams<NoParams> {
 public:
  ScreenPassTechnique(std::string name, std::string shader, std::uint32_t reads, std::vector<std::string> defines = {})
      : TechniqueWithParams(std::move(name), {}),
        shader_(std::move(shader)),
        reads_(reads),
        defines_(std::move(defines)) {}
  void load(const gl::ShaderSource& src) override { program_ = gl::Program::compute(src, shader_, defines_); }
  TechniqueDecl declare() const override {
    TechniqueDecl d;
    d.reads = reads_;
    return d;
  }
  void run(const FrameContext& in) override {
    gl::ScopedPass pass(in.timer, name());
    glBindImageTexture(IMG_OUT, in.reflection->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    program_.dispatch_2d(in.width, in.height);  // out-of-range invocations: imageStore ignores them
  }

 private:
  std::string shader_;
  std::uint32_t reads_;
  std::vector<std::string> defines_;
  gl::Program program_;
};

}  // namespace ssr
