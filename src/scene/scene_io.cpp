// Scene loading: built-in names, JSON scene files, bare OBJ (+ MTL) files.
//
// ---- JSON scene files ----------------------------------------------------------------------
// One object; every key below is optional unless marked (required). Unknown keys are an error,
// wrong types are an error, duplicate keys are an error; // and /* */ comments are allowed.
// Vectors are arrays of 3 numbers. Paths are relative to the JSON file's directory and must
// stay inside it (no absolute paths, no "..", no symlink leading out). Units as in scene.h.
//
//   "name": "pedestal",                    scene name (default: the file name without .json)
//   "description": "...",                  free text, ignored
//   "ambient": 0.3,                        >= 0, scales the environment's diffuse light
//   "environment": {"type": "sky", "zenith": v3, "horizon": v3, "ground": v3, "intensity": 1}
//               or {"type": "constant", "color": v3, "intensity": 1}
//   "materials": {"<name>": {"albedo": v3 in [0,1], "metallic": [0,1], "roughness": [0,1],
//                 "reflectance": [0,1], "emission": v3 >= 0, "albedo_texture": "x.png",
//                 "normal_texture": "n.png", "normal_strength": [0,4], "transparent": bool,
//                 "ior": [1,3]}, ...}
//       The material named "default" (grey, created if not given) is used by OBJ faces without
//       a material and by primitives without "material".
//   "meshes": [{"obj": "meshes/x.obj" (required), "material": "<name>" (replaces the MTL's),
//               "translate": v3, "rotate_deg": v3, "scale": s > 0 or v3 > 0,
//               "reflector": {"center": v3, "tangent": v3, "bitangent": v3,
//                             "half_extents": [hx, hy] > 0}}, ...]
//   "primitives": [{"type": "plane" | "box" | "sphere" | "cylinder" (required), "name": "...",
//                   plane: "size": [x, z], "uv_scale": s;  box: "extents": v3;
//                   sphere: "radius", "segments", "rings";  cylinder: "radius", "height",
//                   "segments"; "material", "translate", "rotate_deg", "scale",
//                   "reflector": true (planes: the plane's own rectangle) or an object as above
//                  }, ...]
//   "lights": [{"type": "point", "position": v3 (required), "color": v3, "intensity", "range"}
//           or {"type": "directional", "direction": v3 (required), "color": v3, "intensity"}]
//   "cameras": [{"name", "position", "target", "up", "fov_y" (degrees), "near", "far"}, ...]
//       The first camera is the default; without "cameras" one camera frames the whole scene.
//
// Transforms are M = T * Rz * Ry * Rx * S (scale first, then rotate about X, Y, Z, then
// translate). Explicit reflector rectangles are in world space (not moved by the transform);
// the normal is cross(bitangent, tangent).
//
// ---- OBJ / MTL -------------------------------------------------------------------------------
// Geometry is parsed by Debian's tinyobjloader (rc10). That version reads out of bounds on
// negative or too-large face indices and silently turns malformed numbers into 0
// (CVE-2020-28589), so every OBJ is first scanned here (numbers, index ranges, sizes) and every
// index is checked again after loading. MTL files are parsed here: Kd -> albedo (clamped to
// [0,1]), Pm -> metallic, Pr -> roughness (else r = sqrt(2 / (Ns + 2))), Ke -> emission,
// Ni -> reflectance and ior, map_Kd -> albedo texture, norm (else bump / map_bump) -> normal
// texture (-bm -> normal strength). MTL files and textures must stay inside the root directory
// (the OBJ's directory, or the JSON file's directory for OBJs placed by a scene file).
// Vertex::uv is the OBJ's vt unchanged: v grows upwards, v = 0 is the image's bottom row (the
// convention of meshgen.cpp; the renderer flips Image rows on upload).
// Missing normals (or zero-length ones) become the face normal; zero-area triangles are dropped.
#include "scene/scene_io.h"

#include <stb_image.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include "core/errors.h"
#include "scene/builtin_scenes.h"
#include "scene/meshgen.h"

namespace ssr {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr std::uintmax_t kMaxObjBytes = 1ull << 30;    // 1 GiB
constexpr std::uintmax_t kMaxMtlBytes = 64ull << 20;   // 64 MiB
constexpr std::uintmax_t kMaxJsonBytes = 16ull << 20;  // 16 MiB
constexpr std::uintmax_t kMaxImageBytes = 256ull << 20;
constexpr std::size_t kMaxTriangles = 50'000'000;   // per file and per scene
constexpr std::size_t kMaxAttributes = 50'000'000;  // each of v, vt, vn
constexpr std::size_t kMaxFaceVertices = 256;
constexpr int kMaxImageSide = 16384;
constexpr float kMaxCoord = 1e7f;  // as in validate()

// ---- errors ---------------------------------------------------------------------------------

// Throws InputError with `msg` as one sentence: no line breaks, one final full stop.
[[noreturn]] void fail(std::string msg) {
  for (char& c : msg)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  while (!msg.empty() && (msg.back() == ' ' || msg.back() == '.')) msg.pop_back();
  throw InputError(msg + ".");
}

// 'text' (built with append: GCC 12 warns wrongly about "'" + std::string at -O2, PR 105329).
std::string q(std::string_view s) {
  std::string r;
  r.reserve(s.size() + 2);
  r.append(1, '\'').append(s).append(1, '\'');
  return r;
}
std::string q(const std::string& s) { return q(std::string_view(s)); }
std::string q(const fs::path& p) { return q(std::string_view(p.native())); }

// ---- files ----------------------------------------------------------------------------------

// Reads a whole regular file of at most `cap` bytes. `what` names it ("OBJ file", ...);
// `context` prefixes the messages (e.g. "MTL file 'x' line 3: ").
std::string read_file(const fs::path& path, std::uintmax_t cap, const std::string& what,
                      const std::string& context = "") {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) fail(context + what + " " + q(path) + " does not exist");
  if (!fs::is_regular_file(st)) fail(context + what + " " + q(path) + " is not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) fail(context + what + " " + q(path) + " could not be read (" + ec.message() + ")");
  if (size > cap)
    fail(context + what + " " + q(path) + " is " + std::to_string(size) + " bytes, more than the " +
         std::to_string(cap) + " supported");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(context + what + " " + q(path) + " could not be opened");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size))
    fail(context + what + " " + q(path) + " could not be read completely");
  return text;
}

// Resolves `rel` (as written in a file) against `base` and checks that it stays inside `root`.
fs::path resolve_inside(const fs::path& root, const fs::path& base, std::string rel,
                        const std::string& context, const std::string& what) {
  std::replace(rel.begin(), rel.end(), '\\', '/');
  if (rel.empty()) fail(context + what + " path is empty");
  const fs::path r(rel);
  if (r.has_root_path())
    fail(context + what + " path " + q(rel) + " is absolute; it must be relative to " + q(base));
  const fs::path full = (base / r).lexically_normal();
  fs::path croot, cfull;
  try {
    croot = fs::weakly_canonical(fs::absolute(root));
    cfull = fs::weakly_canonical(fs::absolute(full));
  } catch (const fs::filesystem_error& e) {
    fail(context + what + " path " + q(rel) + " cannot be resolved (" + e.code().message() + ")");
  }
  const fs::path inside = cfull.lexically_relative(croot);
  if (inside.empty() || *inside.begin() == "..")
    fail(context + what + " path " + q(rel) + " escapes the directory " + q(root));
  return full;
}

// ---- text scanning --------------------------------------------------------------------------

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

bool is_space(char c) { return c == ' ' || c == '\t'; }

