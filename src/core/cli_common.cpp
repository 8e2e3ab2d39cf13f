#include "core/cli_common.h"

#include <regex>

#include "core/errors.h"

namespace ssr {

std::pair<int, int> parse_size(const std::string& text) {
  static const std::regex re(R"(^(\d{1,6})x(\d{1,6})$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    throw InputError("size '" + text + "' is not of the form WIDTHxHEIGHT (e.g. 1280x720).");
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 1 || h < 1) throw InputError("size '" + text + "' must be at least 1x1.");
  return {w, h};
}

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
