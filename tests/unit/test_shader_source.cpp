// Shader source handling without GL: info-log mapping and include expansion.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/errors.h"
#include "gl/program.h"
#include "input_error.h"

using namespace ssr;

TEST(ShaderSource, MapsMesaAndNvidiaLogs) {
  const std::vector<std::string> files = {"shaders/techniques/linear.comp", "shaders/common/frame.glsl"};
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

// A --shaders directory is the whole source: an include that climbs out of it, or names a
// directory, is refused in one sentence (it read any file the path reached).
TEST(ShaderSource, DirectoryIncludesStayInside) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ssrlab-shaders-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::remove_all(dir);
  fs::create_directories(dir / "render" / "sub.glsl");
  std::ofstream(dir / "render" / "up.comp") << "#include \"../../etc/passwd\"\n";
  std::ofstream(dir / "render" / "abs.comp") << "#include \"/etc/passwd\"\n";
  std::ofstream(dir / "render" / "dir.comp") << "#include \"render/sub.glsl\"\n";
  std::ofstream(dir / "render" / "ok.comp") << "#include \"render/../render/inc.glsl\"\nvoid main() {}\n";
  std::ofstream(dir / "render" / "inc.glsl") << "const int k = 1;\n";
  const gl::ShaderSource src(dir);
  std::vector<std::string> files;
  test::expect_message(test::input_error([&] { src.expand("render/up.comp", {}, files); }), {"outside the --shaders directory"});
  test::expect_message(test::input_error([&] { src.expand("render/abs.comp", {}, files); }), {"outside the --shaders directory"});
  test::expect_message(test::input_error([&] { src.expand("render/dir.comp", {}, files); }), {"not a regular file"});
  EXPECT_NE(src.expand("render/ok.comp", {}, files).find("const int k = 1;"), std::string::npos);
  // A compile error names the file where the user has it (it said shaders/... of any directory).
  EXPECT_EQ(src.location("render/ok.comp"), (dir / "render/ok.comp").string());
  EXPECT_EQ(gl::ShaderSource().location("render/ok.comp"), "shaders/render/ok.comp");
  fs::remove_all(dir);
}
