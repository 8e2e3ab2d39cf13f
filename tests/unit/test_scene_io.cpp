// Scene loading (OBJ, MTL, JSON, built-in names) and validate() on hand-made scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "input_error.h"
#include "core/errors.h"
#include "scene/builtin_scenes.h"
#include "scene/scene.h"
#include "scene/scene_io.h"

namespace {

using ssr::InputError;
using ssr::Scene;

const std::string kData = SSRLAB_TEST_DATA;
const std::string kObj = kData + "/obj/";
const std::string kJson = kData + "/json/";
const std::string kPedestal = kData + "/../../assets/scenes/pedestal.json";

using ssr::test::expect_message;
using ssr::test::input_error;

const ssr::Mesh* find_mesh(const Scene& s, const std::string& name) {
  for (const ssr::Mesh& m : s.meshes)
    if (m.name == name) return &m;
  return nullptr;
}

const ssr::Material* find_material(const Scene& s, const std::string& name) {
  for (const ssr::Material& m : s.materials)
    if (m.name == name) return &m;
  return nullptr;
}

// Every triangle's winding agrees with its vertex normals, every vector is finite and unit.
void expect_sane_mesh(const ssr::Mesh& m) {
  SCOPED_TRACE("mesh " + m.name);
  ASSERT_FALSE(m.indices.empty());
  ASSERT_EQ(m.indices.size() % 3, 0u);
  for (const ssr::Vertex& v : m.vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-3f);
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-3f);
    EXPECT_EQ(std::abs(v.tangent.w), 1.0f);
    EXPECT_TRUE(std::isfinite(v.uv.x) && std::isfinite(v.uv.y));
  }
  for (std::size_t i = 0; i < m.indices.size(); i += 3) {
    ASSERT_LT(m.indices[i + 2], m.vertices.size());
    const ssr::Vertex& a = m.vertices[m.indices[i]];
    const ssr::Vertex& b = m.vertices[m.indices[i + 1]];
    const ssr::Vertex& c = m.vertices[m.indices[i + 2]];
    const glm::vec3 fn = glm::cross(b.position - a.position, c.position - a.position);
    ASSERT_GT(glm::length(fn), 0.0f) << "zero-area triangle kept";
    EXPECT_GT(glm::dot(fn, a.normal + b.normal + c.normal), 0.0f) << "triangle " << i / 3;
  }
}

// ---- OBJ / MTL ------------------------------------------------------------------------------

TEST(ObjLoad, CubeMaterialsTexturesAndMeshes) {
  const Scene s = ssr::load_scene_obj(kObj + "cube.obj");
  EXPECT_EQ(s.name, "cube");
  ASSERT_EQ(s.meshes.size(), 2u);  // one per (shape, material)
  const ssr::Mesh* red = find_mesh(s, "cube:red");
  const ssr::Mesh* lamp = find_mesh(s, "cube:lamp");
  ASSERT_TRUE(red && lamp);
  EXPECT_EQ(red->indices.size(), 8u * 3);   // 4 quads
  EXPECT_EQ(lamp->indices.size(), 4u * 3);  // 2 quads, one written with relative indices
  EXPECT_EQ(red->vertices.size(), 16u);     // shared (v, vt, vn) corners
  expect_sane_mesh(*red);
  expect_sane_mesh(*lamp);
  EXPECT_EQ(s.triangle_count(), 12u);

  // The bottom face (relative indices) points down.
  for (const ssr::Vertex& v : lamp->vertices) {
    if (v.position.y < 0) {
      EXPECT_NEAR(v.normal.y, -1.0f, 1e-6f);
    }
  }

  // uv: as written in the OBJ (OpenGL convention, v up; no flip).
  bool found = false;
  for (const ssr::Vertex& v : red->vertices)
    if (v.uv == glm::vec2(0.0f, 0.25f)) found = true;
  EXPECT_TRUE(found);

  const ssr::Material& rm = s.materials[static_cast<std::size_t>(red->material)];
  EXPECT_EQ(rm.name, "red");
  EXPECT_EQ(rm.albedo, glm::vec3(1.0f, 0.2f, 0.1f));           // Kd 1.5 clamped
  EXPECT_NEAR(rm.roughness, std::sqrt(2.0f / 100.0f), 1e-6f);  // from Ns 98
  EXPECT_EQ(rm.metallic, 0.0f);
  ASSERT_EQ(rm.albedo_texture, 0);
  ASSERT_EQ(s.images.size(), 1u);
  const ssr::Image& im = s.images[0];
  ASSERT_EQ(im.width, 2);
  ASSERT_EQ(im.height, 2);
  ASSERT_EQ(im.rgba.size(), 16u);
  EXPECT_EQ(std::vector<int>(im.rgba.begin(), im.rgba.begin() + 4),
            (std::vector<int>{255, 0, 0, 255}));
  EXPECT_EQ(std::vector<int>(im.rgba.begin() + 12, im.rgba.end()),
            (std::vector<int>{255, 255, 255, 128}));

  const ssr::Material& lm = s.materials[static_cast<std::size_t>(lamp->material)];
  EXPECT_EQ(lm.name, "lamp");
  EXPECT_EQ(lm.albedo, glm::vec3(0.5f));  // one-value Kd
  EXPECT_EQ(lm.emission, glm::vec3(2.0f, 1.5f, 1.0f));
  EXPECT_FLOAT_EQ(lm.roughness, 0.3f);
  EXPECT_FLOAT_EQ(lm.metallic, 0.75f);
  EXPECT_NEAR(lm.reflectance, 0.5f, 1e-5f);  // Ni 1.5 -> F0 0.04
  EXPECT_EQ(lm.albedo_texture, -1);

  // A bare OBJ gets a camera framing it and default lights.
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].name, "default");
  EXPECT_FALSE(s.lights.empty());
  EXPECT_NO_THROW(ssr::validate(s));
}

