// ssrlab-view: the interactive viewer (GLFW window + Dear ImGui).
//
//   mouse: left drag orbits around the target, right drag pans, wheel zooms
//   WASD/QE: fly (Shift x4, Ctrl x0.25)   F12: screenshot   F5: reload shaders   F2: hide UI
//   Compare mode: technique A (left) and B (right) on the same frame inputs, with a draggable
//   divider, or a difference heat map of A vs B with the PSNR. The reference and the traceable
//   mask (CPU ray tracing) run on demand, with a progress bar.
//   --frames N --screenshot F.png, or --script FILE (viewer_script.h): scripted runs for tests.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <deque>
#include <filesystem>
#include <map>

#include <CLI/CLI.hpp>

#include "gl/gl.h"
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/panels.h"
#include "app/viewer_preset.h"
#include "app/viewer_script.h"
#include "core/cli_common.h"
#include "gl/readback.h"
#include "core/errors.h"
#include "eval/grid.h"
#include "eval/metrics.h"
#include "eval/runner.h"
#include "gl/context.h"
#include "reference/reference.h"
#include "shared/bindings.h"
#include "render/image_io.h"
#include "render/renderer.h"
#include "scene/animation.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_io.h"
#include "techniques/technique.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

namespace fs = std::filesystem;
using namespace ssr;

namespace {

struct Options {
  std::string scene = "gallery";
  std::string technique = "linear";
  std::vector<std::string> sets;
  std::string size = "1280x720";
  std::string camera;
  std::string view = "final";
  int frames = 0;          // 0 = interactive
  std::string screenshot;  // with --frames: where the last frame goes
  std::string shader_dir;
  std::string technique_b = "none";
  double split = -1;  // < 0: no split at start
  bool diff = false;
  std::string preset;  // a preset to start from
  std::string script;  // scripted input
  std::string ini;     // ImGui layout file; default: the user's config directory
};

enum CompareMode : int { CompareOff = 0, CompareSplit = 1, CompareDiff = 2 };
constexpr int kViewTraceable = VIEW_COUNT;  // the viewer's own view: the reference's classes
const char* const kCompareNames[] = {"off", "split", "diff"};

// Techniques too slow to run every frame (CPU ray tracing): they run when asked.
bool on_demand(const Technique& t) { return t.name() == "reference"; }

// One side of the comparison: its technique, a copy of its last display image, its timings.
struct Side {
  std::unique_ptr<Technique> technique;
  gl::Texture2D copy;       // RGBA8 display image of the last frame it ran
  gl::Texture2D color;      // RGBA16F composited colour of that frame (the A-vs-B figure reads it)
  bool valid = false;       // `copy` holds an image of the current size
  std::string shown_key;    // the frame key of what `copy` shows
  int request = 0;          // on-demand: 2 = asked (UI shows "computing..."), 1 = run this frame
  std::unique_ptr<gl::PassTimer> timer;
  gl::FrameTimes last_times;
  std::deque<float> history;  // technique ms of the last frames
  bool instrumented = false;  // loaded with SSR_TELEMETRY (a telemetry view is shown)
};

// What a technique's image depends on besides the frame inputs: its name and parameter values.
std::string technique_key(Technique& t) {
  std::string k = t.name();
  ParamSet p = t.params();
  for (std::size_t i = 0; i < p.size(); ++i) k += "," + p.to_string(i);
  return k;
}

bool is_frame_pass(const std::string& name) {
  return name == "gbuffer" || name == "lighting" || name == "composite" || name == "display";
}

RgbaImage8 read_rgba8(const gl::Texture2D& tex) {
  return {tex.width(), tex.height(), gl::read_texture<std::uint8_t>(tex, GL_RGBA, GL_UNSIGNED_BYTE, 4)};
}

// Orbit camera state kept as spherical coordinates around the target.
struct OrbitCamera {
  Camera cam;
  float yaw = 0, pitch = 0, distance = 1;
  void from_camera(const Camera& c) {
    cam = c;
    const glm::vec3 d = c.position - c.target;
    distance = std::max(glm::length(d), 1e-3f);
    yaw = std::atan2(d.x, d.z);
    pitch = std::asin(std::clamp(d.y / distance, -1.0f, 1.0f));
  }
  void update_position() {
    pitch = std::clamp(pitch, -1.55f, 1.55f);
    cam.position = cam.target + distance * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                                     std::cos(pitch) * std::cos(yaw));
    cam.up = {0, 1, 0};
  }
};

std::string timestamped_name() {
  char buf[64];
  const std::time_t t = std::time(nullptr);
  std::strftime(buf, sizeof buf, "ssrlab-%Y%m%d-%H%M%S.png", std::localtime(&t));
  return buf;
}

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

bool combo(const char* label, int* current, const std::vector<std::string>& items) {
  return ImGui::Combo(label, current, [](void* data, int i, const char** out) {
    *out = static_cast<const std::vector<std::string>*>(data)->at(static_cast<std::size_t>(i)).c_str();
    return true;
  }, const_cast<std::vector<std::string>*>(&items), static_cast<int>(items.size()));
}

class Viewer {
 public:
  explicit Viewer(const Options& o) : o_(o) {}
  int run();

 private:
  // --- set-up and state changes (all validate first and throw InputError) ---
  void open_window(int w, int h);
  void load_scene_spec(const std::string& spec, const std::string& camera_name);
  void set_technique(Side& side, const std::string& name);
  void apply_sets(const std::vector<std::string>& sets);
  void set_lighting(const std::vector<Light>& lights, const Environment& env, float ambient);
  ViewerPreset capture_preset() const;
  void apply_preset(const ViewerPreset& p);
  void run_command(const ScriptCommand& c);
  // --- one iteration of the main loop ---
  void frame(double dt);
  void handle_input(float dt);
  void draw_ui(double dt);
  void technique_panel(Side& side, const char* label);
  void timing_panel(double dt);
  void render();
  void update_traceable_mask();
  void draw_progress(const std::string& what, double fraction);
  void save(const std::string& path);
  void reload();
  std::string frame_key() const;

  Options o_;
  bool scripted_ = false;  // --frames or --script: on-demand work runs without being asked
  GLFWwindow* window_ = nullptr;
  gl::ContextInfo info_;
  gl::ShaderSource shaders_;
  gl::PassTimer::Clock clock_ = gl::PassTimer::Clock::Cpu;

