// Every technique by name: the screen-space ones (src/techniques) and the two oracles
// (src/reference). Above both layers: what the programs, presets and variants look up.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "render/technique_api.h"

namespace ssr {

struct TechniqueInfo {
  std::string name;
  std::string description;  // one line for `ssrlab techniques`
  std::function<std::unique_ptr<Technique>()> create;  // no GL needed
  // What kind of technique it is: flags that the commands and the viewer read, never names.
  bool truth = false;      // the ground truth every score is taken against: never in "all", never swept
  bool on_demand = false;  // too slow for every frame (CPU ray tracing): the viewer runs it when asked
  bool oracle = false;     // an independent oracle (mirrored cameras): reported as agreement with the truth
};

// Every technique, in the order `ssrlab techniques` lists them.
const std::vector<TechniqueInfo>& technique_registry();
// The named technique's entry; throws InputError listing the known names.
const TechniqueInfo& technique_info(const std::string& name);
// Creates the named technique; throws InputError listing the known names.
std::unique_ptr<Technique> create_technique(const std::string& name);
// The technique every score is taken against (the one flagged `truth`).
const std::string& truth_name();
// Whether `name` is the truth (false for unknown names: no technique's).
bool is_truth(const std::string& name);
// The oracles' names (bench leaves them out of its default list: they have no speed to compare).
std::vector<std::string> oracle_names();

}  // namespace ssr
