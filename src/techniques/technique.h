// The common shape of a technique (a Params table + run).
//
// The interface itself (what a technique declares, reads and writes) is render/technique_api.h.
// Adding a technique: one src/techniques/<name>.cpp (Params table + declare + run), its shaders
// under shaders/techniques/, and one line in src/registry/registry.cpp.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "render/technique_api.h"
#include "shared/bindings.h"

namespace ssr {

// The common shape of a technique: a Params struct P with defaults and its table.
template <class P>
class TechniqueWithParams : public Technique {
 public:
  TechniqueWithParams(std::string name, std::span<const ParamDesc> table)
      : name_(std::move(name)), table_(table) {}
  const std::string& name() const override { return name_; }
  ParamSet params() override { return ParamSet(name_, table_, &params_, &kDefaults); }
  ParamSet ran_params() override { return ran_recorded_ ? ParamSet(name_, table_, &ran_, &kDefaults) : params(); }

 protected:
  // Uploads `values` (default: params_) to the technique UBO and binds it at UBO_TECHNIQUE.
  void bind_params(const P* values = nullptr) {
    if (!ubo_) ubo_ = gl::make_buffer(name_ + " params", sizeof(P));
    glNamedBufferSubData(ubo_.id(), 0, sizeof(P), values ? values : &params_);
    glBindBufferBase(GL_UNIFORM_BUFFER, UBO_TECHNIQUE, ubo_.id());
  }
  P params_{};
  // run() records the parameters it ran with, "auto" resolved (ran_params()).
  void record_run(const P& resolved) {
    ran_ = resolved;
    ran_recorded_ = true;
  }

 private:
  static inline const P kDefaults{};
  std::string name_;
  std::span<const ParamDesc> table_;
  gl::Buffer ubo_;
  P ran_{};
  bool ran_recorded_ = false;
};

}  // namespace ssr
