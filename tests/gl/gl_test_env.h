// Helpers shared by the GL tests.
#pragma once
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gl/program.h"

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

}  // namespace ssr::test
