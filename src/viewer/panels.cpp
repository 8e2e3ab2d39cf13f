#include "viewer/panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <glm/glm.hpp>
#include <imgui.h>

#include "eval/grid.h"
#include "render/renderer.h"
#include "shared/colormap.h"

namespace ssr {

bool draw_param_panel(ParamSet& params, const ParamSet* ran) {
  bool changed = false;
  if (params.size() == 0) {
    ImGui::TextDisabled("(no parameters)");
    return false;
  }
  bool all_default = true;
  for (std::size_t i = 0; i < params.size(); ++i) all_default &= params.get(i) == params.get_default(i);
  ImGui::BeginDisabled(all_default);
  if (ImGui::SmallButton("reset all")) {
    params.reset_all();
    changed = true;
  }
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("every parameter of %s back to its default", params.prefix().c_str());
  for (std::size_t i = 0; i < params.size(); ++i) {
    const ParamDesc& d = params.table()[i];
    ImGui::PushID(static_cast<int>(i));
    const double before = params.get(i);
    // "auto" parameters: a checkbox; unticked, the slider starts at what auto ran with (a jump
    // to the range's middle cut dda's rays on corridor from 734 steps to 91), else at the range's
    // geometric mean.
    const bool resolved = ran && d.has_auto() && !ran->is_auto(i);
    const double resolved_value = resolved ? std::clamp(ran->get(i), d.min, d.max) : before;
    const bool show_resolved = params.is_auto(i) && resolved;  // the slider shows "auto: <value>"
    if (d.has_auto()) {
      bool automatic = params.is_auto(i);
      const double middle = std::sqrt(d.min * d.max);
      if (ImGui::Checkbox("##auto", &automatic))
        params.set(i, automatic ? d.auto_value
                                : resolved ? resolved_value : d.type == ParamType::Float ? middle : std::round(middle));
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("auto: %s", d.help);
      ImGui::SameLine();
      // The checkbox takes its room from the widget, so the row keeps its width.
      ImGui::SetNextItemWidth(ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - ImGui::GetStyle().ItemSpacing.x);
    }
    ImGui::BeginDisabled(params.is_auto(i));
    // A value off its default is drawn highlighted: what was changed is seen at a glance.
    const bool changed_from_default = before != params.get_default(i);
    if (changed_from_default) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.82f, 0.35f, 1.0f));
    switch (d.type) {
      case ParamType::Float: {
        float v = static_cast<float>(show_resolved ? resolved_value : before);
        // Wide ranges are easier to tune on a logarithmic slider.
        const ImGuiSliderFlags flags = (d.min > 0 && d.max / d.min >= 100) ? ImGuiSliderFlags_Logarithmic : 0;
        if (ImGui::SliderFloat(d.name, &v, static_cast<float>(d.min), static_cast<float>(d.max),
                               params.is_auto(i) ? (show_resolved ? "auto: %.4g" : "auto") : "%.4g", flags))
          params.set(i, std::clamp<double>(v, d.min, d.max));
        break;
      }
      case ParamType::Int: {
        int v = static_cast<int>(show_resolved ? resolved_value : before);
        const ImGuiSliderFlags flags = (d.min > 0 && d.max / d.min >= 100) ? ImGuiSliderFlags_Logarithmic : 0;
        if (ImGui::SliderInt(d.name, &v, static_cast<int>(d.min), static_cast<int>(d.max),
                             params.is_auto(i) ? (show_resolved ? "auto: %d" : "auto") : "%d", flags))
          params.set(i, std::clamp<double>(v, d.min, d.max));
        break;
      }
      case ParamType::Bool: {
        bool v = before != 0;
        if (ImGui::Checkbox(d.name, &v)) params.set(i, v ? 1 : 0);
        break;
      }
      case ParamType::Choice: {
        int v = static_cast<int>(before);
        if (ImGui::Combo(d.name, &v, d.choices.data(), static_cast<int>(d.choices.size())))
          params.set(i, v);
        break;
      }
    }
    if (changed_from_default) ImGui::PopStyleColor();
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
      ImGui::SetTooltip("%s\n%s%s%s\nrange %s, default %s", params.key(i).c_str(), d.help,
                        *d.unit ? "\nunit: " : "", d.unit, params.range_string(i).c_str(),
                        params.default_string(i).c_str());
    ImGui::SameLine();
    ImGui::BeginDisabled(params.get(i) == params.get_default(i));
    if (ImGui::SmallButton("reset")) params.reset(i);
    ImGui::EndDisabled();
    changed |= params.get(i) != before;
    ImGui::PopID();
  }
  return changed;
}