  std::string scene_spec_;
  std::vector<Camera> cameras_;  // the scene's named cameras, then the user's bookmarks
  std::vector<Light> lights_;    // edited copies of the scene's lighting
  Environment environment_;
  float ambient_ = 0.3f;
  int lighting_revision_ = 0;
  std::unique_ptr<Renderer> renderer_;
  Side sides_[2];
  OrbitCamera orbit_;
  gl::Program diff_prog_;
  gl::Texture2D composed_;  // what the window and screenshots show (no UI)
  gl::Framebuffer blit_fbo_;  // created once the context exists

  // Traceable mask: a reference of its own, run on demand, shown as its class map.
  std::unique_ptr<Technique> mask_ref_;
  gl::Texture2D mask_tex_;
  std::string mask_key_;
  bool mask_request_ = false;

  int fb_w_ = 0, fb_h_ = 0;
  int frame_index_ = 0;  // the frame being drawn, in the sequence of drawn frames
  FrameRequest current_frame() const { return FrameRequest(orbit_.cam, FrameTime{frame_index_, time_, cut_}); }

  // Playback: scene time (object motion) and, with a path chosen, the camera along it. Time
  // advances by speed / 30 s a drawn frame (not by the wall clock: reproducible screenshots).
  int path_ = -1;  // index into the scene's paths; -1: the free (orbit) camera
  float time_ = 0.0f, speed_ = 1.0f;
  bool playing_ = false, loop_ = true, cut_ = false, cut_next_ = false;
  void advance_time();
  void set_time(float t);
  void time_panel();
  bool view_offered(int view) const;
  int view_ = VIEW_FINAL;
  int compare_ = CompareOff;
  float split_ = 0.5f, diff_scale_ = 0.25f;
  bool dragging_divider_ = false, show_ui_ = true;
  std::string status_;
  bool status_error_ = false;
  std::string psnr_key_;
  double psnr_ = 0;
  bool psnr_valid_ = false;
  // Live truth: an on-demand side (the reference) runs on every frame it is stale, and each new
  // A-vs-B figure is kept for the per-frame plot.
  bool live_truth_ = false;
  std::deque<float> psnr_history_;
  glm::dvec2 last_mouse_{0};
  std::map<int, bool> key_was_down_;
  std::deque<float> frame_ms_;
  std::vector<std::string> view_names_, scene_names_;
  char preset_path_[512] = "ssrlab-preset.json";
  char scene_path_[512] = "";
  int bookmarks_ = 0;
};

void Viewer::open_window(int w, int h) {
  if (!glfwInit()) throw RuntimeError("GLFW could not initialise (no display?).");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(w, h, "ssrlab", nullptr, nullptr);
  if (!window_) throw RuntimeError("no OpenGL 4.5 core window could be created.");
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(scripted_ ? 0 : 1);
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)))
    throw RuntimeError("OpenGL functions could not be loaded.");
  info_ = gl::query_current_context("glfw");
  std::fprintf(stderr, "ssrlab-view: GL via glfw: %s | %s\n", info_.renderer.c_str(), info_.version.c_str());
  // The window system may give less than asked (an X screen holds at most 32767 pixels a side);
  // a smaller frame than the command line named would be a silent lie in every figure.
  int got_w = 0, got_h = 0;
  glfwGetFramebufferSize(window_, &got_w, &got_h);
  GLint max_dims[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_dims);
  if (w > max_dims[0] || h > max_dims[1])
    throw InputError("size " + std::to_string(w) + "x" + std::to_string(h) + " is larger than this GL's viewport limit " +
                     std::to_string(max_dims[0]) + "x" + std::to_string(max_dims[1]) + ".");
  if (got_w != w || got_h != h)
    throw InputError("the window system opened a " + std::to_string(got_w) + "x" + std::to_string(got_h) +
                     " window, not the " + std::to_string(w) + "x" + std::to_string(h) + " asked for.");
  clock_ = info_.software ? gl::PassTimer::Clock::Cpu : gl::PassTimer::Clock::Gpu;
}

void Viewer::load_scene_spec(const std::string& spec, const std::string& camera_name) {
  Scene scene = load_scene(spec);
  path_ = scene.animation.default_path;
  time_ = 0.0f;
  cut_next_ = true;
  const Camera cam = camera_name.empty() ? scene.cameras.front() : scene.camera(camera_name);
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  renderer_ = std::make_unique<Renderer>(scene, std::max(w, 1), std::max(h, 1), shaders_);
  scene_spec_ = spec;
  cameras_ = scene.cameras;
  bookmarks_ = 0;
  lights_ = scene.lights;
  environment_ = scene.environment;
  ambient_ = scene.ambient;
  orbit_.from_camera(cam);
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
  side.shown_key.clear();
  side.request = 0;
  side.history.clear();
}

// Splits assignments between the two techniques by their "<technique>." prefix; keys of
// neither go to A, whose apply reports them.
void Viewer::apply_sets(const std::vector<std::string>& sets) {
  Technique& a = *sides_[0].technique;
  Technique& b = *sides_[1].technique;
  std::vector<std::string> to_a, to_b;
  for (const std::string& s : sets) {
    const std::string prefix = s.substr(0, s.find('.'));
    const bool for_a = prefix == a.name(), for_b = prefix == b.name();
    if (for_b) to_b.push_back(s);
    if (for_a || !for_b) to_a.push_back(s);
  }
  apply_assignments(a, to_a);
  apply_assignments(b, to_b);
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
  p.camera = orbit_.cam;
  p.camera_name = orbit_.cam.name;
  p.technique_a = sides_[0].technique->name();
  p.technique_b = sides_[1].technique->name();
  p.params_a = capture_params(*sides_[0].technique);
  p.params_b = capture_params(*sides_[1].technique);
  p.compare = kCompareNames[compare_];
  p.split = std::clamp(split_, 0.0f, 1.0f);  // Ctrl+click on a slider can type beyond its range
  p.diff_scale = std::clamp(diff_scale_, 0.01f, 1.0f);
  p.view = viewer_view_names()[static_cast<std::size_t>(view_)];
  p.exposure = std::clamp(renderer_->settings.exposure, -20.0f, 20.0f);
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
  const int view = p.view == "traceable" ? kViewTraceable : static_cast<int>(parse_view_mode(p.view));
  if (!p.scene.empty() && p.scene != scene_spec_) load_scene_spec(p.scene, "");
  if (p.camera) orbit_.from_camera(*p.camera);
  else if (!p.camera_name.empty()) run_command({0, "camera", {p.camera_name}});
  if (p.lights || p.environment || p.ambient)
    set_lighting(p.lights.value_or(lights_), p.environment.value_or(environment_), p.ambient.value_or(ambient_));
  set_technique(sides_[0], p.technique_a);
  set_technique(sides_[1], p.technique_b);
  apply_params(*sides_[0].technique, p.params_a);
  apply_params(*sides_[1].technique, p.params_b);
  compare_ = p.compare == "split" ? CompareSplit : p.compare == "diff" ? CompareDiff : CompareOff;
  split_ = p.split;
  diff_scale_ = p.diff_scale;
  view_ = view;
  renderer_->settings.exposure = p.exposure;
}

