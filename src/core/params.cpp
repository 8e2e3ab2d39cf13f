#include "core/params.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "core/errors.h"

namespace ssr {

int ParamSet::find(std::string_view key) const {
  if (key.size() > prefix_.size() && key.substr(0, prefix_.size()) == prefix_ &&
      key[prefix_.size()] == '.')
    key.remove_prefix(prefix_.size() + 1);
  for (std::size_t i = 0; i < table_.size(); ++i)
    if (key == table_[i].name) return static_cast<int>(i);
  return -1;
}

double ParamSet::read(const void* base, std::size_t i) const {
  const auto* p = static_cast<const std::byte*>(base) + table_[i].offset;
  if (table_[i].type == ParamType::Float) {
    float f;
    std::memcpy(&f, p, sizeof f);
    return f;
  }
  std::int32_t v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

double ParamSet::get(std::size_t i) const { return read(data_, i); }
bool ParamSet::is_auto(std::size_t i) const { return table_[i].has_auto() && get(i) == table_[i].auto_value; }
double ParamSet::get_default(std::size_t i) const { return read(defaults_, i); }

namespace {
// A rejected value as the user wrote it, to the digit (format() rounds for tables).
std::string exact(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}
}  // namespace

void ParamSet::set(std::size_t i, double value) {
  const ParamDesc& d = table_[i];
  const bool is_auto = d.has_auto() && value == d.auto_value;
  if (!is_auto && (!std::isfinite(value) || value < d.min || value > d.max))
    throw InputError("parameter '" + key(i) + "' must be in " + range_string(i) + ", got " +
                     exact(value) + ".");
  auto* p = static_cast<std::byte*>(data_) + d.offset;
  if (d.type == ParamType::Float) {
    const float f = static_cast<float>(value);
    std::memcpy(p, &f, sizeof f);
  } else {
    if (value != std::floor(value))
      throw InputError("parameter '" + key(i) + "' must be a whole number, got " +
                       format(i, value) + ".");
    const auto v = static_cast<std::int32_t>(value);
    std::memcpy(p, &v, sizeof v);
  }
}

void ParamSet::set_from_string(std::size_t i, std::string_view text) {
  const ParamDesc& d = table_[i];
  if (text == "auto") {
    if (!d.has_auto()) throw InputError("parameter '" + key(i) + "' does not take auto (it takes " + range_string(i) + ").");
    return set(i, d.auto_value);
  }
  if (d.type == ParamType::Bool) {
    if (text == "true" || text == "on" || text == "1") return set(i, 1);
    if (text == "false" || text == "off" || text == "0") return set(i, 0);
    throw InputError("parameter '" + key(i) + "' takes true or false, got '" +
                     std::string(text) + "'.");
  }
  if (d.type == ParamType::Choice) {
    for (std::size_t c = 0; c < d.choices.size(); ++c)
      if (text == d.choices[c]) return set(i, static_cast<double>(c));
    throw InputError("parameter '" + key(i) + "' takes one of " + range_string(i) + ", got '" +
                     std::string(text) + "'.");
  }
  double v = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || text.empty())
    throw InputError("parameter '" + key(i) + "' takes a number, got '" + std::string(text) + "'.");
  // The number that stands for auto inside the table (e.g. 0 for a cap) is not a number the
  // user may write: only the word means auto.
  if (d.has_auto() && v == d.auto_value && (v < d.min || v > d.max))
    throw InputError("parameter '" + key(i) + "' must be in " + range_string(i) + ", got " +
                     std::string(text) + " (write auto for the automatic value).");
  set(i, v);
}

void ParamSet::copy_values_from(const ParamSet& other) {
  if (other.table_.data() != table_.data() || other.table_.size() != table_.size())
    throw std::logic_error("ParamSet::copy_values_from: '" + other.prefix_ + "' is not a view of '" + prefix_ + "''s table.");
  for (const ParamDesc& d : table_)  // every value is 4 bytes (float or int32: set())
    std::memcpy(static_cast<std::byte*>(data_) + d.offset, static_cast<const std::byte*>(other.data_) + d.offset, 4);
}

void ParamSet::reset(std::size_t i) { set(i, get_default(i)); }
void ParamSet::reset_all() {
  for (std::size_t i = 0; i < table_.size(); ++i) reset(i);
}

std::string ParamSet::format(std::size_t i, double v) const {
  const ParamDesc& d = table_[i];
  if (d.has_auto() && v == d.auto_value) return "auto";
  if (d.type == ParamType::Bool) return v != 0 ? "true" : "false";
  if (d.type == ParamType::Choice) {
    const auto c = static_cast<std::size_t>(v);
    return v >= 0 && c < d.choices.size() && c == v ? d.choices[c] : std::to_string(v);
  }
  std::ostringstream s;
  s.precision(d.type == ParamType::Float ? 6 : 10);
  s << v;
  return s.str();
}

std::string ParamSet::to_string(std::size_t i) const { return format(i, get(i)); }
std::string ParamSet::default_string(std::size_t i) const { return format(i, get_default(i)); }

std::string ParamSet::range_string(std::size_t i) const {
  const ParamDesc& d = table_[i];
  if (d.type == ParamType::Bool) return d.has_auto() ? "auto|true|false" : "true|false";
  if (d.type == ParamType::Choice) {
    std::string s = d.has_auto() ? "auto|" : "";
    for (std::size_t c = 0; c < d.choices.size(); ++c) s += (c ? "|" : "") + std::string(d.choices[c]);
    return s;
  }
  return std::string(d.has_auto() ? "auto|" : "") + "[" + format(i, d.min) + ", " + format(i, d.max) + "]";
}

std::pair<std::string, std::string> split_assignment(std::string_view text) {
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw InputError("'" + std::string(text) + "' is not of the form key=value.");
  return {std::string(text.substr(0, eq)), std::string(text.substr(eq + 1))};
}

}  // namespace ssr
