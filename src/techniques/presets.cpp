#include "techniques/presets.h"

#include "core/errors.h"
#include "techniques/technique.h"

namespace ssr {

const std::vector<Preset>& presets() {
  // The thesis's brute force compares against a depth threshold "according to the step size":
  // thickness = step size. Its max distance is whatever the steps reach.
  static const std::vector<Preset> list = {
      {"thesis-hq", "linear",
       {"linear.max_steps=1024", "linear.step_size=0.1", "linear.thickness=0.1",
        "linear.max_distance=10000", "linear.depth_interp=false"},
       "Kim 2018, fig. 25: brute force high quality, 1024 iterations, step 0.1"},
      {"thesis-lq", "linear",
       {"linear.max_steps=128", "linear.step_size=5", "linear.thickness=5",
        "linear.max_distance=10000", "linear.depth_interp=false"},
       "Kim 2018, fig. 26: brute force low quality, 128 iterations, step 5.0"},
      {"thesis-lq-interp", "linear",
       {"linear.max_steps=128", "linear.step_size=5", "linear.thickness=5",
        "linear.max_distance=10000", "linear.depth_interp=true"},
       "Kim 2018, fig. 29: low quality with depth linear interpolation"},
      {"roberts-default", "linear-binary",
       {"linear-binary.linear_steps=100", "linear-binary.binary_steps=10",
        "linear-binary.thickness=0.1", "linear-binary.max_distance=9", "linear-binary.edge_fade=true"},
       "Roberts: 100 linear + 10 binary steps, thickness 0.1, max distance 9, edge fade"},
      {"roberts-hq", "linear-binary",
       {"linear-binary.linear_steps=500", "linear-binary.binary_steps=10",
        "linear-binary.thickness=0.1", "linear-binary.max_distance=9", "linear-binary.edge_fade=true"},
       "Roberts: 500 linear + 10 binary steps, edge fade"},
  };
  return list;
}

const Preset& find_preset(const std::string& name) {
  std::string known;
  for (const Preset& p : presets()) {
    if (p.name == name) {
      bool exists = false;
      for (const TechniqueInfo& t : technique_registry()) exists |= t.name == p.technique;
      if (!exists)
        throw InputError("preset '" + name + "' needs technique '" + p.technique +
                         "', which this build does not have yet.");
      return p;
    }
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw InputError("unknown preset '" + name + "' (known: " + known + ").");
}

}  // namespace ssr
