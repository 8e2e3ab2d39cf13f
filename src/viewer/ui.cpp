// What the user sees and touches: the layout (the image at the top left, never under a panel;
// the side panel on the right, resizable and hidden with F2; the status bar along the bottom),
// the panels, the legend of the shown view, the keys and the mouse.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <map>

#include "gl/gl.h"
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "eval/metrics.h"
#include "registry/presets.h"
#include "registry/registry.h"
#include "scene/animation.h"
#include "scene/builtin_scenes.h"
#include "shared/colormap.h"
#include "viewer/panels.h"
#include "viewer/viewer.h"

namespace fs = std::filesystem;

namespace ssr {

namespace {

// The keys, declared once: the F1 window lists them, handle_input acts on them.
struct KeyBinding {
  int key;
  const char* name;
  const char* help;
};
constexpr KeyBinding kKeys[] = {
    {GLFW_KEY_F1, "F1", "show or hide this list"},
    {GLFW_KEY_F2, "F2", "show or hide the side panel (command: panel)"},
    {GLFW_KEY_F5, "F5", "reload the shaders (command: reload)"},
    {GLFW_KEY_F12, "F12", "save the image as ssrlab-DATE-TIME.png (command: screenshot)"},
    {GLFW_KEY_I, "I", "pin the inspector to the pixel under the cursor (again: follow the cursor)"},
    {GLFW_KEY_M, "M", "magnifier at the cursor on / off (zoom in the view panel; command: magnifier)"},
    {GLFW_KEY_W, "W / S", "fly forward / back (Shift x4, Ctrl x0.25)"},
    {GLFW_KEY_A, "A / D", "fly left / right"},
    {GLFW_KEY_E, "E / Q", "fly up / down"},
};
constexpr const char* kMouse[][2] = {
    {"left drag", "orbit around the target (on the divider: move it)"},
    {"right drag", "pan"},
    {"wheel", "zoom towards the target"},
    {"panel edge", "drag to resize the side panel"},
};

std::string timestamped_name() {
  char buf[64];
  const std::time_t t = std::time(nullptr);
  std::strftime(buf, sizeof buf, "ssrlab-%Y%m%d-%H%M%S.png", std::localtime(&t));
  return buf;
}

bool combo(const char* label, int* current, const std::vector<std::string>& items) {
  return ImGui::Combo(label, current, [](void* data, int i, const char** out) {
    *out = static_cast<const std::vector<std::string>*>(data)->at(static_cast<std::size_t>(i)).c_str();
    return true;
  }, const_cast<std::vector<std::string>*>(&items), static_cast<int>(items.size()));
}

ImU32 colour(float r, float g, float b, float a = 1.0f) { return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, a)); }

// Room for the longest parameter name of any technique next to its widget, and its reset button.
float label_width() {
  static const float w = [] {
    float m = ImGui::CalcTextSize("reflective_f0").x;
    for (const TechniqueInfo& t : technique_registry()) {
      auto tech = t.create();
      ParamSet p = tech->params();
      for (std::size_t i = 0; i < p.size(); ++i) m = std::max(m, ImGui::CalcTextSize(p.table()[i].name).x);
    }
    return m;
  }();
  const ImGuiStyle& st = ImGui::GetStyle();
  return w + st.ItemInnerSpacing.x + st.ItemSpacing.x + ImGui::CalcTextSize("reset").x + 2.0f * st.FramePadding.x + 4.0f;
}

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar;

}  // namespace

// --- input ---------------------------------------------------------------------------------

