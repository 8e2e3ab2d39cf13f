// The viewer's script parser: every line checked before the window opens.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>

#include "viewer/commands.h"
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
  EXPECT_EQ(cmds[0].verb, Verb::Technique);
  EXPECT_EQ(cmds[0].args, std::vector<std::string>{"hiz"});
  EXPECT_EQ(cmds[0].line, 3);
  EXPECT_EQ(cmds[7].verb, Verb::Minimise);
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
  EXPECT_EQ(error_of("screenshot A.PNG\nresize 720p\n"), "");  // as ssrlab takes them
  // One sentence: no line breaks in any message.
  for (const char* bad : {"jump\n", "frames x\n", "view nosuch\n", "technique nosuch\n"})
    EXPECT_EQ(error_of(bad).find('\n'), std::string::npos) << bad;
}

TEST(ViewerScript, MissingFileIsInputError) {
  EXPECT_THROW(load_viewer_script("/nonexistent/script.txt"), InputError);
  EXPECT_THROW(load_viewer_script("/tmp"), InputError);
}

// The command list is one table: names unique, each with help, in Verb order, and the help
// table (the README's) has one row per command.
TEST(ViewerScript, CommandTableIsComplete) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < kCommandCount; ++i) {
    const CommandInfo& c = kCommands[i];
    EXPECT_TRUE(names.insert(c.name).second) << c.name << " twice";
    EXPECT_GT(std::strlen(c.help), 10u) << c.name;
    EXPECT_EQ(&command_info(c.verb), &c);
    EXPECT_EQ((c.form == ArgForm::None), (*c.args == '\0')) << c.name << ": the help's ARGS and the form disagree";
  }
  const std::string md = commands_markdown();
  EXPECT_EQ(static_cast<std::size_t>(std::count(md.begin(), md.end(), '\n')), kCommandCount + 2);
  const auto cmds = parse_viewer_script("truth manual\nwindow-shot w.png\npanel off\nswap\nstatus\n", "s.txt");
  ASSERT_EQ(cmds.size(), 5u);
  EXPECT_EQ(cmds[0].verb, Verb::Truth);
  EXPECT_NE(error_of("truth sometimes\n").find("now, rest, live, manual"), std::string::npos);
  EXPECT_NE(error_of("panel maybe\n").find("on or off"), std::string::npos);
  EXPECT_NE(error_of("preset nosuch\n").find("s.txt:1:"), std::string::npos);
  EXPECT_NE(error_of("compare sideways\n").find("off, split, diff, grid"), std::string::npos);
  EXPECT_NE(error_of("inspect 3\n").find("two arguments"), std::string::npos);
  EXPECT_NE(error_of("inspect -1 2\n").find("pixel coordinate"), std::string::npos);
  EXPECT_NE(error_of("magnifier 40\n").find("[2,16]"), std::string::npos);
  EXPECT_EQ(parse_viewer_script("inspect 3 4\n", "s.txt")[0].args, std::vector<std::string>{"3 4"});
}
