// The program loader: #include expansion, file:line error reports, embedded vs directory.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/errors.h"
#include "gl/program.h"
#include "gl_test_env.h"
#include "scene/builtin_scenes.h"
#include "techniques/technique.h"
#include "registry/registry.h"

using namespace ssr;
namespace fs = std::filesystem;

namespace {
fs::path make_shader_dir() {
  const fs::path dir = fs::temp_directory_path() / ("ssrlab-shaders-" + std::to_string(::getpid()));
  fs::create_directories(dir / "common");
  std::ofstream(dir / "common/a.glsl") << "#pragma once\nfloat twice(float x) { return 2.0 * x; }\n";
  std::ofstream(dir / "ok.comp") << "#include \"common/a.glsl\"\n#include \"common/a.glsl\"\n"
                                    "layout(local_size_x = 8, local_size_y = 4) in;\n"
                                    "layout(std430, binding = 0) buffer B { float v[]; };\n"
                                    "void main() { v[gl_GlobalInvocationID.x] = twice(float(gl_GlobalInvocationID.x)); }\n";
  std::ofstream(dir / "common/bad.glsl") << "// line 1\n// line 2\nfloat broken() { return undefined_name; }\n";
  std::ofstream(dir / "bad.comp") << "#include \"common/bad.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n";
  return dir;
}
}  // namespace

TEST(Program, IncludesOnceAndRuns) {
  const fs::path dir = make_shader_dir();
  gl::ShaderSource src(dir);
  std::vector<std::string> files;
  const std::string text = src.expand("ok.comp", {}, files);
  EXPECT_EQ(files.size(), 2u);  // ok.comp and common/a.glsl, once
  gl::Program p = gl::Program::compute(src, "ok.comp");
  gl::Buffer buf = gl::make_buffer("test", 64 * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf.id());
  p.dispatch_2d(64, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> out(64);
  glGetNamedBufferSubData(buf.id(), 0, 64 * sizeof(float), out.data());
  for (int i = 0; i < 64; ++i) EXPECT_EQ(out[static_cast<std::size_t>(i)], 2.0f * i);
  fs::remove_all(dir);
  test::expect_no_gl_errors();
}

TEST(Program, CompileErrorNamesFileAndLine) {
  const fs::path dir = make_shader_dir();
  gl::ShaderSource src(dir);
  try {
    gl::Program::compute(src, "bad.comp");
    FAIL() << "expected a compile error";
  } catch (const RuntimeError& e) {
    // Named where it is: in the directory given, not the checkout's shaders/.
    EXPECT_NE(std::string(e.what()).find((dir / "common/bad.glsl").string() + ":3"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
  gl::take_gl_errors();  // a failed compile may be reported through KHR_debug too
}

TEST(Program, EveryEmbeddedProgramCompiles) {
  gl::ShaderSource embedded;
  for (const char* p : {"render/lighting.comp", "render/composite.comp", "render/display.comp",
                        "techniques/linear.comp", "techniques/none.comp", "eval/floor.comp",
                        "techniques/hiz.comp", "render/hiz_pyramid.comp",
                        "reference/shade.comp", "reference/planar_resolve.comp", "techniques/ppr_clear.comp",
                        "techniques/ppr_project.comp", "techniques/ppr_resolve.comp"})
    EXPECT_NO_THROW(gl::Program::compute(embedded, p)) << p;
  EXPECT_NO_THROW(gl::Program::graphics(embedded, "render/gbuffer.vert", "render/gbuffer.frag"));
  test::expect_no_gl_errors();
}

// F5 in the viewer: a shader broken while the program runs is reported with its file:line, and
// the last good programs keep rendering the same frame.
TEST(Program, FailedReloadKeepsTheLastGoodPrograms) {
  const fs::path dir = fs::temp_directory_path() / ("ssrlab-reload-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::copy(SSRLAB_SHADER_DIR, dir, fs::copy_options::recursive);
  const Scene scene = make_builtin_scene("gallery");
  Renderer r(scene, 64, 36, gl::ShaderSource(dir));
  auto technique = create_technique("linear");
  technique->load(r.shaders());
  r.render(scene.cameras.front(), *technique, ViewMode::Final, nullptr);
  const RgbaImage8 before = r.read_display();

  std::ofstream(dir / "render/lighting.comp", std::ios::app) << "\nthis is not GLSL\n";
  try {
    r.reload_shaders();
    ADD_FAILURE() << "expected the reload to fail";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("render/lighting.comp:"), std::string::npos) << e.what();
  }
  gl::take_gl_errors();  // the failed compile may be reported through KHR_debug too
  r.render(scene.cameras.front(), *technique, ViewMode::Final, nullptr);
  test::expect_same_image(r.read_display(), before, "failed-reload-keeps-programs");
  fs::remove_all(dir);
  test::expect_no_gl_errors();
}

// A program compiled with "SSR_ROWS N" covers N pixel rows per invocation (common/screen_rows.glsl)
// and dispatch_2d gives it N times fewer groups: every pixel of an odd size is visited once, by
// no more groups than that.
TEST(Program, SeveralRowsPerInvocationVisitEveryPixelOnce) {
  const fs::path dir = fs::temp_directory_path() / ("ssrlab-rows-" + std::to_string(::getpid()));
  fs::create_directories(dir / "common");
  std::ofstream(dir / "common/screen_rows.glsl") << gl::ShaderSource().read("common/screen_rows.glsl");
  std::ofstream(dir / "rows.comp") << "#include \"common/screen_rows.glsl\"\n"
                                      "layout(local_size_x = 8, local_size_y = 8) in;\n"
                                      "layout(std430, binding = 0) buffer B { uint visits[]; };\n"
                                      "layout(location = 0) uniform ivec2 size;\n"
                                      "void main() {\n"
                                      "  if (gl_LocalInvocationIndex == 0u) atomicAdd(visits[size.x * size.y], 1u);\n"
                                      "  for (int r = 0; r < SSR_ROWS; ++r) {\n"
                                      "    ivec2 p = screen_pixel(r);\n"
                                      "    if (all(lessThan(p, size))) atomicAdd(visits[p.y * size.x + p.x], 1u);\n"
                                      "  }\n"
                                      "}\n";
  const gl::ShaderSource src(dir);
  const int w = 37, h = 29;
  for (int rows : {1, 2, 3, 4}) {
    gl::Program p = gl::Program::compute(src, "rows.comp", {"SSR_ROWS " + std::to_string(rows)});
    std::vector<GLuint> visits(static_cast<std::size_t>(w * h) + 1, 0u);  // the last: work groups run
    gl::Buffer buf = gl::make_buffer("visits", static_cast<GLsizeiptr>(visits.size() * sizeof(GLuint)), visits.data(),
                                     GL_DYNAMIC_STORAGE_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf.id());
    glProgramUniform2i(p.id(), 0, w, h);
    p.dispatch_2d(w, h);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buf.id(), 0, static_cast<GLsizeiptr>(visits.size() * sizeof(GLuint)), visits.data());
    for (std::size_t i = 0; i + 1 < visits.size(); ++i)
      ASSERT_EQ(visits[i], 1u) << rows << " rows: pixel " << i % w << ", " << i / w;
    EXPECT_EQ(visits.back(), static_cast<GLuint>(((w + 7) / 8) * ((h + 8 * rows - 1) / (8 * rows)))) << rows << " rows";
  }
  fs::remove_all(dir);
  test::expect_no_gl_errors();
}
