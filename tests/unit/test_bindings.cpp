// shaders/shared/bindings.h names every binding slot: no two slots of one kind (or a slot and a
// range) overlap, images fit the 8 units GL guarantees, and no source file binds a literal unit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#define SSR_SHARED_BEGIN
#define SSR_SHARED_END
#include "shared/bindings.h"
#include "shared/hiz.h"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = fs::path(SSRLAB_TEST_DATA) / ".." / "..";

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(Bindings, SlotsOfOneKindDoNotOverlap) {
  // Every "#define KIND_NAME value" of bindings.h, by kind.
  const std::string text = read(kRoot / "shaders/shared/bindings.h");
  const std::regex def(R"(#define (UBO|SSBO|TEX|IMG)_(\w+) (\d+))");
  std::map<std::string, std::map<int, std::string>> used;
  int defines = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), def); it != std::sregex_iterator(); ++it) {
    const std::string kind = (*it)[1], name = (*it)[2];
    const int value = std::stoi((*it)[3]);
    // TEX_REF_MAP0 starts a range of REFERENCE_MAX_TEXTURES units.
    const int count = kind == "TEX" && name == "REF_MAP0" ? REFERENCE_MAX_TEXTURES : 1;
    // The Hi-Z pyramid's build borrows a unit per level it writes and one for the depth copy
    // before any other pass binds its own: they must exist, not be free.
    if (kind == "IMG" && name == "HIZ_LEVELS") {
      EXPECT_LE(value + HIZ_LEVELS_PER_DISPATCH + 1, 8);
      continue;
    }
    for (int u = value; u < value + count; ++u) {
      auto [slot, fresh] = used[kind].emplace(u, name);
      EXPECT_TRUE(fresh) << kind << "_" << name << " unit " << u << " is also " << kind << "_" << slot->second;
    }
    ++defines;
  }
  EXPECT_GT(defines, 30);
  EXPECT_LT(used["IMG"].rbegin()->first, 8);  // GL_MAX_IMAGE_UNITS is at least 8
  EXPECT_LT(used["TEX"].rbegin()->first, 80);  // GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS >= 80
}

TEST(Bindings, NoSourceBindsALiteralUnit) {
  const std::regex literal(
      R"(binding\s*=\s*\d|glBind(TextureUnit|ImageTexture)\s*\(\s*\d|glBindBufferBase\s*\(\s*GL_\w+\s*,\s*\d)");
  int files = 0;
  for (const char* dir : {"src", "shaders"})
    for (const auto& e : fs::recursive_directory_iterator(kRoot / dir)) {
      if (!e.is_regular_file()) continue;
      const std::string text = read(e.path());
      std::smatch m;
      EXPECT_FALSE(std::regex_search(text, m, literal)) << e.path() << ": " << m.str();
      ++files;
    }
  EXPECT_GT(files, 50);
}
