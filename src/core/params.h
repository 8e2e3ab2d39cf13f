// One description per parameter (ARCHITECTURE §3).
//
// A technique's Params struct (declared in shaders/shared/<technique>.h, so the GPU reads the
// very same layout) gets one table of ParamDesc. That table drives the CLI (--set), the ImGui
// panel, `ssrlab techniques`, JSON presets and bench sweeps. Keys are "<technique>.<name>".
#pragma once
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ssr {

enum class ParamType { Float, Int, Bool, Choice };

struct ParamDesc {
  const char* name;      // lower_snake_case, unique within the technique
  ParamType type;
  std::size_t offset;    // offsetof(Params, member): float for Float, int32 for Int/Bool/Choice
  double min, max;       // inclusive range (Bool: 0..1, Choice: 0..choices-1)
  double step;           // UI / sweep granularity
  const char* unit;      // "world units", "steps", "" ...
  const char* help;      // one sentence
  std::vector<const char*> choices = {};  // Choice only: the names, stored as their index
  // Parameters that also take "auto" store it as this value (outside [min, max]); the technique
  // resolves it each frame from the scene and the image size. NaN: no "auto".
  double auto_value = std::numeric_limits<double>::quiet_NaN();
  bool has_auto() const { return !std::isnan(auto_value); }
  // Rows shared by several techniques name their table ("ray options", "denoiser"); a
  // technique's own rows leave it empty. The docs summarise shared rows by group.
  const char* group = "";
};

// `d`, also taking "auto" (stored as `sentinel`); the help sentence should say what auto is.
inline ParamDesc with_auto(ParamDesc d, double sentinel = 0.0) {
  d.auto_value = sentinel;
  return d;
}

#define SSR_PARAM_FLOAT(P, m, lo, hi, st, unit, help) \
  ::ssr::ParamDesc { #m, ::ssr::ParamType::Float, offsetof(P, m), lo, hi, st, unit, help }
#define SSR_PARAM_INT(P, m, lo, hi, unit, help) \
  ::ssr::ParamDesc { #m, ::ssr::ParamType::Int, offsetof(P, m), lo, hi, 1, unit, help }
#define SSR_PARAM_BOOL(P, m, help) \
  ::ssr::ParamDesc { #m, ::ssr::ParamType::Bool, offsetof(P, m), 0, 1, 1, "", help }
#define SSR_PARAM_CHOICE(P, m, help, ...)                                                 \
  ::ssr::ParamDesc {                                                                      \
    #m, ::ssr::ParamType::Choice, offsetof(P, m), 0,                                      \
        double(std::vector<const char*>{__VA_ARGS__}.size() - 1), 1, "", help, { __VA_ARGS__ } \
  }

// A type-erased view of one Params instance and its table. Cheap to copy; does not own.
class ParamSet {
 public:
  ParamSet() = default;
  ParamSet(std::string prefix, std::span<const ParamDesc> table, void* data, const void* defaults)
      : prefix_(std::move(prefix)), table_(table), data_(data), defaults_(defaults) {}

  const std::string& prefix() const { return prefix_; }  // the technique name
  std::span<const ParamDesc> table() const { return table_; }
  std::size_t size() const { return table_.size(); }
  std::string key(std::size_t i) const { return prefix_ + "." + table_[i].name; }

  // Index of "name" or "<prefix>.name"; -1 when unknown.
  int find(std::string_view key) const;
  double get(std::size_t i) const;
  bool is_auto(std::size_t i) const;  // the value is the "auto" sentinel
  double get_default(std::size_t i) const;
  // Sets a value; throws InputError (one sentence with the key and range) when out of range,
  // non-finite or not an integer for Int/Bool/Choice.
  void set(std::size_t i, double value);
  // Parses "0.05", "64", "true"/"false"/"on"/"off"/"1"/"0", a choice name, or "auto" where
  // the parameter takes it.
  void set_from_string(std::size_t i, std::string_view text);
  void reset(std::size_t i);
  void reset_all();
  // Every value of `other`, a view of the same table, as stored: not through set(), whose range
  // check a stored float may fail by a rounding (the minimum 1e-4 is 9.9999997e-5 as a float).
  void copy_values_from(const ParamSet& other);
  std::string to_string(std::size_t i) const;          // the value as the CLI would take it
  std::string default_string(std::size_t i) const;
  std::string range_string(std::size_t i) const;       // "[1, 4096]", "auto|[1, 4096]", "true|false", "a|b|c"

 private:
  double read(const void* base, std::size_t i) const;
  std::string format(std::size_t i, double v) const;
  std::string prefix_;
  std::span<const ParamDesc> table_;
  void* data_ = nullptr;
  const void* defaults_ = nullptr;
};

// "key=value" -> (key, value); throws InputError when there is no '='.
std::pair<std::string, std::string> split_assignment(std::string_view text);

}  // namespace ssr
