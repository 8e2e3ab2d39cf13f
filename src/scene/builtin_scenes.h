// Procedural scenes written by the project (no asset files needed).
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

namespace ssr {

struct BuiltinSceneInfo {
  std::string name;
  std::string description;  // one line for `ssrlab scenes`
  // The options it takes ("name:key=value,..."), for pickers: each key with its default and
  // the values to offer (every choice; for numbers the range's ends and a few between).
  struct Option {
    std::string key, default_value;
    std::vector<std::string> values;
  };
  std::vector<Option> options = {};
};

// Every built-in scene, the default (`gallery`) first.
const std::vector<BuiltinSceneInfo>& builtin_scenes();

// Builds the named scene; throws InputError naming the known scenes when there is none.
Scene make_builtin_scene(const std::string& name);

}  // namespace ssr