TEST(ObjLoad, MissingNormalsAndDegenerateTriangles) {
  const Scene s = ssr::load_scene_obj(kObj + "nonormals.obj");
  ASSERT_EQ(s.meshes.size(), 1u);
  const ssr::Mesh& m = s.meshes[0];
  EXPECT_EQ(m.name, "nonormals");
  EXPECT_EQ(m.indices.size(), 6u);  // the collinear triangle is dropped
  expect_sane_mesh(m);
  // No material: the default one.
  EXPECT_EQ(s.materials[static_cast<std::size_t>(m.material)].name, "default");
  // Flat normals: +Z for the first triangle, -Z for the one whose given normal is zero.
  EXPECT_EQ(m.vertices[0].normal, glm::vec3(0, 0, 1));
  EXPECT_EQ(m.vertices[3].normal, glm::vec3(0, 0, -1));
}

TEST(ObjLoad, AppendWithTransformAndOverride) {
  Scene s;
  s.name = "t";
  s.materials.push_back(ssr::Material{});
  s.materials[0].name = "override";
  const glm::mat4 t = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)) *
                      glm::scale(glm::mat4(1.0f), glm::vec3(-2, 1, 1));  // mirroring
  EXPECT_EQ(ssr::append_obj(s, kObj + "cube.obj", t, 0), 1);  // override: one mesh per shape
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.materials.size(), 1u);  // the MTL's materials are not used
  EXPECT_EQ(s.meshes[0].material, 0);
  expect_sane_mesh(s.meshes[0]);  // winding still agrees with the normals
  for (const ssr::Vertex& v : s.meshes[0].vertices) {
    EXPECT_NEAR(std::abs(v.position.x - 10.0f), 1.0f, 1e-5f);
  }
  EXPECT_THROW(ssr::append_obj(s, kObj + "cube.obj", glm::mat4(0.0f)), InputError);
  EXPECT_THROW(ssr::append_obj(s, kObj + "cube.obj", glm::mat4(1.0f), 5), InputError);
}

TEST(ObjLoad, SizeLimitsAndBinaryFiles) {
  const std::filesystem::path dir =
      std::filesystem::path(testing::TempDir()) / "ssrlab_scene_io_limits";
  std::filesystem::create_directories(dir);
  // Above 1 GiB: refused from the size alone (a sparse file, nothing is read).
  const auto huge = dir / "huge.obj";
  { std::ofstream(huge) << "v 0 0 0\n"; }
  std::filesystem::resize_file(huge, (1ull << 30) + 1);
  expect_message(input_error([&] { ssr::load_scene(huge.string()); }),
                 {"huge.obj", "1073741825 bytes", "1073741824"});
  std::filesystem::remove(huge);
  // A face with more vertices than supported.
  const auto wide = dir / "wide.obj";
  {
    std::ofstream o(wide);
    for (int i = 0; i < 300; ++i)
      o << "v " << std::cos(i * 0.02) << " " << std::sin(i * 0.02) << " 0\n";
    o << "f";
    for (int i = 1; i <= 300; ++i) o << " " << i;
    o << "\n";
  }
  expect_message(input_error([&] { ssr::load_scene(wide.string()); }),
                 {"wide.obj", "line 301", "300 vertices", "256"});
  // Binary junk.
  const auto bin = dir / "binary.obj";
  { std::ofstream(bin, std::ios::binary) << std::string("v 0 0 0\0\1\2", 10); }
  expect_message(input_error([&] { ssr::load_scene(bin.string()); }), {"binary.obj", "NUL"});
  std::filesystem::remove_all(dir);
}

