// Every shared struct (shaders/shared/*.h) has the same size in C++ as the GL gives its block:
// std140 for uniform blocks, std430 for storage buffers. A mismatch shifts every member after it
// (or leaves the end of a block outside the buffer). ReferenceParams is C++ only (no block).
#include <gtest/gtest.h>

#include <string>

#include "gl/program.h"
#include "gl_test_env.h"
#include "shared/dda.h"
#include "shared/frame.h"
#include "shared/hiz.h"
#include "shared/linear.h"
#include "shared/linear_binary.h"
#include "shared/ppr.h"
#include "shared/reference.h"
#include "shared/stochastic.h"
#include "shared/telemetry.h"

using namespace ssr;

namespace {

struct Layout {
  const char* type;    // the struct's name in both languages
  const char* member;  // a member the shader reads, so that the block is active
  std::size_t cpp_size;
  bool uniform;        // std140 uniform block, else std430 storage block
};

#define SSR_LAYOUT(T, member, uniform) Layout{#T, member, sizeof(shared::T), uniform}
const Layout kLayouts[] = {
    SSR_LAYOUT(FrameUniforms, "view[0][0]", true),
    SSR_LAYOUT(DrawUniforms, "albedo_metallic.x", true),
    SSR_LAYOUT(LinearParams, "ray.samples", true),
    SSR_LAYOUT(LinearBinaryParams, "ray.samples", true),
    SSR_LAYOUT(DdaParams, "ray.samples", true),
    SSR_LAYOUT(HizParams, "ray.samples", true),
    SSR_LAYOUT(PprParams, "hole_fill", true),
    SSR_LAYOUT(StochasticParams, "denoise.history", true),
    SSR_LAYOUT(DenoisePass, "trace.x", true),
    SSR_LAYOUT(ClassifyParams, "trace_size.x", true),
    SSR_LAYOUT(GpuLight, "position_type.x", false),
    SSR_LAYOUT(PprReflector, "plane.x", false),
    SSR_LAYOUT(ReferenceSample, "position.x", false),
    SSR_LAYOUT(ReferencePixel, "data.x", false),
    SSR_LAYOUT(ReferenceMaterial, "albedo_metallic.x", false),
    SSR_LAYOUT(TileListHeader, "rays", false),
    SSR_LAYOUT(RayListHeader, "count", false),
    SSR_LAYOUT(TelemetryHeader, "warps", false),
};
#undef SSR_LAYOUT

// One compute shader declaring a block per struct (two elements each for storage blocks, whose
// data size is then twice the array stride) and reading one member of each.
std::string layout_shader() {
  std::string s =
      "#include \"shared/frame.h\"\n#include \"shared/ray_options.h\"\n#include \"shared/linear.h\"\n"
      "#include \"shared/linear_binary.h\"\n#include \"shared/dda.h\"\n#include \"shared/hiz.h\"\n"
      "#include \"shared/ppr.h\"\n#include \"shared/reference.h\"\n#include \"shared/stochastic.h\"\n"
      "#include \"shared/telemetry.h\"\n#include \"shared/classification.h\"\n"
      "layout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer Sink { float sink; };\n";
  std::string body;
  int i = 0;
  for (const Layout& l : kLayouts) {
    const std::string n = std::to_string(i++);
    if (l.uniform)
      s += std::string("layout(std140, binding = ") + n + ") uniform Block" + n + " { " + l.type + " v; } b" + n + ";\n";
    else
      s += std::string("layout(std430, binding = ") + std::to_string(i) + ") buffer Block" + n + " { " + l.type +
           " v[2]; } b" + n + ";\n";
    body += std::string("  sink += float(b") + n + (l.uniform ? ".v." : ".v[1].") + l.member + ");\n";
  }
  return s + "void main() {\n" + body + "}\n";
}

}  // namespace

TEST(Layouts, SharedStructsMatchTheirBlocks) {
  const gl::Program prog = test::compile_test_shader("layouts", layout_shader());
  int i = 0;
  for (const Layout& l : kLayouts) {
    const std::string block = "Block" + std::to_string(i++);
    const GLenum iface = l.uniform ? GL_UNIFORM_BLOCK : GL_SHADER_STORAGE_BLOCK;
    const GLuint index = glGetProgramResourceIndex(prog.id(), iface, block.c_str());
    ASSERT_NE(index, GL_INVALID_INDEX) << l.type;
    const GLenum prop = GL_BUFFER_DATA_SIZE;
    GLint size = 0;
    glGetProgramResourceiv(prog.id(), iface, index, 1, &prop, 1, nullptr, &size);
    EXPECT_EQ(static_cast<std::size_t>(size), l.uniform ? l.cpp_size : 2 * l.cpp_size)
        << l.type << (l.uniform ? " (std140)" : " (std430, 2 elements)");
  }
  test::expect_no_gl_errors();
}
