// The viewer's script parser: every line checked before the window opens.
#include <gtest/gtest.h>

#include "app/viewer_script.h"
#include "core/errors.h"

using namespace ssr;

namespace {

std::string error_of(const std::string& text) {
  try {
    parse_viewer_script(text, "s.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ViewerScript, ParsesCommandsCommentsAndLines) {
  const auto cmds = parse_viewer_script(
      "# a comment\n\ntechnique hiz   # trailing comment\nset hiz.max_iterations=64\nframes 3\n"
      "compare split\nsplit 0.25\nview traceable\nresize 200x120\nminimise\nscreenshot a.png\n",
      "s.txt");
  ASSERT_EQ(cmds.size(), 9u);
  EXPECT_EQ(cmds[0].verb, "technique");
  EXPECT_EQ(cmds[0].args, std::vector<std::string>{"hiz"});
  EXPECT_EQ(cmds[0].line, 3);
  EXPECT_EQ(cmds[7].verb, "minimise");
  EXPECT_TRUE(cmds[7].args.empty());
  EXPECT_EQ(cmds[8].line, 11);
}

TEST(ViewerScript, RejectsBadLinesNamingFileAndLine) {
  EXPECT_NE(error_of("frames 1\njump 3\n").find("s.txt:2: unknown command 'jump'"), std::string::npos);
  EXPECT_NE(error_of("frames\n").find("s.txt:1: 'frames' takes one argument"), std::string::npos);
  EXPECT_NE(error_of("minimise now\n").find("takes no argument"), std::string::npos);
  EXPECT_NE(error_of("frames 0\n").find("s.txt:1:"), std::string::npos);
  EXPECT_NE(error_of("frames 2.5\n").find("whole number"), std::string::npos);
  EXPECT_NE(error_of("split 1.5\n").find("[0,1]"), std::string::npos);
  EXPECT_NE(error_of("exposure nan\n").find("finite"), std::string::npos);
  EXPECT_NE(error_of("ambient -1\n").find(">= 0"), std::string::npos);
  EXPECT_NE(error_of("compare sideways\n").find("off, split, diff"), std::string::npos);
  EXPECT_NE(error_of("view nosuch\n").find("s.txt:1:"), std::string::npos);
  EXPECT_NE(error_of("technique nosuch\n").find("s.txt:1:"), std::string::npos);
  EXPECT_NE(error_of("set max_steps=3\n").find("technique.key=value"), std::string::npos);
  EXPECT_NE(error_of("resize 0x10\n").find("s.txt:1:"), std::string::npos);
  EXPECT_NE(error_of("screenshot a.exr\n").find(".png"), std::string::npos);
  // One sentence: no line breaks in any message.
  for (const char* bad : {"jump\n", "frames x\n", "view nosuch\n", "technique nosuch\n"})
    EXPECT_EQ(error_of(bad).find('\n'), std::string::npos) << bad;
}

TEST(ViewerScript, MissingFileIsInputError) {
  EXPECT_THROW(load_viewer_script("/nonexistent/script.txt"), InputError);
  EXPECT_THROW(load_viewer_script("/tmp"), InputError);
}
