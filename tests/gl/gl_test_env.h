// Helpers shared by the GL tests.
#pragma once
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gl/program.h"
#include "render/image_io.h"

#include "gl/context.h"
#include "eval/metrics.h"
#include "render/renderer.h"

namespace ssr::test {

extern gl::HeadlessContext* g_context;

// Fails the current test with the GL errors recorded since the last call.
inline void expect_no_gl_errors() {
  for (const std::string& e : gl::take_gl_errors()) ADD_FAILURE() << "GL error: " << e;
}

inline std::size_t count_nonfinite(const RgbaImageF& im) { return ssr::count_nonfinite(im.pixels); }

// Texel (x, y) with y = 0 the top row.
inline const float* texel(const RgbaImageF& im, int x, int y) {
  return &im.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(im.width) +
                     static_cast<std::size_t>(x)) * 4];
}

// Pixels of planar reflectors (G-buffer reflector id > 0), row 0 = top like read-back images.
inline std::vector<bool> planar_mask(const Renderer& r) {
  const int w = r.width(), h = r.height();
  const std::vector<std::uint16_t> m = r.read_material();
  std::vector<bool> out(static_cast<std::size_t>(w) * h);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = m[i * 4] > 0;
  return out;
}

// Compiles a test's own compute shader `source` (it may #include anything under shaders/) from
// a temporary copy of the shader tree, removed again whatever happens.
inline gl::Program compile_test_shader(const std::string& name, const std::string& source) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ssrlab-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::copy(SSRLAB_SHADER_DIR, dir, fs::copy_options::recursive);
  fs::create_directories(dir / "test");
  std::ofstream(dir / "test" / (name + ".comp")) << source;
  struct Remove {
    fs::path dir;
    ~Remove() { fs::remove_all(dir); }
  } remove{dir};
  return gl::Program::compute(gl::ShaderSource(dir), "test/" + name + ".comp");
}

// A twin test's GPU side: `cases` at SSBO binding 0, one invocation each (local size 64 along
// x), the results read back from binding 1 (the shader writes one Out per case).
template <class Out, class In>
std::vector<Out> run_twin_shader(const gl::Program& prog, const std::vector<In>& cases) {
  const auto n = static_cast<GLsizeiptr>(cases.size());
  gl::Buffer in = gl::make_buffer("twin cases", n * GLsizeiptr(sizeof(In)), cases.data());
  gl::Buffer out = gl::make_buffer("twin results", n * GLsizeiptr(sizeof(Out)));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  prog.dispatch_2d(static_cast<int>(n), 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<Out> results(cases.size());
  glGetNamedBufferSubData(out.id(), 0, n * GLsizeiptr(sizeof(Out)), results.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  return results;
}

// Writes <name>-a.png, <name>-b.png and <name>-diff.png (|a - b| x 16, tone-free) into
// $SSRLAB_TEST_OUT (default: the system's temporary directory); returns "<dir>/<name>-{a,b,diff}.png".
inline std::string write_image_pair(const RgbaImageF& a, const RgbaImageF& b, const std::string& name) {
  namespace fs = std::filesystem;
  const char* env = std::getenv("SSRLAB_TEST_OUT");
  const fs::path dir = env && *env ? fs::path(env) : fs::temp_directory_path();
  std::string file = name;
  for (char& c : file)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
  auto to8 = [](const RgbaImageF& im, auto value) {
    RgbaImage8 out{im.width, im.height, std::vector<std::uint8_t>(im.pixels.size())};
    for (std::size_t i = 0; i < im.pixels.size(); ++i)
      out.pixels[i] = (i & 3) == 3 ? 255 : static_cast<std::uint8_t>(std::clamp(value(i), 0.0f, 1.0f) * 255.0f + 0.5f);
    return out;
  };
  write_png(dir / (file + "-a.png"), to8(a, [&](std::size_t i) { return a.pixels[i]; }));
  write_png(dir / (file + "-b.png"), to8(b, [&](std::size_t i) { return b.pixels[i]; }));
  if (a.pixels.size() == b.pixels.size())
    write_png(dir / (file + "-diff.png"), to8(a, [&](std::size_t i) { return std::abs(a.pixels[i] - b.pixels[i]) * 16.0f; }));
  return (dir / (file + "-{a,b,diff}.png")).string();
}

// Whether two float images are the same bit for bit. When not, the test fails and the pair is
// written (write_image_pair) and named in the failure.
inline bool expect_same_image(const RgbaImageF& a, const RgbaImageF& b, const std::string& name) {
  if (a.width == b.width && a.height == b.height &&
      std::equal(a.pixels.begin(), a.pixels.end(), b.pixels.begin(), b.pixels.end(),
                 [](float x, float y) { return std::memcmp(&x, &y, sizeof x) == 0; }))
    return true;
  ADD_FAILURE() << name << ": the images differ; written " << write_image_pair(a, b, name);
  return false;
}

// Images a test scored (a technique's frame and its truth), kept until the test ends: when it
// fails, gl_test_main.cpp writes each pair (write_image_pair), so a failing threshold test
// leaves the pictures behind too (Falcor's habit).
struct NotedImages {
  std::string name;
  RgbaImageF a, b;
};
inline std::vector<NotedImages>& noted_images() {
  static std::vector<NotedImages> v;
  return v;
}
inline void note_images_for_failure(std::string name, const RgbaImageF& a, const RgbaImageF& b) {
  noted_images().push_back({std::move(name), a, b});
}

// The same for 8-bit images (display images): compared as they are, written as they are.
inline bool expect_same_image(const RgbaImage8& a, const RgbaImage8& b, const std::string& name) {
  auto to_float = [](const RgbaImage8& im) {
    RgbaImageF f{im.width, im.height, std::vector<float>(im.pixels.size())};
    for (std::size_t i = 0; i < im.pixels.size(); ++i) f.pixels[i] = im.pixels[i] / 255.0f;
    return f;
  };
  return expect_same_image(to_float(a), to_float(b), name);
}

}  // namespace ssr::test
