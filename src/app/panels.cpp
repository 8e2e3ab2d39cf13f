#include "app/panels.h"

#include <algorithm>

#include <imgui.h>

namespace ssr {

bool draw_param_panel(ParamSet& params) {
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
    switch (d.type) {
      case ParamType::Float: {
        float v = static_cast<float>(before);
        // Wide ranges are easier to tune on a logarithmic slider.
        const ImGuiSliderFlags flags = (d.min > 0 && d.max / d.min >= 100) ? ImGuiSliderFlags_Logarithmic : 0;
        if (ImGui::SliderFloat(d.name, &v, static_cast<float>(d.min), static_cast<float>(d.max), "%.4g", flags))
          params.set(i, std::clamp<double>(v, d.min, d.max));
        break;
      }
      case ParamType::Int: {
        int v = static_cast<int>(before);
        const ImGuiSliderFlags flags = (d.min > 0 && d.max / d.min >= 100) ? ImGuiSliderFlags_Logarithmic : 0;
        if (ImGui::SliderInt(d.name, &v, static_cast<int>(d.min), static_cast<int>(d.max), "%d", flags))
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
    if (ImGui::IsItemHovered())
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

}  // namespace ssr