void Viewer::handle_input(double dt) {
  const ImGuiIO& io = ImGui::GetIO();
  for (const int key : window_->take_presses()) {
    if (io.WantCaptureKeyboard) continue;  // typing into a field
    if (key == GLFW_KEY_F1) help_shown_ = !help_shown_;
    else if (key == GLFW_KEY_F2) ui_command(Verb::Panel, panel_shown_ ? "off" : "on");
    else if (key == GLFW_KEY_F5) ui_command(Verb::Reload);
    else if (key == GLFW_KEY_F12) ui_command(Verb::Screenshot, timestamped_name());
    else if (key == GLFW_KEY_I) pinned_ = pinned_ ? std::nullopt : hovered_;
    else if (key == GLFW_KEY_M) ui_command(Verb::Magnifier, magnifier_ ? "off" : "8");
  }
  CameraInput in;
  in.dt = dt;
  if (!io.WantCaptureKeyboard) {
    auto held = [&](int key) { return window_->held_or_tapped(key) ? 1.0f : 0.0f; };
    in.fly = {held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q), held(GLFW_KEY_W) - held(GLFW_KEY_S)};
    in.speed = (io.KeyShift ? 4.0f : 1.0f) * (io.KeyCtrl ? 0.25f : 1.0f);
  }
  glm::dvec2 mouse;
  glfwGetCursorPos(window_->handle(), &mouse.x, &mouse.y);
  const glm::vec2 delta = glm::vec2(mouse - last_mouse_);
  last_mouse_ = mouse;
  const float sx = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
  const float image_w = static_cast<float>(image_w_) / sx, image_h = io.DisplaySize.y - kStatusH;
  const bool over_image = mouse.x >= 0 && mouse.x < image_w && mouse.y >= 0 && mouse.y < image_h;
  const float sy = io.DisplayFramebufferScale.y > 0 ? io.DisplayFramebufferScale.y : 1.0f;
  hovered_ = over_image && !io.WantCaptureMouse
                 ? std::optional(glm::ivec2(std::min(static_cast<int>(mouse.x * sx), image_w_ - 1),
                                            std::min(static_cast<int>(mouse.y * sy), image_h_ - 1)))
                 : std::nullopt;
  // The panel's edge: drag it to resize the panel.
  // A press is judged where it happened (ImGui's click position): a slow frame (llvmpipe: up to
  // a second) sees the cursor only after it has moved on.
  const bool near_edge = panel_shown_ && std::abs(static_cast<float>(mouse.x) - image_w) < 5.0f && mouse.y < image_h;
  const ImVec2 click = io.MouseClickedPos[ImGuiMouseButton_Left];
  const bool click_near_edge = panel_shown_ && std::abs(click.x - image_w) < 5.0f && click.y < image_h;
  if (click_near_edge && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) resizing_panel_ = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) resizing_panel_ = false;
  // Dragged: at least 200 px of panel and 64 of image.
  if (resizing_panel_) panel_w_ = std::clamp(io.DisplaySize.x - static_cast<float>(mouse.x), 200.0f, std::max(200.0f, io.DisplaySize.x - 64.0f));
  // The split divider (image coordinates: the image starts at the window's left edge).
  const float divider_x = split_ * image_w;
  const bool near_divider = compare_ == CompareSplit && over_image && std::abs(static_cast<float>(mouse.x) - divider_x) < 6.0f;
  if (!io.WantCaptureMouse && near_divider && !resizing_panel_ && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
    dragging_divider_ = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging_divider_ = false;
  if (dragging_divider_ && image_w > 0) split_ = std::clamp(static_cast<float>(mouse.x) / image_w, 0.0f, 1.0f);
  if (near_edge || resizing_panel_ || ((near_divider && !io.WantCaptureMouse) || dragging_divider_))
    ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  const bool mouse_free = !io.WantCaptureMouse && !dragging_divider_ && !resizing_panel_ && !near_edge;
  // Only movement while a button is held moves the camera: on the frame of the press, the delta
  // since the last frame is travel made before it (a whole slow frame's worth on llvmpipe).
  auto dragging = [](ImGuiMouseButton b) { return ImGui::IsMouseDown(b) && !ImGui::IsMouseClicked(b); };
  if (mouse_free && over_image) {
    if (dragging(ImGuiMouseButton_Left)) in.orbit = delta;
    if (dragging(ImGuiMouseButton_Right)) in.pan = delta;
    in.wheel = io.MouseWheel;
  }
  if (camera_.update(in)) last_moved_ = glfwGetTime();
}

// --- layout --------------------------------------------------------------------------------

void Viewer::layout() {
  const ImGuiIO& io = ImGui::GetIO();
  window_->framebuffer_size(&fb_w_, &fb_h_);
  const float sx = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
  const float sy = io.DisplayFramebufferScale.y > 0 ? io.DisplayFramebufferScale.y : 1.0f;
  // Only a drag narrows the image (handle_input): a --size image keeps its size exactly.
  panel_w_ = std::min(panel_w_, io.DisplaySize.x);
  image_w_ = std::max(0, fb_w_ - (panel_shown_ ? static_cast<int>(std::lround(panel_w_ * sx)) : 0));
  image_h_ = std::max(0, fb_h_ - static_cast<int>(std::lround(kStatusH * sy)));
}

void Viewer::draw_ui(double dt) {
  draw_image_overlays();
  if (panel_shown_) side_panel(dt);
  status_bar(dt);
  if (help_shown_) help_window();
}

