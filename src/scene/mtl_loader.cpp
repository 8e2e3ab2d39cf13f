// MTL files and textures, plus the file reading and path confinement every loader uses.
//
// MTL files are parsed here, not by tinyobjloader (rc10 silently reads garbage as 0):
// Kd -> albedo (clamped to [0,1]), Pm -> metallic, Pr -> roughness (else
// r = sqrt(2 / (Ns + 2))), Ke -> emission, Ni -> reflectance and ior, map_Kd -> albedo texture,
// norm (else bump / map_bump) -> normal texture (-bm -> normal strength). MTL files and
// textures must stay inside the root directory (the OBJ's directory, or the JSON file's
// directory for OBJs placed by a scene file).
#include <stb_image.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>

#include "scene/scene_io_internal.h"

namespace ssr::scene_io_detail {
namespace {

constexpr std::uintmax_t kMaxMtlBytes = 64ull << 20;  // 64 MiB
constexpr std::uintmax_t kMaxImageBytes = 256ull << 20;
constexpr int kMaxImageSide = 16384;
constexpr std::size_t kMaxImagePixels = std::size_t{1} << 26;  // 8192 x 8192
// All of a scene's textures together (1 GiB of RGBA8, about 3 on the GPU with the two uploads
// and mipmaps): a few hundred KB of flat 8192x8192 PNGs must not decode into tens of GiB.
constexpr std::size_t kMaxScenePixels = std::size_t{1} << 28;

// `budget`: the pixels the scene's textures may still take.
Image load_image(const fs::path& path, const std::string& context, std::size_t budget) {
  const std::string bytes = read_file(path, kMaxImageBytes, "texture file", context);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int len = static_cast<int>(bytes.size());
  int w = 0, h = 0, comp = 0;
  // Check the size before decoding, so a tiny file cannot claim a huge allocation.
  if (!stbi_info_from_memory(data, len, &w, &h, &comp))
    fail(context + "texture file " + q(path) + " is not a readable image (" +
         (stbi_failure_reason() ? stbi_failure_reason() : "unknown format") + ")");
  if (w <= 0 || h <= 0 || w > kMaxImageSide || h > kMaxImageSide ||
      static_cast<std::size_t>(w) * static_cast<std::size_t>(h) > kMaxImagePixels)
    fail(context + "texture file " + q(path) + " is " + std::to_string(w) + "x" +
         std::to_string(h) + "; sides must be in [1, " + std::to_string(kMaxImageSide) +
         "] and the pixel count at most " + std::to_string(kMaxImagePixels));
  if (static_cast<std::size_t>(w) * static_cast<std::size_t>(h) > budget)
    fail(context + "texture file " + q(path) + " (" + std::to_string(w) + "x" +
         std::to_string(h) + ") brings the scene's textures above " +
         std::to_string(kMaxScenePixels) + " pixels, more than supported");
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

}  // namespace

// ---- files and paths ------------------------------------------------------------------------

fs::path resolve_inside(const fs::path& root, const fs::path& base, std::string rel,
                        const std::string& context, const std::string& what) {
  std::replace(rel.begin(), rel.end(), '\\', '/');
  if (rel.empty()) fail(context + what + " path is empty");
  const fs::path r(rel);
  if (r.has_root_path())
    fail(context + what + " path " + q(rel) + " is absolute; it must be relative to " + q(base));
  const fs::path full = (base / r).lexically_normal();
  // Compare canonical paths, so that ".." and symlinks leading out are both caught.
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

std::string canonical_key(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(fs::absolute(p), ec);
  return (ec ? p.lexically_normal() : c).string();
}

// ---- textures -------------------------------------------------------------------------------

int add_image(Scene& scene, LoadContext& ctx, const fs::path& path, const std::string& context) {
  const std::string key = canonical_key(path);
  if (auto it = ctx.images.find(key); it != ctx.images.end()) return it->second;
  std::size_t used = 0;
  for (const Image& im : scene.images) used += static_cast<std::size_t>(im.width) * im.height;
  scene.images.push_back(
      load_image(path, context, kMaxScenePixels - std::min(used, kMaxScenePixels)));
  const int index = static_cast<int>(scene.images.size()) - 1;
  ctx.images.emplace(key, index);
  return index;
}

// ---- MTL ------------------------------------------------------------------------------------

void parse_mtl(const fs::path& path, std::vector<MtlMaterial>& out, const std::string& context) {
  const std::string text = read_text_file(path, kMaxMtlBytes, "MTL file", context);
  if (text.find('\0') != std::string::npos)
    fail("MTL file " + q(path) + " contains a NUL byte (is it a binary file?)");
  std::vector<std::string_view> tok;
  MtlMaterial* cur = nullptr;
  // Material name -> position in `out`, for the duplicate check: scanning `out` for every
  // newmtl made a 250 KB file of 20000 materials take half a minute (found while fuzzing).
  std::map<std::string, std::size_t, std::less<>> index;
  for (std::size_t i = 0; i < out.size(); ++i) index.emplace(out[i].name, i);
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
      if (const auto it = index.find(name); it != index.end()) {
        const MtlMaterial& m = out[it->second];
        fail(where() + "material " + q(name) + " is defined twice (first in " + q(m.mtl_file) +
             " line " + std::to_string(m.line) + ")");
      }
      index.emplace(std::string(name), out.size());
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

}  // namespace ssr::scene_io_detail
