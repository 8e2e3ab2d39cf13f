// ssrlab-view: the interactive viewer. One Viewer is one session; its code is split by concern:
//   viewer.cpp            set-up, state changes (scene, techniques, lighting, presets), main loop
//   command_handlers.cpp  one handler per command of commands.h (scripts, keys and buttons)
//   compare.cpp           running the sides, composing A | B / |A - B|, the A-vs-B figure, the truth
//   ui.cpp                layout (image, side panel, status bar), panels, legends, help
//   window.cpp            GLFW + ImGui, keys as events      camera_controller.cpp  orbit / pan / fly
//   panels.cpp            widgets from the parameter tables  preset.cpp  presets as JSON
#pragma once
#include <array>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/objects.h"
#include "gl/program.h"
#include "gl/timer.h"
#include "render/renderer.h"
#include "techniques/technique.h"
#include "viewer/camera_controller.h"
#include "viewer/commands.h"
#include "viewer/inspector.h"
#include "viewer/preset.h"
#include "viewer/window.h"

namespace ssr {

struct ViewerOptions {
  std::string scene = "gallery";
  std::string technique = "linear";
  std::vector<std::string> sets;
  std::string size = "960x540";  // the image; the window adds the side panel and the status bar
  std::string camera;
  std::string view = "final";
  int frames = 0;          // 0 = interactive
  std::string screenshot;  // with --frames: where the last frame goes
  std::string shader_dir;
  std::string technique_b = "none";
  double split = -1;  // < 0: no split at start
  bool diff = false;
  bool no_panel = false;
  std::string preset;  // a preset to start from
  std::string script;  // scripted input
  std::string ini;     // ImGui layout file; default: the user's config directory
};

inline constexpr int kViewTraceable = VIEW_COUNT;  // the viewer's own view: the reference's classes

// One side of the comparison: its technique, a copy of its last display image, its timings.
struct Side {
  std::unique_ptr<Technique> technique;
  gl::Texture2D copy;       // RGBA8 display image of the last frame it ran
  gl::Texture2D color;      // RGBA16F composited colour of that frame (the A-vs-B figure reads it)
  gl::Texture2D debug;      // RGBA16F debug channels of that frame (steps, hits, distance / PPR offsets)
  bool has_debug = false;   // the technique wrote them this frame (declared, and asked for)
  bool valid = false;       // `copy` holds an image of the current size
  bool computed = false;    // it has run since it was chosen (a resize leaves it stale, not "not computed")
  std::string shown_key;    // the frame key of what `copy` shows
  std::string ran_key;      // its inputs' key (no view, no exposure) and technique key: what `color` holds
  int request = 0;          // on-demand: 2 = asked (the image says "computing"), 1 = run this frame
  std::unique_ptr<gl::PassTimer> timer;
  gl::FrameTimes last_times;
  std::deque<float> history;  // technique ms of the last frames
  bool instrumented = false;  // loaded with SSR_TELEMETRY (a telemetry view is shown)
};

class Viewer {
 public:
  explicit Viewer(ViewerOptions o) : o_(std::move(o)) {}
  int run();

  // The commands (commands.h): one handler each, dispatched by execute().
#define SSRLAB_X(id, verb, form, args, help) void on_##id(const std::string& arg);
  SSRLAB_VIEWER_COMMANDS(SSRLAB_X)
#undef SSRLAB_X
  void execute(const ScriptCommand& c);

 private:
  // --- viewer.cpp: set-up and state changes (all validate first and throw InputError) ---
  void load_scene_spec(const std::string& spec, const std::string& camera_name);
  void set_technique(Side& side, const std::string& name);
  void use_named_preset(Side& side, const std::string& name);
  void apply_sets(const std::vector<std::string>& sets);
  void set_lighting(const std::vector<Light>& lights, const Environment& env, float ambient);
  ViewerPreset capture_preset() const;
  void apply_preset(const ViewerPreset& p);
  void advance_time();
  void set_time(float t);
  void save(const std::string& path);
  void reload();
  // One frame: input, panels, the image, present. `advance` false: the same frame drawn again
  // (a window-shot): time, frame index and history stay, and a side whose image is current is
  // not run again.
  void frame(double dt, bool advance = true);
  void present();  // the window's frame (saved when a window-shot is pending)
  void set_status(const std::string& message, bool error);
  // A command from a key or a button: its error goes to the status bar, not up the stack.
  void ui_command(Verb verb, const std::string& arg = "");