std::string Viewer::frame_key() const {
  const Camera& c = orbit_.cam;
  char buf[320];
  std::snprintf(buf, sizeof buf, "%llu|%d|%g %g %g|%g %g %g|%g|%d|%g|%dx%d|%g",
                static_cast<unsigned long long>(renderer_->scene_id()), lighting_revision_, c.position.x,
                c.position.y, c.position.z, c.target.x, c.target.y, c.target.z, c.fov_y_deg, view_,
                renderer_->settings.exposure, fb_w_, fb_h_, time_);
  return buf;
}

void Viewer::save(const std::string& path) {
  write_png(path, composed_ ? read_rgba8(composed_) : renderer_->read_display());
  status_ = "saved " + path;
  status_error_ = false;
  std::printf("ssrlab-view: %s\n", status_.c_str());
}

void Viewer::reload() {
  try {
    renderer_->reload_shaders();
    for (Side& s : sides_) {
      s.technique->load(renderer_->shaders());
      s.instrumented = false;
    }
    if (mask_ref_) mask_ref_->load(renderer_->shaders());
    diff_prog_ = gl::Program::compute(renderer_->shaders(), "render/diff.comp");
    for (Side& s : sides_) s.shown_key.clear();
    status_ = "shaders reloaded";
    status_error_ = false;
  } catch (const std::exception& e) {
    status_ = e.what();  // the last good programs keep running
    status_error_ = true;
    std::fprintf(stderr, "ssrlab-view: reload failed: %s\n", e.what());
  }
}

// A frame with only a progress bar over the last image: long CPU work (the reference) calls it.
void Viewer::draw_progress(const std::string& what, double fraction) {
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(420.0f, io.DisplaySize.x), 0));
  ImGui::Begin("computing", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
  ImGui::Text("%s: CPU ray tracing (Embree)", what.c_str());
  ImGui::ProgressBar(static_cast<float>(std::clamp(fraction, 0.0, 1.0)));
  ImGui::End();
  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_w_, fb_h_);
  if (composed_ && composed_.width() == fb_w_ && composed_.height() == fb_h_) {
    glNamedFramebufferTexture(blit_fbo_.id(), GL_COLOR_ATTACHMENT0, composed_.id(), 0);
    glBlitNamedFramebuffer(blit_fbo_.id(), 0, 0, 0, fb_w_, fb_h_, 0, 0, fb_w_, fb_h_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(window_);
}

void Viewer::run_command(const ScriptCommand& c) {
  const std::string& a = c.args.empty() ? std::string() : c.args[0];
  if (c.verb == "scene") load_scene_spec(a, "");
  else if (c.verb == "camera") {
    auto it = std::find_if(cameras_.begin(), cameras_.end(), [&](const Camera& k) { return k.name == a; });
    if (it == cameras_.end()) throw InputError("the scene has no camera '" + a + "'.");
    orbit_.from_camera(*it);
  } else if (c.verb == "technique") set_technique(sides_[0], a);
  else if (c.verb == "technique-b") set_technique(sides_[1], a);
  else if (c.verb == "set") apply_sets({a});
  else if (c.verb == "compare") compare_ = a == "split" ? CompareSplit : a == "diff" ? CompareDiff : CompareOff;
  else if (c.verb == "split") {
    split_ = std::stof(a);
    compare_ = CompareSplit;
  } else if (c.verb == "view") view_ = a == "traceable" ? kViewTraceable : static_cast<int>(parse_view_mode(a));
  else if (c.verb == "exposure") renderer_->settings.exposure = std::stof(a);
  else if (c.verb == "ambient") set_lighting(lights_, environment_, std::stof(a));
  else if (c.verb == "screenshot") save(a);
  else if (c.verb == "preset-save") {
    save_preset(a, capture_preset());
    std::printf("ssrlab-view: preset saved to %s\n", a.c_str());
  } else if (c.verb == "preset-load") apply_preset(load_preset(a));
  else if (c.verb == "resize") {
    const auto [w, h] = parse_size(a);
    glfwSetWindowSize(window_, w, h);
  } else if (c.verb == "minimise") glfwIconifyWindow(window_);
  else if (c.verb == "restore") glfwRestoreWindow(window_);
  else if (c.verb == "reload") reload();
  else if (c.verb == "path") {
    if (a == "free") path_ = -1;
    else {
      const Animation& anim = renderer_->scene().animation;
      find_path(renderer_->scene(), a);  // throws InputError naming the paths
      for (std::size_t i = 0; i < anim.paths.size(); ++i)
        if (anim.paths[i].name == a) path_ = static_cast<int>(i);
    }
    set_time(time_);
  } else if (c.verb == "time") set_time(std::stof(a));
  else if (c.verb == "play") playing_ = true;
  else if (c.verb == "pause") playing_ = false;
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
    const std::string name = orbit_.cam.name;
    Camera c = camera_at(p, time_, cameras_.front());
    c.name = name;
    orbit_.from_camera(c);
    if (cut_between(p, std::min(before, time_), std::max(before, time_))) cut_next_ = true;
  }
  if (time_ < before) cut_next_ = true;
}

