// OBJ files: pre-scan, tinyobjloader, validation, mesh building; and the defaults (lights,
// framing camera) for scenes that bring none.
//
// Geometry is parsed by Debian's tinyobjloader (rc10). That version reads out of bounds on
// negative or too-large face indices and silently turns malformed numbers into 0
// (CVE-2020-28589), so every OBJ is first scanned here (numbers, index ranges, sizes) and every
// index is checked again after loading. MTL files are parsed by mtl_loader.cpp instead.
// Vertex::uv is the OBJ's vt unchanged: v grows upwards, v = 0 is the image's bottom row (the
// convention of meshgen.cpp; the renderer flips Image rows on upload).
// Missing normals (or zero-length ones) become the face normal; zero-area triangles are dropped.
#include <tiny_obj_loader.h>

#include <algorithm>
#include <istream>
#include <limits>
#include <set>
#include <streambuf>
#include <unordered_map>

#include "scene/meshgen.h"
#include "scene/scene_io.h"
#include "scene/scene_io_internal.h"

namespace ssr {
namespace scene_io_detail {
namespace {

constexpr std::uintmax_t kMaxObjBytes = 1ull << 30;  // 1 GiB
constexpr std::size_t kMaxAttributes = 50'000'000;   // each of v, vt, vn
constexpr std::size_t kMaxFaceVertices = 256;
constexpr float kMaxCoord = 1e7f;  // as in validate()

// ---- OBJ ------------------------------------------------------------------------------------

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

// tinyobjloader rc10 reads a number's exponent into an int and overflows it (undefined
// behaviour) on 10-digit exponents such as "0e2147483648" (found by fuzzing). Such numbers can
// only spell 0 ("0e...", "1e-...") or be refused as overflowing, so they are refused here.
bool exponent_too_long(std::string_view s) {
  std::size_t i = s.find_first_of("eE");
  if (i == std::string_view::npos) return false;
  if (++i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  while (i < s.size() && s[i] == '0') ++i;  // leading zeros do not grow tinyobjloader's int
  return s.size() - i > 9;
}

struct ObjScan {
  std::size_t nv = 0, nvt = 0, nvn = 0, triangles = 0, faces = 0;
  std::size_t meshes = 0;  // at most this many: runs of faces between o, g and usemtl lines
  std::vector<std::pair<std::string, std::size_t>> mtllibs;  // file name, line
  std::vector<std::pair<std::string, std::size_t>> usemtls;  // material name, line
};

// Checks everything tinyobjloader rc10 does not: numbers, index ranges (relative indices
// before the first element, absolute ones past the end), sizes. Line numbers in messages.
ObjScan scan_obj(const fs::path& path, std::string_view text) {
  ObjScan s;
  struct Deferred {  // the largest absolute index of a kind, checked at the end
    long long index = 0;
    std::size_t line = 0;
  } max_v, max_vt, max_vn;
  bool run_open = false;  // faces seen since the last o, g or usemtl line
  std::vector<std::string_view> tok;
  for_each_line(text, [&](std::size_t line_no, std::string_view line) {
    tokenize(line, tok);
    if (tok.empty() || tok[0][0] == '#') return;
    auto where = [&] { return "OBJ file " + q(path) + " line " + std::to_string(line_no) + ": "; };
    const std::string_view key = tok[0];
    auto numbers = [&](std::size_t min_n, std::size_t max_n, const char* what) {
      std::size_t n = 0;
      for (std::size_t i = 1; i < tok.size() && tok[i][0] != '#'; ++i, ++n)
        if (!parse_float(tok[i]) || exponent_too_long(tok[i]))
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
            fail(where() + std::string(what) + " has a malformed or out-of-range " + kinds[k].name + " index " +
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
        if (!run_open) ++s.meshes, run_open = true;
        s.triangles += n - 2;
        if (s.triangles > kMaxTriangles)
          fail("OBJ file " + q(path) + " has more than " + std::to_string(kMaxTriangles) +
               " triangles, more than supported");
      }
    } else if (key == "o" || key == "g" || key == "usemtl") {
      run_open = false;
      if (key == "usemtl") {
        if (tok.size() < 2 || tok[1][0] == '#') fail(where() + "'usemtl' names no material");
        s.usemtls.emplace_back(std::string(tok[1]), line_no);  // tinyobjloader reads one token too
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
      t = len > 1e-6f && std::isfinite(len) ? t / len : meshgen::any_orthogonal(v.normal);
    } else {
      t = meshgen::any_orthogonal(v.normal);
    }
    v.tangent = glm::vec4(t, w);
  }
}

}  // namespace

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
  const float axes = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
  if (!std::isfinite(det) || !(axes > 0.0f) || !(std::abs(det) > 1e-6f * axes))
    fail("OBJ file " + q(path) + ": the transform is singular (a zero scale?)");
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));