// On the image: the divider and the A / B labels, and what is not current ("computing", "stale").
// Never in screenshots (they read the composed image, not the window).
void Viewer::draw_image_overlays() {
  const ImGuiIO& io = ImGui::GetIO();
  const float sx = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
  const float w = static_cast<float>(image_w_) / sx, h = io.DisplaySize.y - kStatusH;
  if (w <= 0 || h <= 0) return;
  ImDrawList* bg = ImGui::GetBackgroundDrawList();
  bg->PushClipRect(ImVec2(0, 0), ImVec2(w, h));
  const float x = compare_ == CompareSplit ? split_ * w : 0.0f;
  const float cw = std::floor(static_cast<float>(render_w()) / sx), ch = std::floor(static_cast<float>(render_h()) / sx);
  // Labels wrap to the room they have (a long "A: dda stride=2 ..." ran into the other half and
  // off the image); `bottom`: `at` is the label's bottom-left corner, so more lines go upwards.
  auto label = [&](ImVec2 at, const std::string& text, float room, bool bottom = false) {  // on a dark box
    room = std::max(room, 40.0f);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, room);
    if (bottom) at.y -= size.y;
    bg->AddRectFilled(ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + size.x + 3, at.y + size.y + 2), colour(0, 0, 0, 0.7f), 2.0f);
    bg->AddText(nullptr, 0.0f, at, colour(1, 1, 1), text.c_str(), nullptr, room);
  };
  const bool one_image = view_ == kViewTraceable;  // the reference's mask: neither A nor B
  if (compare_ == CompareGrid && !one_image) {
    const std::string names[4] = {"A: " + side_label(0), "B: " + side_label(1),
                                   "truth: " + sides_[2].technique->name(), "|A - truth|"};
    for (int c = 0; c < 4; ++c)
      label(ImVec2(cw * static_cast<float>(c % 2) + 8, ch * static_cast<float>(c / 2 + 1) - 6), names[c], cw - 16, true);
    bg->AddLine(ImVec2(cw, 0), ImVec2(cw, 2 * ch), colour(1, 1, 1, 0.5f));
    bg->AddLine(ImVec2(0, ch), ImVec2(2 * cw, ch), colour(1, 1, 1, 0.5f));
  }
  if (compare_ == CompareSplit && !one_image) {
    bg->AddLine(ImVec2(x, 0), ImVec2(x, h), dragging_divider_ ? colour(1, 0.86f, 0.31f) : colour(1, 1, 1, 0.8f), 2.0f);
    const std::string left = "A: " + side_label(0), right = "B: " + side_label(1);
    const float left_room = std::max(x - 16, 40.0f), right_room = std::max(w - x - 16, 40.0f);
    const float left_w = ImGui::CalcTextSize(left.c_str(), nullptr, false, left_room).x;
    label(ImVec2(std::max(x - 8 - left_w, 4.0f), h - 6), left, left_room, true);
    label(ImVec2(std::min(x + 8, w - right_room - 8), h - 6), right, right_room, true);
  }
  // A side that is not current says so on its part of the image.
  const int n = active_sides();
  for (int i = 0; i < n && view_ != kViewTraceable; ++i) {
    const Side& s = sides_[i];
    std::string what;
    if (!side_fills_view(i, view_))  // its half is blank: not data to read as the legend says
      what = s.technique->name() + " does not produce the '" + view_names_[static_cast<std::size_t>(view_)] + "' view";
    else if (side_current(i)) continue;
    else if (s.request > 0) what = "computing " + s.technique->name() + " ...";
    else if (!on_demand(i)) continue;  // every-frame sides are current after this frame
    else if (!s.computed) what = s.technique->name() + ": not computed yet" +
                              (truth_policy_ == TruthPolicy::Rest ? " (once the camera rests)" : " (press 'compute now')");
    else what = s.technique->name() + " is STALE: it shows an earlier view" +
                (truth_policy_ == TruthPolicy::Rest ? " (recomputed once the camera rests)" : " (press 'compute now')");
    // The side's part of the image: the banner stays inside it.
    float x0 = compare_ == CompareSplit ? (i == 0 ? 0.0f : x) : 0.0f, x1 = compare_ == CompareSplit && i == 0 ? x : w;
    float y0 = compare_ == CompareDiff ? 8.0f + 26.0f * static_cast<float>(i) : 8.0f;
    if (compare_ == CompareGrid) {
      x0 = cw * static_cast<float>(i % 2);
      x1 = x0 + cw;
      y0 = ch * static_cast<float>(i / 2) + 8.0f;
    }
    const float room = std::max(x1 - x0 - 24, 40.0f);  // wrapped inside the side's part
    const ImVec2 size = ImGui::CalcTextSize(what.c_str(), nullptr, false, room);
    bg->PushClipRect(ImVec2(x0, 0), ImVec2(x1, h), true);
    bg->AddRectFilled(ImVec2(x0 + 8, y0), ImVec2(x0 + 16 + size.x, y0 + size.y + 8), colour(0.55f, 0.1f, 0.05f, 0.85f), 3.0f);
    bg->AddText(nullptr, 0.0f, ImVec2(x0 + 12, y0 + 4), colour(1, 0.9f, 0.8f), what.c_str(), nullptr, room);
    bg->PopClipRect();
  }
  if (magnifier_ > 0 && hovered_ && composed_) draw_magnifier();
  // The pinned pixel (I): a ring around it, so the values in the panel have a place.
  if (pinned_) {
    const float sy = io.DisplayFramebufferScale.y > 0 ? io.DisplayFramebufferScale.y : 1.0f;
    const ImVec2 c((static_cast<float>(pinned_->x) + 0.5f) / sx, (static_cast<float>(pinned_->y) + 0.5f) / sy);
    bg->AddCircle(c, 7.0f, colour(0, 0, 0, 0.8f), 16, 3.0f);
    bg->AddCircle(c, 7.0f, colour(1, 0.86f, 0.31f), 16, 1.5f);
  }
  bg->PopClipRect();
}