// Splits on spaces and tabs.
void tokenize(std::string_view line, std::vector<std::string_view>& out) {
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
std::optional<float> parse_float(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
  float v = 0.0f;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// An integer in int range written in full; nullopt otherwise.
std::optional<long long> parse_int(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
  long long v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || v > 2147483647LL || v < -2147483647LL)
    return std::nullopt;
  return v;
}

// ---- images ---------------------------------------------------------------------------------

Image load_image(const fs::path& path, const std::string& context) {
  const std::string bytes = read_file(path, kMaxImageBytes, "texture file", context);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int len = static_cast<int>(bytes.size());
  int w = 0, h = 0, comp = 0;
  if (!stbi_info_from_memory(data, len, &w, &h, &comp))
    fail(context + "texture file " + q(path) + " is not a readable image (" +
         (stbi_failure_reason() ? stbi_failure_reason() : "unknown format") + ")");
  if (w <= 0 || h <= 0 || w > kMaxImageSide || h > kMaxImageSide)
    fail(context + "texture file " + q(path) + " is " + std::to_string(w) + "x" +
         std::to_string(h) + "; sides must be in [1, " + std::to_string(kMaxImageSide) + "]");
  stbi_uc* pixels = stbi_load_from_memory(data, len, &w, &h, &comp, 4);
  if (!pixels)
    fail(context + "texture file " + q(path) + " could not be decoded (" +
         (stbi_failure_reason() ? stbi_failure_reason() : "unknown error") + ")");
  Image im;
  im.width = w;
  im.height = h;
  im.rgba.assign(pixels, pixels + static_cast<std::size_t>(w) * h * 4);
  stbi_image_free(pixels);
  return im;
}

// ---- load context ---------------------------------------------------------------------------

// State shared by all the OBJ files of one scene: caches and the running triangle count.
struct LoadContext {
  std::map<std::string, int> images;     // canonical path -> Scene::images index
  std::map<std::string, int> materials;  // canonical MTL path + '\n' + name -> material
  std::size_t triangles = 0;
};

std::string canonical_key(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(fs::absolute(p), ec);
  return (ec ? p.lexically_normal() : c).string();
}

int add_image(Scene& scene, LoadContext& ctx, const fs::path& path, const std::string& context) {
  const std::string key = canonical_key(path);
  if (auto it = ctx.images.find(key); it != ctx.images.end()) return it->second;
  scene.images.push_back(load_image(path, context));
  const int index = static_cast<int>(scene.images.size()) - 1;
  ctx.images.emplace(key, index);
  return index;
}

// The material named "default", added (grey, roughness 0.5) when the scene has none.
int default_material(Scene& scene) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == "default") return static_cast<int>(i);
  Material m;
  m.name = "default";
  scene.materials.push_back(m);
  return static_cast<int>(scene.materials.size()) - 1;
}

// ---- MTL ------------------------------------------------------------------------------------

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

// Parses one MTL file (our own parser: tinyobjloader rc10 silently reads garbage as 0).
void parse_mtl(const fs::path& path, std::vector<MtlMaterial>& out, const std::string& context) {
  const std::string text = read_file(path, kMaxMtlBytes, "MTL file", context);
  if (text.find('\0') != std::string::npos)
    fail("MTL file " + q(path) + " contains a NUL byte (is it a binary file?)");
  std::vector<std::string_view> tok;
  MtlMaterial* cur = nullptr;
  for_each_line(text, [&](std::size_t line_no, std::string_view line) {
    tokenize(line, tok);
    if (tok.empty() || tok[0][0] == '#') return;
    auto where = [&] { return "MTL file " + q(path) + " line " + std::to_string(line_no) + ": "; };
    const std::string_view key = tok[0];
    // Arguments up to a trailing comment.
    std::vector<std::string_view> args;
    for (std::size_t i = 1; i < tok.size() && tok[i][0] != '#'; ++i) args.push_back(tok[i]);

    auto number = [&](std::string_view s) {
      const auto v = parse_float(s);
      if (!v) fail(where() + q(key) + " has a malformed or non-finite number " + q(s));
      return *v;
    };
    auto scalar = [&]() {
      if (args.size() != 1) fail(where() + q(key) + " needs exactly one number");
      return number(args[0]);
    };
    auto colour = [&]() {
      if (!args.empty() && (args[0] == "spectral" || args[0] == "xyz"))
        fail(where() + q(std::string(key) + " " + std::string(args[0])) +
             " colours are not supported; use r g b");
      if (args.size() != 1 && args.size() != 3) fail(where() + q(key) + " needs 1 or 3 numbers");
      const float r = number(args[0]);
      return args.size() == 1 ? glm::vec3(r) : glm::vec3(r, number(args[1]), number(args[2]));
    };
    auto texture = [&]() {
      MtlTexture t;
      t.line = line_no;
      std::size_t i = 1;
      auto numbers = [&](std::size_t min_n, std::size_t max_n, const std::string& opt) {
        std::size_t n = 0;
        float first = 0.0f;
        while (n < max_n && i < tok.size() && parse_float(tok[i])) {
          if (n == 0) first = *parse_float(tok[i]);
          ++n, ++i;
        }
        if (n < min_n) fail(where() + "texture option '" + opt + "' needs a number");
        return first;
      };
      while (i < tok.size() && tok[i].size() > 1 && tok[i][0] == '-') {
        const std::string opt(tok[i++]);
        if (opt == "-blendu" || opt == "-blendv" || opt == "-clamp") {
          if (i >= tok.size() || (tok[i] != "on" && tok[i] != "off"))
            fail(where() + "texture option '" + opt + "' needs 'on' or 'off'");
          ++i;
        } else if (opt == "-boost" || opt == "-texres") {
          numbers(1, 1, opt);
        } else if (opt == "-bm") {
          t.bump_multiplier = numbers(1, 1, opt);
        } else if (opt == "-mm") {
          numbers(1, 2, opt);
        } else if (opt == "-o" || opt == "-s" || opt == "-t") {
          numbers(1, 3, opt);
        } else if (opt == "-type" || opt == "-imfchan" || opt == "-colorspace") {
          if (i >= tok.size()) fail(where() + "texture option '" + opt + "' needs a value");
          ++i;
        } else {
          fail(where() + "unknown texture option " + q(opt));
        }
      }
      if (i >= tok.size()) fail(where() + q(key) + " needs a file name");
      // The file name runs to the end of the line (it may contain spaces).
      std::string_view rest = line.substr(static_cast<std::size_t>(tok[i].data() - line.data()));
      while (!rest.empty() && is_space(rest.back())) rest.remove_suffix(1);
      t.file = std::string(rest);
      return t;
    };

    if (key == "newmtl") {
      std::string_view name = line.substr(static_cast<std::size_t>(key.data() - line.data()) + 6);
      while (!name.empty() && is_space(name.front())) name.remove_prefix(1);
      while (!name.empty() && is_space(name.back())) name.remove_suffix(1);
      if (name.empty()) fail(where() + "'newmtl' needs a material name");
      for (const MtlMaterial& m : out)
        if (m.name == name)
          fail(where() + "material " + q(name) + " is defined twice (first in " + q(m.mtl_file) +
               " line " + std::to_string(m.line) + ")");
      out.push_back(MtlMaterial{});
      cur = &out.back();
      cur->name = std::string(name);
      cur->mtl_file = path;
      cur->line = line_no;
      return;
    }
    static const std::set<std::string_view> kKnown = {
        "Ka",     "Kd",    "Ks",        "Ke",     "Kt",   "Tf",   "Ns",       "Ni",
        "d",      "Tr",    "Pr",        "Pm",     "Ps",   "Pc",   "Pcr",      "aniso",
        "anisor", "illum", "sharpness", "map_Kd", "norm", "bump", "map_bump", "map_Bump"};
    if (!kKnown.count(key)) return;  // other statements (map_Ks, refl, ...) are not used
    if (!cur) fail(where() + q(key) + " comes before any 'newmtl'");
    if (key == "Kd") {
      cur->kd = colour();
      cur->has_kd = true;
    } else if (key == "Ke") {
      cur->ke = colour();
    } else if (key == "Ka" || key == "Ks" || key == "Kt" || key == "Tf") {
      colour();  // checked, not used
    } else if (key == "Ns") {
      cur->ns = scalar();
    } else if (key == "Ni") {
      cur->ni = scalar();
    } else if (key == "Pr") {
      cur->pr = scalar();
    } else if (key == "Pm") {
      cur->pm = scalar();
    } else if (key == "d") {
      if (!args.empty() && args[0] == "-halo") args.erase(args.begin());
      scalar();
    } else if (key == "illum") {
      if (args.size() != 1 || !parse_int(args[0])) fail(where() + "'illum' needs one integer");
    } else if (key == "map_Kd") {
      cur->map_kd = texture();
    } else if (key == "norm") {
      cur->norm = texture();
    } else if (key == "bump" || key == "map_bump" || key == "map_Bump") {
      cur->bump = texture();
    } else {
      scalar();  // Tr, Ps, Pc, Pcr, aniso, anisor, sharpness: checked, not used
    }
  });
}