  const std::string text = read_text_file(path, kMaxObjBytes, "OBJ file");
  if (text.find('\0') != std::string::npos)
    fail("OBJ file " + q(path) + " contains a NUL byte (is it a binary file?)");
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    fail("OBJ file " + q(path) + " is empty");
  const ObjScan scan = scan_obj(path, text);
  if (scan.faces == 0) fail("OBJ file " + q(path) + " has no faces");
  if (scene.meshes.size() + scan.meshes > static_cast<std::size_t>(Scene::kMaxMeshes))
    fail("OBJ file " + q(path) + " brings the scene to more than " +
         std::to_string(Scene::kMaxMeshes) + " meshes (groups of faces), more than supported");
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
  // A name its MTL files do not define is a typo, not a request for the default material
  // (without any mtllib, usemtl lines are only names: the default material, as documented).
  // tinyobjloader reads one word after usemtl and knows the materials from the first mtllib on.
  if (!scan.mtllibs.empty() && material_override < 0) {
    std::set<std::string> defined;
    for (const MtlMaterial& m : mtl) defined.insert(m.name);
    const std::size_t first_mtllib = scan.mtllibs.front().second;
    for (const auto& [name, line] : scan.usemtls) {
      if (line >= first_mtllib && defined.count(name)) continue;
      const std::string where = "OBJ file " + q(path) + " line " + std::to_string(line) + ": ";
      if (line < first_mtllib) fail(where + "'usemtl " + name + "' comes before the first 'mtllib'");
      for (const std::string& d : defined)  // "newmtl Material 1" defines one name with a space
        if (d.size() > name.size() && d.compare(0, name.size(), name) == 0 && is_space(d[name.size()]))
          fail(where + "material " + q(d) + " has a space in its name, which usemtl cannot name");
      fail(where + "material " + q(name) + " is not defined in its MTL files");
    }
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
    // fail() folds err's line breaks and trailing full stop into the one sentence.
    if (!ok || !err.empty())
      fail("OBJ file " + q(path) + " could not be parsed: " +
           (err.empty() ? "unknown error" : err));
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
  int fallback = -1;  // default_material() searches by name: once per file, not once per face
  auto resolve_material = [&](int id) {
    if (material_override >= 0) return material_override;
    if (id < 0 || id >= static_cast<int>(mtl.size()))
      return fallback >= 0 ? fallback : (fallback = default_material(scene));
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
    // material -> builders index: searching `builders` for every face was quadratic in the
    // number of materials (found while fuzzing).
    std::unordered_map<int, std::size_t> builder_of;
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
      const auto [slot, is_new] = builder_of.try_emplace(material, builders.size());
      if (is_new) builders.push_back(Builder{material, Mesh{}, {}});
      Builder* const b = &builders[slot->second];
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

// ---- defaults for scenes without materials, lights or cameras -------------------------------

namespace {

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

}  // namespace

int default_material(Scene& scene) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == "default") return static_cast<int>(i);
  Material m;
  m.name = "default";
  scene.materials.push_back(m);
  return static_cast<int>(scene.materials.size()) - 1;
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

void validate_file(const Scene& s, const fs::path& file) {
  try {
    validate(s);
  } catch (const InputError& e) {
    fail("scene file " + q(file) + " is invalid: " + e.what());
  }
}

}  // namespace scene_io_detail

using namespace scene_io_detail;

// ---- public API -----------------------------------------------------------------------------

int append_obj(Scene& scene, const fs::path& path, const glm::mat4& transform,
               int material_override) {
  LoadContext ctx;
  ctx.triangles = scene.triangle_count();
  return append_obj_impl(scene, ctx, path, directory_of(path), transform, material_override);
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

}  // namespace ssr