// A box near the cursor showing the image around it at magnifier_ x, nearest filtering (the
// composed image's own filter), with the centre pixel outlined.
void Viewer::draw_magnifier() {
  const ImGuiIO& io = ImGui::GetIO();
  const float sx = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
  const float w = static_cast<float>(image_w_) / sx, h = io.DisplaySize.y - kStatusH;
  const float box = std::min({176.0f, w, h});
  const float zoom = static_cast<float>(magnifier_);
  const ImVec2 m = io.MousePos;
  ImVec2 p0(m.x + 24, m.y + 24);
  if (p0.x + box > w) p0.x = m.x - 24 - box;
  if (p0.y + box > h) p0.y = m.y - 24 - box;
  p0 = ImVec2(std::max(p0.x, 0.0f), std::max(p0.y, 0.0f));
  const float half = box / zoom * 0.5f;  // image pixels either side of the centre
  const float cx = static_cast<float>(hovered_->x) + 0.5f, cy = static_cast<float>(hovered_->y) + 0.5f;
  const float iw = static_cast<float>(image_w_), ih = static_cast<float>(image_h_);
  // The texture's rows go up: v = 1 is the image's top row.
  const ImVec2 uv0((cx - half) / iw, 1.0f - (cy - half) / ih), uv1((cx + half) / iw, 1.0f - (cy + half) / ih);
  ImDrawList* bg = ImGui::GetBackgroundDrawList();
  bg->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(composed_.id())), p0, ImVec2(p0.x + box, p0.y + box),
               uv0, uv1);
  bg->AddRect(p0, ImVec2(p0.x + box, p0.y + box), colour(1, 1, 1, 0.9f));
  const ImVec2 c(p0.x + box * 0.5f, p0.y + box * 0.5f);
  bg->AddRect(ImVec2(c.x - zoom * 0.5f, c.y - zoom * 0.5f), ImVec2(c.x + zoom * 0.5f, c.y + zoom * 0.5f), colour(1, 0.2f, 0.9f));
  char label[32];
  std::snprintf(label, sizeof label, "%dx", magnifier_);
  bg->AddText(ImVec2(p0.x + 4, p0.y + 2), colour(1, 1, 1), label);
}

// The values of the pinned pixel, or of the one under the cursor.
void Viewer::inspector_panel() {
  const std::optional<glm::ivec2> p = pinned_ ? pinned_ : hovered_;
  if (!p || !composed_ || p->x >= image_w_ || p->y >= image_h_) {
    ImGui::TextDisabled("hover the image (I pins a pixel)");
    return;
  }
  PixelValues j;
  try {
    j = inspect(p->x, p->y);
  } catch (const std::exception& e) {
    ImGui::TextDisabled("%s", e.what());
    return;
  }
  ImGui::Text("pixel %d, %d%s", p->x, p->y, pinned_ ? " (pinned: I to follow the cursor)" : "");
  draw_pixel_values(j);
}

// The status bar: panel and keys toggles, the latest message (errors red), the truth's state,
// the device and the frame time.
void Viewer::status_bar(double dt) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - kStatusH));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, kStatusH));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(6, 4));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
  ImGui::Begin("##status", nullptr, kFixed | ImGuiWindowFlags_NoScrollbar);
  StatusLine line{status_, status_error_, truth_state() == "none" ? "" : truth_state(), shown_frame_ms(dt),
                  window_->info().renderer};
  const StatusActions act = draw_status_line(line, panel_shown_);
  if (act.toggle_panel) ui_command(Verb::Panel, panel_shown_ ? "off" : "on");
  if (act.toggle_keys) help_shown_ = !help_shown_;
  ImGui::End();
  ImGui::PopStyleVar(2);
}

void Viewer::help_window() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::Begin("keys and mouse (F1)", &help_shown_, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
  if (ImGui::BeginTable("keys", 2)) {
    for (const KeyBinding& k : kKeys) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(k.name);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(k.help);
    }
    for (const auto& m : kMouse) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(m[0]);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(m[1]);
    }
    ImGui::EndTable();
  }
  ImGui::TextDisabled("Scripts (--script FILE) take the commands of `ssrlab-view --help-script`.");
  ImGui::End();
}

// The legend of what the image shows: a colour bar with its scale and unit, swatches, or how
// the colour encodes a vector; the difference view's heat scale.
void Viewer::legend() {
  if (compare_ == CompareDiff && view_ != kViewTraceable) draw_difference_legend(diff_scale_);
  else if (view_ == kViewTraceable) draw_class_legend();
  else draw_view_legend(view_table()[static_cast<std::size_t>(view_)], renderer_->settings.exposure);
  if (compare_ == CompareGrid) draw_difference_legend(diff_scale_, "|A - truth| (the fourth cell)");
}

// --- the side panel ------------------------------------------------------------------------

