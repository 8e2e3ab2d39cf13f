// The technique registry and the common shape of a technique (a Params table + run).
//
// The interface itself (what a technique declares, reads and writes) is render/technique_api.h.
// Adding a technique: one src/techniques/<name>.cpp (Params table + declare + run), its shaders
// under shaders/techniques/, and one line in registry.cpp.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "render/technique_api.h"
#include "shared/bindings.h"

namespace ssr {

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
