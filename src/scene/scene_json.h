// Pieces of the JSON scene-file schema (scene_json.cpp) that other JSON files embed, e.g. the
// viewer's presets: a light, the environment and a camera are read, checked and written with the
// same keys and the same rules everywhere.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace ssr::scene_json {

// A JSON object as scene files are read: comments allowed; syntax errors, duplicate keys and
// anything but an object throw InputError of one sentence starting with `label`.
nlohmann::json parse(const std::string& text, const std::string& label);

// Readers. `label` starts every message (e.g. "viewer preset 'p.json'"), `where` is the key
// path of `j` (e.g. "lights[0]"); problems throw InputError of one sentence naming both.
// Missing optional keys take the scene.h defaults.
Light read_light(const nlohmann::json& j, const std::string& label, const std::string& where);
Environment read_environment(const nlohmann::json& j, const std::string& label,
                             const std::string& where);
// A "cameras" entry; `default_name` when it has no "name".
Camera read_camera(const nlohmann::json& j, const std::string& label, const std::string& where,
                   const std::string& default_name);

// Writers: what the readers take back. An environment writes only its type's colours, a
// camera its name only when it has one.
nlohmann::ordered_json write_light(const Light& light);
nlohmann::ordered_json write_environment(const Environment& env);
nlohmann::ordered_json write_camera(const Camera& camera);

// The shortest decimal that reads back as `v`, so that written files say 0.3, not
// 0.30000001192092896.
double json_float(float v);
nlohmann::ordered_json json_vec3(const glm::vec3& v);

}  // namespace ssr::scene_json
