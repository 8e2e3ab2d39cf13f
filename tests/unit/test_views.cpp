// The views are one table (render/views.cpp) over the shared VIEW_* numbers: the table is in
// number order and complete, names are unique, and the display pass's view chain
// (shaders/common/display_views.glsl) handles every number the table has.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "render/views.h"

namespace {

TEST(Views, OneTableInNumberOrderAndTheDisplayPassHandlesEach) {
  const auto& table = ssr::view_table();
  ASSERT_EQ(table.size(), static_cast<std::size_t>(VIEW_COUNT));
  std::set<std::string> names;
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(table[i].mode), i) << table[i].name;
    EXPECT_TRUE(names.insert(table[i].name).second) << table[i].name << " twice";
    EXPECT_GT(std::string(table[i].description).size(), 8u) << table[i].name;
    EXPECT_EQ(ssr::parse_view_mode(table[i].name), table[i].mode);
  }
  // Every VIEW_* number of shared/display.h but the count is tested in the view chain.
  std::ifstream header(std::string(SSRLAB_SHADER_DIR) + "/shared/display.h");
  std::ifstream chain(std::string(SSRLAB_SHADER_DIR) + "/common/display_views.glsl");
  ASSERT_TRUE(header && chain);
  std::stringstream h, c;
  h << header.rdbuf();
  c << chain.rdbuf();
  const std::string chain_text = c.str();
  const std::string header_text = h.str();
  const std::regex define(R"(#define (VIEW_[A-Z_0-9]+) (\d+))");
  std::size_t views = 0;
  for (std::sregex_iterator it(header_text.begin(), header_text.end(), define), end; it != end; ++it) {
    const std::string name = (*it)[1];
    if (name == "VIEW_COUNT") continue;
    ++views;
    EXPECT_NE(chain_text.find(name), std::string::npos) << name << " is not handled by the display pass";
  }
  EXPECT_EQ(views, table.size());
}

}  // namespace
