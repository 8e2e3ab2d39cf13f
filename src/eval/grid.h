// Images for people: labelled comparison grids and difference heat maps.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "eval/breakdown.h"
#include "eval/metrics.h"

namespace ssr {

// 8-bit sRGB from display values in [0,1].
RgbaImage8 to_rgba8(const RgbaImageF& display);

// |a - b| (mean over RGB of display values) on reflective pixels, scaled so that `full_scale`
// is the hottest colour; non-reflective pixels are dark grey.
RgbaImage8 heat_map(const RgbaImageF& a, const RgbaImageF& b, const std::vector<PixelClass>& cls,
                    float full_scale = 0.25f);

// The ground truth's classes: traceable green, missing red, sky blue, not reflective black.
glm::vec3 class_colour(PixelClass c);  // display colour in [0, 1]
RgbaImage8 class_map(const std::vector<PixelClass>& cls, int width, int height);

// A technique's hit classes over a dimmed grey copy of `backdrop` (display values): correct
// hit green, false hit red, missed hit yellow, correct miss (missing or sky, not claimed) blue,
// not handled purple.
RgbaImage8 hit_class_map(const std::vector<HitClass>& hits, const RgbaImageF& backdrop);

struct GridTile {
  std::string label;
  RgbaImage8 image;
};
// Tiles of equal size, row-major, `columns` per row, each with its label drawn on a dark strip.
RgbaImage8 make_grid(const std::vector<GridTile>& tiles, int columns);

}  // namespace ssr
