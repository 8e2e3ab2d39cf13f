// The one JSON reading layer (scene files, viewer presets): parsing with comments, duplicate
// keys and syntax errors reported as one sentence, and typed getters that name the document and
// the key on every error.
#pragma once
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "core/files.h"

namespace ssr {


// A JSON object as ssrlab's files are read: comments allowed; syntax errors, duplicate keys and
// anything but an object throw InputError of one sentence starting with `label`.
nlohmann::json parse_json_object(const std::string& text, const std::string& label);

// Typed getters over one JSON document: every problem is an InputError of one sentence that
// starts with the document's label ("scene file 'a.json'", "viewer preset 'p.json'") and names
// the key path ("lights[0].color").
class JsonReader {
 public:
  explicit JsonReader(std::string label, std::filesystem::path file = {})
      : file_(std::move(file)), label_(std::move(label)) {}
  const std::filesystem::path& file() const { return file_; }  // the file read (relative paths), if any
  const std::string& label() const { return label_; }

  [[noreturn]] void fail_at(const std::string& where, const std::string& what) const {
    files::fail(label_ + ": " + files::q(where) + " " + what);
  }

  static std::string join(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
  }
  static std::string index(const std::string& parent, std::size_t i) {
    return parent + "[" + std::to_string(i) + "]";
  }

  const nlohmann::json& object(const nlohmann::json& j, const std::string& where) const {
    if (!j.is_object()) fail_at(where, "must be an object");
    return j;
  }
  const nlohmann::json& array(const nlohmann::json& j, const std::string& where) const {
    if (!j.is_array()) fail_at(where, "must be an array");
    return j;
  }

  // Every key of `obj` must be in `allowed`; `for_what` (e.g. " for a box") ends the key's name
  // in the message.
  void keys(const nlohmann::json& obj, const std::string& where, const std::vector<std::string_view>& allowed,
            const std::string& for_what = "") const {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      if (std::find(allowed.begin(), allowed.end(), it.key()) != allowed.end()) continue;
      std::string list;
      for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      files::fail(label_ + ": unknown key " + files::q(join(where, it.key())) + for_what +
           " (allowed here: " + list + ")");
    }
  }

  float number(const nlohmann::json& j, const std::string& where, float lo, float hi) const {
    if (!j.is_number()) fail_at(where, "must be a number");
    const double v = j.get<double>();
    if (!std::isfinite(v) || std::abs(v) > 3.0e38) fail_at(where, "must be a finite number");
    // Checked as the float it is stored as: 1.001 is 1.00100005 as a float, the bound 1.001f too.
    const float f = static_cast<float>(v);
    if (f < lo || f > hi)
      fail_at(where, "must be in [" + fmt(lo) + ", " + fmt(hi) + "], not " + fmt(v));
    return f;
  }
  float number(const nlohmann::json& obj, const std::string& parent, const char* key, float def, float lo,
               float hi) const {
    return obj.contains(key) ? number(obj[key], join(parent, key), lo, hi) : def;
  }
  int integer(const nlohmann::json& obj, const std::string& parent, const char* key, int def, int lo,
              int hi) const {
    if (!obj.contains(key)) return def;
    const std::string where = join(parent, key);
    if (!obj[key].is_number_integer()) fail_at(where, "must be an integer");
    const auto v = obj[key].get<long long>();
    if (v < lo || v > hi)
      fail_at(where, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return static_cast<int>(v);
  }
  glm::vec3 vec3(const nlohmann::json& j, const std::string& where, float lo = -1e7f, float hi = 1e7f) const {
    if (!j.is_array() || j.size() != 3) fail_at(where, "must be an array of 3 numbers");
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) {
      if (!j[static_cast<std::size_t>(i)].is_number())
        fail_at(where, "must be an array of 3 numbers");
      v[i] = number(j[static_cast<std::size_t>(i)], where, lo, hi);
    }
    return v;
  }
  glm::vec3 vec3(const nlohmann::json& obj, const std::string& parent, const char* key, glm::vec3 def,
                 float lo = -1e7f, float hi = 1e7f) const {
    return obj.contains(key) ? vec3(obj[key], join(parent, key), lo, hi) : def;
  }
  glm::vec3 required_vec3(const nlohmann::json& obj, const std::string& parent, const char* key) const {
    if (!obj.contains(key)) fail_at(join(parent, key), "is required");
    return vec3(obj[key], join(parent, key));
  }
  glm::vec2 vec2(const nlohmann::json& j, const std::string& where, float lo, float hi) const {
    if (!j.is_array() || j.size() != 2) fail_at(where, "must be an array of 2 numbers");
    glm::vec2 v;
    for (int i = 0; i < 2; ++i) {
      if (!j[static_cast<std::size_t>(i)].is_number())
        fail_at(where, "must be an array of 2 numbers");
      v[i] = number(j[static_cast<std::size_t>(i)], where, lo, hi);
    }
    return v;
  }
  // Free text ("description"): any string, empty included.
  std::string text(const nlohmann::json& j, const std::string& where) const {
    if (!j.is_string()) fail_at(where, "must be a string");
    return j.get<std::string>();
  }
  std::string string(const nlohmann::json& j, const std::string& where) const {
    std::string s = text(j, where);
    if (s.empty()) fail_at(where, "must not be empty");
    return s;
  }
  std::string one_of(const nlohmann::json& j, const std::string& where, const std::vector<std::string>& names) const {
    const std::string s = string(j, where);
    if (std::find(names.begin(), names.end(), s) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      fail_at(where, "must be one of " + list + ", not " + files::q(s));
    }
    return s;
  }
  std::string string(const nlohmann::json& obj, const std::string& parent, const char* key,
                     const std::string& def) const {
    return obj.contains(key) ? string(obj[key], join(parent, key)) : def;
  }
  bool boolean(const nlohmann::json& obj, const std::string& parent, const char* key, bool def) const {
    if (!obj.contains(key)) return def;
    if (!obj[key].is_boolean()) fail_at(join(parent, key), "must be true or false");
    return obj[key].get<bool>();
  }
  // A unit vector from a non-zero one.
  glm::vec3 direction(const nlohmann::json& j, const std::string& where) const {
    const glm::vec3 v = vec3(j, where);
    const float len = glm::length(v);
    if (!(len > 1e-6f) || !std::isfinite(len)) fail_at(where, "must be a non-zero vector");
    return v / len;
  }

  static std::string fmt(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
  }

 private:
  std::filesystem::path file_;
  std::string label_;  // starts every message
};

}  // namespace ssr