// Turns a parsed MTL material into a scene Material (textures loaded, values clamped).
int add_mtl_material(Scene& scene, LoadContext& ctx, const MtlMaterial& mm, const fs::path& root) {
  const std::string key = canonical_key(mm.mtl_file) + "\n" + mm.name;
  if (auto it = ctx.materials.find(key); it != ctx.materials.end()) return it->second;
  Material m;
  m.name = mm.name;
  const fs::path base = mm.mtl_file.parent_path();
  auto texture = [&](const MtlTexture& t) {
    const std::string context =
        "MTL file " + q(mm.mtl_file) + " line " + std::to_string(t.line) + ": ";
    const fs::path p = resolve_inside(root, base, t.file, context, "texture");
    return add_image(scene, ctx, p, context);
  };
  m.albedo = glm::clamp(mm.has_kd ? mm.kd : (mm.map_kd.empty() ? glm::vec3(0.8f) : glm::vec3(1.0f)),
                        0.0f, 1.0f);
  m.emission = glm::max(mm.ke, glm::vec3(0.0f));
  m.metallic = std::clamp(mm.pm.value_or(0.0f), 0.0f, 1.0f);
  if (mm.pr) {
    m.roughness = std::clamp(*mm.pr, 0.0f, 1.0f);
  } else if (mm.ns) {
    const float ns = std::max(*mm.ns, 0.0f);
    m.roughness = std::clamp(std::sqrt(2.0f / (ns + 2.0f)), 0.0f, 1.0f);
  }
  if (mm.ni && *mm.ni >= 1.0f) {
    const float n = std::min(*mm.ni, 3.0f);
    const float f0 = (n - 1.0f) * (n - 1.0f) / ((n + 1.0f) * (n + 1.0f));
    m.reflectance = std::clamp(std::sqrt(f0 / 0.16f), 0.0f, 1.0f);
    m.ior = n;
  }
  if (!mm.map_kd.empty()) m.albedo_texture = texture(mm.map_kd);
  const MtlTexture& normal = mm.norm.empty() ? mm.bump : mm.norm;
  if (!normal.empty()) {
    m.normal_texture = texture(normal);
    m.normal_strength = std::clamp(normal.bump_multiplier, 0.0f, 4.0f);
  }
  scene.materials.push_back(m);
  const int index = static_cast<int>(scene.materials.size()) - 1;
  ctx.materials.emplace(key, index);
  return index;
}

// Hands our pre-parsed MTL materials to tinyobjloader, which only needs their names and ids.
class PreparsedMaterials : public tinyobj::MaterialReader {
 public:
  explicit PreparsedMaterials(const std::vector<MtlMaterial>& mats) : mats_(mats) {}
  bool operator()(const std::string&, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* map, std::string*, std::string*) override {
    if (done_) return true;
    done_ = true;
    for (const MtlMaterial& m : mats_) {
      tinyobj::material_t t{};
      t.name = m.name;
      map->emplace(m.name, static_cast<int>(materials->size()));
      materials->push_back(t);
    }
    return true;
  }

 private:
  const std::vector<MtlMaterial>& mats_;
  bool done_ = false;
};

// ---- OBJ ------------------------------------------------------------------------------------

struct ObjScan {
  std::size_t nv = 0, nvt = 0, nvn = 0, triangles = 0, faces = 0;
  std::vector<std::pair<std::string, std::size_t>> mtllibs;  // file name, line
};

// Checks everything tinyobjloader rc10 does not: numbers, index ranges (relative indices
// before the first element, absolute ones past the end), sizes. Line numbers in messages.
ObjScan scan_obj(const fs::path& path, std::string_view text) {
  ObjScan s;
  struct Deferred {  // the largest absolute index of a kind, checked at the end
    long long index = 0;
    std::size_t line = 0;
  } max_v, max_vt, max_vn;
  std::vector<std::string_view> tok;
  for_each_line(text, [&](std::size_t line_no, std::string_view line) {
    tokenize(line, tok);
    if (tok.empty() || tok[0][0] == '#') return;
    auto where = [&] { return "OBJ file " + q(path) + " line " + std::to_string(line_no) + ": "; };
    const std::string_view key = tok[0];
    auto numbers = [&](std::size_t min_n, std::size_t max_n, const char* what) {
      std::size_t n = 0;
      for (std::size_t i = 1; i < tok.size() && tok[i][0] != '#'; ++i, ++n)
        if (!parse_float(tok[i]))
          fail(where() + what + " has a malformed or non-finite number " + q(tok[i]));
      if (n < min_n || n > max_n)
        fail(where() + what + " needs " + std::to_string(min_n) +
             (min_n == max_n ? "" : " to " + std::to_string(max_n)) + " numbers, not " +
             std::to_string(n));
    };
    auto check_count = [&](std::size_t n, const char* what) {
      if (n > kMaxAttributes)
        fail("OBJ file " + q(path) + " has more than " + std::to_string(kMaxAttributes) + " " +
             what + ", more than supported");
    };
    if (key == "v") {
      numbers(3, 7, "vertex");
      check_count(++s.nv, "vertices");
    } else if (key == "vt") {
      numbers(1, 3, "texture coordinate");
      check_count(++s.nvt, "texture coordinates");
    } else if (key == "vn") {
      numbers(3, 3, "normal");
      check_count(++s.nvn, "normals");
    } else if (key == "f" || key == "l" || key == "p") {
      const char* what = key == "f" ? "face" : key == "l" ? "line" : "point";
      const std::size_t n = tok.size() - 1;
      if (key == "f" && n < 3)
        fail(where() + "a face needs at least 3 vertices, not " + std::to_string(n));
      if (n < 1) fail(where() + std::string(what) + " has no vertices");
      if (n > kMaxFaceVertices)
        fail(where() + std::string(what) + " has " + std::to_string(n) +
             " vertices, more than the " + std::to_string(kMaxFaceVertices) + " supported");
      for (std::size_t i = 1; i < tok.size(); ++i) {
        // i, i/j, i//k, i/j/k
        std::string_view parts[3];
        std::size_t nparts = 0;
        std::string_view t = tok[i];
        while (true) {
          const std::size_t slash = t.find('/');
          if (nparts == 3)
            fail(where() + std::string(what) + " vertex " + q(tok[i]) + " has more than 3 indices");
          parts[nparts++] = t.substr(0, slash);
          if (slash == std::string_view::npos) break;
          t.remove_prefix(slash + 1);
        }
        if (nparts == 2 && parts[1].empty())
          fail(where() + std::string(what) + " vertex " + q(tok[i]) + " is malformed");
        struct Kind {
          const char* name;
          const char* plural;
          std::size_t count;
          Deferred* max;
        } kinds[3] = {{"vertex", "vertices", s.nv, &max_v},
                      {"texture coordinate", "texture coordinates", s.nvt, &max_vt},
                      {"normal", "normals", s.nvn, &max_vn}};
        for (std::size_t k = 0; k < nparts; ++k) {
          if (k == 1 && parts[k].empty() && nparts == 3) continue;  // i//k
          const auto idx = parse_int(parts[k]);
          if (!idx)
            fail(where() + std::string(what) + " has a malformed " + kinds[k].name + " index " +
                 q(parts[k]) + (parts[k] == tok[i] ? std::string() : " in " + q(tok[i])));
          if (*idx == 0)
            fail(where() + std::string(what) + " has " + kinds[k].name +
                 " index 0 (OBJ indices start at 1)");
          if (*idx < 0 && static_cast<std::size_t>(-*idx) > kinds[k].count)
            fail(where() + std::string(what) + " has relative " + kinds[k].name + " index " +
                 std::to_string(*idx) + " but only " + std::to_string(kinds[k].count) + " " +
                 (kinds[k].count == 1 ? std::string(kinds[k].name) + " precedes it"
                                      : std::string(kinds[k].plural) + " precede it"));
          if (*idx > kinds[k].max->index) *kinds[k].max = Deferred{*idx, line_no};
        }
      }
      if (key == "f") {
        ++s.faces;
        s.triangles += n - 2;
        if (s.triangles > kMaxTriangles)
          fail("OBJ file " + q(path) + " has more than " + std::to_string(kMaxTriangles) +
               " triangles, more than supported");
      }
    } else if (key == "mtllib") {
      // Names separated by spaces; "\ " is a space inside a name (as in tinyobjloader).
      std::string_view rest = line.substr(static_cast<std::size_t>(key.data() - line.data()) + 6);
      std::string name;
      auto flush = [&] {
        if (!name.empty()) s.mtllibs.emplace_back(name, line_no);
        name.clear();
      };
      for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == '\\' && i + 1 < rest.size() && rest[i + 1] == ' ') {
          name += ' ';
          ++i;
        } else if (is_space(rest[i])) {
          flush();
        } else {
          name += rest[i];
        }
      }
      flush();
    } else if (key == "t" || key == "vw") {
      fail(where() + "the tinyobjloader extension " + q(key) + " is not supported");
    }
  });
  const Deferred* maxes[3] = {&max_v, &max_vt, &max_vn};
  const std::size_t counts[3] = {s.nv, s.nvt, s.nvn};
  const char* names[3][2] = {
      {"vertex", "vertices"}, {"texture coordinate", "texture coordinates"}, {"normal", "normals"}};
  for (int k = 0; k < 3; ++k)
    if (maxes[k]->index > 0 && static_cast<std::size_t>(maxes[k]->index) > counts[k])
      fail("OBJ file " + q(path) + " line " + std::to_string(maxes[k]->line) + ": " + names[k][0] +
           " index " + std::to_string(maxes[k]->index) + " is past the end (the file has " +
           std::to_string(counts[k]) + " " + names[k][counts[k] == 1 ? 0 : 1] + ")");
  return s;
}