namespace {

// What a widget produced, made valid: a non-finite value (typed "nan") keeps the old one, the
// rest is clamped to the range scene files accept, so edited scenes still load and validate.
float valid(float v, float before, float lo, float hi) {
  return std::isfinite(v) ? std::clamp(v, lo, hi) : before;
}

// A float dragged within [lo, hi]. The speed follows the magnitude (1% a pixel), so that both
// 0.05 and 5000 are in reach; ImGui's logarithmic drags scale by the whole range, far too slow
// for ranges up to 1e9.
bool drag(const char* label, float& x, float lo, float hi) {
  float v = x;
  const float speed = std::max(std::abs(x), 1.0f) * 0.01f;
  if (!ImGui::DragFloat(label, &v, speed, lo, hi, "%.4g", ImGuiSliderFlags_AlwaysClamp))
    return false;
  x = valid(v, x, lo, hi);
  return true;
}

bool drag3(const char* label, glm::vec3& x, float lo, float hi) {
  glm::vec3 v = x;
  if (!ImGui::DragFloat3(label, &v.x, 0.05f, lo, hi, "%.3f", ImGuiSliderFlags_AlwaysClamp)) return false;
  for (int i = 0; i < 3; ++i) x[i] = valid(v[i], x[i], lo, hi);
  return true;
}

// A linear colour; HDR, as lights and skies go above 1.
bool color_edit(const char* label, glm::vec3& c) {
  glm::vec3 v = c;
  if (!ImGui::ColorEdit3(label, &v.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)) return false;
  for (int i = 0; i < 3; ++i) c[i] = valid(v[i], c[i], 0.0f, kSceneValueMax);
  return true;
}

void tooltip(const char* text) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

}  // namespace

bool draw_lights_panel(std::vector<Light>& lights) {
  bool changed = false;
  int remove = -1;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    Light& l = lights[i];
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::TreeNodeEx("light", ImGuiTreeNodeFlags_DefaultOpen, "light %zu: %s", i,
                          l.type == Light::Type::Point ? "point" : "directional")) {
      int type = l.type == Light::Type::Point ? 0 : 1;
      ImGui::RadioButton("point", &type, 0);
      ImGui::SameLine();
      ImGui::RadioButton("directional", &type, 1);
      changed |= type != (l.type == Light::Type::Point ? 0 : 1);
      l.type = type == 0 ? Light::Type::Point : Light::Type::Directional;
      ImGui::SameLine();
      if (ImGui::SmallButton("remove")) remove = static_cast<int>(i);
      if (l.type == Light::Type::Point) {
        changed |= drag3("position", l.position, -1e7f, 1e7f);
        changed |= drag("range", l.range, 1e-3f, 1e7f);
        tooltip("distance where the smooth falloff reaches zero");
      } else {
        // Yaw and pitch of the direction the light travels: it stays a unit vector.
        const glm::vec3 d = l.direction;
        float yaw = glm::degrees(std::atan2(d.x, d.z));
        float pitch = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
        const ImGuiSliderFlags clamp = ImGuiSliderFlags_AlwaysClamp;
        bool turned = ImGui::SliderFloat("yaw", &yaw, -180.0f, 180.0f, "%.1f deg", clamp);
        tooltip("direction the light travels, about +Y (0: towards +Z)");
        turned |= ImGui::SliderFloat("pitch", &pitch, -90.0f, 90.0f, "%.1f deg", clamp);
        tooltip("direction the light travels, above the horizontal (-90: straight down)");
        if (turned && std::isfinite(yaw) && std::isfinite(pitch)) {
          const float y = glm::radians(yaw), p = glm::radians(std::clamp(pitch, -90.0f, 90.0f));
          l.direction = {std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y)};
          changed = true;
        }
        ImGui::TextDisabled("direction %.3f %.3f %.3f", l.direction.x, l.direction.y, l.direction.z);
      }
      changed |= color_edit("color", l.color);
      changed |= drag("intensity", l.intensity, 0.0f, 1e9f);
      tooltip(l.type == Light::Type::Point ? "radiant intensity" : "irradiance");
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (remove >= 0) {
    lights.erase(lights.begin() + remove);
    changed = true;
  }
  const bool full = lights.size() >= static_cast<std::size_t>(Scene::kMaxLights);
  ImGui::BeginDisabled(full);
  if (ImGui::Button("add light")) {
    Light l;
    l.position = {0.0f, 2.0f, 0.0f};
    lights.push_back(l);
    changed = true;
  }
  ImGui::EndDisabled();
  if (full && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("at most %d lights", Scene::kMaxLights);
  return changed;
}

