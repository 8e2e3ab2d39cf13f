#include "viewer/preset.h"

#include "core/json_reader.h"
#include "viewer/commands.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/cli_common.h"
#include "core/errors.h"
#include "eval/results.h"
#include "render/renderer.h"
#include "core/files.h"
#include "scene/scene_json.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

namespace ssr {

const std::vector<std::string>& viewer_view_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = view_mode_names();
    n.push_back("traceable");
    return n;
  }();
  return names;
}

namespace {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;
using files::fail;
using files::q;

constexpr std::uintmax_t kMaxPresetBytes = 1u << 20;

// A captured value as JSON, typed as param_value_json types it (number, true/false, or a
// choice's name as a string).
ojson value_json(const std::string& text) {
  if (text == "true" || text == "false") return text == "true";
  const char* first = text.data();
  const char* last = first + text.size();
  long long i = 0;
  if (auto r = std::from_chars(first, last, i); r.ec == std::errc() && r.ptr == last) return i;
  double d = 0;
  if (auto r = std::from_chars(first, last, d); r.ec == std::errc() && r.ptr == last) return d;
  return text;
}

// {"name": ..., "params": {...}} -> name and "name=value" list, checked on a fresh instance.
void read_technique(const JsonReader& r, const json& j, const std::string& key, std::string& name,
                    std::vector<std::string>& params) {
  r.object(j, key);
  r.keys(j, key, {"name", "params"});
  if (!j.contains("name")) r.fail_at(key + ".name", "is required");
  std::vector<std::string> names;
  for (const TechniqueInfo& t : technique_registry()) names.push_back(t.name);
  name = r.one_of(j["name"], key + ".name", names);
  params.clear();
  if (j.contains("params")) {
    const json& p = r.object(j["params"], key + ".params");
    for (auto it = p.begin(); it != p.end(); ++it) {
      const json& v = it.value();
      const std::string k = key + ".params." + it.key();
      std::string text;
      if (v.is_boolean()) text = v.get<bool>() ? "true" : "false";
      else if (v.is_number()) text = v.dump();  // the shortest exact form, as written
      else if (v.is_string()) text = v.get<std::string>();
      else r.fail_at(k, "must be a number, true/false or a choice's name");
      params.push_back(it.key() + "=" + text);
    }
  }
  const auto technique = create_technique(name);
  try {
    apply_params(*technique, params);
  } catch (const InputError& e) {
    fail(r.label() + ": " + q(key + ".params") + ": " + e.what());
  }
  // In table order (JSON objects are read sorted by key), as capture_params lists them.
  const ParamSet table = technique->params();
  std::stable_sort(params.begin(), params.end(), [&](const std::string& a, const std::string& b) {
    return table.find(split_assignment(a).first) < table.find(split_assignment(b).first);
  });
}

}  // namespace

std::vector<std::string> capture_params(Technique& technique) {
  const ParamSet p = technique.params();
  std::vector<std::string> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::string value = p.to_string(i);
    if (p.table()[i].type == ParamType::Float && !p.is_auto(i)) {  // to_string rounds to 6 digits
      char buf[64];
      const auto r = std::to_chars(buf, buf + sizeof buf, static_cast<float>(p.get(i)));
      value.assign(buf, r.ptr);
    }
    out.push_back(std::string(p.table()[i].name) + "=" + value);
  }
  return out;
}

void apply_params(Technique& technique, const std::vector<std::string>& params) {
  std::vector<std::string> prefixed;
  for (const std::string& a : params) {
    const std::string key = split_assignment(a).first;
    if (key.find('.') != std::string::npos)
      throw InputError("parameter name '" + key + "' must not have a technique prefix.");
    prefixed.push_back(technique.name() + "." + a);
  }
  // Checked on a fresh instance first, so that a bad value changes nothing.
  apply_assignments(*create_technique(technique.name()), prefixed);
  technique.params().reset_all();
  apply_assignments(technique, prefixed);
}

std::string preset_to_json_text(const ViewerPreset& p) {
  using scene_json::json_float;
  ojson j;
  j["version"] = kViewerPresetVersion;
  if (!p.scene.empty()) j["scene"] = p.scene;
  if (p.camera) {
    Camera c = *p.camera;
    c.name = p.camera_name;
    j["camera"] = scene_json::write_camera(c);
  } else if (!p.camera_name.empty()) {
    j["camera"] = {{"name", p.camera_name}};
  }
  auto technique = [](const std::string& name, const std::vector<std::string>& params) {
    ojson values = ojson::object();
    for (const std::string& a : params) {
      auto [k, v] = split_assignment(a);
      values[k] = value_json(v);
    }
    return ojson{{"name", name}, {"params", values}};
  };
  j["technique_a"] = technique(p.technique_a, p.params_a);
  j["technique_b"] = technique(p.technique_b, p.params_b);
  if (p.params_truth) j["truth"] = technique(truth_name(), *p.params_truth);
  j["compare"] = p.compare;
  j["split"] = json_float(p.split);
  j["diff_scale"] = json_float(p.diff_scale);
  j["view"] = p.view;
  j["exposure"] = json_float(p.exposure);
  j["reflective_f0"] = json_float(p.reflective_f0);
  if (p.lights) {
    j["lights"] = ojson::array();
    for (const Light& l : *p.lights) j["lights"].push_back(scene_json::write_light(l));
  }
  if (p.environment) j["environment"] = scene_json::write_environment(*p.environment);
  if (p.ambient) j["ambient"] = json_float(*p.ambient);
  // dump(2) puts every number of a vector on its own line: keep number arrays on one line.
  const std::string text = j.dump(2);
  static const std::regex number_array(R"(\[\s+([-+0-9.eE]+(?:,\s+[-+0-9.eE]+)*)\s+\])");
  static const std::regex separator(R"(,\s+)");
  std::string out;
  auto begin = text.cbegin();
  for (std::smatch m; std::regex_search(begin, text.cend(), m, number_array); begin = m[0].second)
    out.append(m.prefix().first, m.prefix().second)
        .append("[" + std::regex_replace(m[1].str(), separator, ", ") + "]");
  out.append(begin, text.cend());
  return out + "\n";
}