// A streambuf reading a string in place (tinyobjloader wants an istream).
struct MemoryBuffer : std::streambuf {
  MemoryBuffer(const char* begin, std::size_t size) {
    char* b = const_cast<char*>(begin);
    setg(b, b, b + size);
  }
};

struct CornerKey {
  int v, vt, vn;
  bool operator==(const CornerKey&) const = default;
};
struct CornerHash {
  std::size_t operator()(const CornerKey& k) const {
    std::uint64_t h = static_cast<std::uint32_t>(k.v);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.vt);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.vn);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

// Any unit vector perpendicular to the unit vector n.
glm::vec3 perpendicular(const glm::vec3& n) {
  const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(a, n));
}

// Keeps what compute_tangents produced where it is a unit tangent orthogonal to the normal;
// repairs anything else (no uvs, degenerate uvs) so no NaN reaches the renderer.
void fix_tangents(Mesh& mesh) {
  for (Vertex& v : mesh.vertices) {
    glm::vec3 t(v.tangent);
    const float w = v.tangent.w < 0.0f ? -1.0f : 1.0f;
    const bool ok = std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) &&
                    std::abs(glm::length(t) - 1.0f) < 1e-3f &&
                    std::abs(glm::dot(t, v.normal)) < 1e-3f && std::abs(v.tangent.w) == 1.0f;
    if (ok) continue;
    if (std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) {
      t -= v.normal * glm::dot(v.normal, t);
      const float len = glm::length(t);
      t = len > 1e-6f && std::isfinite(len) ? t / len : perpendicular(v.normal);
    } else {
      t = perpendicular(v.normal);
    }
    v.tangent = glm::vec4(t, w);
  }
}