bool draw_environment_panel(Environment& env, float& ambient) {
  bool changed = false;
  int type = env.type == Environment::Type::Sky ? 0 : 1;
  ImGui::RadioButton("sky", &type, 0);
  ImGui::SameLine();
  ImGui::RadioButton("constant", &type, 1);
  changed |= type != (env.type == Environment::Type::Sky ? 0 : 1);
  env.type = type == 0 ? Environment::Type::Sky : Environment::Type::Constant;
  if (env.type == Environment::Type::Sky) {
    changed |= color_edit("zenith", env.zenith);
    changed |= color_edit("horizon", env.horizon);
    changed |= color_edit("ground", env.ground);
  } else {
    changed |= color_edit("color", env.constant);
  }
  changed |= drag("intensity", env.intensity, 0.0f, kSceneValueMax);
  tooltip("scales the environment's colours");
  changed |= drag("ambient", ambient, 0.0f, kSceneValueMax);
  tooltip("scales the environment's diffuse (ambient) light");
  return changed;
}

bool draw_camera_panel(Camera& c) {
  bool changed = false;
  float fov = c.fov_y_deg;
  if (ImGui::SliderFloat("fov y", &fov, 5.0f, 150.0f, "%.1f deg")) {
    c.fov_y_deg = valid(fov, c.fov_y_deg, 1.001f, 178.999f);
    changed = true;
  }
  // Each plane is kept on its side of the other: 0 < near < far.
  changed |= drag("near", c.near_plane, 1e-6f, std::max(c.far_plane / 1.001f, 1e-6f));
  changed |= drag("far", c.far_plane, std::min(c.near_plane * 1.001f, 1e7f), 1e7f);
  ImGui::TextDisabled("position %.3f %.3f %.3f", c.position.x, c.position.y, c.position.z);
  ImGui::TextDisabled("target   %.3f %.3f %.3f", c.target.x, c.target.y, c.target.z);
  return changed;
}

namespace {

const ImVec4 kErrorColour(1.0f, 0.45f, 0.4f, 1.0f);

ImU32 rgb(glm::vec3 c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x, c.y, c.z, 1.0f)); }

// A 64-step colour bar over the available width, then "0 ... full+ unit" under it.
template <class Map>
void colour_bar(Map map, float full, const char* unit, bool clamps) {
  const float w = std::max(ImGui::GetContentRegionAvail().x - 8.0f, 60.0f), h = 12.0f;
  const ImVec2 p = ImGui::GetCursorScreenPos();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  constexpr int kSteps = 64;
  for (int i = 0; i < kSteps; ++i)
    dl->AddRectFilled(ImVec2(p.x + w * static_cast<float>(i) / kSteps, p.y),
                      ImVec2(p.x + w * static_cast<float>(i + 1) / kSteps + 1, p.y + h),
                      rgb(map((static_cast<float>(i) + 0.5f) / kSteps)));
  ImGui::Dummy(ImVec2(w, h));
  ImGui::TextUnformatted("0");
  char right[96];
  std::snprintf(right, sizeof right, "%.3g%s %s", full, clamps ? "+" : "", unit);
  ImGui::SameLine(std::max(ImGui::GetCursorPosX(), w - ImGui::CalcTextSize(right).x + ImGui::GetStyle().WindowPadding.x));
  ImGui::TextUnformatted(right);
}

