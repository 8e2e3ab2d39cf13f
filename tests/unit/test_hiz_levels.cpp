// The `hiz` pyramid's level chain: GL mip sizes (floor halving to 1x1) whose footprints (2 or,
// for an odd source's last texel, 3 texels) cover every source texel.
#include <gtest/gtest.h>

#include "render/hiz_pyramid.h"

using ssr::hiz_level_sizes;

namespace {
void expect_chain_covers(int w, int h) {
  const auto s = hiz_level_sizes(w, h);
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.front(), std::make_pair(w, h));
  EXPECT_EQ(s.back(), std::make_pair(1, 1));
  for (std::size_t k = 1; k < s.size(); ++k)
    for (auto [size, prev] : {std::pair{s[k].first, s[k - 1].first}, std::pair{s[k].second, s[k - 1].second}}) {
      if (prev == 1) {
        EXPECT_EQ(size, 1);  // a 1-texel side stays 1 while the other one halves
      } else {  // footprints of 2, the last one 3 for an odd source: exactly the source
        EXPECT_LE(2 * size, prev) << w << "x" << h << " level " << k;
        EXPECT_LE(prev, 2 * size + 1) << w << "x" << h << " level " << k;
      }
    }
}
}  // namespace

TEST(HizLevels, FullHd) {
  const std::vector<std::pair<int, int>> want = {{1920, 1080}, {960, 540}, {480, 270}, {240, 135},
                                                 {120, 67},    {60, 33},   {30, 16},   {15, 8},
                                                 {7, 4},       {3, 2},     {1, 1}};
  EXPECT_EQ(hiz_level_sizes(1920, 1080), want);
  expect_chain_covers(1920, 1080);
}

TEST(HizLevels, OddTinyAndThin) {
  for (auto [w, h] : {std::pair{1921, 1081}, {97, 55}, {1, 1}, {1, 7}, {300, 1}, {3, 3}, {8192, 4320}})
    expect_chain_covers(w, h);
  EXPECT_EQ(hiz_level_sizes(1, 1).size(), 1u);
  EXPECT_EQ(hiz_level_sizes(300, 1).size(), 9u);  // the GL chain: 1 + floor(log2(max(w, h)))
}