  // --- compare.cpp ---
  void render(bool advance);
  // Moves the side's completed timer frames into its rolling history and last_times.
  void take_times(Side& s);
  void update_traceable_mask();
  std::string frame_key() const;
  // Side i's state for the panel, the banner and status: "computing", "current", "stale" or
  // "not computed".
  std::string side_state(int i) const;
  std::string inputs_key() const;  // frame_key() without the view and the exposure (display only)
  bool side_current(int i) const;  // the side's image shows the current frame and parameters
  bool truth_stale() const;        // an on-demand side (the reference) shows another frame
  bool on_demand(int i) const;
  int active_sides() const;
  void ensure_grid_truth();  // A; A and B; A, B and the truth (grid)
  // The frame the techniques render: the image, or a quarter of it in the grid.
  int render_w() const { return compare_ == CompareGrid ? image_w_ / 2 : image_w_; }
  int render_h() const { return compare_ == CompareGrid ? image_h_ / 2 : image_h_; }
  std::string truth_state() const;  // "none", "current", "stale" or "computing"
  bool figure_shown() const;        // the A-vs-B figure is of the current frame and shown
  FrameRequest current_frame() const;

  // --- ui.cpp ---
  void handle_input(double dt);
  void layout();                    // where the image, the panel and the status bar go
  void draw_ui(double dt);
  void draw_image_overlays();
  void side_panel(double dt);
  void status_bar(double dt);
  void legend();
  void help_window();
  void scene_panel();
  void view_panel();
  void technique_panel(int side);
  void time_panel();
  void timing_panel(double dt);
  // The frame time to show: dt, or for a frame drawn again without time passing (dt 0: a
  // window-shot, the first frame) the last timed frame's; none before one was timed.
  std::optional<double> shown_frame_ms(double dt) const;
  void draw_progress(const std::string& what, double fraction);
  void inspector_panel();
  // The collapsing header of a panel section (kPanelSections), opened or closed first when the
  // `section` command asked; true while it is open.
  bool section_header(PanelSection s);
  void draw_magnifier();
  PixelValues inspect(int x, int y) const;  // inspector.h's values of image pixel (x, y)
  bool view_offered(int view) const;
  // Side i's technique fills `view` (the final image and the non-debug views: every technique).
  bool side_fills_view(int i, int view) const;
  bool truth_figure_shown() const;  // the grid's A-vs-truth figure is current (with figure_shown())
  // Side i's technique, and where A and B run the same one, the parameters in which it differs
  // from the other side ("hiz max_iterations=8"): the split's and the grid's labels.
  std::string side_label(int i) const;

  ViewerOptions o_;
  bool scripted_ = false;  // --frames or --script: on-demand work runs without being asked
  // Declared before every GL owner below: members die in reverse order, so the textures,
  // programs, techniques and the renderer go while the window's context is still current.
  std::unique_ptr<Window> window_;
  gl::ShaderSource shaders_;
  gl::PassTimer::Clock clock_ = gl::PassTimer::Clock::Cpu;

  std::string scene_spec_;
  std::vector<Camera> cameras_;  // the scene's named cameras, then the user's bookmarks
  std::vector<Light> lights_;    // edited copies of the scene's lighting
  Environment environment_;
  float ambient_ = 0.3f;
  int lighting_revision_ = 0;
  std::unique_ptr<Renderer> renderer_;
  Side sides_[3];  // A, B, and the grid's truth
  CameraController camera_;
  double last_moved_ = 0;   // glfw time the camera last moved (the truth waits for it to rest)
  gl::Program diff_prog_;
  gl::Texture2D composed_;    // what the image area and screenshots show (no UI)
  gl::Texture2D grid_diff_;   // the grid's |A - truth| cell
  gl::Framebuffer blit_fbo_;  // created once the context exists

