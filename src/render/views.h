// What the display pass can show (--view, the viewer's view list): one table.
#pragma once
#include <string>
#include <vector>

#include "shared/display.h"

namespace ssr {

enum class ViewMode : int {
  Final = VIEW_FINAL, Reflection = VIEW_REFLECTION, Confidence = VIEW_CONFIDENCE,
  Lit = VIEW_LIT, Normal = VIEW_NORMAL, Depth = VIEW_DEPTH, Albedo = VIEW_ALBEDO,
  Roughness = VIEW_ROUGHNESS, Metallic = VIEW_METALLIC, Mask = VIEW_MASK,
  Steps = VIEW_STEPS, Hits = VIEW_HITS, Distance = VIEW_DISTANCE, Offsets = VIEW_OFFSETS,
  Holes = VIEW_HOLES, Reflected = VIEW_REFLECTED, Motion = VIEW_MOTION,
  Classes = VIEW_CLASSES, Raw = VIEW_RAW, RayLength = VIEW_RAY_LENGTH, Spatial = VIEW_SPATIAL,
  Temporal = VIEW_TEMPORAL, Variance = VIEW_VARIANCE, History = VIEW_HISTORY,
  Iterations = VIEW_ITERATIONS, IdleLanes = VIEW_IDLE_LANES,
};

// How to read a view: the viewer draws it as a colour bar or swatches next to the image.
struct Legend {
  enum Kind {
    Radiance,  // HDR radiance through the display transform (exposure): no scale to read
    Grey,      // value / full as grey
    Heat,      // value / full through shared/colormap.h's heat()
    Swatches,  // categories, one colour each
    Encoded,   // a vector packed into rgb: the description says how
  } kind = Radiance;
  float full = 1.0f;       // Grey and Heat: the value drawn white / hottest (above: clamped)
  const char* unit = "";   // of `full`
  struct Swatch {
    const char* name;
    float r, g, b;         // display colour in [0, 1]
  };
  std::vector<Swatch> swatches;
};

struct ViewInfo {
  ViewMode mode;
  const char* name;         // as the CLI takes it
  const char* description;  // one line
  // A view of the technique debug image: offered only for techniques that declare it
  // (TechniqueDecl::debug_views); every other view exists for every technique.
  bool debug;
  // Shown from the per-ray telemetry (render/telemetry.h): the technique runs instrumented
  // (SSR_TELEMETRY) with a TelemetryBuffer bound. Offered for techniques that record it.
  bool telemetry = false;
  Legend legend = {};
};
// Every view, in ViewMode order.
const std::vector<ViewInfo>& view_table();
// Names as the CLI takes them ("final", "reflection", ...), in ViewMode order.
const std::vector<std::string>& view_mode_names();
// Throws InputError naming every view, and `also_known` after them (a command's own views).
ViewMode parse_view_mode(const std::string& name, const std::vector<std::string>& also_known = {});
const ViewInfo& view_info(ViewMode mode);

}  // namespace ssr
