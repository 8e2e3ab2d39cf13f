// The viewer's session: set-up, the state changes every command and panel goes through, and the
// main loop. Each state change validates first and throws InputError, changing nothing.
#include "viewer/viewer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "gl/gl.h"
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "core/cli_common.h"
#include "core/errors.h"
#include "registry/presets.h"
#include "registry/registry.h"
#include "render/image_io.h"
#include "reference/reference.h"
#include "scene/animation.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_io.h"
#include "gl/readback.h"
#include "techniques/assignments.h"

namespace fs = std::filesystem;

namespace ssr {

namespace {

// Where ImGui keeps its window layout between runs: $XDG_CONFIG_HOME/ssrlab or ~/.config/ssrlab.
std::string default_ini_path() {
  fs::path dir;
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) dir = fs::path(x) / "ssrlab";
  else if (const char* h = std::getenv("HOME"); h && *h) dir = fs::path(h) / ".config" / "ssrlab";
  else return "imgui.ini";
  std::error_code ec;
  fs::create_directories(dir, ec);
  return ec ? std::string("imgui.ini") : (dir / "imgui.ini").string();
}

// Scenes the picker offers: the built-ins, then the JSON scenes shipped in assets/scenes.
std::vector<std::string> scene_choices() {
  std::vector<std::string> names;
  for (const BuiltinSceneInfo& s : builtin_scenes()) names.push_back(s.name);
  std::error_code ec;
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(SSRLAB_ASSET_DIR) / "scenes", ec))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  names.insert(names.end(), files.begin(), files.end());
  return names;
}

int parse_view(const std::string& name) {
  return name == "traceable" ? kViewTraceable : static_cast<int>(parse_view_mode(name));
}

}  // namespace

void Viewer::set_status(const std::string& message, bool error) {
  status_ = message;
  status_error_ = error;
  if (error) std::fprintf(stderr, "ssrlab-view: %s\n", message.c_str());
}

void Viewer::ui_command(Verb verb, const std::string& arg) {
  try {
    execute({0, verb, arg.empty() ? std::vector<std::string>{} : std::vector<std::string>{arg}});
  } catch (const std::exception& e) {
    set_status(e.what(), true);
  }
}

void Viewer::load_scene_spec(const std::string& spec, const std::string& camera_name) {
  Scene scene = load_scene(spec);
  path_ = scene.animation.default_path;
  time_ = 0.0f;
  cut_next_ = true;
  const Camera cam = camera_name.empty() ? scene.cameras.front() : scene.camera(camera_name);
  renderer_ = std::make_unique<Renderer>(scene, std::max(image_w_, 1), std::max(image_h_, 1), shaders_);
  scene_spec_ = spec;
  cameras_ = scene.cameras;
  bookmarks_ = 0;
  lights_ = scene.lights;
  environment_ = scene.environment;
  ambient_ = scene.ambient;
  camera_.set(cam);
  for (Side& s : sides_) {
    s.valid = false;
    s.shown_key.clear();
  }
  mask_key_.clear();
  psnr_valid_ = false;
  psnr_history_.clear();
}

void Viewer::set_technique(Side& side, const std::string& name) {
  std::unique_ptr<Technique> next = create_technique(name);
  next->load(renderer_->shaders());
  side.technique = std::move(next);
  side.instrumented = false;
  set_reference_progress(*side.technique, [this](double f) { draw_progress("reference", f); });
  side.valid = false;
  side.computed = false;
  side.shown_key.clear();
  side.ran_key.clear();
  side.request = 0;
  side.history.clear();
}

// A named preset (registry/presets.h): its technique with its assignments, checked first.
void Viewer::use_named_preset(Side& side, const std::string& name) {
  const Preset& p = find_preset(name);
  std::unique_ptr<Technique> probe = create_technique(p.technique);
  apply_assignments(*probe, p.assignments);  // throws before anything changes
  set_technique(side, p.technique);
  apply_assignments(*side.technique, p.assignments);
  set_status("preset " + name + ": " + p.source, false);
}

