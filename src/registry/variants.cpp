#include "registry/variants.h"

#include <algorithm>
#include <set>

#include "core/cli_common.h"
#include "core/errors.h"
#include "registry/presets.h"
#include "techniques/technique.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

namespace ssr {

std::string Variant::label() const {
  if (!preset.empty()) return technique + " [" + preset + "]";
  // Every parameter the command line gave, --set ones before the swept ones, each key once with
  // its last value: a row called "hiz" is hiz at its defaults (with --set hiz.denoise=true it
  // read as the default).
  std::vector<std::string> keys;
  for (const std::string& a : assignments) {
    const std::string key = split_assignment(a).first;
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  }
  std::string out = technique;
  for (const std::string& key : keys)
    for (auto it = assignments.rbegin(); it != assignments.rend(); ++it)
      if (split_assignment(*it).first == key) {
        out += " " + it->substr(technique.size() + 1);  // "max_steps=64"
        break;
      }
  return out;
}

std::vector<std::string> split_list(const std::string& text, const std::string& what) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item.empty()) throw InputError(what + " list '" + text + "' has an empty item.");
    // A repeat would run (or print) the same thing twice, as rows a reader takes for two.
    if (std::find(out.begin(), out.end(), item) != out.end())
      throw InputError(what + " list names '" + item + "' twice.");
    out.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

namespace {
std::string technique_of(const std::string& key) {
  const auto dot = key.find('.');
  if (dot == std::string::npos || dot == 0)
    throw InputError("parameter key '" + key + "' must be of the form <technique>.<name>.");
  return key.substr(0, dot);
}
}  // namespace

std::vector<std::string> sets_for(const std::string& technique, const std::vector<std::string>& sets) {
  std::vector<std::string> out;
  for (const std::string& s : sets)
    if (technique_of(split_assignment(s).first) == technique) out.push_back(s);
  return out;
}

std::vector<Variant> build_variants(const std::vector<std::string>& techniques,
                                    const std::vector<std::string>& sets,
                                    const std::vector<std::string>& sweeps,
                                    const std::vector<std::string>& preset_names) {
  std::set<std::string> running(techniques.begin(), techniques.end());
  for (const std::string& t : techniques) create_technique(t);  // unknown names throw
  auto check_owner = [&](const std::string& key) {
    const std::string t = technique_of(key);
    FrameSettings scratch;
    const ParamSet frame = frame_settings_params(scratch);
    if (t == frame.prefix()) {  // "frame.exposure": a frame setting, given by its own option
      const int i = frame.find(key);
      if (i < 0) throw InputError("unknown frame setting '" + key + "'.");
      throw InputError("'" + key + "' is a frame setting, not a technique's parameter: give it as " +
                       frame_setting_option(frame.table()[static_cast<std::size_t>(i)]) + ".");
    }
    if (!running.count(t) && !is_truth(t))  // the truth's parameters may be set whatever runs
      throw InputError("parameter '" + key + "' belongs to technique '" + t + "', which is not being run.");
  };
  for (const std::string& s : sets) check_owner(split_assignment(s).first);

  // key -> values, per technique, in command-line order.
  // A key swept twice, set and swept, or a value listed twice would run fewer or the same variants
  // than the command line reads as: refused.
  std::map<std::string, std::vector<std::pair<std::string, std::vector<std::string>>>> sweep_of;
  std::set<std::string> swept;
  for (const std::string& s : sweeps) {
    auto [key, values] = split_assignment(s);
    check_owner(key);
    if (is_truth(technique_of(key))) throw InputError("the reference cannot be swept.");
    if (!swept.insert(key).second)
      throw InputError("--sweep names '" + key + "' twice (give all its values in one list).");
    for (const std::string& set : sets)
      if (split_assignment(set).first == key)
        throw InputError("'" + key + "' is both set (--set) and swept (--sweep).");
    std::vector<std::string> list = split_list(values, "--sweep '" + key + "'");  // a value twice: refused
    // Also one value written two ways (0.1 and 0.10): compared as the parameter stores them.
    auto probe = create_technique(technique_of(key));
    ParamSet params = probe->params();
    const int index = params.find(key);  // unknown: the validation below names the known keys
    std::vector<std::string> stored;
    for (const std::string& v : list) {
      if (index < 0) break;
      try {
        params.set_from_string(static_cast<std::size_t>(index), v);
      } catch (const InputError&) {
        break;  // a bad value: the validation below says so, after the variant count's check
      }
      stored.push_back(params.to_string(static_cast<std::size_t>(index)));
      const auto first = std::find(stored.begin(), stored.end() - 1, stored.back());
      if (first != stored.end() - 1)
        throw InputError("--sweep '" + key + "' gives one value twice ('" + list[static_cast<std::size_t>(first - stored.begin())] +
                         "' and '" + v + "').");
    }
    sweep_of[technique_of(key)].push_back({key, std::move(list)});
  }

  // Count before building: sweeps multiply, and a few long lists would exhaust memory.
  constexpr std::size_t kMaxVariants = 10000;
  std::size_t count = preset_names.size();
  for (const std::string& t : techniques) {
    std::size_t n = 1;
    for (const auto& sweep : sweep_of[t])
      n = std::min(n * sweep.second.size(), kMaxVariants + 1);
    count += n;
  }
  if (count > kMaxVariants)
    throw InputError("the techniques, sweeps and presets give more than " +
                     std::to_string(kMaxVariants) + " variants, more than supported.");
  std::vector<Variant> out;
  for (const std::string& t : techniques) {
    std::vector<Variant> vs = {{t, "", sets_for(t, sets), {}}};
    for (const auto& [key, values] : sweep_of[t]) {
      std::vector<Variant> next;
      for (const Variant& v : vs)
        for (const std::string& value : values) {
          Variant n = v;
          n.assignments.push_back(key + "=" + value);
          n.swept_keys.push_back(key);
          next.push_back(n);
        }
      vs = next;
    }
    out.insert(out.end(), vs.begin(), vs.end());
  }
  for (auto it = preset_names.begin(); it != preset_names.end(); ++it) {
    const Preset& p = find_preset(*it);
    if (std::find(preset_names.begin(), it, *it) != it) throw InputError("--preset '" + *it + "' is given twice.");
    out.push_back({p.technique, p.name, p.assignments, {}});
  }
  // Validate every assignment now, before any GL work.
  for (const Variant& v : out) {
    auto t = create_technique(v.technique);
    apply_assignments(*t, v.assignments);
  }
  return out;
}

std::vector<std::string> technique_names(const std::optional<std::string>& list,
                                         const std::vector<std::string>& also_left_out) {
  if (list) return split_list(*list, "technique");  // given empty: an error, not "all"
  std::vector<std::string> names;
  for (const TechniqueInfo& t : technique_registry())
    if (!t.truth && std::find(also_left_out.begin(), also_left_out.end(), t.name) == also_left_out.end())
      names.push_back(t.name);
  return names;
}

}  // namespace ssr
