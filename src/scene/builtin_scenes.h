// Procedural scenes written by the project (no asset files needed).
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

namespace ssr {

struct BuiltinSceneInfo {
  std::string name;
  std::string description;  // one line for `ssrlab scenes`
};

// Every built-in scene, the default (`gallery`) first.
const std::vector<BuiltinSceneInfo>& builtin_scenes();

// Builds the named scene; throws InputError naming the known scenes when there is none.
Scene make_builtin_scene(const std::string& name);

}  // namespace ssr
