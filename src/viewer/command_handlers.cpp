// One handler per command of commands.h. Scripts, keys and buttons all come through execute(),
// so a button does exactly what its script line does.
#include <algorithm>
#include <cstdio>

#include "gl/gl.h"
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include "core/cli_common.h"
#include "core/errors.h"
#include "core/json_reader.h"
#include "eval/metrics.h"
#include "registry/presets.h"
#include "techniques/assignments.h"
#include "scene/animation.h"
#include "viewer/viewer.h"

namespace ssr {

void Viewer::execute(const ScriptCommand& c) {
  // Built from the same list as the commands: a command without a handler does not link.
  using Handler = void (Viewer::*)(const std::string&);
  static constexpr Handler kHandlers[] = {
#define SSRLAB_X(id, verb, form, args, help) &Viewer::on_##id,
      SSRLAB_VIEWER_COMMANDS(SSRLAB_X)
#undef SSRLAB_X
  };
  static_assert(std::size(kHandlers) == kCommandCount);
  (this->*kHandlers[static_cast<std::size_t>(c.verb)])(c.args.empty() ? std::string() : c.args[0]);
}

void Viewer::on_Scene(const std::string& a) { load_scene_spec(a, ""); }

void Viewer::on_Camera(const std::string& a) {
  auto it = std::find_if(cameras_.begin(), cameras_.end(), [&](const Camera& k) { return k.name == a; });
  if (it == cameras_.end()) throw InputError("the scene has no camera '" + a + "'.");
  camera_.set(*it);
  cut_next_ = true;  // a jump: last frame's history shows another view
}

void Viewer::on_Technique(const std::string& a) { set_technique(sides_[0], a); }
void Viewer::on_TechniqueB(const std::string& a) { set_technique(sides_[1], a); }
void Viewer::on_Set(const std::string& a) { apply_sets({a}); }
// B alone: apply_assignments refuses a prefix that is not B's technique.
void Viewer::on_SetB(const std::string& a) { apply_assignments(*sides_[1].technique, {a}); }

void Viewer::on_Preset(const std::string& a) { use_named_preset(sides_[0], a); }
void Viewer::on_PresetB(const std::string& a) { use_named_preset(sides_[1], a); }

void Viewer::on_Swap(const std::string&) {
  std::swap(sides_[0], sides_[1]);
  psnr_key_.clear();
}

void Viewer::on_Compare(const std::string& a) {
  compare_ = parse_compare_mode(a);
  ensure_grid_truth();
}

void Viewer::on_Split(const std::string& a) {
  split_ = static_cast<float>(std::stod(a));  // checked in [0, 1] (stof threw on 1e-50)
  compare_ = CompareSplit;
}

void Viewer::on_View(const std::string& a) {
  const int view = a == "traceable" ? kViewTraceable : static_cast<int>(parse_view_mode(a));
  // A debug view no shown technique fills would silently stay on the final image.
  if (!view_offered(view)) {
    std::string shown;
    for (int i = 0; i < active_sides(); ++i) shown += (i ? ", " : "") + sides_[i].technique->name();
    throw InputError(view == kViewTraceable ? "the traceable mask is one image: not in the grid."
                                            : "view '" + a + "' is not filled by " + shown + " (see ssrlab views).");
  }
  view_ = view;
}

void Viewer::on_Exposure(const std::string& a) { set_frame_setting(renderer_->settings, "exposure", std::stod(a)); }
void Viewer::on_ReflectiveF0(const std::string& a) {
  set_frame_setting(renderer_->settings, "reflective_f0", std::stod(a));  // the table's range, one sentence
}
void Viewer::on_Ambient(const std::string& a) {
  const double v = std::stod(a);  // checked >= 0 and finite
  if (v > kSceneValueMax)
    throw InputError("ambient '" + a + "' must be in [0, " + JsonReader::fmt(kSceneValueMax) + "], as in a scene file.");
  set_lighting(lights_, environment_, static_cast<float>(v));
}
void Viewer::on_Frames(const std::string& a) { frames_left_ = std::stoi(a); }
void Viewer::on_Screenshot(const std::string& a) {
  // Not an empty PNG reported as saved.
  if (render_w() <= 0 || render_h() <= 0)
    throw InputError("the grid's cells of a " + std::to_string(image_w_) + "x" + std::to_string(image_h_) +
                     " image are empty: nothing to save.");
  if (!composed_) throw InputError("there is no image to save before the first frame (run 'frames 1' first).");
  render(/*advance=*/false);  // a change since the last frame (a `set`) shows: it saved the image before it
  save(a);
}

void Viewer::on_PresetSave(const std::string& a) {
  save_preset(a, capture_preset());
  set_status("preset saved to " + a, false);
  std::printf("ssrlab-view: %s\n", status_.c_str());
}

void Viewer::on_PresetLoad(const std::string& a) {
  apply_preset(load_preset(a));
  set_status("preset loaded from " + a, false);
}

void Viewer::on_Resize(const std::string& a) {
  const auto [w, h] = parse_size(a);
  // Checked before the window changes: a window system clamps sizes (X to 16 bits), and the
  // renderer would then refuse a size nobody asked for.
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
  if (w > max_side || h > max_side)
    throw InputError("size " + a + " is not supported by this GL (each side must be in [1, " + std::to_string(max_side) + "]).");
  window_->set_size(w + (panel_shown_ ? static_cast<int>(panel_w_) : 0), h + static_cast<int>(kStatusH));
}

void Viewer::on_Minimise(const std::string&) { glfwIconifyWindow(window_->handle()); }
void Viewer::on_Restore(const std::string&) { glfwRestoreWindow(window_->handle()); }
void Viewer::on_Panel(const std::string& a) { panel_shown_ = a == "on"; }

void Viewer::on_Section(const std::string& a) {  // "NAME open|closed", checked by the parser
  const auto space = a.find(' ');
  section_request_[parse_panel_section(a.substr(0, space))] = a.substr(space + 1) == "open";
}

void Viewer::on_Reload(const std::string&) { reload(); }

void Viewer::on_Path(const std::string& a) {
  const int before = path_;
  if (a == "free") path_ = -1;
  else {
    const Animation& anim = renderer_->scene().animation;
    find_path(renderer_->scene(), a);  // throws InputError naming the paths
    for (std::size_t i = 0; i < anim.paths.size(); ++i)
      if (anim.paths[i].name == a) path_ = static_cast<int>(i);
  }
  if (path_ >= 0 && path_ != before) cut_next_ = true;  // the camera jumps onto the new path
  set_time(time_);
}

void Viewer::on_Time(const std::string& a) {
  const double t = std::stod(a);  // checked >= 0 and finite
  const float end = renderer_->scene().animation.duration;
  // As the time slider: within the scene's animation (a later time wrapped to 0 on the next frame).
  if (t > end) {
    char bound[32];
    std::snprintf(bound, sizeof bound, "%g", end);
    throw InputError("time '" + a + "' is past the scene's end (" + bound + " s).");
  }
  set_time(static_cast<float>(t));
}
void Viewer::on_Play(const std::string&) { playing_ = true; }
void Viewer::on_Pause(const std::string&) { playing_ = false; }

void Viewer::on_Truth(const std::string& a) {
  if (a == "now") {
    bool any = false;
    for (int i = 0; i < active_sides(); ++i) {  // A, B, and the grid's truth when shown
      if (!on_demand(i)) continue;
      any = true;
      if (!side_current(i)) sides_[i].request = 2;
    }
    if (!any) set_status("truth now: no side shown is the reference (make it A or B, or show the grid)", false);
  } else {
    truth_policy_ = a == "live" ? TruthPolicy::Live : a == "rest" ? TruthPolicy::Rest : TruthPolicy::Manual;
  }
}

void Viewer::on_TruthNoise(const std::string& a) { truth_noise_ = a == "on"; }

// Draws the window again (the same frame: time and history stay; a side whose settings changed
// since it was drawn runs) and saves it as presented.
void Viewer::on_WindowShot(const std::string& a) {
  window_shot_ = a;
  frame(0.0, /*advance=*/false);
}

void Viewer::on_Inspect(const std::string& a) {
  if (!inspected_) {  // the debug image it reads is written from the next frame on: one more frame
    inspected_ = true;
    frame(0.0);
  }
  const auto space = a.find(' ');
  const glm::ivec2 p(std::stoi(a.substr(0, space)), std::stoi(a.substr(space + 1)));
  const PixelValues j = inspect(p.x, p.y);  // throws outside the image
  pinned_ = p;  // the panel and the ring show it too, as after pressing I there
  std::printf("ssrlab-view: inspect %s\n", j.dump().c_str());
  std::fflush(stdout);
}

void Viewer::on_Magnifier(const std::string& a) { magnifier_ = a == "off" ? 0 : std::stoi(a); }

// What the status bar says, for scripts and tests: {"message", "error", "device", "clock",
// "frame_ms" (the last timed frame; null before one), "image": [w, h], "truth": "none" | "current" | "stale" | "not computed" | "computing", "psnr",
// "psnr_truth" (the grid's A against its truth), "truth_noise" (its noise floor, dB, "none" or
// null: Viewer::truth_noise_shown), "sections_open" (the panel's, as last drawn),
// "frame" (the index of the frame shown: history counts it), "history" (true: carried over from
// the frame before; false: restarted by a cut, a jump or a change), "history_break" (why not, or
// null), "time" (scene seconds)}.
void Viewer::on_Status(const std::string&) {
  nlohmann::json j;
  j["message"] = status_;
  j["error"] = status_error_;
  j["device"] = window_->info().renderer;
  j["clock"] = clock_ == gl::PassTimer::Clock::Gpu ? "gpu" : "cpu";
  const std::optional<double> ms = shown_frame_ms(0.0);
  j["frame_ms"] = ms ? nlohmann::json(*ms) : nlohmann::json();  // null before a frame was timed
  j["image"] = {image_w_, image_h_};
  j["truth"] = truth_state();
  j["psnr"] = figure_shown() ? nlohmann::json(psnr_) : nlohmann::json(nullptr);
  j["psnr_truth"] = truth_figure_shown() ? nlohmann::json(psnr_truth_) : nlohmann::json(nullptr);
  // The truth's noise floor (truth-noise on, a current truth shown); null otherwise. A truth that
  // samples no pixel (exact rays only) is the same in both runs: its floor is infinite, "none".
  const std::optional<double> floor = truth_noise_shown();
  j["truth_noise"] = !floor ? nlohmann::json(nullptr) : *floor >= kPsnrCap ? nlohmann::json("none") : nlohmann::json(*floor);
  nlohmann::json open = nlohmann::json::array();  // as last drawn (none with the panel hidden)
  for (const SectionInfo& s : kPanelSections)
    if (panel_shown_ && section_open_[s.section]) open.push_back(s.name);
  j["sections_open"] = open;
  j["frame"] = frame_index_;
  j["history"] = renderer_->history_valid();
  j["history_break"] = renderer_->history_valid() ? nlohmann::json() : nlohmann::json(renderer_->history_break());
  j["time"] = time_;
  std::printf("ssrlab-view: status %s\n", j.dump().c_str());
  std::fflush(stdout);
}

}  // namespace ssr
