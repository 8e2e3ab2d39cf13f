#include "eval/grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "eval/video.h"

namespace ssr {

namespace {
std::uint8_t to8(float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// A compact perceptual ramp (black -> purple -> orange -> yellow), like "inferno".
void ramp(float t, std::uint8_t* out) {
  static const float stops[5][3] = {{0.0f, 0.0f, 0.02f}, {0.34f, 0.06f, 0.43f}, {0.73f, 0.21f, 0.33f},
                                    {0.98f, 0.55f, 0.04f}, {0.99f, 1.0f, 0.64f}};
  t = std::clamp(t, 0.0f, 1.0f) * 4.0f;
  const int i = std::min(static_cast<int>(t), 3);
  const float f = t - static_cast<float>(i);
  for (int c = 0; c < 3; ++c) out[c] = to8(stops[i][c] + (stops[i + 1][c] - stops[i][c]) * f);
  out[3] = 255;
}
}  // namespace

RgbaImage8 to_rgba8(const RgbaImageF& d) {
  RgbaImage8 out{d.width, d.height, std::vector<std::uint8_t>(d.pixels.size())};
  for (std::size_t i = 0; i < d.pixels.size(); ++i)
    out.pixels[i] = (i % 4 == 3) ? 255 : to8(std::isfinite(d.pixels[i]) ? d.pixels[i] : 1.0f);
  return out;
}

RgbaImage8 heat_map(const RgbaImageF& a, const RgbaImageF& b, const std::vector<PixelClass>& cls,
                    float full_scale) {
  if (a.width != b.width || a.height != b.height || cls.size() != static_cast<std::size_t>(a.width) * a.height)
    throw std::invalid_argument("heat_map: sizes differ");
  RgbaImage8 out{a.width, a.height, std::vector<std::uint8_t>(a.pixels.size())};
  for (std::size_t p = 0; p < cls.size(); ++p) {
    std::uint8_t* o = &out.pixels[p * 4];
    if (cls[p] == PixelClass::NotReflective) {
      o[0] = o[1] = o[2] = 24;
      o[3] = 255;
      continue;
    }
    float d = 0;
    for (int c = 0; c < 3; ++c) {
      const float x = std::abs(a.pixels[p * 4 + static_cast<std::size_t>(c)] - b.pixels[p * 4 + static_cast<std::size_t>(c)]);
      d += std::isfinite(x) ? x : 1.0f;
    }
    ramp(d / 3.0f / full_scale, o);
  }
  return out;
}

glm::vec3 class_colour(PixelClass c) {
  static const std::uint8_t colors[4][3] = {{0, 0, 0}, {40, 190, 80}, {220, 50, 40}, {60, 110, 230}};
  const auto* k = colors[static_cast<std::size_t>(c) & 3u];
  return glm::vec3(k[0], k[1], k[2]) / 255.0f;
}

RgbaImage8 class_map(const std::vector<PixelClass>& cls, int width, int height) {
  RgbaImage8 out{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
  for (std::size_t p = 0; p < cls.size() && p * 4 < out.pixels.size(); ++p) {
    const glm::vec3 c = class_colour(cls[p]) * 255.0f + 0.5f;
    for (int k = 0; k < 3; ++k) out.pixels[p * 4 + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(c[k]);
    out.pixels[p * 4 + 3] = 255;
  }
  return out;
}

RgbaImage8 hit_class_map(const std::vector<HitClass>& hits, const RgbaImageF& backdrop) {
  if (hits.size() != static_cast<std::size_t>(backdrop.width) * backdrop.height)
    throw std::invalid_argument("hit_class_map: sizes differ");
  static const std::uint8_t colors[6][3] = {
      {0, 0, 0}, {40, 190, 80}, {230, 40, 40}, {240, 200, 40}, {60, 110, 230}, {150, 60, 170}};
  RgbaImage8 out{backdrop.width, backdrop.height, std::vector<std::uint8_t>(hits.size() * 4)};
  for (std::size_t p = 0; p < hits.size(); ++p) {
    std::uint8_t* o = &out.pixels[p * 4];
    if (hits[p] == HitClass::NotReflective) {
      const float* b = &backdrop.pixels[p * 4];
      const float luma = 0.2126f * b[0] + 0.7152f * b[1] + 0.0722f * b[2];
      o[0] = o[1] = o[2] = to8(0.35f * (std::isfinite(luma) ? luma : 0.0f));
    } else {
      for (int k = 0; k < 3; ++k) o[k] = colors[static_cast<std::size_t>(hits[p])][k];
    }
    o[3] = 255;
  }
  return out;
}

RgbaImage8 make_grid(const std::vector<GridTile>& tiles, int columns) {
  if (tiles.empty()) return {};
  const int tw = tiles[0].image.width, th = tiles[0].image.height;
  // Labels wrap to the tile's width (a cut label lost its PSNR at 160x90); the strip is as tall
  // as the longest.
  const int scale = label_scale(tw);
  std::vector<std::string> labels;
  int label_height = 0;
  for (const GridTile& t : tiles) {
    labels.push_back(wrap_label(t.label, tw - 3, scale));
    label_height = std::max(label_height, label_size(labels.back(), scale).second);
  }
  const int strip = label_height + 4, gap = 4;
  const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
  RgbaImage8 out{columns * tw + (columns - 1) * gap, rows * (th + strip) + (rows - 1) * gap, {}};
  out.pixels.assign(static_cast<std::size_t>(out.width) * out.height * 4, 40);
  for (std::size_t i = 3; i < out.pixels.size(); i += 4) out.pixels[i] = 255;
  for (std::size_t t = 0; t < tiles.size(); ++t) {
    const RgbaImage8& im = tiles[t].image;
    if (im.width != tw || im.height != th) throw std::invalid_argument("make_grid: tiles differ in size");
    const int ox = static_cast<int>(t % static_cast<std::size_t>(columns)) * (tw + gap);
    const int oy = static_cast<int>(t / static_cast<std::size_t>(columns)) * (th + strip + gap);
    for (int y = 0; y < strip; ++y)
      for (int x = 0; x < tw; ++x) {
        std::uint8_t* o = &out.pixels[(static_cast<std::size_t>(oy + y) * out.width + ox + x) * 4];
        o[0] = o[1] = o[2] = 16;
      }
    draw_label(out, ox + 1, oy + 1, labels[t], scale);
    for (int y = 0; y < th; ++y)
      std::copy_n(&im.pixels[static_cast<std::size_t>(y) * tw * 4], static_cast<std::size_t>(tw) * 4,
                  &out.pixels[(static_cast<std::size_t>(oy + strip + y) * out.width + ox) * 4]);
  }
  return out;
}

}  // namespace ssr