// Splits assignments between the techniques by their "<technique>." prefix: A, B, or the truth
// (the grid's third side, made for them when neither A nor B is the truth); keys of none go to
// A, whose apply reports them.
void Viewer::apply_sets(const std::vector<std::string>& sets) {
  Technique& a = *sides_[0].technique;
  Technique& b = *sides_[1].technique;
  std::vector<std::string> to_a, to_b, to_truth;
  for (const std::string& s : sets) {
    const std::string prefix = s.substr(0, s.find('.'));
    const bool for_a = prefix == a.name(), for_b = prefix == b.name();
    const bool for_truth = !for_a && !for_b && is_truth(prefix);
    if (for_truth) {
      if (!sides_[2].technique || sides_[2].technique->name() != prefix) {
        if (renderer_) set_technique(sides_[2], prefix);  // with GL: loaded now
        else sides_[2].technique = create_technique(prefix);  // before GL: run() loads it
      }
      to_truth.push_back(s);
    }
    if (for_b) to_b.push_back(s);
    if (for_a || (!for_b && !for_truth)) to_a.push_back(s);
  }
  apply_assignments(a, to_a);
  apply_assignments(b, to_b);
  if (!to_truth.empty()) apply_assignments(*sides_[2].technique, to_truth);
}

void Viewer::set_lighting(const std::vector<Light>& lights, const Environment& env, float ambient) {
  renderer_->set_lighting(lights, env, ambient);  // throws, changing nothing, when invalid
  lights_ = lights;
  environment_ = env;
  ambient_ = ambient;
  ++lighting_revision_;
}

ViewerPreset Viewer::capture_preset() const {
  ViewerPreset p;
  p.scene = scene_spec_;
  p.camera = camera_.camera();
  p.camera_name = camera_.camera().name;
  p.technique_a = sides_[0].technique->name();
  p.technique_b = sides_[1].technique->name();
  p.params_a = capture_params(*sides_[0].technique);
  p.params_b = capture_params(*sides_[1].technique);
  if (sides_[2].technique) p.params_truth = capture_params(*sides_[2].technique);  // the grid's
  p.compare = kCompareModes[compare_].name;
  p.split = std::clamp(split_, 0.0f, 1.0f);  // Ctrl+click on a slider can type beyond its range
  p.diff_scale = std::clamp(diff_scale_, 0.01f, 1.0f);
  p.view = viewer_view_names()[static_cast<std::size_t>(view_)];
  p.exposure = renderer_->settings.exposure;  // kept in the table's range by every path that sets it
  p.reflective_f0 = renderer_->settings.reflective_f0;
  p.lights = lights_;
  p.environment = environment_;
  p.ambient = ambient_;
  return p;
}

// Techniques, parameters and the view are checked before anything changes; a scene or camera
// that does not load stops it part-way (the error names it).
void Viewer::apply_preset(const ViewerPreset& p) {
  std::unique_ptr<Technique> a = create_technique(p.technique_a), b = create_technique(p.technique_b);
  apply_params(*a, p.params_a);
  apply_params(*b, p.params_b);
  if (p.params_truth) apply_params(*create_technique(truth_name()), *p.params_truth);
  const int view = parse_view(p.view);
  if (!p.scene.empty() && p.scene != scene_spec_) load_scene_spec(p.scene, "");
  if (p.camera) {
    camera_.set(*p.camera);
    cut_next_ = true;
  } else if (!p.camera_name.empty()) on_Camera(p.camera_name);
  if (p.lights || p.environment || p.ambient)
    set_lighting(p.lights.value_or(lights_), p.environment.value_or(environment_), p.ambient.value_or(ambient_));
  set_technique(sides_[0], p.technique_a);
  set_technique(sides_[1], p.technique_b);
  apply_params(*sides_[0].technique, p.params_a);
  apply_params(*sides_[1].technique, p.params_b);
  compare_ = parse_compare_mode(p.compare);
  ensure_grid_truth();
  if (p.params_truth) {  // the grid's truth, made now if the preset's compare mode is not the grid
    if (!sides_[2].technique) set_technique(sides_[2], truth_name());
    apply_params(*sides_[2].technique, *p.params_truth);
  } else if (sides_[2].technique) {
    apply_params(*sides_[2].technique, {});  // left out: its defaults, as every parameter left out
  }
  split_ = p.split;
  diff_scale_ = p.diff_scale;
  view_ = view;
  set_frame_setting(renderer_->settings, "exposure", p.exposure);
  set_frame_setting(renderer_->settings, "reflective_f0", p.reflective_f0);
}