int append_obj_impl(Scene& scene, LoadContext& ctx, const fs::path& path, const fs::path& root,
                    const glm::mat4& transform, int material_override) {
  if (material_override >= static_cast<int>(scene.materials.size()))
    fail("OBJ file " + q(path) + ": material override " + std::to_string(material_override) +
         " is out of range");
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(transform[c][r]))
        fail("OBJ file " + q(path) + ": the transform is not finite");
  if (transform[0][3] != 0.0f || transform[1][3] != 0.0f || transform[2][3] != 0.0f ||
      transform[3][3] != 1.0f)
    fail("OBJ file " + q(path) + ": the transform must be affine");
  const glm::mat3 linear(transform);
  const float det = glm::determinant(linear);
  if (!std::isfinite(det) || std::abs(det) < 1e-12f)
    fail("OBJ file " + q(path) + ": the transform is singular (a zero scale?)");
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));

  const std::string text = read_file(path, kMaxObjBytes, "OBJ file");
  if (text.find('\0') != std::string::npos)
    fail("OBJ file " + q(path) + " contains a NUL byte (is it a binary file?)");
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    fail("OBJ file " + q(path) + " is empty");
  const ObjScan scan = scan_obj(path, text);
  if (scan.faces == 0) fail("OBJ file " + q(path) + " has no faces");
  if (ctx.triangles + scan.triangles > kMaxTriangles)
    fail("OBJ file " + q(path) + " brings the scene above " + std::to_string(kMaxTriangles) +
         " triangles, more than supported");

  // MTL files: all of them, parsed here, inside the root.
  std::vector<MtlMaterial> mtl;
  std::set<std::string> mtl_files;
  for (const auto& [lib, line] : scan.mtllibs) {
    const std::string context = "OBJ file " + q(path) + " line " + std::to_string(line) + ": ";
    const fs::path p = resolve_inside(root, path.parent_path(), lib, context, "MTL");
    if (mtl_files.insert(canonical_key(p)).second) parse_mtl(p, mtl, context);
  }

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  {
    MemoryBuffer buf(text.data(), text.size());
    std::istream in(&buf);
    PreparsedMaterials reader(mtl);
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &reader,
                                     /*triangulate=*/true, /*default_vcols_fallback=*/false);
    if (!ok || !err.empty()) {
      std::string m = err.empty() ? std::string("unknown error") : err;
      for (char& c : m)
        if (c == '\n' || c == '\r') c = ' ';
      while (!m.empty() && (m.back() == ' ' || m.back() == '.')) m.pop_back();
      fail("OBJ file " + q(path) + " could not be parsed: " + m);
    }
  }

  // Everything again, after loading: sizes, values, every index.
  const std::size_t nv = attrib.vertices.size() / 3, nvt = attrib.texcoords.size() / 2,
                    nvn = attrib.normals.size() / 3;
  if (attrib.vertices.size() % 3 || attrib.texcoords.size() % 2 || attrib.normals.size() % 3 ||
      nv != scan.nv || nvt != scan.nvt || nvn != scan.nvn)
    fail("OBJ file " + q(path) + " was read inconsistently (attribute counts disagree)");
  for (const auto* arr : {&attrib.vertices, &attrib.texcoords, &attrib.normals})
    for (float x : *arr)
      if (!std::isfinite(x)) fail("OBJ file " + q(path) + " has a non-finite number");

  std::vector<glm::vec3> wpos(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    const glm::vec4 p = transform * glm::vec4(attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                                              attrib.vertices[3 * i + 2], 1.0f);
    wpos[i] = glm::vec3(p);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
        std::abs(p.x) > kMaxCoord || std::abs(p.y) > kMaxCoord || std::abs(p.z) > kMaxCoord)
      fail("OBJ file " + q(path) + ": vertex " + std::to_string(i + 1) +
           " lies beyond 1e7 units (after the transform)");
  }
  std::vector<glm::vec3> wnrm(nvn);
  std::vector<char> wnrm_ok(nvn, 0);
  for (std::size_t i = 0; i < nvn; ++i) {
    const glm::vec3 n(attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]);
    const glm::vec3 w = normal_matrix * n;
    const float len = glm::length(w);
    if (glm::length(n) > 1e-12f && std::isfinite(len) && len > 1e-20f) {
      wnrm[i] = w / len;
      wnrm_ok[i] = std::isfinite(wnrm[i].x) && std::isfinite(wnrm[i].y) && std::isfinite(wnrm[i].z);
    }
  }

  // Materials used by this file, created on first use.
  std::vector<int> scene_material(mtl.size(), -1);
  auto resolve_material = [&](int id) {
    if (material_override >= 0) return material_override;
    if (id < 0 || id >= static_cast<int>(mtl.size())) return default_material(scene);
    int& m = scene_material[static_cast<std::size_t>(id)];
    if (m < 0) m = add_mtl_material(scene, ctx, mtl[static_cast<std::size_t>(id)], root);
    return m;
  };

  const std::string stem = path.stem().string();
  const bool flip = det < 0.0f;  // mirroring transforms: keep the winding counter-clockwise
  int added = 0;
  for (std::size_t si = 0; si < shapes.size(); ++si) {
    const tinyobj::mesh_t& sm = shapes[si].mesh;
    const std::size_t nfaces = sm.num_face_vertices.size();
    if (sm.indices.size() != nfaces * 3 || sm.material_ids.size() != nfaces)
      fail("OBJ file " + q(path) + " was read inconsistently (shape " + q(shapes[si].name) +
           " has mismatched face counts)");
    struct Builder {
      int material;
      Mesh mesh;
      std::unordered_map<CornerKey, std::uint32_t, CornerHash> corners;
    };
    std::vector<Builder> builders;
    for (std::size_t f = 0; f < nfaces; ++f) {
      if (sm.num_face_vertices[f] != 3)
        fail("OBJ file " + q(path) + ": face " + std::to_string(f + 1) + " of shape " +
             q(shapes[si].name) + " was not triangulated");
      tinyobj::index_t c[3] = {sm.indices[3 * f], sm.indices[3 * f + 1], sm.indices[3 * f + 2]};
      for (const tinyobj::index_t& ix : c) {
        if (ix.vertex_index < 0 || static_cast<std::size_t>(ix.vertex_index) >= nv ||
            ix.texcoord_index < -1 ||
            (ix.texcoord_index >= 0 && static_cast<std::size_t>(ix.texcoord_index) >= nvt) ||
            ix.normal_index < -1 ||
            (ix.normal_index >= 0 && static_cast<std::size_t>(ix.normal_index) >= nvn))
          fail("OBJ file " + q(path) + ": face " + std::to_string(f + 1) + " of shape " +
               q(shapes[si].name) + " has an index out of range");
      }
      if (flip) std::swap(c[1], c[2]);
      const glm::dvec3 p0(wpos[static_cast<std::size_t>(c[0].vertex_index)]);
      const glm::dvec3 e1 = glm::dvec3(wpos[static_cast<std::size_t>(c[1].vertex_index)]) - p0;
      const glm::dvec3 e2 = glm::dvec3(wpos[static_cast<std::size_t>(c[2].vertex_index)]) - p0;
      const glm::dvec3 cr = glm::cross(e1, e2);
      const double area2 = glm::length(cr);
      if (!(area2 > 1e-7 * glm::length(e1) * glm::length(e2)) || !(area2 > 0.0))
        continue;  // zero-area triangle: dropped
      const glm::vec3 face_normal(cr / area2);

      const int material = resolve_material(sm.material_ids[f]);
      auto b = std::find_if(builders.begin(), builders.end(),
                            [&](const Builder& x) { return x.material == material; });
      if (b == builders.end()) {
        builders.push_back(Builder{material, Mesh{}, {}});
        b = builders.end() - 1;
      }
      for (const tinyobj::index_t& ix : c) {
        const bool has_normal =
            ix.normal_index >= 0 && wnrm_ok[static_cast<std::size_t>(ix.normal_index)];
        const CornerKey key{ix.vertex_index, ix.texcoord_index, ix.normal_index};
        if (has_normal) {
          if (auto it = b->corners.find(key); it != b->corners.end()) {
            b->mesh.indices.push_back(it->second);
            continue;
          }
        }
        Vertex v;
        v.position = wpos[static_cast<std::size_t>(ix.vertex_index)];
        v.normal = has_normal ? wnrm[static_cast<std::size_t>(ix.normal_index)] : face_normal;
        if (ix.texcoord_index >= 0) {
          const std::size_t t = 2 * static_cast<std::size_t>(ix.texcoord_index);
          v.uv = glm::vec2(attrib.texcoords[t], attrib.texcoords[t + 1]);  // as in the OBJ
        } else {
          v.uv = glm::vec2(0.0f);
        }
        v.tangent = glm::vec4(0.0f);
        const auto vi = static_cast<std::uint32_t>(b->mesh.vertices.size());
        b->mesh.vertices.push_back(v);
        b->mesh.indices.push_back(vi);
        if (has_normal) b->corners.emplace(key, vi);
      }
    }
    const std::string shape_name = shapes[si].name.empty() ? stem : shapes[si].name;
    for (Builder& b : builders) {
      b.corners = {};
      b.mesh.name =
          builders.size() > 1
              ? shape_name + ":" + scene.materials[static_cast<std::size_t>(b.material)].name
              : shape_name;
      b.mesh.material = b.material;
      meshgen::compute_tangents(b.mesh);
      fix_tangents(b.mesh);
      ctx.triangles += b.mesh.indices.size() / 3;
      scene.meshes.push_back(std::move(b.mesh));
      ++added;
    }
  }
  if (added == 0) fail("OBJ file " + q(path) + " has no triangles with a non-zero area");
  return added;
}

// ---- defaults for scenes without lights or cameras ------------------------------------------

struct Bounds {
  glm::vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
};

Bounds scene_bounds(const Scene& s) {
  Bounds b;
  for (const Mesh& m : s.meshes)
    for (const Vertex& v : m.vertices) {
      b.lo = glm::min(b.lo, v.position);
      b.hi = glm::max(b.hi, v.position);
    }
  if (b.lo.x > b.hi.x) b.lo = b.hi = glm::vec3(0.0f);
  return b;
}

Camera framing_camera(const Scene& s) {
  const Bounds b = scene_bounds(s);
  const glm::vec3 center = 0.5f * (b.lo + b.hi);
  const float radius = std::max(0.5f * glm::length(b.hi - b.lo), 1e-3f);
  Camera c;
  c.name = "default";
  c.fov_y_deg = 50.0f;
  const float dist = 1.15f * radius / std::sin(glm::radians(0.5f * c.fov_y_deg));
  c.target = center;
  c.position = center + dist * glm::normalize(glm::vec3(0.55f, 0.45f, 1.0f));
  c.up = glm::vec3(0, 1, 0);
  c.near_plane = std::max(dist - 1.5f * radius, dist * 1e-3f);
  c.far_plane = dist + 4.0f * radius;
  return c;
}

void add_default_lights(Scene& s) {
  const Bounds b = scene_bounds(s);
  const float radius = std::max(0.5f * glm::length(b.hi - b.lo), 1e-3f);
  Light sun;
  sun.type = Light::Type::Directional;
  sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
  sun.color = glm::vec3(1.0f, 0.96f, 0.9f);
  sun.intensity = 2.5f;
  s.lights.push_back(sun);
  Light fill;
  fill.type = Light::Type::Point;
  fill.position = 0.5f * (b.lo + b.hi) + glm::vec3(0.8f, 1.5f, 1.2f) * radius;
  fill.color = glm::vec3(0.9f, 0.95f, 1.0f);
  fill.intensity = 2.0f * radius * radius;
  fill.range = 8.0f * radius;
  s.lights.push_back(fill);
}

