// libFuzzer target: a bare OBJ with its MTL, through load_scene_obj (scan, tinyobjloader,
// index checks, MTL parsing, textures, validate) and append_obj with a mirroring transform.
//
// Input: OBJ text, then optionally "\n@@@@\n" and the text of m.mtl (the OBJ names it with
// "mtllib m.mtl"). ssr::InputError is the expected way to reject an input; any other exception
// (uncaught: abort), crash, sanitizer report, timeout or out-of-memory is a finding.
#include <cstddef>
#include <cstdint>

#include "core/errors.h"
#include "fuzz_common.h"
#include "scene/scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parts = fuzz::split({reinterpret_cast<const char*>(data), size}, 2);
  const fuzz::fs::path& dir = fuzz::scratch_dir();
  const fuzz::fs::path obj = dir / "m.obj";
  fuzz::write_file(obj, parts[0]);
  fuzz::write_file(dir / "m.mtl", parts[1]);
  ssr::Scene s;
  try {
    s = ssr::load_scene_obj(obj);
  } catch (const ssr::InputError&) {
    return 0;
  }
  // A mirrored copy takes the winding-flip path and the material override, which a JSON scene
  // (positive scales only) cannot reach. It may be rejected (e.g. moved beyond 1e7 units).
  try {
    ssr::append_obj(s, obj, glm::mat4(glm::vec4(-1, 0, 0, 0), glm::vec4(0, 1, 0, 0),
                                      glm::vec4(0, 0, 1, 0), glm::vec4(5, 0, 0, 1)),
                    0);
  } catch (const ssr::InputError&) {
  }
  fuzz::require_valid(s);
  return 0;
}