void Viewer::save(const std::string& path) {
  RgbaImage8 im{composed_.width(), composed_.height(),
                gl::read_texture<std::uint8_t>(composed_, GL_RGBA, GL_UNSIGNED_BYTE, 4)};
  write_png(path, im);
  set_status("saved " + path, false);
  std::printf("ssrlab-view: %s\n", status_.c_str());
}

void Viewer::reload() {
  try {
    renderer_->reload_shaders();
    for (Side& s : sides_) {
      if (!s.technique) continue;  // the grid's truth before the grid was shown
      s.technique->load(renderer_->shaders());
      s.instrumented = false;
    }
    if (mask_ref_) mask_ref_->load(renderer_->shaders());
    if (noise_truth_) noise_truth_->load(renderer_->shaders());
    noise_ran_key_.clear();  // the second truth runs again with the new shaders
    diff_prog_ = gl::Program::compute(renderer_->shaders(), "render/diff.comp");
    for (Side& s : sides_) {  // nothing shown was drawn by these programs: every side runs again
      s.shown_key.clear();
      s.ran_key.clear();
    }
    psnr_key_.clear();
    set_status("shaders reloaded", false);
  } catch (const std::exception& e) {
    set_status(e.what(), true);  // the last good programs keep running
  }
}

// The next drawn frame's time: one step further when playing; wraps (a cut) or stops at the end.
void Viewer::advance_time() {
  const float duration = renderer_->scene().animation.duration;
  float t = time_;
  if (playing_) t += speed_ / 30.0f;
  if (t > duration) {
    if (loop_ && duration > 0) {
      t = 0.0f;
      cut_next_ = true;
    } else {
      t = duration;
      playing_ = false;
    }
  }
  set_time(t);
}

// Moves to scene time `t`: the path's camera (a cut when the path cuts in between, or when the
// time jumps back) and the object motion.
void Viewer::set_time(float t) {
  const float before = time_;
  time_ = std::max(t, 0.0f);
  const Animation& anim = renderer_->scene().animation;
  if (path_ >= 0 && path_ < static_cast<int>(anim.paths.size())) {
    const CameraPath& p = anim.paths[static_cast<std::size_t>(path_)];
    Camera c = camera_at(p, time_, cameras_.front());
    c.name = camera_.camera().name;
    camera_.set(c);
    if (cut_between(p, std::min(before, time_), std::max(before, time_))) cut_next_ = true;
  }
  if (time_ < before) cut_next_ = true;
}

void Viewer::present() {
  if (window_shot_.empty()) return window_->present();
  RgbaImage8 shot;
  window_->present(&shot);
  write_png(window_shot_, shot);
  std::printf("ssrlab-view: window saved to %s\n", window_shot_.c_str());
  window_shot_.clear();
}