void Viewer::side_panel(double dt) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - panel_w_, 0));
  ImGui::SetNextWindowSize(ImVec2(panel_w_, io.DisplaySize.y - kStatusH));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
  ImGui::Begin("##panel", nullptr, kFixed);
  ImGui::PopStyleVar();
  ImGui::PushItemWidth(-label_width());
  // Pinned at the top: what the image shows and the figure read from it.
  legend();
  if (compare_ != CompareOff) {
    if (figure_shown()) {
      if (psnr_ >= kPsnrCap) ImGui::Text("PSNR A vs B: identical");
      else ImGui::Text("PSNR A vs B: %.2f dB", psnr_);
      if (ImGui::IsItemHovered()) {
        // Its history makes the figure of such a technique move over frames; compare scores one
        // frame without history (cornell stochastic: compare 22.77 dB, here 22.91 at frame 1,
        // 23.21 from frame 8).
        bool varies = false;
        for (int i = 0; i < 2; ++i) varies |= sides_[i].technique->declare().varies_per_frame;
        ImGui::SetTooltip("final image, reflective and glass pixels, display values: compare's 'PSNR' when B is the "
                          "reference%s",
                          varies ? ".\nThis frame's, with its history: compare scores a first frame (no history), "
                                   "ssrlab sequence scores every frame."
                                 : "");
      }
      if (truth_figure_shown()) {  // the grid's fourth cell
        if (psnr_truth_ >= kPsnrCap) ImGui::Text("PSNR A vs truth: identical");
        else ImGui::Text("PSNR A vs truth: %.2f dB", psnr_truth_);
      }
      if (const std::optional<double> floor = truth_noise_shown()) {  // truth-noise on
        if (*floor >= kPsnrCap) ImGui::Text("truth noise floor: none (exact rays)");
        else ImGui::Text("truth noise floor: %.2f dB", *floor);
        if (ImGui::IsItemHovered())
          ImGui::SetTooltip("a second truth with another seed: what a noise-free truth would score against this one.\n"
                            "A figure near it is the truth's noise, not the technique's error (raise reference.samples).");
      }
      if (compare_ == CompareGrid)  // each cell renders at a quarter of the image: its own figures
        ImGui::TextDisabled("(at the cells' %dx%d, as compare --size %dx%d)", render_w(), render_h(), render_w(),
                            render_h());
    } else if (const int i = on_demand(0) && !side_current(0) ? 0 : on_demand(1) && !side_current(1) ? 1 : -1; i >= 0) {
      // An on-demand side of this figure (A or B; the grid's truth has a figure of its own).
      ImGui::TextColored(ImVec4(1, 0.6f, 0.4f, 1), "PSNR A vs B: - (%s is %s)", sides_[i].technique->name().c_str(),
                         side_state(i).c_str());
    } else if (view_ != VIEW_FINAL) {
      ImGui::TextDisabled("PSNR A vs B: in the final view only");
    } else if (!side_current(0) || !side_current(1)) {  // e.g. the image resized under a panel drag
      ImGui::TextDisabled("PSNR A vs B: - (the next frame has it)");
    } else {
      ImGui::TextDisabled("PSNR A vs B: - (no reflective or glass pixels)");
    }
  }
  ImGui::Separator();
  ImGui::BeginChild("##sections");
  ImGui::PushItemWidth(-label_width());
  if (section_header(SectionInspector)) inspector_panel();
  if (section_header(SectionScene)) scene_panel();
  if (section_header(SectionLights)) {
    std::vector<Light> lights = lights_;
    Environment env = environment_;
    float ambient = ambient_;
    if (draw_lights_panel(lights) | draw_environment_panel(env, ambient)) {
      try {
        set_lighting(lights, env, ambient);
      } catch (const std::exception& e) {
        set_status(e.what(), true);
      }
    }
  }
  if (section_header(SectionTime)) time_panel();
  if (section_header(SectionView)) view_panel();
  if (section_header(SectionTechniqueA)) technique_panel(0);
  section_open_[SectionTechniqueB] = false;  // not drawn without B
  if (compare_ != CompareOff && section_header(SectionTechniqueB)) technique_panel(1);
  if (section_header(SectionPresets)) {
    ImGui::InputText("file", preset_path_, sizeof preset_path_);
    if (ImGui::Button("save")) ui_command(Verb::PresetSave, preset_path_);
    ImGui::SameLine();
    if (ImGui::Button("load")) ui_command(Verb::PresetLoad, preset_path_);
    // The preset files next to the named one.
    std::vector<std::string> files;
    std::error_code ec;
    const fs::path dir = fs::path(preset_path_).parent_path().empty() ? fs::path(".") : fs::path(preset_path_).parent_path();
    for (const auto& e : fs::directory_iterator(dir, ec))
      if (e.path().extension() == ".json") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    if (!files.empty() && ImGui::BeginCombo("files here", "load a preset file ...")) {
      for (const std::string& f : files)
        if (ImGui::Selectable(f.c_str())) {
          std::snprintf(preset_path_, sizeof preset_path_, "%s", f.c_str());
          ui_command(Verb::PresetLoad, f);
        }
      ImGui::EndCombo();
    }
    ImGui::TextDisabled("techniques, parameters, view, camera, lights (JSON)");
  }
  if (section_header(SectionTiming)) timing_panel(dt);
  ImGui::PopItemWidth();
  ImGui::EndChild();
  ImGui::PopItemWidth();
  ImGui::End();
}

bool Viewer::section_header(PanelSection s) {
  const SectionInfo& info = kPanelSections[s];
  if (section_request_[s]) ImGui::SetNextItemOpen(*section_request_[s]);
  section_request_[s].reset();
  section_open_[s] = ImGui::CollapsingHeader(info.label, info.open_at_start ? ImGuiTreeNodeFlags_DefaultOpen : 0);
  return section_open_[s];
}

