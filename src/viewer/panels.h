// ImGui panels: technique parameters drawn from the Params tables (the one description per
// parameter), the scene's lights and environment, the camera. No window code here, so the panels
// also run against ImGui's null backend in tests (tests/ui).
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "gl/timer.h"
#include "render/views.h"
#include "scene/scene.h"
#include "core/params.h"

namespace ssr {

// One widget per parameter (slider with the table's range, checkbox, or combo), the help text
// as a tooltip, a reset button per parameter and a 'reset all' button. Returns true when a value changed.
// `ran`: the values the technique last ran with, "auto" resolved (Technique::ran_params()): an auto
// slider shows its value, and unticking auto starts there (else at the range's geometric mean).
bool draw_param_panel(ParamSet& params, const ParamSet* ran = nullptr);

// The scene's lights: per light its type, position (point) or direction (directional, as yaw and
// pitch, so it stays a unit vector), colour, intensity and range (point); add and remove within
// Scene::kMaxLights. Values stay in the ranges that validate() and scene files accept, so the
// result can go to Renderer::set_lighting and into a preset. Returns true when something changed.
bool draw_lights_panel(std::vector<Light>& lights);

// The environment (sky or constant colour, intensity) and the scene's ambient factor, kept in
// the ranges scene files accept. Returns true when something changed.
bool draw_environment_panel(Environment& environment, float& ambient);

// Field of view, near and far of `camera` (kept valid: 1 < fov < 179, 0 < near < far), and its
// position and target as read-outs. Returns true when something changed.
bool draw_camera_panel(Camera& camera);

// How to read the image: the view's legend (render/views.h: a colour bar with its scale and
// unit, swatches, or the description of an encoding; tone-mapped views name the exposure), the
// difference view's heat scale, the reference's class colours (eval/grid.h's class_colour).
// The bars are drawn with shared/colormap.h, the function the image was drawn with.
void draw_view_legend(const ViewInfo& view, float exposure);
void draw_difference_legend(float full_scale, const char* what = "|A - B|");
void draw_class_legend();

// The status bar's line: two toggles (panel, keys), the latest message (errors red, clipped to
// the room left, whole in a tooltip), then the truth's state, the frame time and the device.
struct StatusLine {
  std::string message;
  bool error = false;
  std::string truth;     // "" (no on-demand side), "current", "stale", "computing"
  std::optional<double> frame_ms;  // the last frame's wall clock, start to start (the timing panel
                                   // has the passes'); none before a frame has been timed
  std::string device;
};
struct StatusActions {
  bool toggle_panel = false, toggle_keys = false;
};
StatusActions draw_status_line(const StatusLine& line, bool panel_shown);

// The timing panel: per pass each column's ms and % of its frame (the union of the columns'
// passes, then the total), each column's rolling technique time and the frame time as plots
// the width of the panel; the header says gpu or cpu.
struct TimingColumn {
  std::string label;      // "A", "B", "truth"
  std::string technique;
  gl::FrameTimes passes;  // the last frame's
  std::vector<float> history;  // technique ms of the last frames
};
// The timing table's text: a header, a row per pass (each pass once, nested passes indented),
// then "total"; per column its ms and share. The frame's inputs (G-buffer, lighting: drawn once,
// under the first side) appear in every column, marked "*", and count in every total.
struct TimingTable {
  std::vector<std::vector<std::string>> cells;
  bool shared_inputs = false;  // some rows are marked "*"
};
TimingTable timing_table(const std::vector<TimingColumn>& columns, bool gpu);
void draw_timing(const std::vector<TimingColumn>& columns, const std::vector<float>& frame_ms, double last_frame_ms,
                 bool gpu);
// A note in the disabled text colour, wrapped at the panel's width (the panel is narrow).
void text_disabled_wrapped(const char* text);

// The pixel inspector's values (viewer/inspector.h's JSON): one line a value, then per side.
void draw_pixel_values(const nlohmann::ordered_json& values);

}  // namespace ssr