// Validates and names the file in the message.
void validate_file(const Scene& s, const fs::path& file) {
  try {
    validate(s);
  } catch (const InputError& e) {
    fail("scene file " + q(file) + " is invalid: " + e.what());
  }
}

// ---- JSON -----------------------------------------------------------------------------------

// Reading one JSON scene file: typed getters that name the file and the key on every error.
class JsonReader {
 public:
  explicit JsonReader(fs::path file) : file_(std::move(file)) {}
  const fs::path& file() const { return file_; }

  [[noreturn]] void fail_at(const std::string& where, const std::string& what) const {
    fail("scene file " + q(file_) + ": " + q(where) + " " + what);
  }

  static std::string join(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
  }
  static std::string index(const std::string& parent, std::size_t i) {
    return parent + "[" + std::to_string(i) + "]";
  }

  const json& object(const json& j, const std::string& where) const {
    if (!j.is_object()) fail_at(where, "must be an object");
    return j;
  }
  const json& array(const json& j, const std::string& where) const {
    if (!j.is_array()) fail_at(where, "must be an array");
    return j;
  }

  // Every key of `obj` must be in `allowed`.
  void keys(const json& obj, const std::string& where,
            std::initializer_list<std::string_view> allowed) const {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      if (std::find(allowed.begin(), allowed.end(), it.key()) != allowed.end()) continue;
      std::string list;
      for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail("scene file " + q(file_) + ": unknown key " + q(join(where, it.key())) +
           " (allowed here: " + list + ")");
    }
  }

  float number(const json& j, const std::string& where, float lo, float hi) const {
    if (!j.is_number()) fail_at(where, "must be a number");
    const double v = j.get<double>();
    if (!std::isfinite(v) || std::abs(v) > 3.0e38) fail_at(where, "must be a finite number");
    if (v < lo || v > hi)
      fail_at(where, "must be in [" + fmt(lo) + ", " + fmt(hi) + "], not " + fmt(v));
    return static_cast<float>(v);
  }
  float number(const json& obj, const std::string& parent, const char* key, float def, float lo,
               float hi) const {
    return obj.contains(key) ? number(obj[key], join(parent, key), lo, hi) : def;
  }
  int integer(const json& obj, const std::string& parent, const char* key, int def, int lo,
              int hi) const {
    if (!obj.contains(key)) return def;
    const std::string where = join(parent, key);
    if (!obj[key].is_number_integer()) fail_at(where, "must be an integer");
    const auto v = obj[key].get<long long>();
    if (v < lo || v > hi)
      fail_at(where, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return static_cast<int>(v);
  }
  glm::vec3 vec3(const json& j, const std::string& where, float lo = -1e7f, float hi = 1e7f) const {
    if (!j.is_array() || j.size() != 3) fail_at(where, "must be an array of 3 numbers");
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) {
      if (!j[static_cast<std::size_t>(i)].is_number())
        fail_at(where, "must be an array of 3 numbers");
      v[i] = number(j[static_cast<std::size_t>(i)], where, lo, hi);
    }
    return v;
  }
  glm::vec3 vec3(const json& obj, const std::string& parent, const char* key, glm::vec3 def,
                 float lo = -1e7f, float hi = 1e7f) const {
    return obj.contains(key) ? vec3(obj[key], join(parent, key), lo, hi) : def;
  }
  glm::vec3 required_vec3(const json& obj, const std::string& parent, const char* key) const {
    if (!obj.contains(key)) fail_at(join(parent, key), "is required");
    return vec3(obj[key], join(parent, key));
  }
  glm::vec2 vec2(const json& j, const std::string& where, float lo, float hi) const {
    if (!j.is_array() || j.size() != 2) fail_at(where, "must be an array of 2 numbers");
    glm::vec2 v;
    for (int i = 0; i < 2; ++i) {
      if (!j[static_cast<std::size_t>(i)].is_number())
        fail_at(where, "must be an array of 2 numbers");
      v[i] = number(j[static_cast<std::size_t>(i)], where, lo, hi);
    }
    return v;
  }
  std::string string(const json& j, const std::string& where) const {
    if (!j.is_string()) fail_at(where, "must be a string");
    std::string s = j.get<std::string>();
    if (s.empty()) fail_at(where, "must not be empty");
    return s;
  }
  std::string string(const json& obj, const std::string& parent, const char* key,
                     const std::string& def) const {
    return obj.contains(key) ? string(obj[key], join(parent, key)) : def;
  }
  bool boolean(const json& obj, const std::string& parent, const char* key, bool def) const {
    if (!obj.contains(key)) return def;
    if (!obj[key].is_boolean()) fail_at(join(parent, key), "must be true or false");
    return obj[key].get<bool>();
  }
  // A unit vector from a non-zero one.
  glm::vec3 direction(const json& j, const std::string& where) const {
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
  fs::path file_;
};

json parse_json_file(const fs::path& path) {
  const std::string text = read_file(path, kMaxJsonBytes, "scene file");
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    fail("scene file " + q(path) + " is empty");
  // Duplicate keys are an error (nlohmann keeps the last one silently).
  std::vector<std::set<std::string>> seen;
  std::string duplicate;
  auto callback = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) {
      seen.emplace_back();
    } else if (event == json::parse_event_t::object_end) {
      if (!seen.empty()) seen.pop_back();
    } else if (event == json::parse_event_t::key && !seen.empty()) {
      const std::string k = parsed.get<std::string>();
      if (!seen.back().insert(k).second && duplicate.empty()) duplicate = k;
    }
    return true;
  };
  json j;
  try {
    j = json::parse(text, callback, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    const std::string what = e.what();
    static const std::regex re(R"(at line (\d+), column (\d+): (.*)$)");
    std::smatch m;
    if (std::regex_search(what, m, re))
      fail("scene file " + q(path) + " has a JSON syntax error at line " + m[1].str() +
           ", column " + (m[2].str() == "0" ? std::string("1") : m[2].str()) + ": " + m[3].str());
    fail("scene file " + q(path) + " has a JSON syntax error near byte " + std::to_string(e.byte));
  }
  if (!duplicate.empty()) fail("scene file " + q(path) + " has the key " + q(duplicate) + " twice");
  if (!j.is_object()) fail("scene file " + q(path) + " must hold a JSON object");
  return j;
}

glm::mat4 read_transform(const JsonReader& r, const json& obj, const std::string& where) {
  const glm::vec3 t = r.vec3(obj, where, "translate", glm::vec3(0.0f));
  const glm::vec3 rot = r.vec3(obj, where, "rotate_deg", glm::vec3(0.0f), -36000.0f, 36000.0f);
  glm::vec3 s(1.0f);
  if (obj.contains("scale")) {
    const std::string w = JsonReader::join(where, "scale");
    if (obj["scale"].is_number())
      s = glm::vec3(r.number(obj["scale"], w, 1e-6f, 1e6f));
    else if (obj["scale"].is_array())
      s = r.vec3(obj["scale"], w, 1e-6f, 1e6f);
    else
      r.fail_at(w, "must be a number or an array of 3 numbers");
  }
  glm::mat4 m = glm::translate(glm::mat4(1.0f), t);
  m = glm::rotate(m, glm::radians(rot.z), glm::vec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rot.y), glm::vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rot.x), glm::vec3(1, 0, 0));
  return glm::scale(m, s);
}