void Viewer::time_panel() {
  const Animation& anim = renderer_->scene().animation;
  std::vector<std::string> names = {"free camera"};
  for (const CameraPath& p : anim.paths) names.push_back(p.name);
  int current = path_ + 1;
  if (combo("path", &current, names)) {
    path_ = current - 1;
    set_time(time_);
  }
  if (path_ >= 0 && ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", anim.paths[static_cast<std::size_t>(path_)].description.c_str());
  if (ImGui::Button(playing_ ? "pause" : "play")) playing_ = !playing_;
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
  ImGui::TextDisabled("frame %d, %s", frame_index_, renderer_->history_valid() ? "history carried" : "history restarted");
}

// Debug views are offered for the techniques that produce them (their declarations).
bool Viewer::view_offered(int view) const {
  if (view == kViewTraceable || view >= static_cast<int>(view_table().size())) return true;
  const ViewInfo& v = view_table()[static_cast<std::size_t>(view)];
  if (!v.debug) return true;
  for (int i = 0; i < (compare_ == CompareOff ? 1 : 2); ++i) {
    const std::vector<ViewMode> d = sides_[i].technique->declare().debug_views;
    if (std::find(d.begin(), d.end(), v.mode) != d.end()) return true;
  }
  return false;
}

void Viewer::handle_input(float dt) {
  const ImGuiIO& io = ImGui::GetIO();
  // ImGui 1.86 has no named keys: GLFW key state, edges detected here.
  auto down = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS; };
  auto pressed = [&](int key) {
    const bool d = down(key), was = key_was_down_[key];
    key_was_down_[key] = d;
    return d && !was;
  };
  if (!io.WantCaptureKeyboard) {
    if (pressed(GLFW_KEY_F2)) show_ui_ = !show_ui_;
    if (pressed(GLFW_KEY_F12)) save(timestamped_name());
    if (pressed(GLFW_KEY_F5)) reload();
    const float speed = 3.0f * dt * (io.KeyShift ? 4.0f : 1.0f) * (io.KeyCtrl ? 0.25f : 1.0f);
    const glm::vec3 fwd = glm::normalize(orbit_.cam.target - orbit_.cam.position);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
    glm::vec3 move{0};
    if (down(GLFW_KEY_W)) move += fwd;
    if (down(GLFW_KEY_S)) move -= fwd;
    if (down(GLFW_KEY_D)) move += right;
    if (down(GLFW_KEY_A)) move -= right;
    if (down(GLFW_KEY_E)) move.y += 1;
    if (down(GLFW_KEY_Q)) move.y -= 1;
    orbit_.cam.position += move * speed;
    orbit_.cam.target += move * speed;
  }
  glm::dvec2 mouse;
  glfwGetCursorPos(window_, &mouse.x, &mouse.y);
  const glm::vec2 delta = glm::vec2(mouse - last_mouse_);
  last_mouse_ = mouse;
  // The split divider: drag it with the left button (window coordinates, as ImGui's).
  const float divider_x = split_ * io.DisplaySize.x;
  const bool near_divider = compare_ == CompareSplit && std::abs(static_cast<float>(mouse.x) - divider_x) < 6.0f;
  if (!io.WantCaptureMouse && near_divider && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) dragging_divider_ = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging_divider_ = false;
  if (dragging_divider_ && io.DisplaySize.x > 0)
    split_ = std::clamp(static_cast<float>(mouse.x) / io.DisplaySize.x, 0.0f, 1.0f);
  if ((near_divider && !io.WantCaptureMouse) || dragging_divider_) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  if (io.WantCaptureMouse || dragging_divider_) return;
  if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    orbit_.from_camera(orbit_.cam);
    orbit_.yaw -= delta.x * 0.005f;
    orbit_.pitch += delta.y * 0.005f;
    orbit_.update_position();
  }
  if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
    const glm::vec3 fwd = glm::normalize(orbit_.cam.target - orbit_.cam.position);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, fwd);
    const float k = glm::length(orbit_.cam.target - orbit_.cam.position) * 0.002f;
    const glm::vec3 pan = (-right * delta.x + up * delta.y) * k;
    orbit_.cam.position += pan;
    orbit_.cam.target += pan;
  }
  if (io.MouseWheel != 0) {
    orbit_.from_camera(orbit_.cam);
    orbit_.distance = std::clamp(orbit_.distance * std::pow(0.9f, io.MouseWheel), 0.05f, 1000.0f);
    orbit_.update_position();
  }
}

// Technique picker + parameter panel of one side.
void Viewer::technique_panel(Side& side, const char* label) {
  ImGui::PushID(label);
  if (ImGui::BeginCombo(label, side.technique->name().c_str())) {
    for (const TechniqueInfo& t : technique_registry()) {
      if (ImGui::Selectable(t.name.c_str(), t.name == side.technique->name())) {
        try {
          set_technique(side, t.name);
        } catch (const std::exception& e) {
          status_ = e.what();
          status_error_ = true;
        }
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t.description.c_str());
    }
    ImGui::EndCombo();
  }
  if (on_demand(*side.technique)) {
    ImGui::BeginDisabled(side.request > 0);
    if (ImGui::Button("compute")) side.request = 2;
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (side.request > 0) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "computing...");
    else if (!side.valid) ImGui::TextDisabled("not computed yet (CPU ray tracing: on demand)");
    else if (side.shown_key != frame_key() + "|" + technique_key(*side.technique))
      ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "stale: the view changed");
    else ImGui::TextDisabled("up to date");
    ImGui::Checkbox("every frame (live truth)", &live_truth_);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("run it on every changed frame (playback: the A-vs-B figure per frame is plotted); slow");
  }
  if (ImGui::TreeNodeEx("parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
    ParamSet params = side.technique->params();
    draw_param_panel(params);
    ImGui::TreePop();
  }
  ImGui::PopID();
}

