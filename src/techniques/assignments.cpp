#include "techniques/assignments.h"

#include "core/errors.h"
#include "core/params.h"

namespace ssr {

void apply_assignments(Technique& technique, const std::vector<std::string>& assignments) {
  ParamSet params = technique.params();
  for (const std::string& a : assignments) {
    auto [key, value] = split_assignment(a);
    const auto dot = key.find('.');
    if (dot == std::string::npos)
      throw InputError("parameter key '" + key + "' must be of the form <technique>.<name>.");
    if (key.substr(0, dot) != technique.name())
      throw InputError("parameter '" + key + "' does not belong to technique '" +
                       technique.name() + "'.");
    const int i = params.find(key);
    if (i < 0) {
      std::string known;
      for (std::size_t k = 0; k < params.size(); ++k) known += (k ? ", " : "") + params.key(k);
      throw InputError("unknown parameter '" + key + "'" +
                       (known.empty() ? " (technique '" + technique.name() + "' has none)."
                                      : " (known: " + known + ")."));
    }
    params.set_from_string(static_cast<std::size_t>(i), value);
  }
}

}  // namespace ssr
