// Dear ImGui without a window: the null-backend pattern. A context, a display size and a built
// font atlas are all NewFrame needs; Render only fills draw lists, which nothing draws. The
// mouse is set directly (ImGui 1.86: io.MousePos / io.MouseDown, no input events yet).
//
// Debian's prebuilt libimgui keeps its IM_ASSERTs (assert()), so a misuse aborts the test binary
// with ImGui's message; unbalanced stacks (PushID, BeginDisabled, TreeNode ...) are caught here
// first by ImGui's own recovery, which logs them into errors().
#pragma once
#include <cfloat>
#include <cstdarg>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>

namespace ssr::test {

class ImGuiHarness {
 public:
  using Draw = std::function<bool()>;
  static constexpr float kWidth = 800, kHeight = 6000;

  ImGuiHarness() {
    IMGUI_CHECKVERSION();
    ctx_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    io.DisplaySize = ImVec2(kWidth, kHeight);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas; nothing uploads it
  }
  ~ImGuiHarness() { ImGui::DestroyContext(ctx_); }
  ImGuiHarness(const ImGuiHarness&) = delete;
  ImGuiHarness& operator=(const ImGuiHarness&) = delete;

  // One frame with `draw` inside a full-screen, undecorated window at the origin; returns
  // what `draw` returned.
  bool frame(const Draw& draw) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = mouse_;
    io.MouseDown[0] = down_;
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(io.DisplaySize);
    ImGui::Begin("test", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                      ImGuiWindowFlags_NoSavedSettings);
    const bool result = draw();
    bottom_ = ImGui::GetCursorScreenPos().y;
    ImGui::ErrorCheckEndWindowRecover(&log_error, this);
    ImGui::End();
    ImGui::ErrorCheckEndFrameRecover(&log_error, this);
    ImGui::Render();
    return result;
  }

  // The item under the mouse in the last frame (0: none); disabled items count too. Not
  // ImGui::GetHoveredID(), which falls back to the frame before.
  static ImGuiID hovered() { return ImGui::GetCurrentContext()->HoveredId; }

  // Where each item was found hovered: the box of the grid points over it.
  struct Hit {
    ImVec2 min{FLT_MAX, FLT_MAX}, max{-FLT_MAX, -FLT_MAX};
    ImVec2 center() const { return ImVec2((min.x + max.x) / 2, (min.y + max.y) / 2); }
    ImVec2 left() const { return ImVec2(min.x, (min.y + max.y) / 2); }
    ImVec2 right() const { return ImVec2(max.x, (min.y + max.y) / 2); }
  };
  // Hovers a grid over the drawn content and records which item each point is over. The
  // prebuilt ImGui has no test-engine hooks, so this is how items and their places are found.
  // Rows start at `from_y`.
  std::map<ImGuiID, Hit> scan(const Draw& draw, float step_x = 8, float step_y = 3, float from_y = 1) {
    down_ = false;
    move(ImVec2(-100, -100));
    frame(draw);
    const float bottom = bottom_;
    std::map<ImGuiID, Hit> hits;
    for (float y = from_y; y < bottom; y += step_y)
      for (float x = 1; x < kWidth; x += step_x) {
        move(ImVec2(x, y));
        frame(draw);
        if (const ImGuiID id = hovered()) {
          Hit& h = hits[id];
          h.min = ImVec2(std::min(h.min.x, x), std::min(h.min.y, y));
          h.max = ImVec2(std::max(h.max.x, x), std::max(h.max.y, y));
        }
      }
    move(ImVec2(-100, -100));
    frame(draw);
    return hits;
  }

  // `h` widened to the item's exact horizontal extent on the row through its centre.
  Hit exact(ImGuiID id, Hit h, const Draw& draw) {
    const float y = h.center().y;
    auto over = [&](float x) {
      move(ImVec2(x, y));
      frame(draw);
      return hovered() == id;
    };
    while (h.min.x > 0 && over(h.min.x - 1)) h.min.x -= 1;
    while (h.max.x < kWidth && over(h.max.x + 1)) h.max.x += 1;
    return h;
  }

  void move(ImVec2 p) { mouse_ = p; }
  float bottom() const { return bottom_; }  // of the content, after the last frame
  // Hover, press, release at `at`: true when `draw` returned true on any of those frames.
  bool click(ImVec2 at, const Draw& draw) {
    move(at);
    bool changed = frame(draw);
    down_ = true;
    changed |= frame(draw);
    down_ = false;
    changed |= frame(draw);
    return changed;
  }
  // Press at `at`, move by `dx` pixels in steps while held, release.
  bool drag(ImVec2 at, float dx, const Draw& draw) {
    move(at);
    bool changed = frame(draw);
    down_ = true;
    changed |= frame(draw);
    for (int i = 1; i <= 8; ++i) {
      move(ImVec2(at.x + dx * static_cast<float>(i) / 8, at.y));
      changed |= frame(draw);
    }
    down_ = false;
    changed |= frame(draw);
    return changed;
  }

  const std::vector<std::string>& errors() const { return errors_; }

 private:
  static void log_error(void* self, const char* fmt, ...) {
    char buf[512];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, args);
    va_end(args);
    static_cast<ImGuiHarness*>(self)->errors_.emplace_back(buf);
  }

  ImGuiContext* ctx_ = nullptr;
  ImVec2 mouse_{-100, -100};
  bool down_ = false;
  float bottom_ = 0;
  std::vector<std::string> errors_;
};

// The ID of the item `label` under the IDs `path`, pushed in order as the panel pushes them.
// Call it inside a frame, in the window the panel draws into.
inline ImGuiID item_id(std::initializer_list<std::variant<int, const char*>> path, const char* label) {
  for (const auto& p : path) {
    if (std::holds_alternative<int>(p)) ImGui::PushID(std::get<int>(p));
    else ImGui::PushID(std::get<const char*>(p));
  }
  const ImGuiID id = ImGui::GetID(label);
  for (std::size_t i = 0; i < path.size(); ++i) ImGui::PopID();
  return id;
}

}  // namespace ssr::test
