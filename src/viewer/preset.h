// Viewer presets: the viewer's state as a JSON file, to come back to a view or share it.
//
// ---- format (version 1) ---------------------------------------------------------------------
// One object. Only "version" is required; unknown keys, wrong types, duplicate keys and
// out-of-range numbers are errors; // and /* */ comments are allowed. Lights, environment and
// camera use the keys of scene files (assets/scenes/README.md, src/scene/scene_json.cpp).
//
//   "version": 1                          this format (required)
//   "scene": "gallery"                    as --scene: a built-in name or a scene file path
//   "camera": {"name": "overview"}        a camera of the scene by name, or a pose written as a
//             {"name", "position", "target", "up", "fov_y", "near", "far"}   scene file's
//                                         "cameras" entry (the name then says where it came from)
//   "technique_a": {"name": "linear", "params": {"max_steps": 64, "depth_interp": true}}
//   "technique_b": {"name": "none", "params": {}}
//   "truth": {"name": "reference", "params": {"samples": 4}}   the grid's truth (its name is the
//                                         registry's truth technique's; written once it exists;
//                                         left out: its defaults)
//       params: parameter names without the technique prefix; numbers, true/false or a
//       choice's name, checked as --set checks them; names left out take their defaults
//   "compare": "off"                      a compare mode (commands.h: off, split, diff, grid)
//   "split": 0.5                          divider position in [0, 1]
//   "diff_scale": 0.25                    heat map full scale in [0.01, 1]
//   "view": "final"                       a --view name, or "traceable" (viewer_view_names)
//   "exposure": 0                         stops, in [-20, 20]
//   "reflective_f0": 0.1                  pixels whose max F0 reaches this do reflection work
//                                         (the frame settings' table: [0.001, 1])
//   "lights": [...]                       replace the scene's lights (at most Scene::kMaxLights)
//   "environment": {...}                  replaces the scene's environment
//   "ambient": 0.3                        replaces the scene's ambient, >= 0
//
// Keys left out take the defaults of ViewerPreset below; lights, environment, ambient and
// camera left out mean "as the scene has them", scene left out means "the current scene".
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "techniques/technique.h"
#include "techniques/assignments.h"

namespace ssr {

inline constexpr int kViewerPresetVersion = 1;

// The renderer's views (view_mode_names), then the viewer's own "traceable": the reference's
// per-pixel classes (traceable / missing / sky), computed on demand.
const std::vector<std::string>& viewer_view_names();

struct ViewerPreset {
  std::string scene;                  // "" = the current scene
  std::string camera_name;            // the scene camera (or where `camera` came from)
  std::optional<Camera> camera;       // a pose (its name: camera_name); none = the scene's
                                      // camera `camera_name`
  std::string technique_a = "linear", technique_b = "none";
  std::vector<std::string> params_a, params_b;  // "name=value", no technique prefix
  std::optional<std::vector<std::string>> params_truth;  // the grid's truth, when it has one
  std::string compare = "off";        // kCompareModes' names
  float split = 0.5f, diff_scale = 0.25f;
  std::string view = "final";
  float exposure = 0.0f;
  float reflective_f0 = FrameSettings{}.reflective_f0;
  std::optional<std::vector<Light>> lights;
  std::optional<Environment> environment;
  std::optional<float> ambient;
};

// Every parameter of `technique` as "name=value" (no prefix) in table order; floats in the
// shortest form that reads back as the same value.
std::vector<std::string> capture_params(Technique& technique);

// Defaults, then `params` ("name=value", no prefix), each checked as --set checks it
// (apply_assignments). Throws InputError on an unknown name or a bad value, leaving
// `technique` unchanged.
void apply_params(Technique& technique, const std::vector<std::string>& params);

std::string preset_to_json_text(const ViewerPreset& preset);

// Parses and checks everything (technique names and parameters included); throws InputError of
// one sentence starting with `where` (e.g. "viewer preset 'p.json'") and naming the key.
ViewerPreset preset_from_json_text(const std::string& text, const std::string& where);

// Writes atomically (temporary file + rename: an existing file survives a failure). A preset
// that would not load back throws InputError and writes nothing; a write failure RuntimeError.
void save_preset(const std::filesystem::path& path, const ViewerPreset& preset);

// Missing, unreadable, oversized or invalid files throw InputError.
ViewerPreset load_preset(const std::filesystem::path& path);

}  // namespace ssr
