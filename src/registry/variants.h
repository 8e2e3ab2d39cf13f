// What `compare` and `bench` run: techniques x parameter sweeps, plus named presets.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ssr {

struct Variant {
  std::string technique;
  std::string preset;                    // "" unless it comes from --preset
  std::vector<std::string> assignments;  // "technique.key=value", applied in order
  std::vector<std::string> swept_keys;   // the keys sweeps varied, in command-line order
  // "linear", "hiz denoise=true" (--set), "dda stride=2 max_steps=64" (--sweep), "linear [thesis-hq]"
  std::string label() const;
};

// Builds and validates the variants (InputError on any unknown technique, key or value):
//  - each technique once with the --set values that name it, times every --sweep on it
//    (several sweeps of one technique: their cartesian product);
//  - each preset as its own variant (a preset given twice is an error);
//  - --set / --sweep keys of a technique that is not run are an error, except `reference.*`.
std::vector<Variant> build_variants(const std::vector<std::string>& techniques,
                                    const std::vector<std::string>& sets,
                                    const std::vector<std::string>& sweeps,
                                    const std::vector<std::string>& preset_names);

// The --set values that name `technique` (for the reference, say).
std::vector<std::string> sets_for(const std::string& technique, const std::vector<std::string>& sets);

// "a,b,c" -> {a, b, c}; an empty item or one named twice is an error.
std::vector<std::string> split_list(const std::string& text, const std::string& what);

// The techniques a command runs: the --techniques list, or (not given) every registered technique
// except the reference and those named in `also_left_out`.
std::vector<std::string> technique_names(const std::optional<std::string>& list,
                                         const std::vector<std::string>& also_left_out = {});

}  // namespace ssr
