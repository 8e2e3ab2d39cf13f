// CPU images read back from the GL (row 0 is the top row, as in image files).
#pragma once
#include <cstdint>
#include <vector>

namespace ssr {

struct RgbaImage8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // RGBA8, sRGB encoded
};

struct RgbaImageF {
  int width = 0, height = 0;
  std::vector<float> pixels;         // RGBA32F, linear unless said otherwise
  const float* at(int x, int y) const {
    return &pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(x)) * 4];
  }
  float* at(int x, int y) {
    return &pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(x)) * 4];
  }
};

}  // namespace ssr