ViewerPreset preset_from_json_text(const std::string& text, const std::string& where) {
  const json j = parse_json_object(text, where);
  const JsonReader r(where);
  r.keys(j, "", {"version", "scene", "camera", "technique_a", "technique_b", "truth", "compare", "split",
                 "diff_scale", "view", "exposure", "reflective_f0", "lights", "environment", "ambient"});
  if (!j.contains("version")) r.fail_at("version", "is required");
  if (!j["version"].is_number_integer() || j["version"].get<long long>() != kViewerPresetVersion)
    r.fail_at("version", "must be " + std::to_string(kViewerPresetVersion) +
                             " (the format this ssrlab reads), not " + j["version"].dump());
  ViewerPreset p;
  if (j.contains("scene")) p.scene = r.string(j["scene"], "scene");
  if (j.contains("camera")) {
    const json& c = r.object(j["camera"], "camera");
    if (c.size() == 1 && c.contains("name")) {
      p.camera_name = r.string(c["name"], "camera.name");
    } else {
      p.camera = scene_json::read_camera(c, where, "camera", "");
      p.camera_name = p.camera->name;
    }
  }
  if (j.contains("technique_a"))
    read_technique(r, j["technique_a"], "technique_a", p.technique_a, p.params_a);
  if (j.contains("technique_b"))
    read_technique(r, j["technique_b"], "technique_b", p.technique_b, p.params_b);
  if (j.contains("truth")) {
    std::string name;
    read_technique(r, j["truth"], "truth", name, p.params_truth.emplace());
    if (name != truth_name()) r.fail_at("truth.name", "must be '" + truth_name() + "', not '" + name + "'");
  }
  if (j.contains("compare")) p.compare = r.one_of(j["compare"], "compare", compare_mode_names());
  if (j.contains("split")) p.split = r.number(j["split"], "split", 0.0f, 1.0f);
  if (j.contains("diff_scale")) p.diff_scale = r.number(j["diff_scale"], "diff_scale", 0.01f, 1.0f);
  if (j.contains("view")) p.view = r.one_of(j["view"], "view", viewer_view_names());
  FrameSettings settings;
  const ParamSet frame = frame_settings_params(settings);
  auto frame_setting = [&](const char* key, float& out) {  // in the range of the frame settings' own table
    if (!j.contains(key)) return;
    const ParamDesc& e = frame.table()[static_cast<std::size_t>(frame.find(key))];
    out = r.number(j[key], key, static_cast<float>(e.min), static_cast<float>(e.max));
  };
  frame_setting("exposure", p.exposure);
  frame_setting("reflective_f0", p.reflective_f0);
  if (j.contains("lights")) {
    const json& l = j["lights"];
    if (!l.is_array()) r.fail_at("lights", "must be an array");
    if (l.size() > static_cast<std::size_t>(Scene::kMaxLights))
      r.fail_at("lights", "has " + std::to_string(l.size()) + " lights, more than the " +
                              std::to_string(Scene::kMaxLights) + " supported");
    p.lights.emplace();
    for (std::size_t i = 0; i < l.size(); ++i)
      p.lights->push_back(scene_json::read_light(l[i], where, "lights[" + std::to_string(i) + "]"));
  }
  if (j.contains("environment"))
    p.environment = scene_json::read_environment(j["environment"], where, "environment");
  if (j.contains("ambient")) p.ambient = r.number(j["ambient"], "ambient", 0.0f, kSceneValueMax);
  return p;
}

void save_preset(const std::filesystem::path& path, const ViewerPreset& preset) {
  const std::string text = preset_to_json_text(preset);
  preset_from_json_text(text, "viewer preset " + q(path));  // never write what would not load
  write_text_file_atomic(path, text);
}

ViewerPreset load_preset(const std::filesystem::path& path) {
  return preset_from_json_text(files::read_text_file(path, kMaxPresetBytes, "viewer preset"),
                               "viewer preset " + q(path));
}

}  // namespace ssr