void Viewer::scene_panel() {
  // The scene files by their file names (the full path is the tooltip), and the current one found
  // however it was named (a relative path on the command line, "./x.json").
  if (scene_labels_.size() != scene_names_.size()) {
    scene_labels_.clear();
    for (const std::string& n : scene_names_)
      scene_labels_.push_back(n.find('/') == std::string::npos ? n : std::filesystem::path(n).filename().string());
    scene_choice_for_.reset();
  }
  if (scene_choice_for_ != scene_spec_) {
    scene_choice_for_ = scene_spec_;
    scene_choice_ = -1;
    std::error_code ec;
    for (std::size_t i = 0; i < scene_names_.size() && scene_choice_ < 0; ++i)
      if (scene_names_[i] == scene_spec_ || (scene_names_[i].find('/') != std::string::npos &&
                                             std::filesystem::equivalent(scene_names_[i], scene_spec_, ec)))
        scene_choice_ = static_cast<int>(i);
  }
  int current = scene_choice_;
  if (combo("scene", &current, scene_labels_) && current >= 0) ui_command(Verb::Scene, scene_names_[static_cast<std::size_t>(current)]);
  if (ImGui::IsItemHovered() && !scene_spec_.empty()) ImGui::SetTooltip("%s", scene_spec_.c_str());
  // Built-in scenes' options, one combo each: the spec becomes "name:key=value,..." as --scene takes it.
  const std::string base = scene_spec_.substr(0, scene_spec_.find(':'));
  for (const BuiltinSceneInfo& s : builtin_scenes()) {
    if (s.name != base) continue;
    std::map<std::string, std::string> chosen;  // the current spec's options
    if (const auto colon = scene_spec_.find(':'); colon != std::string::npos) {
      std::string rest = scene_spec_.substr(colon + 1) + ",";
      for (std::size_t at = 0, comma; (comma = rest.find(',', at)) != std::string::npos; at = comma + 1) {
        const std::string kv = rest.substr(at, comma - at);
        if (const auto eq = kv.find('='); eq != std::string::npos) chosen[kv.substr(0, eq)] = kv.substr(eq + 1);
      }
    }
    for (const BuiltinSceneInfo::Option& o : s.options) {
      if (o.values.empty()) continue;
      const std::string now = chosen.count(o.key) ? chosen[o.key] : o.default_value.empty() ? "-" : o.default_value;
      if (!ImGui::BeginCombo(o.key.c_str(), now.c_str())) continue;
      for (const std::string& v : o.values) {
        if (!ImGui::Selectable(v.c_str(), v == now)) continue;
        std::map<std::string, std::string> next = chosen;
        next[o.key] = v;
        std::string spec = base;
        for (const auto& [k, x] : next) spec += (spec == base ? ":" : ",") + k + "=" + x;
        ui_command(Verb::Scene, spec);
      }
      ImGui::EndCombo();
    }
  }
  ImGui::InputTextWithHint("##scenepath", ".json or .obj path", scene_path_, sizeof scene_path_);
  ImGui::SameLine();
  if (ImGui::Button("open") && scene_path_[0]) ui_command(Verb::Scene, scene_path_);
  if (ImGui::BeginCombo("camera", camera_.camera().name.c_str())) {
    for (const Camera& c : cameras_)
      if (ImGui::Selectable(c.name.c_str(), c.name == camera_.camera().name)) ui_command(Verb::Camera, c.name);
    ImGui::EndCombo();
  }
  if (ImGui::Button("bookmark this view")) {
    Camera c = camera_.camera();
    c.name = "bookmark " + std::to_string(++bookmarks_);
    cameras_.push_back(c);
    camera_.camera().name = c.name;
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("adds the current view to the camera list (saved with presets)");
  if (draw_camera_panel(camera_.camera())) last_moved_ = glfwGetTime();
}

void Viewer::view_panel() {
  if (ImGui::BeginCombo("view", view_names_[static_cast<std::size_t>(view_)].c_str())) {
    for (int v = 0; v < static_cast<int>(view_names_.size()); ++v)
      if (view_offered(v) && ImGui::Selectable(view_names_[static_cast<std::size_t>(v)].c_str(), v == view_))
        ui_command(Verb::View, view_names_[static_cast<std::size_t>(v)]);
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("only the views the shown techniques produce; the legend at the top says how to read it");
  if (view_ == kViewTraceable) {
    if (mask_request_) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "computing...");
    else if (mask_key_ != inputs_key()) {
      if (ImGui::Button("compute traceable mask")) mask_request_ = true;
      ImGui::SameLine();
      ImGui::TextDisabled(mask_key_.empty() ? "not computed" : "stale");
    } else ImGui::TextDisabled("traceable mask up to date");
  }
  ParamSet frame = frame_settings_params(renderer_->settings);  // exposure, reflective_f0: one table
  draw_param_panel(frame);
  bool magnify = magnifier_ > 0;
  if (ImGui::Checkbox("magnifier (M)", &magnify)) magnifier_ = magnify ? 8 : 0;
  if (magnify) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - label_width() + 40.0f);
    ImGui::SliderInt("zoom", &magnifier_, 2, 16, "%dx");
  }
  int mode = compare_;
  for (const CompareInfo& c : kCompareModes) {
    if (c.mode != CompareOff) ImGui::SameLine();
    ImGui::RadioButton(c.label, &mode, c.mode);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (command: compare %s)", c.help, c.name);
  }
  if (mode != compare_) ui_command(Verb::Compare, kCompareModes[mode].name);
  if (compare_ == CompareSplit) ImGui::SliderFloat("divider", &split_, 0.0f, 1.0f, "%.3f");
  if (compare_ == CompareDiff) {
    ImGui::SliderFloat("full scale", &diff_scale_, 0.01f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("mean |A - B| over RGB (display values) shown as the hottest colour");
  }
  if (compare_ != CompareOff) {
    if (ImGui::Button("swap A and B")) ui_command(Verb::Swap);
    ImGui::SameLine();
    if (ImGui::Button("B is the truth") && !is_truth(sides_[1].technique->name()))
      ui_command(Verb::TechniqueB, truth_name());
    if (sides_[0].technique->name() == sides_[1].technique->name()) {
      ImGui::SameLine();
      if (ImGui::Button("A's values to B")) {
        try {
          apply_params(*sides_[1].technique, capture_params(*sides_[0].technique));
        } catch (const std::exception& e) {
          set_status(e.what(), true);
        }
      }
    }
    if (psnr_history_.size() > 1) {
      const std::vector<float> h(psnr_history_.begin(), psnr_history_.end());
      ImGui::PlotLines("##psnr history", h.data(), static_cast<int>(h.size()), 0, "PSNR A vs B per frame (dB)", FLT_MAX,
                       FLT_MAX, ImVec2(ImGui::GetContentRegionAvail().x, 50.0f));
    }
  }
}