// Per-pass times of the last frame of each side (one column each), the technique's rolling
// plot and the frame time. Marked `cpu` where the GL cannot time on the GPU (llvmpipe).
void Viewer::timing_panel(double dt) {
  const char* clock_name = sides_[0].timer->clock_name();
  const int n = compare_ != CompareOff ? 2 : 1;
  std::vector<std::string> passes;
  for (int i = 0; i < n; ++i)
    for (const auto& p : sides_[i].last_times)
      if (std::find(passes.begin(), passes.end(), p.name) == passes.end()) passes.push_back(p.name);
  if (ImGui::BeginTable("passes", n + 1, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn(clock_name[0] == 'g' ? "pass (gpu ms)" : "pass (cpu ms)");
    for (int i = 0; i < n; ++i) ImGui::TableSetupColumn(i == 0 ? "A" : "B");
    ImGui::TableHeadersRow();
    std::vector<double> total(static_cast<std::size_t>(n), 0.0);
    for (const std::string& pass : passes) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(pass.c_str());
      for (int i = 0; i < n; ++i) {
        ImGui::TableNextColumn();
        for (const auto& p : sides_[i].last_times)
          if (p.name == pass) {
            ImGui::Text("%7.3f", p.ms);
            total[static_cast<std::size_t>(i)] += p.ms;
          }
      }
    }
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("total");
    for (int i = 0; i < n; ++i) {
      ImGui::TableNextColumn();
      ImGui::Text("%7.3f", total[static_cast<std::size_t>(i)]);
    }
    ImGui::EndTable();
  }
  for (int i = 0; i < n; ++i) {
    const Side& s = sides_[i];
    if (s.history.empty()) continue;
    const std::vector<float> h(s.history.begin(), s.history.end());
    const float hi = *std::max_element(h.begin(), h.end());
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%s %s: %.3f ms (%s)", i == 0 ? "A" : "B",
                  s.technique->name().c_str(), h.back(), clock_name);
    ImGui::PushID(i);
    ImGui::PlotLines("##technique", h.data(), static_cast<int>(h.size()), 0, overlay, 0.0f,
                     std::max(hi * 1.2f, 1e-3f), ImVec2(-1, 45));
    ImGui::PopID();
  }
  if (!frame_ms_.empty()) {
    const std::vector<float> f(frame_ms_.begin(), frame_ms_.end());
    const float hi = *std::max_element(f.begin(), f.end());
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "frame %.1f ms (wall clock)", dt * 1000.0);
    ImGui::PlotLines("##frame", f.data(), static_cast<int>(f.size()), 0, overlay, 0.0f, std::max(hi * 1.2f, 1.0f),
                     ImVec2(-1, 45));
  }
  if (clock_ == gl::PassTimer::Clock::Cpu)
    ImGui::TextDisabled("cpu: CPU clock around glFinish (llvmpipe), not GPU time");
}