  // The truth's own noise (truth-noise on): a second truth with another seed, run after each new
  // truth image; half their mean squared difference, as PSNR, is the noise floor (README "The
  // truth's own noise", as compare and bench estimate it).
  bool truth_noise_ = false;
  std::unique_ptr<Technique> noise_truth_;  // the second truth, set up anew for each truth
  RgbaImageF noise_color_;       // the second truth's composited colour
  std::string noise_ran_key_;    // the truth side's ran_key it was run for
  std::string noise_shown_key_;  // the truth side's shown_key the figure is of
  std::optional<double> noise_psnr_;
  int current_truth_side() const;  // the reference side shown and current, or -1
  int noise_truth_side() const;    // that side where truth-noise applies (a compare mode, final view), or -1
  void update_truth_noise();
  std::optional<double> truth_noise_shown() const;  // the floor, where a current truth is shown

  // Traceable mask: a reference of its own, run on demand, shown as its class map.
  std::unique_ptr<Technique> mask_ref_;
  gl::Texture2D mask_tex_;
  std::string mask_key_;
  bool mask_request_ = false;

  // Layout, in framebuffer pixels: the image at the top left, the side panel on the right, the
  // status bar along the bottom. The image is rendered at its own size (never under a panel).
  int fb_w_ = 0, fb_h_ = 0;
  int image_w_ = 0, image_h_ = 0;
  float panel_w_ = 360.0f;
  bool panel_shown_ = true, help_shown_ = false, resizing_panel_ = false;
  static constexpr float kStatusH = 26.0f;
  int frame_index_ = 0;  // the frame being drawn, in the sequence of drawn frames

  // Playback: scene time (object motion) and, with a path chosen, the camera along it. Time
  // advances by speed / 30 s a drawn frame (not by the wall clock: reproducible screenshots).
  int path_ = -1;  // index into the scene's paths; -1: the free (orbit) camera
  float time_ = 0.0f, speed_ = 1.0f;
  bool playing_ = false, loop_ = true, cut_ = false, cut_next_ = false;
  int view_ = VIEW_FINAL;
  int compare_ = CompareOff;
  float split_ = 0.5f, diff_scale_ = 0.25f;
  bool dragging_divider_ = false;
  std::string status_;
  bool status_error_ = false;
  std::string psnr_key_;
  double psnr_ = 0;
  bool psnr_valid_ = false;
  double psnr_truth_ = 0;  // the grid: A against its truth (the fourth cell's figure)
  bool psnr_truth_valid_ = false;
  // When the truth (an on-demand side) is recomputed: once the camera rests, on every changed
  // frame (playback plots the figure per frame; scripted runs start with it), or when asked.
  enum class TruthPolicy { Manual, Rest, Live } truth_policy_ = TruthPolicy::Rest;
  std::string window_shot_;  // where the next presented frame's whole window goes
  static constexpr double kRestSeconds = 0.5;
  std::deque<float> psnr_history_;
  glm::dvec2 last_mouse_{0};
  std::deque<float> frame_ms_;
  std::vector<std::string> view_names_, scene_names_;
  std::vector<std::string> scene_labels_;           // scene_names_ as the picker shows them
  std::optional<std::string> scene_choice_for_;     // the scene spec scene_choice_ was found for
  int scene_choice_ = -1;                           // its index in scene_names_, or -1
  char preset_path_[512] = "ssrlab-preset.json";
  char scene_path_[512] = "";
  int bookmarks_ = 0;
  int frames_left_ = 0;  // scripted: frames to run before the next command
  // Inspection: the pixel under the cursor (or pinned with I), the magnifier's zoom (0: off).
  std::optional<glm::ivec2> hovered_, pinned_;
  int magnifier_ = 0;
  // The inspector reads the techniques' debug image (steps, hits, offsets), which they write
  // only when asked (Renderer::debug_outputs): while its panel section is open
  // (section_open_[SectionInspector]), and after a scripted `inspect`.
  bool inspected_ = false;
  // Sections: what the `section` command asked for (applied at the next draw) and what was
  // open at the last draw (`status` reports it).
  std::array<std::optional<bool>, kPanelSectionCount> section_request_{};
  std::array<bool, kPanelSectionCount> section_open_{};
};

}  // namespace ssr