// Technique picker + parameter panel of one side (values off their default are highlighted).
void Viewer::technique_panel(int i) {
  Side& side = sides_[i];
  ImGui::PushID(i);
  if (ImGui::BeginCombo(i == 0 ? "A" : "B", side.technique->name().c_str())) {
    for (const TechniqueInfo& t : technique_registry()) {
      if (ImGui::Selectable(t.name.c_str(), t.name == side.technique->name()))
        ui_command(i == 0 ? Verb::Technique : Verb::TechniqueB, t.name);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t.description.c_str());
    }
    ImGui::EndCombo();
  }
  // A short preview: the panel's default width cut "set up from a preset ..." to "set up from a pre".
  if (ImGui::BeginCombo("named preset", "apply one ...")) {
    for (const Preset& p : presets()) {
      if (ImGui::Selectable(p.name.c_str())) {
        if (i == 0) ui_command(Verb::Preset, p.name);
        else {
          try {
            use_named_preset(side, p.name);
          } catch (const std::exception& e) {
            set_status(e.what(), true);
          }
        }
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: %s", p.technique.c_str(), p.source.c_str());
    }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("set this side up from a named preset (ssrlab techniques lists them)");
  if (on_demand(i)) {
    ImGui::BeginDisabled(side.request > 0 || side_current(i));
    if (ImGui::Button("compute now")) ui_command(Verb::Truth, "now");
    ImGui::EndDisabled();
    ImGui::SameLine();
    const std::string state = side_state(i);
    if (state == "current") ImGui::TextDisabled("up to date");
    else ImGui::TextColored(ImVec4(1, 0.6f, 0.4f, 1), "%s", state.c_str());
    int policy = static_cast<int>(truth_policy_);
    ImGui::RadioButton("when asked", &policy, static_cast<int>(TruthPolicy::Manual));
    ImGui::SameLine();
    ImGui::RadioButton("at rest", &policy, static_cast<int>(TruthPolicy::Rest));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("recompute it %.1f s after the view last changed", kRestSeconds);
    ImGui::SameLine();
    ImGui::RadioButton("every frame", &policy, static_cast<int>(TruthPolicy::Live));
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("run it on every changed frame (playback: the A-vs-B figure per frame is plotted); slow");
    if (policy != static_cast<int>(truth_policy_)) truth_policy_ = static_cast<TruthPolicy>(policy);
    bool noise = truth_noise_;
    if (ImGui::Checkbox("estimate its noise", &noise)) ui_command(Verb::TruthNoise, noise ? "on" : "off");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("after each new truth, a second one with another seed (twice the time): the figures at the top "
                        "show the truth's noise floor");
  }
  ParamSet params = side.technique->params();
  const ParamSet ran = side.technique->ran_params();
  draw_param_panel(params, &ran);
  ImGui::PopID();
}

void Viewer::time_panel() {
  const Animation& anim = renderer_->scene().animation;
  std::vector<std::string> names = {"free camera"};
  for (const CameraPath& p : anim.paths) names.push_back(p.name);
  int current = path_ + 1;
  // "camera path": the scene panel's "path" is the scene's option (the path it starts on).
  if (combo("camera path", &current, names)) ui_command(Verb::Path, current == 0 ? "free" : names[static_cast<std::size_t>(current)]);
  if (path_ >= 0 && ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", anim.paths[static_cast<std::size_t>(path_)].description.c_str());
  if (ImGui::Button(playing_ ? "pause" : "play")) ui_command(playing_ ? Verb::Pause : Verb::Play);
  ImGui::SameLine();
  if (ImGui::Button("step")) set_time(time_ + speed_ / 30.0f);
  ImGui::SameLine();
  ImGui::Checkbox("loop", &loop_);
  ImGui::SameLine();
  if (ImGui::Button("reset history")) cut_next_ = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the next frame is a camera cut: every technique's history restarts");
  float t = time_;
  if (ImGui::SliderFloat("time", &t, 0.0f, std::max(anim.duration, 0.01f), "%.2f s")) set_time(t);
  ImGui::SliderFloat("speed", &speed_, 0.1f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic);
  if (renderer_->history_valid())
    ImGui::TextDisabled("frame %d, history carried", frame_index_);
  else
    ImGui::TextDisabled("frame %d, history restarted: %s", frame_index_, renderer_->history_break());
}

std::optional<double> Viewer::shown_frame_ms(double dt) const {
  if (dt > 0.0) return dt * 1000.0;
  return frame_ms_.empty() ? std::nullopt : std::optional<double>(frame_ms_.back());
}

// Per-pass times of the last frame of each side (ms and % of that side's frame), the
// technique's rolling plot and the frame time. Labelled `gpu` or `cpu` (llvmpipe: CPU clock).
void Viewer::timing_panel(double dt) {
  std::vector<TimingColumn> columns;
  for (int i = 0; i < active_sides(); ++i) {
    const Side& s = sides_[i];
    columns.push_back({i == 0 ? "A" : i == 1 ? "B" : "truth", s.technique->name(), s.last_times,
                       std::vector<float>(s.history.begin(), s.history.end())});
  }
  draw_timing(columns, std::vector<float>(frame_ms_.begin(), frame_ms_.end()), shown_frame_ms(dt).value_or(0.0),
              clock_ == gl::PassTimer::Clock::Gpu);
  if (renderer_->debug_outputs)
    text_disabled_wrapped("includes the debug image the inspector reads (bench leaves it out: tracers up to a fifth "
                          "faster)");
}

// A frame with only a progress bar over the last image: long CPU work (the reference) calls it.
void Viewer::draw_progress(const std::string& what, double fraction) {
  window_->poll();
  window_->begin_ui();
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(image_w_) * 0.5f, static_cast<float>(image_h_) * 0.5f), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(420.0f, io.DisplaySize.x), 0));
  ImGui::Begin("computing", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
  ImGui::Text("%s: CPU ray tracing (Embree)", what.c_str());
  ImGui::ProgressBar(static_cast<float>(std::clamp(fraction, 0.0, 1.0)));
  ImGui::End();
  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_w_, fb_h_);
  if (composed_ && composed_.width() == image_w_ && composed_.height() == image_h_) {
    glNamedFramebufferTexture(blit_fbo_.id(), GL_COLOR_ATTACHMENT0, composed_.id(), 0);
    glBlitNamedFramebuffer(blit_fbo_.id(), 0, 0, 0, image_w_, image_h_, 0, fb_h_ - image_h_, image_w_, fb_h_,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  window_->present();
}

// The technique and every parameter not at its default, as the CLI labels a --set row: "hiz"
// alone is hiz at its defaults (a side with denoise=true read as plain hiz). Past four, a count.
std::string Viewer::side_label(int i) const {
  Technique& t = *sides_[i].technique;
  std::string label = t.name();
  ParamSet mine = t.params();
  constexpr int kShown = 4;
  int set = 0;
  for (std::size_t k = 0; k < mine.size(); ++k)
    if (mine.to_string(k) != mine.default_string(k) && ++set <= kShown)
      label += " " + std::string(mine.table()[k].name) + "=" + mine.to_string(k);
  if (set > kShown) label += " (+" + std::to_string(set - kShown) + " more set)";
  return label;
}

// Debug views are offered for the techniques that produce them (their declarations).
bool Viewer::side_fills_view(int i, int view) const {
  if (view >= static_cast<int>(view_table().size())) return true;  // the traceable mask
  const ViewInfo& v = view_table()[static_cast<std::size_t>(view)];
  if (!v.debug) return true;
  const std::vector<ViewMode> d = sides_[i].technique->declare().debug_views;
  return std::find(d.begin(), d.end(), v.mode) != d.end();
}

// A split shows a debug view when either side fills it (the other half says it does not); the
// difference needs both (against a blank half it would be a picture of the one side).
bool Viewer::view_offered(int view) const {
  if (view == kViewTraceable) return compare_ != CompareGrid;  // the mask is one image
  if (view < static_cast<int>(view_table().size()) && view_table()[static_cast<std::size_t>(view)].debug &&
      compare_ == CompareGrid)
    return false;  // the grid sets A against its truth, which has no debug views
  int filled = 0;
  for (int i = 0; i < active_sides(); ++i) filled += side_fills_view(i, view) ? 1 : 0;
  return compare_ == CompareDiff ? filled == active_sides() : filled > 0;
}

}  // namespace ssr