// A colour box and its name, on the line of the one before (`first`: a new line) where both fit.
void swatch(const char* name, glm::vec3 c, bool first) {
  if (!first) {
    ImGui::SameLine();
    const float need = 12.0f + ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize(name).x;
    if (ImGui::GetContentRegionAvail().x < need) ImGui::NewLine();
  }
  ImGui::ColorButton(name, ImVec4(c.x, c.y, c.z, 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
  ImGui::SameLine();
  ImGui::TextUnformatted(name);
}

}  // namespace

void draw_view_legend(const ViewInfo& view, float exposure) {
  const Legend& l = view.legend;
  ImGui::TextWrapped("%s: %s", view.name, view.description);
  switch (l.kind) {
    case Legend::Radiance:
      ImGui::TextDisabled("tone mapped (ACES, sRGB) at %+.2f stops", exposure);
      break;
    case Legend::Grey:
      colour_bar([](float t) { return glm::vec3(t); }, l.full, l.unit, false);
      break;
    case Legend::Heat:
      colour_bar([](float t) { return shared::heat(t); }, l.full, l.unit, true);
      break;
    case Legend::Swatches:
      for (const Legend::Swatch& s : l.swatches) swatch(s.name, glm::vec3(s.r, s.g, s.b), &s == &l.swatches.front());
      break;
    case Legend::Encoded:
      break;  // the description says how
  }
}

void draw_difference_legend(float full_scale, const char* what) {
  ImGui::TextWrapped("difference %s (display values, mean of RGB)", what);
  colour_bar([](float t) { return shared::heat(t); }, full_scale, "of full white", true);
}

void draw_class_legend() {
  ImGui::TextUnformatted("the reference's class of each reflective pixel");
  for (const PixelClass c : {PixelClass::Traceable, PixelClass::Missing, PixelClass::Sky})
    swatch(c == PixelClass::Traceable ? "traceable" : c == PixelClass::Missing ? "missing" : "sky", class_colour(c),
           c == PixelClass::Traceable);
}

void draw_pixel_values(const nlohmann::ordered_json& values) {
  auto text = [](const nlohmann::ordered_json& v) {
    char buf[32];
    if (v.is_number_float()) {
      std::snprintf(buf, sizeof buf, "%.4g", v.get<double>());
      return std::string(buf);
    }
    if (v.is_null()) return std::string("-");  // not known (no reference computed: the class)
    if (!v.is_array()) return v.dump();
    std::string s;
    for (const auto& e : v) {
      if (e.is_number_float()) std::snprintf(buf, sizeof buf, "%.4g", e.get<double>());
      else std::snprintf(buf, sizeof buf, "%s", e.dump().c_str());
      s += (s.empty() ? "" : "  ") + std::string(buf);
    }
    return s;
  };
  auto line = [&](const std::string& k, const nlohmann::ordered_json& v) {
    ImGui::TextDisabled("%s", k.c_str());
    ImGui::SameLine(110);
    ImGui::TextUnformatted(text(v).c_str());
  };
  for (const auto& [k, v] : values.items())
    if (!v.is_object() && k != "pixel") line(k, v);
  for (const char* side : {"a", "b", "truth"}) {
    if (!values.contains(side)) continue;
    const nlohmann::ordered_json& s = values[side];
    ImGui::Separator();
    ImGui::Text("%s: %s%s", side, s.value("technique", "?").c_str(), s.value("current", true) ? "" : " (stale)");
    for (const auto& [k, v] : s.items())
      if (k != "technique" && k != "current") line(k, v);
  }
}

StatusActions draw_status_line(const StatusLine& line, bool panel_shown) {
  StatusActions act;
  if (ImGui::SmallButton(panel_shown ? "panel >" : "< panel")) act.toggle_panel = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("show or hide the side panel (F2)");
  ImGui::SameLine();
  if (ImGui::SmallButton("keys")) act.toggle_keys = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("keys and mouse (F1)");
  char right[256];
  const std::string truth = line.truth.empty() ? "" : "truth: " + line.truth + "  |  ";
  char ms[32] = "-";
  if (line.frame_ms) std::snprintf(ms, sizeof ms, "%.1f", *line.frame_ms);
  std::snprintf(right, sizeof right, "%sframe %s ms (wall clock)  |  %s", truth.c_str(), ms, line.device.c_str());
  const float right_w = ImGui::CalcTextSize(right).x;
  ImGui::SameLine();
  const float msg_w = ImGui::GetContentRegionAvail().x - right_w - 12.0f;
  if (msg_w > 20 && !line.message.empty()) {
    // One line (a shader error's file:line:col is on its second), clipped to the room left of
    // the figures; the item is that room, so the figures keep their place. All of it on hover.
    std::string shown = line.message;
    for (char& c : shown)
      if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const ImVec2 size(msg_w, ImGui::GetTextLineHeight());
    const ImVec4 clip(p.x, p.y, p.x + size.x, p.y + size.y);
    ImGui::GetWindowDrawList()->AddText(nullptr, 0.0f, p, ImGui::GetColorU32(line.error ? kErrorColour : ImVec4(0.8f, 0.9f, 0.8f, 1)),
                                        shown.c_str(), nullptr, 0.0f, &clip);
    ImGui::Dummy(size);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", line.message.c_str());
    ImGui::SameLine();
  }
  ImGui::SetCursorPosX(std::max(ImGui::GetCursorPosX(), ImGui::GetWindowWidth() - right_w - 8.0f));
  ImGui::TextDisabled("%s", right);
  return act;
}

TimingTable timing_table(const std::vector<TimingColumn>& columns, bool gpu) {
  const std::size_t n = columns.size();
  std::vector<gl::PassTime> rows;  // each pass once (its name and depth), in the columns' order
  std::vector<double> total(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    total[i] = gl::outer_ms(columns[i].passes);  // nested passes are inside their span's time
    auto after = rows.begin();  // a pass new to the table goes after this column's previous row
    for (const auto& p : columns[i].passes) {
      auto at = std::find_if(rows.begin(), rows.end(), [&](const gl::PassTime& r) { return r.name == p.name; });
      if (at == rows.end()) {
        // A nested pass goes after the span's rows of the columns before (B's own passes below
        // A's, all under the technique's span).
        if (p.depth > 0)
          while (after != rows.end() && after->depth > 0) ++after;
        at = rows.insert(after, p);
      }
      after = at + 1;
    }
  }
  // The frame's inputs (G-buffer, lighting) render once, under the first side that runs: they
  // belong to every side's frame, so each column shows them (marked) and its total counts them.
  // Totals that left them out of B's column made the side that happened to be A look slower.
  auto own_ms = [&](std::size_t i, const std::string& name) -> std::optional<double> {
    for (const auto& p : columns[i].passes)
      if (p.name == name) return p.ms;
    return std::nullopt;
  };
  std::vector<std::pair<std::string, double>> shared;  // each input drawn, with its time
  for (std::size_t k = 0; k < kFrameInputPasses; ++k) {
    const std::string name = kFramePasses[k];
    std::optional<double> drawn;
    for (std::size_t i = 0; i < n && !drawn; ++i) drawn = own_ms(i, name);
    if (!drawn) continue;
    shared.emplace_back(name, *drawn);
    for (std::size_t i = 0; i < n; ++i)  // a column that did not run (no passes) stays empty
      if (!own_ms(i, name) && !columns[i].passes.empty()) total[i] += *drawn;
  }
  const auto shared_ms = [&](const std::string& name) -> std::optional<double> {
    for (const auto& [input, ms] : shared)
      if (input == name) return ms;
    return std::nullopt;
  };
  // The cells as text first, so each column is as wide as its widest cell (a fitted column keeps
  // the width of the first frame it saw: "total" alone, before the passes' rows arrived).
  // Times in three significant digits (four from 1000 ms): the table fits the panel's default
  // width with llvmpipe's hundreds of ms as with a GPU's hundredths.
  auto ms_text = [](double ms) {
    char buf[32];
    std::snprintf(buf, sizeof buf, ms >= 100.0 ? "%.0f" : ms >= 10.0 ? "%.1f" : ms >= 1.0 ? "%.2f" : "%.3f", ms);
    return std::string(buf);
  };
  std::vector<std::vector<std::string>> cells;  // header, one row a pass, total
  cells.push_back({gpu ? "pass (gpu)" : "pass (cpu)"});
  for (const TimingColumn& c : columns) {
    cells.back().push_back(c.label + " ms");
    cells.back().push_back("%");
  }
  auto row = [&](const std::string& name, auto&& ms_of) {
    cells.push_back({name});
    for (std::size_t i = 0; i < n; ++i) {
      const std::optional<double> ms = ms_of(i);
      cells.back().push_back(ms ? ms_text(*ms) : "");
      cells.back().push_back(ms && total[i] > 0 ? std::to_string(std::lround(100.0 * *ms / total[i])) : "");
    }
  };
  for (const gl::PassTime& r : rows)
    row(std::string(2 * static_cast<std::size_t>(r.depth), ' ') + r.name + (shared_ms(r.name) ? " *" : ""),
        [&](std::size_t i) -> std::optional<double> {
          if (const auto ms = own_ms(i, r.name)) return ms;
          return columns[i].passes.empty() ? std::nullopt : shared_ms(r.name);
        });
  row("total", [&](std::size_t i) -> std::optional<double> {
    return columns[i].passes.empty() ? std::nullopt : std::optional(total[i]);  // not run yet: nothing
  });
  return {cells, !shared.empty()};
}

void draw_timing(const std::vector<TimingColumn>& columns, const std::vector<float>& frame_ms, double last_frame_ms,
                 bool gpu) {
  const std::size_t n = columns.size();
  const TimingTable table = timing_table(columns, gpu);
  const std::vector<std::vector<std::string>>& cells = table.cells;
  const int n_cols = static_cast<int>(1 + 2 * n);
  if (n > 0 && ImGui::BeginTable("passes", n_cols, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
    for (int c = 0; c < n_cols; ++c) {
      float w = 0;
      for (const auto& r : cells) w = std::max(w, ImGui::CalcTextSize(r[static_cast<std::size_t>(c)].c_str()).x);
      ImGui::TableSetupColumn(cells[0][static_cast<std::size_t>(c)].c_str(), ImGuiTableColumnFlags_WidthFixed, w);
    }
    ImGui::TableHeadersRow();
    for (std::size_t r = 1; r < cells.size(); ++r) {
      ImGui::TableNextRow();
      for (const std::string& text : cells[r]) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(text.c_str());
      }
    }
    ImGui::EndTable();
    if (table.shared_inputs) ImGui::TextDisabled("* the frame's inputs: drawn once for every side");
  }
  const float plot_w = std::max(ImGui::GetContentRegionAvail().x, 60.0f);  // ImGui 1.86 draws nothing for -1
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<float>& h = columns[i].history;
    if (h.empty()) continue;
    const float hi = *std::max_element(h.begin(), h.end());
    char overlay[128];
    std::snprintf(overlay, sizeof overlay, "%s %s: %.3f ms %s (max %.3f)", columns[i].label.c_str(),
                  columns[i].technique.c_str(), h.back(), gpu ? "gpu" : "cpu", hi);
    ImGui::PushID(static_cast<int>(i));
    ImGui::PlotLines("##technique", h.data(), static_cast<int>(h.size()), 0, overlay, 0.0f, std::max(hi * 1.2f, 1e-3f),
                     ImVec2(plot_w, 45));
    ImGui::PopID();
  }
  if (!frame_ms.empty()) {
    const float hi = *std::max_element(frame_ms.begin(), frame_ms.end());
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "frame %.1f ms (wall clock)", last_frame_ms);
    ImGui::PlotLines("##frame", frame_ms.data(), static_cast<int>(frame_ms.size()), 0, overlay, 0.0f,
                     std::max(hi * 1.2f, 1.0f), ImVec2(plot_w, 45));
  }
  if (!gpu) text_disabled_wrapped("cpu: CPU clock around glFinish (llvmpipe), not GPU time");
}

void text_disabled_wrapped(const char* text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", text);
  ImGui::PopStyleColor();
}

}  // namespace ssr
