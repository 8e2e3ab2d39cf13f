// Named parameter sets: the seeds' own configurations, selectable with --preset.
#pragma once
#include <string>
#include <vector>

namespace ssr {

struct Preset {
  std::string name;         // e.g. "thesis-hq"
  std::string technique;    // the technique it configures
  std::vector<std::string> assignments;  // "technique.key=value"
  std::string source;       // where the numbers come from
};

const std::vector<Preset>& presets();
// The named preset; throws InputError listing the names, or naming the missing technique.
const Preset& find_preset(const std::string& name);

}  // namespace ssr