void Viewer::frame(double dt, bool advance) {
  if (!advance)  // drawn again to be saved: the panel shows the timings still in the timers' ring
    for (Side& s : sides_) {
      s.timer->flush();
      take_times(s);
    }
  window_->begin_ui();
  handle_input(dt);
  layout();
  draw_ui(dt);
  ImGui::Render();
  if (fb_w_ <= 0 || fb_h_ <= 0 || image_w_ <= 0 || image_h_ <= 0) {  // minimised: nothing to draw
    present();
    return;
  }
  render(advance);
  // The image at the top left (GL rows go up: it ends at the window's top), the rest cleared
  // for the panels.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_w_, fb_h_);
  glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glNamedFramebufferTexture(blit_fbo_.id(), GL_COLOR_ATTACHMENT0, composed_.id(), 0);
  glBlitNamedFramebuffer(blit_fbo_.id(), 0, 0, 0, image_w_, image_h_, 0, fb_h_ - image_h_, image_w_, fb_h_,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  present();
  if (dt > 0.0) {  // a frame drawn again for a window-shot or the inspector (dt 0) is not timed
    frame_ms_.push_back(static_cast<float>(dt * 1000.0));
    while (frame_ms_.size() > 240) frame_ms_.pop_front();
  }
}

int Viewer::run() {
  const auto [w, h] = parse_size(o_.size);
  // Everything the command line names is checked before a window opens.
  std::vector<ScriptCommand> script;
  const std::string script_name = o_.script;
  if (!o_.script.empty()) script = load_viewer_script(o_.script);
  if (!o_.screenshot.empty() && o_.frames <= 0)
    throw InputError("--screenshot needs --frames N: the frame it captures (F12 saves one in an interactive session).");
  if (!o_.screenshot.empty()) image_format_for(o_.screenshot);
  if (o_.frames > 0) {  // --frames N [--screenshot F]: a two-line script
    script.push_back({0, Verb::Frames, {std::to_string(o_.frames)}});
    if (!o_.screenshot.empty()) script.push_back({0, Verb::Screenshot, {o_.screenshot}});
  }
  scripted_ = !script.empty();
  if (scripted_) truth_policy_ = TruthPolicy::Live;  // a script's frames show the truth of their view
  std::optional<ViewerPreset> preset;
  if (!o_.preset.empty()) preset = load_preset(o_.preset);
  Scene probe = load_scene(o_.scene);  // fails before the window opens
  if (!o_.camera.empty()) probe.camera(o_.camera);
  sides_[0].technique = create_technique(o_.technique);
  sides_[1].technique = create_technique(o_.technique_b);
  apply_sets(o_.sets);  // checks the keys before GL
  const int initial_view = parse_view(o_.view);

  // The image is --size; the window adds the panel (unless hidden) and the status bar.
  panel_shown_ = !o_.no_panel;
  const int chrome_w = panel_shown_ ? static_cast<int>(panel_w_) : 0, chrome_h = static_cast<int>(kStatusH);
  window_ = std::make_unique<Window>(w + chrome_w, h + chrome_h, !scripted_, o_.ini.empty() ? default_ini_path() : o_.ini);
  clock_ = window_->info().software ? gl::PassTimer::Clock::Cpu : gl::PassTimer::Clock::Gpu;
  image_w_ = w;
  image_h_ = h;
  // Live reload reads shaders from the source tree when it is there, else the embedded copy.
  std::string shader_dir = o_.shader_dir;
  if (shader_dir.empty() && fs::is_directory(SSRLAB_SHADER_DIR)) shader_dir = SSRLAB_SHADER_DIR;
  shaders_ = shader_dir.empty() ? gl::ShaderSource() : gl::ShaderSource(fs::path(shader_dir));
  load_scene_spec(o_.scene, o_.camera);
  for (Side& s : sides_) {
    s.timer = std::make_unique<gl::PassTimer>(clock_);
    if (!s.technique) continue;  // the grid's truth: made when the grid is first shown
    s.technique->load(renderer_->shaders());
    set_reference_progress(*s.technique, [this](double f) { draw_progress("reference", f); });
  }
  diff_prog_ = gl::Program::compute(renderer_->shaders(), "render/diff.comp");
  blit_fbo_ = gl::Framebuffer("viewer blit");
  view_ = initial_view;
  compare_ = o_.diff ? CompareDiff : o_.split >= 0 ? CompareSplit : CompareOff;
  if (o_.split >= 0) split_ = static_cast<float>(o_.split);
  if (preset) apply_preset(*preset);
  view_names_ = viewer_view_names();
  scene_names_ = scene_choices();

  std::optional<double> last_time;  // the previous frame's start: the first frame has none
  std::size_t next_command = 0;
  while (!window_->should_close()) {
    // Scripted runs: commands run between frames, until a `frames N` asks for frames.
    while (scripted_ && frames_left_ == 0) {
      if (next_command == script.size()) return 0;
      const ScriptCommand& c = script[next_command++];
      try {
        execute(c);
      } catch (const InputError& e) {
        throw InputError(c.line > 0 ? script_where(script_name, c) + e.what() : e.what());
      } catch (const RuntimeError& e) {  // the machine failed (a full disk): still say where
        throw RuntimeError(c.line > 0 ? script_where(script_name, c) + e.what() : e.what());
      }
    }
    window_->poll();
    const double now = glfwGetTime();
    frame(last_time ? now - *last_time : 0.0);  // dt: the frame before this one, start to start
    last_time = now;
    if (frames_left_ > 0 && --frames_left_ == 0 && compare_ != CompareOff && psnr_valid_)
      std::printf("ssrlab-view: PSNR A vs B %.2f dB\n", psnr_);
  }
  return 0;
}

}  // namespace ssr
