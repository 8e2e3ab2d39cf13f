// load_scene: picks the loader for "--scene S". The loaders themselves are in scene_json.cpp,
// obj_loader.cpp and mtl_loader.cpp (scene_io_internal.h lists what they share).
#include "scene/scene_io.h"

#include <cctype>
#include <string_view>

#include "scene/builtin_scenes.h"
#include "scene/scene_io_internal.h"

namespace ssr {

using namespace scene_io_detail;

namespace {

bool ends_with_ci(const std::string& s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i])
      return false;
  return true;
}

std::string builtin_names() {
  std::string list;
  for (const BuiltinSceneInfo& b : builtin_scenes()) list += (list.empty() ? "" : ", ") + b.name;
  return list;
}

}  // namespace

Scene load_scene(const std::string& name_or_path) {
  // A built-in name, or one with options ("gallery:reflectors=4"): the part before ':' names a
  // built-in scene and no file of that exact name exists (files keep their behaviour).
  const std::string base = name_or_path.substr(0, name_or_path.find(':'));
  const fs::path p(name_or_path);
  for (const BuiltinSceneInfo& b : builtin_scenes()) {
    std::error_code ec;
    if (b.name == base && (base == name_or_path || !fs::exists(p, ec))) {
      Scene s = make_builtin_scene(name_or_path);
      validate(s);
      return s;
    }
  }
  const bool is_json = ends_with_ci(name_or_path, ".json"),
             is_obj = ends_with_ci(name_or_path, ".obj");
  if (is_json || is_obj) {
    std::error_code ec;
    if (!fs::exists(p, ec)) fail("scene file " + q(p) + " does not exist");
    return is_json ? load_scene_json(p) : load_scene_obj(p);
  }
  std::error_code ec;
  if (fs::exists(p, ec))
    fail("scene file " + q(p) +
         " is neither a .json nor an .obj file (built-in scenes: " + builtin_names() + ")");
  fail("unknown scene " + q(name_or_path) + ": give a built-in name (" + builtin_names() +
       ") or a .json or .obj file");
}

}  // namespace ssr