void Viewer::draw_ui(double dt) {
  const ImGuiIO& io = ImGui::GetIO();
  if (compare_ == CompareSplit) {  // the divider and labels are UI: never in screenshots
    ImDrawList* bg = ImGui::GetBackgroundDrawList();
    const float x = split_ * io.DisplaySize.x;
    bg->AddLine(ImVec2(x, 0), ImVec2(x, io.DisplaySize.y),
                dragging_divider_ ? IM_COL32(255, 220, 80, 255) : IM_COL32(255, 255, 255, 200), 2.0f);
    if (show_ui_) {
      const std::string left = "A: " + sides_[0].technique->name(), right = "B: " + sides_[1].technique->name();
      bg->AddText(ImVec2(x - 8 - ImGui::CalcTextSize(left.c_str()).x, io.DisplaySize.y - 22),
                  IM_COL32(255, 255, 255, 230), left.c_str());
      bg->AddText(ImVec2(x + 8, io.DisplaySize.y - 22), IM_COL32(255, 255, 255, 230), right.c_str());
    }
  }
  if (!show_ui_) return;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(400, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("ssrlab");
  ImGui::TextDisabled("%s", info_.renderer.c_str());

  if (ImGui::CollapsingHeader("scene and camera", ImGuiTreeNodeFlags_DefaultOpen)) {
    int current = static_cast<int>(std::find(scene_names_.begin(), scene_names_.end(), scene_spec_) - scene_names_.begin());
    if (current >= static_cast<int>(scene_names_.size())) current = -1;
    if (combo("scene", &current, scene_names_) && current >= 0) {
      try {
        load_scene_spec(scene_names_[static_cast<std::size_t>(current)], "");
      } catch (const std::exception& e) {
        status_ = e.what();
        status_error_ = true;
      }
    }
    ImGui::InputTextWithHint("##scenepath", ".json or .obj path", scene_path_, sizeof scene_path_);
    ImGui::SameLine();
    if (ImGui::Button("open") && scene_path_[0]) {
      try {
        load_scene_spec(scene_path_, "");
      } catch (const std::exception& e) {
        status_ = e.what();
        status_error_ = true;
      }
    }
    if (ImGui::BeginCombo("camera", orbit_.cam.name.c_str())) {
      for (const Camera& c : cameras_)
        if (ImGui::Selectable(c.name.c_str(), c.name == orbit_.cam.name)) orbit_.from_camera(c);
      ImGui::EndCombo();
    }
    if (ImGui::Button("bookmark this view")) {
      Camera c = orbit_.cam;
      c.name = "bookmark " + std::to_string(++bookmarks_);
      cameras_.push_back(c);
      orbit_.cam.name = c.name;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("adds the current view to the camera list (saved with presets)");
    draw_camera_panel(orbit_.cam);
  }
  if (ImGui::CollapsingHeader("lights and environment")) {
    std::vector<Light> lights = lights_;
    Environment env = environment_;
    float ambient = ambient_;
    const bool changed = draw_lights_panel(lights) | draw_environment_panel(env, ambient);
    if (changed) {
      try {
        set_lighting(lights, env, ambient);
      } catch (const std::exception& e) {
        status_ = e.what();
        status_error_ = true;
      }
    }
  }
  if (ImGui::CollapsingHeader("time and camera paths")) time_panel();
  if (ImGui::CollapsingHeader("view and compare", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (ImGui::BeginCombo("view", view_names_[static_cast<std::size_t>(view_)].c_str())) {
      for (int v = 0; v < static_cast<int>(view_names_.size()); ++v)
        if (view_offered(v) && ImGui::Selectable(view_names_[static_cast<std::size_t>(v)].c_str(), v == view_)) view_ = v;
      ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("G-buffer channels, lit colour, reflection, confidence, tracer heat maps, PPR buffers,\n"
                        "and 'traceable': the reference's classes (green traceable, red missing, blue sky)");
    if (view_ == kViewTraceable) {
      if (mask_request_) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "computing...");
      else if (mask_key_ != frame_key()) {
        if (ImGui::Button("compute traceable mask")) mask_request_ = true;
        ImGui::SameLine();
        ImGui::TextDisabled(mask_key_.empty() ? "not computed" : "stale");
      } else ImGui::TextDisabled("traceable mask up to date");
    }
    ImGui::SliderFloat("exposure", &renderer_->settings.exposure, -8.0f, 8.0f, "%.2f stops");
    ImGui::TextUnformatted("compare:");
    ImGui::SameLine();
    ImGui::RadioButton("A only", &compare_, CompareOff);
    ImGui::SameLine();
    ImGui::RadioButton("split", &compare_, CompareSplit);
    ImGui::SameLine();
    ImGui::RadioButton("difference", &compare_, CompareDiff);
    if (compare_ == CompareSplit) ImGui::SliderFloat("divider", &split_, 0.0f, 1.0f, "%.3f");
    if (compare_ == CompareDiff) {
      ImGui::SliderFloat("full scale", &diff_scale_, 0.01f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("mean |A - B| over RGB (display values) shown as the hottest colour");
    }
    if (compare_ != CompareOff) {
      if (sides_[0].request > 0 || sides_[1].request > 0) ImGui::Text("PSNR A vs B: computing...");
      else if (view_ != VIEW_FINAL) ImGui::TextDisabled("PSNR A vs B: in the final view only");
      else if (!psnr_valid_) ImGui::TextDisabled("PSNR A vs B: - (no reflective pixels)");
      else if (psnr_ >= kPsnrCap) ImGui::Text("PSNR A vs B: identical");
      else ImGui::Text("PSNR A vs B: %.2f dB", psnr_);
      if (psnr_history_.size() > 1) {
        const std::vector<float> h(psnr_history_.begin(), psnr_history_.end());
        ImGui::PlotLines("##psnr history", h.data(), static_cast<int>(h.size()), 0, "PSNR A vs B per frame", FLT_MAX,
                         FLT_MAX, ImVec2(ImGui::GetContentRegionAvail().x, 60.0f));
      }
      ImGui::TextDisabled("final image, reflective pixels, display values:");
      ImGui::TextDisabled("compare's 'PSNR' when B is the reference");
    }
  }
  if (ImGui::CollapsingHeader("technique A", ImGuiTreeNodeFlags_DefaultOpen)) technique_panel(sides_[0], "A");
  if (compare_ != CompareOff && ImGui::CollapsingHeader("technique B", ImGuiTreeNodeFlags_DefaultOpen))
    technique_panel(sides_[1], "B");
  if (ImGui::CollapsingHeader("presets")) {
    ImGui::InputText("file", preset_path_, sizeof preset_path_);
    if (ImGui::Button("save")) {
      try {
        save_preset(preset_path_, capture_preset());
        status_ = std::string("preset saved to ") + preset_path_;
        status_error_ = false;
      } catch (const std::exception& e) {
        status_ = e.what();
        status_error_ = true;
      }
    }
    ImGui::SameLine();
    if (ImGui::Button("load")) {
      try {
        apply_preset(load_preset(preset_path_));
        status_ = std::string("preset loaded from ") + preset_path_;
        status_error_ = false;
      } catch (const std::exception& e) {
        status_ = e.what();
        status_error_ = true;
      }
    }
    ImGui::TextDisabled("techniques, parameters, view, camera, lights (JSON, written atomically)");
  }
  if (ImGui::CollapsingHeader("timing", ImGuiTreeNodeFlags_DefaultOpen)) timing_panel(dt);
  if (!status_.empty()) {
    if (status_error_) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.4f, 1));
    ImGui::TextWrapped("%s", status_.c_str());
    if (status_error_) ImGui::PopStyleColor();
  }
  ImGui::End();
}

// Runs the reference of the mask on demand (or in scripted runs) and turns its classes into an image.
void Viewer::update_traceable_mask() {
  const std::string key = frame_key();
  if (mask_key_ == key || !(mask_request_ || scripted_)) return;
  mask_request_ = false;
  if (!mask_ref_) {
    mask_ref_ = create_technique("reference");
    mask_ref_->load(renderer_->shaders());
    set_reference_progress(*mask_ref_, [this](double f) { draw_progress("traceable mask", f); });
  }
  renderer_->render(current_frame(), *mask_ref_, ViewMode::Final, nullptr);
  const ReferenceOutputs out = reference_outputs(*mask_ref_);
  RgbaImage8 im = class_map(*out.classes, fb_w_, fb_h_);
  gl::flip_rows(im.pixels, fb_w_, fb_h_, 4);  // texture rows go bottom-up
  mask_tex_ = gl::Texture2D("viewer traceable mask", GL_RGBA8, fb_w_, fb_h_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(mask_tex_.id(), 0, 0, 0, fb_w_, fb_h_, GL_RGBA, GL_UNSIGNED_BYTE, im.pixels.data());
  mask_key_ = key;
}

void Viewer::render() {
  renderer_->resize(fb_w_, fb_h_);
  ++frame_index_;  // every drawn frame is the next one of a sequence: history carries
  advance_time();
  cut_ = cut_next_;
  cut_next_ = false;
  if (!view_offered(view_)) view_ = VIEW_FINAL;  // the technique changed: its debug view is gone
  if (!composed_ || composed_.width() != fb_w_ || composed_.height() != fb_h_) {
    composed_ = gl::Texture2D("viewer composed", GL_RGBA8, fb_w_, fb_h_);
    for (Side& s : sides_) {
      s.copy = gl::Texture2D("viewer side copy", GL_RGBA8, fb_w_, fb_h_);
      s.color = gl::Texture2D("viewer side colour", GL_RGBA16F, fb_w_, fb_h_);
      const std::uint8_t black[4] = {0, 0, 0, 255};
      glClearTexImage(s.copy.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, black);
      s.valid = false;
      s.shown_key.clear();
    }
    psnr_valid_ = false;
    psnr_key_.clear();
  }
  if (view_ == kViewTraceable) {
    update_traceable_mask();
    if (mask_tex_.width() == fb_w_ && mask_tex_.height() == fb_h_)
      glCopyImageSubData(mask_tex_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, composed_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                         fb_w_, fb_h_, 1);
    return;
  }
  const std::string fkey = frame_key();
  const int n_sides = compare_ == CompareOff ? 1 : 2;
  for (int i = 0; i < n_sides; ++i) {
    Side& s = sides_[i];
    if (s.request == 2) {  // one frame showing "computing..." first
      s.request = 1;
      continue;
    }
    const std::string key = fkey + "|" + technique_key(*s.technique);
    // On-demand techniques run when asked (and in scripted runs, whenever their image is stale).
    const bool run_it = !on_demand(*s.technique) || s.request == 1 ||
                        ((scripted_ || live_truth_) && s.shown_key != key);
    if (!run_it) continue;
    s.request = 0;
    // The telemetry views show an instrumented build's counts (its timings then include them).
    const bool telemetry = view_ < static_cast<int>(view_table().size()) &&
                           view_table()[static_cast<std::size_t>(view_)].telemetry;
    if (telemetry != s.instrumented) {
      s.technique->load(telemetry ? renderer_->shaders().with_defines({"SSR_TELEMETRY"}) : renderer_->shaders());
      s.instrumented = telemetry;
    }
    if (telemetry) renderer_->telemetry().begin(fb_w_, fb_h_);
    s.timer->begin_frame();
    // The inputs render once a frame: the second side's render() finds them current.
    renderer_->render(current_frame(), *s.technique, static_cast<ViewMode>(view_), s.timer.get());
    s.timer->end_frame();
    glMemoryBarrier(GL_ALL_BARRIER_BITS);  // the display pass wrote with imageStore
    glCopyImageSubData(renderer_->display().id(), GL_TEXTURE_2D, 0, 0, 0, 0, s.copy.id(), GL_TEXTURE_2D, 0, 0,
                       0, 0, fb_w_, fb_h_, 1);
    glCopyImageSubData(renderer_->color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, s.color.id(), GL_TEXTURE_2D, 0, 0,
                       0, 0, fb_w_, fb_h_, 1);
    s.valid = true;
    s.shown_key = key;
    if (!s.timer->completed().empty()) {
      s.last_times = s.timer->completed().back();
      s.timer->completed().clear();
      double tech = 0;
      for (const auto& p : s.last_times)
        if (!is_frame_pass(p.name)) tech += p.ms;
      s.history.push_back(static_cast<float>(tech));
      while (s.history.size() > 120) s.history.pop_front();
    }
  }
  // Compose A | B (split), the heat map (difference), or A alone.
  if (compare_ == CompareDiff) {
    glUseProgram(diff_prog_.id());
    glBindTextureUnit(TEX_DIFF_A, sides_[0].copy.id());
    glBindTextureUnit(TEX_DIFF_B, sides_[1].copy.id());
    glBindImageTexture(IMG_DIFF_OUT, composed_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glUniform1f(0, diff_scale_);
    diff_prog_.dispatch_2d(fb_w_, fb_h_);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    glBindTextureUnit(TEX_DIFF_A, 0);
    glBindTextureUnit(TEX_DIFF_B, 0);
  } else {
    glCopyImageSubData(sides_[0].copy.id(), GL_TEXTURE_2D, 0, 0, 0, 0, composed_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       fb_w_, fb_h_, 1);
    const int x0 = std::clamp(static_cast<int>(std::lround(split_ * static_cast<float>(fb_w_))), 0, fb_w_);
    if (compare_ == CompareSplit && x0 < fb_w_)
      glCopyImageSubData(sides_[1].copy.id(), GL_TEXTURE_2D, 0, x0, 0, 0, composed_.id(), GL_TEXTURE_2D, 0, x0, 0,
                         0, fb_w_ - x0, fb_h_, 1);
  }
  // PSNR of A vs B, on the CPU, whenever either image changed.
  if (compare_ != CompareOff && sides_[0].valid && sides_[1].valid) {
    const std::string key = sides_[0].shown_key + "#" + sides_[1].shown_key;
    if (key != psnr_key_) {
      // The shared metric code over compare's pixels: the final image's display values on the
      // reflective pixels of this frame's G-buffer (both sides ran on it: the key holds the frame).
      std::optional<double> p;
      if (view_ == VIEW_FINAL) {
        const float exposure = renderer_->settings.exposure;
        p = psnr_where(display_values(renderer_->read_texture(sides_[0].color), exposure),
                       display_values(renderer_->read_texture(sides_[1].color), exposure), reflective_pixels(*renderer_));
      }
      psnr_valid_ = p.has_value();
      psnr_ = p.value_or(0.0);
      psnr_key_ = key;
      if (p && std::isfinite(*p)) {
        psnr_history_.push_back(static_cast<float>(std::min(*p, kPsnrCap)));
        while (psnr_history_.size() > 300) psnr_history_.pop_front();
      }
    }
  } else if (compare_ != CompareOff) {
    psnr_valid_ = false;
    psnr_key_.clear();
  }
}

void Viewer::frame(double dt) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  handle_input(static_cast<float>(dt));
  draw_ui(dt);
  ImGui::Render();
  glfwGetFramebufferSize(window_, &fb_w_, &fb_h_);
  if (fb_w_ <= 0 || fb_h_ <= 0) return;  // minimised: a 0x0 framebuffer, nothing to draw
  render();
  glNamedFramebufferTexture(blit_fbo_.id(), GL_COLOR_ATTACHMENT0, composed_.id(), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_w_, fb_h_);
  glBlitNamedFramebuffer(blit_fbo_.id(), 0, 0, 0, fb_w_, fb_h_, 0, 0, fb_w_, fb_h_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(window_);
  frame_ms_.push_back(static_cast<float>(dt * 1000.0));
  while (frame_ms_.size() > 240) frame_ms_.pop_front();
}

int Viewer::run() {
  const auto [w, h] = parse_size(o_.size);
  // Everything the command line names is checked before a window opens.
  std::vector<ScriptCommand> script;
  std::string script_name = o_.script;
  if (!o_.script.empty()) script = load_viewer_script(o_.script);
  if (o_.frames > 0) {  // --frames N [--screenshot F]: a two-line script
    script.push_back({0, "frames", {std::to_string(o_.frames)}});
    if (!o_.screenshot.empty()) script.push_back({0, "screenshot", {o_.screenshot}});
  }
  if (!o_.screenshot.empty() && o_.frames <= 0)
    throw InputError("--screenshot needs --frames N: the frame it captures (F12 saves one in an interactive session).");
  if (!o_.screenshot.empty()) image_format_for(o_.screenshot);
  scripted_ = !script.empty();
  std::optional<ViewerPreset> preset;
  if (!o_.preset.empty()) preset = load_preset(o_.preset);
  Scene probe = load_scene(o_.scene);  // fails before the window opens
  if (!o_.camera.empty()) probe.camera(o_.camera);
  {
    std::unique_ptr<Technique> a = create_technique(o_.technique), b = create_technique(o_.technique_b);
    sides_[0].technique = std::move(a);
    sides_[1].technique = std::move(b);
    apply_sets(o_.sets);  // checks the keys before GL
  }
  const int initial_view = o_.view == "traceable" ? kViewTraceable : static_cast<int>(parse_view_mode(o_.view));

  // Owners in creation order, so that destruction runs backwards: GL objects (renderer,
  // techniques) die while the context is still current, the window last.
  struct GlfwSession {
    GLFWwindow** window;
    ~GlfwSession() {
      if (*window) glfwDestroyWindow(*window);
      glfwTerminate();
    }
  } glfw{&window_};
  open_window(w, h);
  struct ImGuiSession {
    ~ImGuiSession() {
      ImGui_ImplOpenGL3_Shutdown();
      ImGui_ImplGlfw_Shutdown();
      ImGui::DestroyContext();
    }
  };
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  const std::string ini = o_.ini.empty() ? default_ini_path() : o_.ini;
  ImGui::GetIO().IniFilename = ini.c_str();  // layout kept between runs
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 450");
  ImGuiSession imgui_session;
  struct GlOwners {  // released before ImGui and the window go
    Viewer* v;
    ~GlOwners() {
      for (Side& s : v->sides_) s = Side{};
      v->mask_ref_.reset();
      v->mask_tex_ = {};
      v->composed_ = {};
      v->blit_fbo_ = {};
      v->diff_prog_ = {};
      v->renderer_.reset();
    }
  } gl_owners{this};

  // Live reload reads shaders from the source tree when it is there, else the embedded copy.
  std::string shader_dir = o_.shader_dir;
  if (shader_dir.empty() && fs::is_directory(SSRLAB_SHADER_DIR)) shader_dir = SSRLAB_SHADER_DIR;
  shaders_ = shader_dir.empty() ? gl::ShaderSource() : gl::ShaderSource(fs::path(shader_dir));
  load_scene_spec(o_.scene, o_.camera);
  for (Side& s : sides_) {
    s.technique->load(renderer_->shaders());
    set_reference_progress(*s.technique, [this](double f) { draw_progress("reference", f); });
    s.timer = std::make_unique<gl::PassTimer>(clock_);
  }
  diff_prog_ = gl::Program::compute(renderer_->shaders(), "render/diff.comp");
  blit_fbo_ = gl::Framebuffer("viewer blit");
  view_ = initial_view;
  compare_ = o_.diff ? CompareDiff : o_.split >= 0 ? CompareSplit : CompareOff;
  if (o_.split >= 0) split_ = static_cast<float>(o_.split);
  if (preset) apply_preset(*preset);
  view_names_ = viewer_view_names();
  scene_names_ = scene_choices();

  double last_time = glfwGetTime();
  std::size_t next_command = 0;
  int frames_left = 0;
  while (!glfwWindowShouldClose(window_)) {
    // Scripted runs: commands run between frames, until a `frames N` asks for frames.
    while (scripted_ && frames_left == 0) {
      if (next_command == script.size()) return 0;
      const ScriptCommand& c = script[next_command++];
      try {
        if (c.verb == "frames") frames_left = std::stoi(c.args[0]);
        else run_command(c);
      } catch (const InputError& e) {
        throw InputError(c.line > 0 ? script_where(script_name, c) + e.what() : e.what());
      }
    }
    glfwPollEvents();
    const double now = glfwGetTime();
    frame(now - last_time);
    last_time = now;
    if (frames_left > 0 && --frames_left == 0 && compare_ != CompareOff && psnr_valid_)
      std::printf("ssrlab-view: PSNR A vs B %.2f dB\n", psnr_);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ssrlab-view: interactive screen-space reflection viewer"};
  Options o;
  app.add_option("--scene", o.scene, "Built-in scene name or a .json/.obj path.")->capture_default_str();
  app.add_option("--technique", o.technique, "Technique A (the left of a split).")->capture_default_str();
  app.add_option("--set", o.sets, "Parameter assignment technique.key=value (repeatable).");
  app.add_option("--size", o.size, "Window size WIDTHxHEIGHT.")->capture_default_str();
  app.add_option("--camera", o.camera, "Named camera of the scene.");
  app.add_option("--view", o.view, "Initial view (final, reflection, confidence, lit, ..., traceable).")->capture_default_str();
  app.add_option("--frames", o.frames, "Render this many frames, then exit (0: interactive).")->check(CLI::Range(0, 100000));
  app.add_option("--screenshot", o.screenshot, "With --frames: write the last frame to this PNG.");
  app.add_option("--shaders", o.shader_dir, "Shader directory for live reload (F5).");
  app.add_option("--technique-b", o.technique_b, "Technique B (right of the split, or diffed against A).")->capture_default_str();
  app.add_option("--split", o.split, "Start in split view with the divider at X (0..1 of the width).")->check(CLI::Range(0.0, 1.0));
  app.add_flag("--diff", o.diff, "Start in difference mode: a heat map of |A - B| and the PSNR.");
  app.add_option("--preset", o.preset, "Start from a JSON preset saved by the viewer.");
  app.add_option("--script", o.script, "Run the commands of this file (see viewer_script.h), then exit.");
  app.add_option("--ini", o.ini, "ImGui layout file (default: ~/.config/ssrlab/imgui.ini).");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "ssrlab-view: %s\n", e.what());
    return 2;
  }
  try {
    return Viewer(o).run();
  } catch (const InputError& e) {
    std::fprintf(stderr, "ssrlab-view: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ssrlab-view: %s\n", e.what());
    return 1;
  }
}
