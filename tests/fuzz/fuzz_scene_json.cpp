// libFuzzer target: a JSON scene file through load_scene_json (parsing, schema, transforms,
// primitives, reflectors, lights, cameras, the OBJs it places, validate).
//
// Input: scene.json, then optionally "\n@@@@\n" + m.obj and "\n@@@@\n" + m.mtl, so the scene
// can place "m.obj" (which can name "mtllib m.mtl"). ssr::InputError is the expected way to
// reject an input; anything else is a finding (see fuzz_obj.cpp).
#include <cstddef>
#include <cstdint>

#include "core/errors.h"
#include "fuzz_common.h"
#include "scene/scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parts = fuzz::split({reinterpret_cast<const char*>(data), size}, 3);
  const fuzz::fs::path& dir = fuzz::scratch_dir();
  fuzz::write_file(dir / "scene.json", parts[0]);
  fuzz::write_file(dir / "m.obj", parts[1]);
  fuzz::write_file(dir / "m.mtl", parts[2]);
  ssr::Scene s;
  try {
    s = ssr::load_scene_json(dir / "scene.json");
  } catch (const ssr::InputError&) {
    return 0;
  }
  fuzz::require_valid(s);
  return 0;
}
