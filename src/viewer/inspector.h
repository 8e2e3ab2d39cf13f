// The pixel inspector: everything the frame knows about one pixel of the image, read back from
// the renderer's targets and the sides' copies (1x1 reads). The panel shows it under the cursor;
// the `inspect X Y` command prints it as one JSON line (tests compare it with the CLI's views).
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "gl/objects.h"
#include "reference/pixel_class.h"
#include "render/renderer.h"

namespace ssr {

// One side's images of the frame, as the viewer keeps them.
struct SideImages {
  std::string technique;
  const gl::Texture2D* color = nullptr;    // RGBA16F composited colour
  const gl::Texture2D* display = nullptr;  // RGBA8 display image (of the shown view)
  const gl::Texture2D* debug = nullptr;    // RGBA16F debug channels (null: the technique writes none)
  bool ppr_offsets = false;                // debug .xy are PPR's source offsets
};

// x, y: image pixel, row 0 at the top. `classes`: the reference's classes of this frame (row 0 =
// top) when one is current. `truth`: the side (0 or 1) that is the ground truth, if any.
// Keys: pixel, depth (reversed-Z), view_depth (m), normal (view space), roughness, albedo,
// metallic, reflector, reflectance, flags, object, emission, motion (px), reflective, class,
// exposure, and per side
// (side_key: "a", "b", "truth"): technique, colour (linear), display (0..255 of the shown view), steps, hits,
// hit_distance, offset (ppr), error (mean |side - truth| of display values, 0..1).
// In that order (ordered_json): the panel lists them as a reader takes them in, not sorted.
using PixelValues = nlohmann::ordered_json;
PixelValues inspect_pixel(const Renderer& r, int x, int y, const SideImages* sides, int n_sides,
                          const std::vector<PixelClass>* classes, std::optional<int> truth);

const char* pixel_class_name(PixelClass c);
// The JSON key of side i: "a", "b", "truth" (the grid's third).
const char* side_key(int i);

}  // namespace ssr
