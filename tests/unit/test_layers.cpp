// The layers of docs/ARCHITECTURE.md §2 include only downwards: a file in one folder of src/
// includes headers of its own folder and of the folders below it, never of one above. (Until
// each layer is its own library, this test is what keeps the order.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = fs::path(SSRLAB_TEST_DATA) / ".." / "..";

// The order of ARCHITECTURE §2, bottom first.
const std::map<std::string, int> kLayer = {{"core", 0},      {"gl", 1},         {"scene", 1},
                                           {"render", 2},    {"techniques", 3}, {"reference", 4},
                                           {"registry", 5},  {"eval", 6},       {"app", 7},
                                           {"viewer", 7}};

}  // namespace

TEST(Layers, SourcesIncludeOnlyDownwards) {
  const std::regex include_re(R"re(^\s*#\s*include\s+"([a-z_]+)/[^"]+")re");
  std::size_t files = 0;
  for (const auto& [dir, level] : kLayer) {
    for (const auto& e : fs::recursive_directory_iterator(kRoot / "src" / dir)) {
      if (!e.is_regular_file()) continue;
      ++files;
      std::ifstream in(e.path());
      std::string line;
      int line_no = 0;
      while (std::getline(in, line)) {
        ++line_no;
        std::smatch m;
        if (!std::regex_search(line, m, include_re)) continue;
        const auto it = kLayer.find(m[1].str());
        if (it == kLayer.end()) continue;  // shared/ (the C++/GLSL headers) and third-party paths
        // gl and scene are side by side: neither includes the other.
        const bool sibling = it->second == level && it->first != dir;
        EXPECT_TRUE(it->second < level || it->first == dir)
            << e.path().lexically_relative(kRoot) << ":" << line_no << " includes " << m[1] << "/ ("
            << (sibling ? "a sibling layer" : "a layer above") << ")";
      }
    }
  }
  EXPECT_GT(files, 50u);
}