Reflector read_reflector(const JsonReader& r, const json& j, const std::string& where) {
  r.object(j, where);
  r.keys(j, where, {"center", "tangent", "bitangent", "half_extents"});
  Reflector refl;
  refl.center = r.required_vec3(j, where, "center");
  for (const char* k : {"tangent", "bitangent"})
    if (!j.contains(k)) r.fail_at(JsonReader::join(where, k), "is required");
  refl.tangent = r.direction(j["tangent"], JsonReader::join(where, "tangent"));
  refl.bitangent = r.direction(j["bitangent"], JsonReader::join(where, "bitangent"));
  if (std::abs(glm::dot(refl.tangent, refl.bitangent)) > 1e-3f)
    r.fail_at(where, "needs orthogonal tangent and bitangent");
  const std::string he = JsonReader::join(where, "half_extents");
  if (!j.contains("half_extents")) r.fail_at(he, "is required");
  refl.half_extents = r.vec2(j["half_extents"], he, 0.0f, 1e7f);
  if (!(refl.half_extents.x > 0.0f) || !(refl.half_extents.y > 0.0f))
    r.fail_at(he, "must be positive (zero-area reflectors are not allowed)");
  return refl;
}

// Adds `refl`, returning its 1-based id.
int add_reflector(Scene& s, const JsonReader& r, const std::string& where, const Reflector& refl) {
  if (s.reflectors.size() >= static_cast<std::size_t>(Scene::kMaxReflectors))
    r.fail_at(where, "is reflector number " + std::to_string(s.reflectors.size() + 1) +
                         ", more than the " + std::to_string(Scene::kMaxReflectors) + " supported");
  s.reflectors.push_back(refl);
  return static_cast<int>(s.reflectors.size());
}

void read_environment(const JsonReader& r, const json& j, Environment& env) {
  const std::string where = "environment";
  r.object(j, where);
  const std::string type = r.string(j, where, "type", "sky");
  if (type == "sky") {
    r.keys(j, where, {"type", "zenith", "horizon", "ground", "intensity"});
    env.type = Environment::Type::Sky;
    env.zenith = r.vec3(j, where, "zenith", env.zenith, 0.0f, 1e6f);
    env.horizon = r.vec3(j, where, "horizon", env.horizon, 0.0f, 1e6f);
    env.ground = r.vec3(j, where, "ground", env.ground, 0.0f, 1e6f);
  } else if (type == "constant") {
    r.keys(j, where, {"type", "color", "intensity"});
    env.type = Environment::Type::Constant;
    env.constant = r.vec3(j, where, "color", env.constant, 0.0f, 1e6f);
  } else {
    r.fail_at("environment.type", "must be \"sky\" or \"constant\", not " + q(type));
  }
  env.intensity = r.number(j, where, "intensity", env.intensity, 0.0f, 1e6f);
}

void read_materials(const JsonReader& r, const json& j, Scene& s, LoadContext& ctx,
                    const fs::path& dir) {
  r.object(j, "materials");
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string where = "materials." + it.key();
    const json& m = r.object(it.value(), where);
    r.keys(m, where,
           {"albedo", "metallic", "roughness", "reflectance", "emission", "albedo_texture",
            "normal_texture", "normal_strength", "transparent", "ior"});
    Material mat;
    mat.name = it.key();
    if (mat.name.empty()) r.fail_at(where, "needs a non-empty name");
    mat.albedo = r.vec3(m, where, "albedo", mat.albedo, 0.0f, 1.0f);
    mat.metallic = r.number(m, where, "metallic", mat.metallic, 0.0f, 1.0f);
    mat.roughness = r.number(m, where, "roughness", mat.roughness, 0.0f, 1.0f);
    mat.reflectance = r.number(m, where, "reflectance", mat.reflectance, 0.0f, 1.0f);
    mat.emission = r.vec3(m, where, "emission", mat.emission, 0.0f, 1e6f);
    mat.normal_strength = r.number(m, where, "normal_strength", mat.normal_strength, 0.0f, 4.0f);
    mat.transparent = r.boolean(m, where, "transparent", mat.transparent);
    mat.ior = r.number(m, where, "ior", mat.ior, 1.0f, 3.0f);
    for (const char* key : {"albedo_texture", "normal_texture"}) {
      if (!m.contains(key)) continue;
      const std::string w = JsonReader::join(where, key);
      const std::string context = "scene file " + q(r.file()) + ": " + q(w) + ": ";
      const fs::path p = resolve_inside(dir, dir, r.string(m[key], w), context, "texture");
      const int image = add_image(s, ctx, p, context);
      (std::string_view(key) == "albedo_texture" ? mat.albedo_texture : mat.normal_texture) = image;
    }
    s.materials.push_back(mat);
  }
}

int find_material(const JsonReader& r, const Scene& s, const json& obj, const std::string& where) {
  const std::string name = r.string(obj["material"], JsonReader::join(where, "material"));
  for (std::size_t i = 0; i < s.materials.size(); ++i)
    if (s.materials[i].name == name) return static_cast<int>(i);
  std::string list;
  for (const Material& m : s.materials) list += (list.empty() ? "" : ", ") + m.name;
  r.fail_at(JsonReader::join(where, "material"),
            "names the unknown material " + q(name) +
                " (materials: " + (list.empty() ? "none" : list) + ")");
}

void read_meshes(const JsonReader& r, const json& j, Scene& s, LoadContext& ctx,
                 const fs::path& dir) {
  r.array(j, "meshes");
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = JsonReader::index("meshes", i);
    const json& m = r.object(j[i], where);
    r.keys(m, where, {"obj", "material", "translate", "rotate_deg", "scale", "reflector"});
    if (!m.contains("obj")) r.fail_at(where + ".obj", "is required");
    const std::string rel = r.string(m["obj"], where + ".obj");
    const std::string context = "scene file " + q(r.file()) + ": " + q(where + ".obj") + ": ";
    const fs::path obj = resolve_inside(dir, dir, rel, context, "OBJ");
    std::error_code ec;
    if (!fs::is_regular_file(obj, ec)) fail(context + "OBJ file " + q(obj) + " does not exist");
    const int material = m.contains("material") ? find_material(r, s, m, where) : -1;
    const glm::mat4 transform = read_transform(r, m, where);
    int reflector = 0;
    if (m.contains("reflector")) {
      if (!m["reflector"].is_object())
        r.fail_at(where + ".reflector",
                  "must be an object with center, tangent, bitangent and half_extents");
      reflector = add_reflector(s, r, where + ".reflector",
                                read_reflector(r, m["reflector"], where + ".reflector"));
    }
    const std::size_t first = s.meshes.size();
    try {
      append_obj_impl(s, ctx, obj, dir, transform, material);
    } catch (const InputError& e) {
      fail(context + e.what());
    }
    for (std::size_t k = first; k < s.meshes.size(); ++k) s.meshes[k].reflector = reflector;
  }
}

