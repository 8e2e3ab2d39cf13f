// Shared by the scene loaders only; not part of the public API (that is scene_io.h).
//
//   scene_io.cpp    load_scene: built-in name, .json or .obj
//   scene_json.cpp  JSON scene files (the schema is at its top)
//   obj_loader.cpp  OBJ files: pre-scan, tinyobjloader, validation, meshes; scene defaults
//   mtl_loader.cpp  MTL files, textures, reading files, keeping paths inside a root directory
//
// Every error is an InputError of one sentence naming the file (see fail()).
#pragma once
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <glm/glm.hpp>

#include "core/errors.h"
#include "core/files.h"
#include "scene/scene.h"

namespace ssr::scene_io_detail {

namespace fs = std::filesystem;

constexpr std::size_t kMaxTriangles = 50'000'000;  // per file and per scene

// ---- errors ---------------------------------------------------------------------------------

// One-sentence errors, quoting and file reading live in core/files.h (presets use them too).
using files::fail;
using files::q;
using files::read_file;
using files::read_text_file;

// ---- files and paths (mtl_loader.cpp) -------------------------------------------------------


// Resolves `rel` (as written in a file) against `base` and checks that it stays inside `root`.
fs::path resolve_inside(const fs::path& root, const fs::path& base, std::string rel,
                        const std::string& context, const std::string& what);

// A key naming the file itself, however the path was spelt (for caches).
std::string canonical_key(const fs::path& p);

// The directory a file's relative paths start from ("." for a bare file name).
inline fs::path directory_of(const fs::path& file) {
  return file.parent_path().empty() ? fs::path(".") : file.parent_path();
}

// ---- text scanning (OBJ and MTL) ------------------------------------------------------------

// Calls f(line_number, line) for every line; "\n", "\r\n" and "\r" all end a line (as in
// tinyobjloader's safeGetline).
template <class F>
void for_each_line(std::string_view text, F&& f) {
  std::size_t pos = 0, line_no = 0;
  while (pos < text.size()) {
    std::size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string_view::npos) end = text.size();
    f(++line_no, text.substr(pos, end - pos));
    if (end >= text.size()) break;
    pos = end + 1;
    if (text[end] == '\r' && pos < text.size() && text[pos] == '\n') ++pos;
  }
}

inline bool is_space(char c) { return c == ' ' || c == '\t'; }

// Splits on spaces and tabs.
inline void tokenize(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    while (j < line.size() && !is_space(line[j])) ++j;
    out.push_back(line.substr(i, j - i));
    i = j;
  }
}

// A finite float written in full (a leading '+' is allowed); nullopt otherwise.
inline std::optional<float> parse_float(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
  float v = 0.0f;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec == std::errc::result_out_of_range && r.ptr == s.data() + s.size()) {
    // Underflow (1e-50) reads as 0 or a denormal, as in other OBJ readers; overflow (1e39)
    // stays refused. strtod's decimal point is LC_NUMERIC's, which nothing here changes.
    const double d = std::strtod(std::string(s).c_str(), nullptr);
    if (!(std::abs(d) <= std::numeric_limits<float>::max())) return std::nullopt;
    v = static_cast<float>(d);
  } else if (r.ec != std::errc() || r.ptr != s.data() + s.size())
    return std::nullopt;
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

// An integer in int range written in full; nullopt otherwise.
inline std::optional<long long> parse_int(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
  long long v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || v > 2147483647LL || v < -2147483647LL)
    return std::nullopt;
  return v;
}

// ---- per-scene caches and textures ---------------------------------------------------------

// State shared by all the OBJ files of one scene: caches and the running triangle count.
struct LoadContext {
  std::map<std::string, int> images;     // canonical path -> Scene::images index
  std::map<std::string, int> materials;  // canonical MTL path + '\n' + name -> material
  std::size_t triangles = 0;
};

// Loads a texture once per scene (cached by canonical path); returns its Scene::images index.
// Defined in mtl_loader.cpp.
int add_image(Scene& scene, LoadContext& ctx, const fs::path& path, const std::string& context);

// ---- MTL (mtl_loader.cpp) -------------------------------------------------------------------

struct MtlTexture {
  std::string file;  // as written
  std::size_t line = 0;
  float bump_multiplier = 1.0f;
  bool empty() const { return file.empty(); }
};

struct MtlMaterial {
  std::string name;
  fs::path mtl_file;
  std::size_t line = 0;
  glm::vec3 kd{0.8f};
  glm::vec3 ke{0.0f};
  bool has_kd = false;
  std::optional<float> ns, ni, pr, pm;
  MtlTexture map_kd, norm, bump;
};

// Parses one MTL file, appending its materials to `out` (names must be unique across `out`).
void parse_mtl(const fs::path& path, std::vector<MtlMaterial>& out, const std::string& context);

// Turns a parsed MTL material into a scene Material (once per scene); returns its index.
// Textures must stay inside `root`.
int add_mtl_material(Scene& scene, LoadContext& ctx, const MtlMaterial& mm, const fs::path& root);

// ---- OBJ and scene defaults (obj_loader.cpp) ------------------------------------------------

// append_obj with the scene's caches; MTL files and textures must stay inside `root`.
int append_obj_impl(Scene& scene, LoadContext& ctx, const fs::path& path, const fs::path& root,
                    const glm::mat4& transform, int material_override);

// The material named "default", added (grey, roughness 0.5) when the scene has none.
int default_material(Scene& scene);

// A camera framing the bounds of every mesh (for files without cameras).
Camera framing_camera(const Scene& s);

// validate(s), naming `file` in the message.
void validate_file(const Scene& s, const fs::path& file);

}  // namespace ssr::scene_io_detail