TEST(ObjLoad, ByteOrderMarksAndUndefinedMaterials) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "ssrlab_scene_io_bom";
  std::filesystem::create_directories(dir);
  auto write = [&](const char* name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  };
  // A UTF-8 byte-order mark (Windows editors) is not part of the first line: the first vertex
  // and the first newmtl survive it.
  const std::string bom = "\xEF\xBB\xBF";
  write("bom.mtl", bom + "newmtl red\nKd 1 0 0\n");
  const std::string tri = "mtllib bom.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nusemtl red\nf 1 2 3\n";
  const Scene s = ssr::load_scene_obj(write("bom.obj", bom + "v 9 9 9\n" + tri));
  const Scene plain = ssr::load_scene_obj(write("plain.obj", "v 9 9 9\n" + tri));
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_EQ(plain.meshes.size(), 1u);
  ASSERT_EQ(s.meshes[0].vertices.size(), plain.meshes[0].vertices.size());
  for (std::size_t i = 0; i < s.meshes[0].vertices.size(); ++i)
    EXPECT_EQ(s.meshes[0].vertices[i].position, plain.meshes[0].vertices[i].position);
  const ssr::Material* red = find_material(s, "red");
  ASSERT_NE(red, nullptr);
  EXPECT_EQ(red->albedo, glm::vec3(1, 0, 0));
  // A usemtl name its MTL files do not define is a typo: file, line, name.
  expect_message(input_error([&] {
                   ssr::load_scene_obj(write("typo.obj", "mtllib bom.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                         "usemtl rde\nf 1 2 3\n"));
                 }),
                 {"typo.obj", "line 5", "'rde'", "not defined"});
  // Before the first mtllib tinyobjloader knows no material; a name with a space is two words.
  expect_message(input_error([&] {
                   ssr::load_scene_obj(write("early.obj", "usemtl red\nmtllib bom.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                          "f 1 2 3\n"));
                 }),
                 {"early.obj", "line 1", "before the first 'mtllib'"});
  write("spaced.mtl", "newmtl Material 1\nKd 1 0 0\n");
  expect_message(input_error([&] {
                   ssr::load_scene_obj(write("spaced.obj", "mtllib spaced.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                           "usemtl Material 1\nf 1 2 3\n"));
                 }),
                 {"spaced.obj", "line 5", "'Material 1'", "space"});
  // Without any mtllib a usemtl line only names the part: the default material.
  const Scene bare = ssr::load_scene_obj(write("bare.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n"));
  EXPECT_NE(find_material(bare, "default"), nullptr);
  std::filesystem::remove_all(dir);
}

struct BadFile {
  const char* file;  // under tests/data
  std::vector<std::string> fragments;
};

class MalformedObj : public testing::TestWithParam<BadFile> {};

TEST_P(MalformedObj, ThrowsInputErrorNamingTheProblem) {
  const BadFile& c = GetParam();
  const std::string msg = input_error([&] { ssr::load_scene(kData + "/" + c.file); });
  std::vector<std::string> fragments = c.fragments;
  expect_message(msg, fragments);
}

INSTANTIATE_TEST_SUITE_P(
    Obj, MalformedObj,
    testing::Values(
        BadFile{"obj/bad_negative_index.obj", {"bad_negative_index.obj", "line 4", "-9", "only 3"}},
        BadFile{"obj/bad_index_past_end.obj",
                {"bad_index_past_end.obj", "line 5", "index 4", "past the end"}},
        BadFile{"obj/bad_normal_index.obj",
                {"bad_normal_index.obj", "line 5", "normal index 2", "past the end"}},
        BadFile{"obj/bad_texcoord_index.obj",
                {"bad_texcoord_index.obj", "line 5", "-2", "texture coordinate"}},
        BadFile{"obj/bad_zero_index.obj", {"bad_zero_index.obj", "line 4", "index 0"}},
        BadFile{"obj/bad_nan_vertex.obj", {"bad_nan_vertex.obj", "line 2", "'nan'"}},
        BadFile{"obj/bad_huge_vertex.obj", {"bad_huge_vertex.obj", "line 3", "'1e39'"}},
        BadFile{"obj/bad_garbage_number.obj", {"bad_garbage_number.obj", "line 2", "'abc'"}},
        // Found by fuzzing: tinyobjloader's int exponent overflowed (undefined behaviour).
        BadFile{"obj/bad_exponent_overflow.obj",
                {"bad_exponent_overflow.obj", "line 2", "'0e2147483648'"}},
        BadFile{"obj/bad_garbage_index.obj", {"bad_garbage_index.obj", "line 4", "'2x'"}},
        BadFile{"obj/bad_face_two_vertices.obj",
                {"bad_face_two_vertices.obj", "line 3", "at least 3"}},
        BadFile{"obj/bad_no_faces.obj", {"bad_no_faces.obj", "no faces"}},
        BadFile{"obj/empty.obj", {"empty.obj", "is empty"}},
        BadFile{"obj/all_degenerate.obj", {"all_degenerate.obj", "non-zero area"}},
        BadFile{"obj/bad_missing_texture.obj",
                {"missing_texture.mtl", "line 3", "gone.png", "does not exist"}},
        BadFile{"obj/bad_escape_texture.obj",
                {"escape_texture.mtl", "line 3", "../json/meshes/tex.png", "escapes"}},
        BadFile{"obj/bad_absolute_texture.obj",
                {"absolute_texture.mtl", "line 2", "/etc/hostname", "absolute"}},
        BadFile{"obj/bad_corrupt_texture.obj", {"corrupt.png", "not a readable image"}},
        BadFile{"obj/bad_mtl_nan.obj", {"nan.mtl", "line 2", "'Kd'", "'nan'"}},
        BadFile{"obj/bad_mtl_garbage.obj", {"garbage.mtl", "line 3", "'Ns'", "'1O0'"}},
        BadFile{"obj/bad_missing_mtl.obj",
                {"bad_missing_mtl.obj", "line 1", "nowhere.mtl", "does not exist"}}),
    [](const testing::TestParamInfo<BadFile>& info) {
      std::string name = std::string(info.param.file);
      name = name.substr(name.find('/') + 1);
      name = name.substr(0, name.find('.'));
      return name;
    });

// ---- JSON -----------------------------------------------------------------------------------

TEST(JsonLoad, GoodFile) {
  const Scene s = ssr::load_scene_json(kJson + "good.json");
  EXPECT_EQ(s.name, "json-good");
  EXPECT_FLOAT_EQ(s.ambient, 0.25f);
  EXPECT_EQ(s.environment.type, ssr::Environment::Type::Constant);
  EXPECT_EQ(s.environment.constant, glm::vec3(0.2f, 0.3f, 0.4f));
  EXPECT_FLOAT_EQ(s.environment.intensity, 2.0f);

  ASSERT_EQ(s.meshes.size(), 4u);
  const ssr::Mesh* quad = &s.meshes[0];
  const ssr::Mesh* mirror = &s.meshes[1];
  const ssr::Mesh* ground = find_mesh(s, "ground");
  const ssr::Mesh* sphere = find_mesh(s, "sphere1");
  ASSERT_TRUE(ground && sphere);
  expect_sane_mesh(*quad);
  expect_sane_mesh(*mirror);

  // Transforms: scale 2 then translate; rotate 90 degrees about X then translate.
  for (const ssr::Vertex& v : quad->vertices) {
    EXPECT_NEAR(v.position.y, 2.0f, 1e-6f);
    EXPECT_NEAR(std::abs(v.position.x), 2.0f, 1e-6f);
    EXPECT_NEAR(v.normal.y, 1.0f, 1e-6f);
  }
  for (const ssr::Vertex& v : mirror->vertices) {
    EXPECT_NEAR(v.position.z, -3.0f, 1e-5f);
    EXPECT_NEAR(v.normal.z, 1.0f, 1e-5f);
  }

  // Materials: the MTL's for the first mesh, the override for the second, "default" for the
  // sphere; tex.png is loaded once although two materials use it.
  EXPECT_EQ(s.materials[static_cast<std::size_t>(quad->material)].name, "tiles");
  EXPECT_EQ(s.materials[static_cast<std::size_t>(mirror->material)].name, "mirror");
  EXPECT_EQ(s.materials[static_cast<std::size_t>(sphere->material)].name, "default");
  const ssr::Material* floor = find_material(s, "floor");
  ASSERT_TRUE(floor);
  EXPECT_EQ(floor->albedo, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_FLOAT_EQ(floor->roughness, 0.2f);
  EXPECT_EQ(s.images.size(), 1u);
  EXPECT_EQ(find_material(s, "mirror")->albedo_texture, 0);
  EXPECT_EQ(find_material(s, "tiles")->albedo_texture, 0);
  EXPECT_FLOAT_EQ(find_material(s, "tiles")->roughness, 0.4f);

  // Reflectors: explicit for the mirror, the plane's own rectangle for the ground.
  ASSERT_EQ(s.reflectors.size(), 2u);
  EXPECT_EQ(quad->reflector, 0);
  EXPECT_EQ(mirror->reflector, 1);
  EXPECT_EQ(ground->reflector, 2);
  EXPECT_EQ(s.reflectors[0].center, glm::vec3(0, 1, -3));
  EXPECT_NEAR(glm::dot(s.reflectors[0].normal(), glm::vec3(0, 0, 1)), 1.0f, 1e-6f);
  const ssr::Reflector& g = s.reflectors[1];
  EXPECT_NEAR(glm::length(g.center - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(g.half_extents.x, 5.0f, 1e-5f);
  EXPECT_NEAR(g.half_extents.y, 6.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(g.normal(), glm::vec3(0, 1, 0)), 1.0f, 1e-6f);

  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, ssr::Light::Type::Point);
  EXPECT_FLOAT_EQ(s.lights[0].range, 12.0f);
  EXPECT_EQ(s.lights[1].type, ssr::Light::Type::Directional);
  EXPECT_EQ(s.lights[1].direction, glm::vec3(0, -1, 0));  // normalised

  ASSERT_EQ(s.cameras.size(), 2u);
  EXPECT_EQ(s.cameras[0].name, "default");
  EXPECT_FLOAT_EQ(s.cameras[0].fov_y_deg, 45.0f);
  EXPECT_EQ(s.camera("top").far_plane, 100.0f);
  EXPECT_NO_THROW(ssr::validate(s));
}

TEST(JsonLoad, MinimalFileGetsDefaults) {
  const Scene s = ssr::load_scene(kJson + "minimal.json");
  EXPECT_EQ(s.name, "minimal");
  ASSERT_EQ(s.cameras.size(), 1u);  // framing camera
  EXPECT_EQ(s.cameras[0].name, "default");
  EXPECT_TRUE(s.lights.empty());
  EXPECT_NO_THROW(ssr::validate(s));
}

class MalformedJson : public testing::TestWithParam<BadFile> {};

TEST_P(MalformedJson, ThrowsInputErrorNamingTheProblem) {
  const BadFile& c = GetParam();
  const std::string msg = input_error([&] { ssr::load_scene(kData + "/" + c.file); });
  expect_message(msg, c.fragments);
}

INSTANTIATE_TEST_SUITE_P(
    Json, MalformedJson,
    testing::Values(
        BadFile{"json/bad_syntax.json", {"bad_syntax.json", "line 3", "column", "syntax error"}},
        // Found by fuzzing: nlohmann throws out_of_range, not parse_error, for this.
        BadFile{"json/bad_number_overflow.json",
                {"bad_number_overflow.json", "number overflow", "1e400"}},
        BadFile{"json/bad_unclosed.json", {"bad_unclosed.json", "line 5", "syntax error"}},
        BadFile{"json/empty.json", {"empty.json", "is empty"}},
        BadFile{"json/bad_not_object.json", {"bad_not_object.json", "object"}},
        BadFile{"json/bad_unknown_key.json",
                {"bad_unknown_key.json", "unknown key", "'materials.floor.rougness'"}},
        BadFile{"json/bad_unknown_top_key.json",
                {"bad_unknown_top_key.json", "unknown key", "'colour'"}},
        BadFile{"json/bad_wrong_type.json",
                {"bad_wrong_type.json", "'materials.floor.roughness' must be a number"}},
        BadFile{"json/bad_wrong_vec.json",
                {"bad_wrong_vec.json", "'meshes[0].translate'", "3 numbers"}},
        BadFile{"json/bad_out_of_range.json",
                {"bad_out_of_range.json", "'materials.floor.roughness'", "[0, 1]"}},
        BadFile{"json/bad_missing_mesh.json",
                {"bad_missing_mesh.json", "missing.obj", "does not exist"}},
        BadFile{"json/bad_escape.json", {"bad_escape.json", "../obj/cube.obj", "escapes"}},
        BadFile{"json/bad_absolute.json", {"bad_absolute.json", "/etc/hostname.obj", "absolute"}},
        BadFile{"json/bad_zero_reflector.json",
                {"bad_zero_reflector.json", "half_extents", "zero-area"}},
        BadFile{"json/bad_skew_reflector.json",
                {"bad_skew_reflector.json", "'meshes[0].reflector'", "orthogonal"}},
        BadFile{"json/bad_unknown_material.json",
                {"bad_unknown_material.json", "'meshes[0].material'", "'nope'"}},
        BadFile{"json/bad_duplicate_key.json", {"bad_duplicate_key.json", "'name' twice"}},
        BadFile{"json/bad_light_key.json", {"bad_light_key.json", "'lights[0].direction'"}},
        BadFile{"json/bad_camera_up.json", {"bad_camera_up.json", "'cameras[0].up'", "parallel"}},
        BadFile{"json/bad_primitive_type.json",
                {"bad_primitive_type.json", "'primitives[0].type'", "'torus'"}},
        BadFile{"json/bad_zero_scale.json", {"bad_zero_scale.json", "'meshes[0].scale'"}},
        BadFile{"json/bad_no_meshes.json", {"bad_no_meshes.json", "no meshes"}},
        BadFile{"json/bad_obj_inside.json",
                {"bad_obj_inside.json", "'meshes[0].obj'", "broken.obj", "line 3", "-5"}}),
    [](const testing::TestParamInfo<BadFile>& info) {
      std::string name = std::string(info.param.file);
      name = name.substr(name.find('/') + 1);
      name = name.substr(0, name.find('.'));
      return name;
    });

// ---- found by fuzzing (tests/fuzz, docs/ROBUSTNESS.md) --------------------------------------

std::filesystem::path fuzz_file(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(testing::TempDir()) / "ssrlab_fuzz_regressions";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

// Inputs that the fuzzers found slow: quadratic work in big, valid-looking files (the old code
// took minutes at these sizes), since made linear. They must still load correctly; there is no
// timing assert (timings belong in `ssrlab bench`): a return to quadratic time shows as the
// suite's timeout.
TEST(FuzzRegressions, LongJsonArraysParseQuickly) {
  // nlohmann's parse() with a callback (used to catch duplicate keys) rescanned the enclosing
  // array after every object.
  std::string text = "{\"primitives\": [{}";
  for (int i = 1; i < 200000; ++i) text += ",{}";
  text += "]}";
  const auto path = fuzz_file("long_array.json", text);
  expect_message(input_error([&] { ssr::load_scene_json(path); }),
                 {"long_array.json", "'primitives[0].type'", "required"});
  // Duplicate keys are still found, at any depth.
  const auto dup = fuzz_file("nested_duplicate.json",
                             R"({"materials": {"a": {"albedo": [1, 1, 1], "albedo": [0, 0, 0]}}})");
  expect_message(input_error([&] { ssr::load_scene_json(dup); }), {"'albedo' twice"});
}

TEST(FuzzRegressions, ManyObjMaterialsLoadQuickly) {
  // parse_mtl compared every newmtl with all earlier materials; append_obj searched its mesh
  // builders, and the scene's materials for "default", once per face.
  constexpr int n = 20000;
  std::string mtl, obj = "mtllib many.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < 20 * n; ++i) obj += "f 1 2 3\n";  // before any usemtl: "default"
  for (int i = 0; i < n; ++i) {
    mtl += "newmtl m" + std::to_string(i) + "\n";
    obj += "usemtl m" + std::to_string(i) + "\nf 1 2 3\n";
  }
  fuzz_file("many.mtl", mtl);
  const auto path = fuzz_file("many.obj", obj);
  Scene s;
  s = ssr::load_scene_obj(path);
  EXPECT_EQ(s.materials.size(), std::size_t{n} + 1);  // and "default"
  EXPECT_EQ(s.meshes.size(), std::size_t{n} + 1);
  // The name index still finds a duplicate and names the first definition.
  fuzz_file("many.mtl", mtl + "newmtl m7\n");
  expect_message(input_error([&] { ssr::load_scene_obj(path); }),
                 {"many.mtl", "line 20001", "'m7'", "defined twice", "line 8"});
}

TEST(FuzzRegressions, ManyJsonMaterialsAndPrimitivesLoadQuickly) {
  // find_material and the primitives' default material were linear searches per primitive.
  constexpr int materials = 100000, primitives = 20000;
  std::string text = "{\"materials\": {";
  for (int i = 0; i < materials; ++i) text += (i ? ", \"m" : "\"m") + std::to_string(i) + "\": {}";
  text += "}, \"primitives\": [";
  for (int i = 0; i < 2 * primitives; ++i)
    text += std::string(i ? ", " : "") + R"({"type": "plane", "size": [1, 1])" +
            (i % 2 ? "}" : R"(, "material": "m99999"})");
  text += "]}";
  const auto path = fuzz_file("many_materials.json", text);
  Scene s;
  s = ssr::load_scene_json(path);
  ASSERT_EQ(s.meshes.size(), std::size_t{2 * primitives});
  EXPECT_EQ(s.materials[static_cast<std::size_t>(s.meshes[0].material)].name, "m99999");
  EXPECT_EQ(s.materials[static_cast<std::size_t>(s.meshes[1].material)].name, "default");
}

// ---- load_scene dispatch and the example scene -------------------------------------------------

// A range's end values are legal, as the float they are stored as: 1.001 and 178.999 were
// refused ("must be in [1.001, 178.999], not 1.001") when compared as doubles with float bounds.
TEST(JsonLoad, RangeEndsAreAccepted) {
  for (const char* fov : {"1.001", "178.999"}) {
    const auto file = fuzz_file(std::string("fov_") + fov + ".json",
                                std::string(R"({"primitives": [{"type": "plane", "name": "floor", "size": [10, 10]}],
                                               "cameras": [{"name": "c", "position": [0, 1, 3], "target": [0, 0, 0], "fov_y": )") +
                                    fov + "}]}");
    EXPECT_NO_THROW(ssr::load_scene(file.string())) << fov;
  }
}

TEST(LoadScene, ExamplePedestalScene) {
  const Scene s = ssr::load_scene(kPedestal);
  EXPECT_EQ(s.name, "pedestal");
  EXPECT_EQ(s.reflectors.size(), 2u);
  EXPECT_EQ(s.cameras.size(), 3u);
  EXPECT_NO_THROW(s.camera("mirror"));
  EXPECT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.images.size(), 2u);  // checker.png, bumps.png
  for (const char* name : {"pedestal:stone", "pedestal:gold", "panel", "mirror", "floor"})
    EXPECT_TRUE(find_mesh(s, name)) << name;
  for (const char* name : {"pedestal:stone", "pedestal:gold", "panel", "mirror"})
    expect_sane_mesh(*find_mesh(s, name));
  const ssr::Material* gold = find_material(s, "gold");
  ASSERT_TRUE(gold);
  EXPECT_FLOAT_EQ(gold->metallic, 1.0f);
  EXPECT_FLOAT_EQ(gold->roughness, 0.22f);
  const ssr::Material* stone = find_material(s, "stone");
  ASSERT_TRUE(stone);
  EXPECT_GE(stone->normal_texture, 0);
  EXPECT_FLOAT_EQ(stone->normal_strength, 0.6f);
  EXPECT_EQ(find_mesh(s, "mirror")->reflector, 1);
  EXPECT_EQ(find_mesh(s, "floor")->reflector, 2);
  EXPECT_NO_THROW(ssr::validate(s));
}

TEST(LoadScene, Dispatch) {
  const std::string builtin = ssr::builtin_scenes().front().name;
  EXPECT_NO_THROW(ssr::load_scene(builtin));
  EXPECT_EQ(ssr::load_scene(kObj + "cube.obj").meshes.size(), 2u);

  expect_message(input_error([&] { ssr::load_scene(kJson + "nope.json"); }),
                 {"scene file", "nope.json", "does not exist"});
  expect_message(input_error([&] { ssr::load_scene(kObj + "nope.obj"); }),
                 {"nope.obj", "does not exist"});
  expect_message(input_error([&] { ssr::load_scene_json(kJson + "nope.json"); }),
                 {"nope.json", "does not exist"});
  expect_message(input_error([&] { ssr::load_scene("no-such-scene"); }),
                 {"'no-such-scene'", builtin});
  expect_message(input_error([&] { ssr::load_scene(kObj + "cube.mtl"); }),
                 {"cube.mtl", ".json", ".obj", builtin});
  expect_message(input_error([&] { ssr::load_scene(kData + "/obj"); }), {"obj", builtin});
}

// ---- validate() on hand-made scenes ------------------------------------------------------------

Scene tiny_scene() {
  Scene s;
  s.name = "tiny";
  ssr::Mesh m;
  m.name = "tri";
  const glm::vec4 t(1, 0, 0, 1);
  m.vertices = {{{0, 0, 0}, {0, 0, 1}, {0, 0}, t},
                {{1, 0, 0}, {0, 0, 1}, {1, 0}, t},
                {{0, 1, 0}, {0, 0, 1}, {0, 1}, t}};
  m.indices = {0, 1, 2};
  s.meshes.push_back(m);
  s.materials.push_back(ssr::Material{});
  s.materials[0].name = "m";
  s.cameras.push_back(ssr::Camera{});
  s.cameras[0].name = "default";
  return s;
}

void expect_invalid(const Scene& s, const std::string& fragment) {
  expect_message(input_error([&] { ssr::validate(s); }), {"'tiny'", fragment});
}

TEST(Validate, AcceptsAMinimalScene) { EXPECT_NO_THROW(ssr::validate(tiny_scene())); }

TEST(Validate, RejectsBrokenInvariants) {
  {
    Scene s = tiny_scene();
    s.meshes[0].indices[2] = 3;
    expect_invalid(s, "vertex index 3");
  }
  {
    Scene s = tiny_scene();
    s.meshes[0].indices.pop_back();
    expect_invalid(s, "multiple of 3");
  }
  {
    Scene s = tiny_scene();
    s.meshes[0].vertices[1].normal = glm::vec3(0, 0, 2);
    expect_invalid(s, "not unit length");
  }
  {
    Scene s = tiny_scene();
    s.meshes[0].vertices[0].position.x = std::nanf("");
    expect_invalid(s, "not finite");
  }
  {
    Scene s = tiny_scene();
    s.materials[0].albedo = glm::vec3(1.5f, 0, 0);
    expect_invalid(s, "albedo must be in [0,1]");
  }
  {
    Scene s = tiny_scene();
    s.materials[0].albedo_texture = 0;  // no images
    expect_invalid(s, "albedo texture index");
  }
  {
    Scene s = tiny_scene();
    s.meshes[0].reflector = 1;  // no reflectors
    expect_invalid(s, "reflector id");
  }
  {
    Scene s = tiny_scene();
    s.reflectors.push_back(ssr::Reflector{});
    s.reflectors[0].half_extents = glm::vec2(1.0f, 0.0f);
    expect_invalid(s, "zero-area");
  }
  {
    Scene s = tiny_scene();
    s.reflectors.push_back(ssr::Reflector{});
    s.reflectors[0].bitangent = glm::normalize(glm::vec3(1, 0, 1));
    expect_invalid(s, "not orthogonal");
  }
  {
    Scene s = tiny_scene();
    s.cameras[0].target = s.cameras[0].position;
    expect_invalid(s, "target equals its position");
  }
  {
    Scene s = tiny_scene();
    s.cameras[0].up = glm::normalize(s.cameras[0].target - s.cameras[0].position);
    expect_invalid(s, "parallel");
  }
  {
    Scene s = tiny_scene();
    s.lights.resize(Scene::kMaxLights + 1);
    expect_invalid(s, "more than the 32");
  }
  {
    Scene s = tiny_scene();
    s.lights.push_back(ssr::Light{});
    s.lights[0].type = ssr::Light::Type::Directional;
    s.lights[0].direction = glm::vec3(0.0f);
    expect_invalid(s, "unit direction");
  }
  {
    Scene s = tiny_scene();
    s.meshes.clear();
    expect_invalid(s, "no meshes");
  }
  {
    Scene s = tiny_scene();
    s.images.push_back(ssr::Image{2, 2, std::vector<std::uint8_t>(15)});
    expect_invalid(s, "inconsistent size");
  }
  {
    Scene s = tiny_scene();
    s.environment.intensity = -1.0f;
    expect_invalid(s, "environment");
  }
}

}  // namespace