void read_primitives(const JsonReader& r, const json& j, Scene& s) {
  r.array(j, "primitives");
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = JsonReader::index("primitives", i);
    const json& p = r.object(j[i], where);
    if (!p.contains("type")) r.fail_at(where + ".type", "is required");
    const std::string type = r.string(p["type"], where + ".type");
    const std::initializer_list<std::string_view> common = {
        "type", "name", "material", "translate", "rotate_deg", "scale", "reflector"};
    auto allowed = [&](std::initializer_list<std::string_view> extra) {
      std::vector<std::string_view> all(common);
      all.insert(all.end(), extra);
      for (auto it = p.begin(); it != p.end(); ++it)
        if (std::find(all.begin(), all.end(), it.key()) == all.end()) {
          std::string list;
          for (std::string_view a : all) list += (list.empty() ? "" : ", ") + std::string(a);
          fail("scene file " + q(r.file()) + ": unknown key " + q(where + "." + it.key()) +
               " for a " + type + " (allowed here: " + list + ")");
        }
    };
    Mesh mesh;
    glm::vec2 plane_size(0.0f);
    if (type == "plane") {
      allowed({"size", "uv_scale"});
      if (!p.contains("size")) r.fail_at(where + ".size", "is required");
      plane_size = r.vec2(p["size"], where + ".size", 1e-6f, 1e6f);
      mesh = meshgen::plane(plane_size, r.number(p, where, "uv_scale", 1.0f, 1e-6f, 1e6f));
    } else if (type == "box") {
      allowed({"extents"});
      mesh = meshgen::box(r.vec3(p, where, "extents", glm::vec3(1.0f), 1e-6f, 1e6f));
    } else if (type == "sphere") {
      allowed({"radius", "segments", "rings"});
      mesh = meshgen::sphere(r.number(p, where, "radius", 0.5f, 1e-6f, 1e6f),
                             r.integer(p, where, "segments", 48, 3, 1024),
                             r.integer(p, where, "rings", 24, 2, 1024));
    } else if (type == "cylinder") {
      allowed({"radius", "height", "segments"});
      mesh = meshgen::cylinder(r.number(p, where, "radius", 0.5f, 1e-6f, 1e6f),
                               r.number(p, where, "height", 1.0f, 1e-6f, 1e6f),
                               r.integer(p, where, "segments", 32, 3, 1024));
    } else {
      r.fail_at(where + ".type",
                "must be \"plane\", \"box\", \"sphere\" or \"cylinder\", not " + q(type));
    }
    const glm::mat4 transform = read_transform(r, p, where);
    meshgen::transform(mesh, transform);
    mesh.name = r.string(p, where, "name", type + std::to_string(i));
    mesh.material = p.contains("material") ? find_material(r, s, p, where) : default_material(s);
    if (p.contains("reflector")) {
      const std::string w = where + ".reflector";
      const json& rj = p["reflector"];
      if (rj.is_boolean()) {
        if (type != "plane") r.fail_at(w, "can be true only for a plane; give a rectangle object");
        if (rj.get<bool>()) {
          Reflector refl;
          const glm::vec3 tx(transform * glm::vec4(1, 0, 0, 0)),
              tz(transform * glm::vec4(0, 0, 1, 0));
          refl.center = glm::vec3(transform * glm::vec4(0, 0, 0, 1));
          refl.tangent = glm::normalize(tx);
          refl.bitangent = glm::normalize(tz);
          refl.half_extents = 0.5f * plane_size * glm::vec2(glm::length(tx), glm::length(tz));
          mesh.reflector = add_reflector(s, r, w, refl);
        }
      } else if (rj.is_object()) {
        mesh.reflector = add_reflector(s, r, w, read_reflector(r, rj, w));
      } else {
        r.fail_at(w, "must be true, false or a rectangle object");
      }
    }
    s.meshes.push_back(std::move(mesh));
  }
}

void read_lights(const JsonReader& r, const json& j, Scene& s) {
  r.array(j, "lights");
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = JsonReader::index("lights", i);
    const json& l = r.object(j[i], where);
    if (!l.contains("type")) r.fail_at(where + ".type", "is required");
    const std::string type = r.string(l["type"], where + ".type");
    Light light;
    if (type == "point") {
      r.keys(l, where, {"type", "position", "color", "intensity", "range"});
      light.type = Light::Type::Point;
      light.position = r.required_vec3(l, where, "position");
      light.range = r.number(l, where, "range", light.range, 1e-6f, 1e7f);
    } else if (type == "directional") {
      r.keys(l, where, {"type", "direction", "color", "intensity"});
      light.type = Light::Type::Directional;
      if (!l.contains("direction")) r.fail_at(where + ".direction", "is required");
      light.direction = r.direction(l["direction"], where + ".direction");
    } else {
      r.fail_at(where + ".type", "must be \"point\" or \"directional\", not " + q(type));
    }
    light.color = r.vec3(l, where, "color", light.color, 0.0f, 1e6f);
    light.intensity = r.number(l, where, "intensity", light.intensity, 0.0f, 1e9f);
    s.lights.push_back(light);
  }
}

void read_cameras(const JsonReader& r, const json& j, Scene& s) {
  r.array(j, "cameras");
  if (j.empty()) r.fail_at("cameras", "must not be empty (leave it out to frame the scene)");
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string where = JsonReader::index("cameras", i);
    const json& c = r.object(j[i], where);
    r.keys(c, where, {"name", "position", "target", "up", "fov_y", "near", "far"});
    Camera cam;
    cam.name = r.string(c, where, "name", i == 0 ? "default" : "camera" + std::to_string(i));
    for (const Camera& other : s.cameras)
      if (other.name == cam.name)
        r.fail_at(where + ".name", "repeats the camera name " + q(cam.name));
    cam.position = r.vec3(c, where, "position", cam.position);
    cam.target = r.vec3(c, where, "target", cam.target);
    if (c.contains("up")) cam.up = r.direction(c["up"], where + ".up");
    cam.fov_y_deg = r.number(c, where, "fov_y", cam.fov_y_deg, 1.001f, 178.999f);
    cam.near_plane = r.number(c, where, "near", cam.near_plane, 1e-6f, 1e7f);
    cam.far_plane = r.number(c, where, "far", cam.far_plane, 1e-6f, 1e7f);
    if (!(cam.far_plane > cam.near_plane)) r.fail_at(where + ".far", "must be greater than near");
    if (glm::length(cam.target - cam.position) < 1e-6f)
      r.fail_at(where + ".target", "must differ from the position");
    if (glm::length(glm::cross(glm::normalize(cam.target - cam.position), cam.up)) <
        1e-6f * glm::length(cam.up))
      r.fail_at(where + ".up", "must not be parallel to the view direction");
    s.cameras.push_back(cam);
  }
}

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

// ---- public API -----------------------------------------------------------------------------

int append_obj(Scene& scene, const fs::path& path, const glm::mat4& transform,
               int material_override) {
  LoadContext ctx;
  ctx.triangles = scene.triangle_count();
  return append_obj_impl(scene, ctx, path,
                         path.parent_path().empty() ? fs::path(".") : path.parent_path(), transform,
                         material_override);
}

Scene load_scene_obj(const fs::path& path) {
  Scene s;
  s.name = path.stem().string();
  append_obj(s, path, glm::mat4(1.0f));
  if (s.materials.empty()) default_material(s);
  add_default_lights(s);
  s.cameras.push_back(framing_camera(s));
  validate_file(s, path);
  return s;
}

Scene load_scene_json(const fs::path& path) {
  const json j = parse_json_file(path);
  const JsonReader r(path);
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  r.keys(j, "",
         {"name", "description", "ambient", "environment", "materials", "meshes", "primitives",
          "lights", "cameras"});
  Scene s;
  LoadContext ctx;
  s.name = r.string(j, "", "name", path.stem().string());
  if (j.contains("description")) r.string(j["description"], "description");
  s.ambient = r.number(j, "", "ambient", s.ambient, 0.0f, 1e6f);
  if (j.contains("environment")) read_environment(r, j["environment"], s.environment);
  if (j.contains("materials")) read_materials(r, j["materials"], s, ctx, dir);
  if (j.contains("meshes")) read_meshes(r, j["meshes"], s, ctx, dir);
  if (j.contains("primitives")) read_primitives(r, j["primitives"], s);
  if (s.meshes.empty()) fail("scene file " + q(path) + " has no meshes or primitives");
  if (s.triangle_count() > kMaxTriangles)
    fail("scene file " + q(path) + " has more than " + std::to_string(kMaxTriangles) +
         " triangles, more than supported");
  if (j.contains("lights")) read_lights(r, j["lights"], s);
  if (s.lights.size() > static_cast<std::size_t>(Scene::kMaxLights))
    r.fail_at("lights", "has " + std::to_string(s.lights.size()) + " lights, more than the " +
                            std::to_string(Scene::kMaxLights) + " supported");
  if (j.contains("cameras"))
    read_cameras(r, j["cameras"], s);
  else
    s.cameras.push_back(framing_camera(s));
  validate_file(s, path);
  return s;
}

Scene load_scene(const std::string& name_or_path) {
  for (const BuiltinSceneInfo& b : builtin_scenes())
    if (b.name == name_or_path) {
      Scene s = make_builtin_scene(name_or_path);
      validate(s);
      return s;
    }
  const fs::path p(name_or_path);
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
