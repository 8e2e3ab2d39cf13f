// Shader source handling without GL: info-log mapping and include expansion.
#include <gtest/gtest.h>

#include "core/errors.h"
#include "gl/program.h"

using namespace ssr;

TEST(ShaderSource, MapsMesaAndNvidiaLogs) {
  const std::vector<std::string> files = {"techniques/linear.comp", "common/frame.glsl"};
  EXPECT_EQ(gl::map_info_log("1:12(5): error: `x' undeclared\n", files),
            "shaders/common/frame.glsl:12:5: error: `x' undeclared\n");
  EXPECT_EQ(gl::map_info_log("0(7) : error C1008: undefined variable \"y\"\n", files),
            "shaders/techniques/linear.comp:7: error C1008: undefined variable \"y\"\n");
  EXPECT_EQ(gl::map_info_log("something else\n", files), "something else\n");
}

TEST(ShaderSource, EmbeddedExpansionHasVersionFirstAndSharedHeaders) {
  gl::ShaderSource src;
  std::vector<std::string> files;
  const std::string text = src.expand("techniques/linear.comp", {"FOO 1"}, files);
  EXPECT_EQ(text.rfind("#version 450 core\n#define FOO 1\n", 0), 0u);
  EXPECT_NE(std::find(files.begin(), files.end(), "shared/linear.h"), files.end());
  EXPECT_NE(std::find(files.begin(), files.end(), "shared/frame.h"), files.end());
  EXPECT_EQ(text.find("#include \""), std::string::npos);  // <...> ones sit in C++-only blocks
  EXPECT_THROW(src.read("does/not/exist.glsl"), RuntimeError);
}
