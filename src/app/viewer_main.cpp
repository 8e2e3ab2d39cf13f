// ssrlab-view: the interactive viewer (GLFW window + Dear ImGui).
//
//   mouse: left drag orbits around the target, right drag pans, wheel zooms
//   WASD/QE: fly (Shift x4, Ctrl x0.25)   F12: screenshot   F5: reload shaders   F2: hide UI
//   --frames N --screenshot F.png: render N frames, save the frame, exit (for tests).
//   Compare mode: technique A (left) and B (right) on the same frame inputs, with a draggable
//   divider (--technique-b NAME --split X), or a difference heat map of A vs B (--diff).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <deque>
#include <filesystem>
#include <map>

#include <CLI/CLI.hpp>
#include <glm/gtc/constants.hpp>

#include "gl/gl.h"
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/panels.h"
#include "core/cli_common.h"
#include "core/errors.h"
#include "gl/context.h"
#include "render/image_io.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "techniques/technique.h"

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
};

enum CompareMode : int { CompareOff = 0, CompareSplit = 1, CompareDiff = 2 };

// Techniques too slow to run every frame (CPU ray tracing): they run when asked.
bool on_demand(const Technique& t) { return t.name() == "reference"; }

// One side of the comparison: its technique, a copy of its last display image, its timings.
struct Side {
  std::unique_ptr<Technique> technique;
  gl::Texture2D copy;       // RGBA8 display image of the last frame it ran
  bool valid = false;       // `copy` holds an image of the current size
  std::string shown_key;    // the frame key of what `copy` shows
  int request = 0;          // on-demand: 2 = asked (UI shows "computing..."), 1 = run this frame
  std::unique_ptr<gl::PassTimer> timer;
  gl::FrameTimes last_times;
  std::deque<float> history;  // technique ms of the last frames
};

// What a technique's image depends on besides the frame inputs: its name and parameter values.
std::string technique_key(Technique& t) {
  std::string k = t.name();
  ParamSet p = t.params();
  for (std::size_t i = 0; i < p.size(); ++i) k += "," + p.to_string(i);
  return k;
}

std::string frame_key(const Camera& c, int view, float exposure, int w, int h) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%g %g %g|%g %g %g|%g|%d|%g|%dx%d", c.position.x, c.position.y,
                c.position.z, c.target.x, c.target.y, c.target.z, c.fov_y_deg, view, exposure, w, h);
  return buf;
}

bool is_frame_pass(const std::string& name) {
  return name == "gbuffer" || name == "lighting" || name == "composite" || name == "display";
}

RgbaImage8 read_rgba8(const gl::Texture2D& tex) {
  const int w = tex.width(), h = tex.height();
  RgbaImage8 im{w, h, {}};
  im.pixels.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(tex.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(im.pixels.size()),
                    im.pixels.data());
  const std::size_t row = static_cast<std::size_t>(w) * 4;
  for (int y = 0; y < h / 2; ++y)
    std::swap_ranges(im.pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)),
                     im.pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y + 1)),
                     im.pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(h - 1 - y)));
  return im;
}

// PSNR (dB) of two RGBA8 images over RGB, values in [0,1]; infinity when equal.
double psnr8(const RgbaImage8& a, const RgbaImage8& b) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i + 3 < a.pixels.size() && i + 3 < b.pixels.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c, ++n) {
      const double d = (double(a.pixels[i + c]) - double(b.pixels[i + c])) / 255.0;
      sum += d * d;
    }
  if (n == 0 || sum == 0) return INFINITY;
  return 10.0 * std::log10(1.0 / (sum / static_cast<double>(n)));
}

// Splits --set assignments between the two techniques by their "<technique>." prefix; keys of
// neither go to A, whose apply reports them.
void apply_sets(Technique& a, Technique& b, const std::vector<std::string>& sets) {
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

int run(const Options& o) {
  const auto [w, h] = parse_size(o.size);
  const ViewMode initial_view = parse_view_mode(o.view);
  Scene scene = load_scene(o.scene);
  std::unique_ptr<Technique> requested = create_technique(o.technique);  // validated before GL
  std::unique_ptr<Technique> requested_b = create_technique(o.technique_b);
  apply_sets(*requested, *requested_b, o.sets);
  OrbitCamera orbit;
  orbit.from_camera(o.camera.empty() ? scene.cameras.front() : scene.camera(o.camera));
  if (!o.screenshot.empty()) image_format_for(o.screenshot);

  // Owners in creation order, so that destruction runs backwards: GL objects (renderer,
  // technique) die while the context is still current, the window last.
  struct GlfwWindow {
    GLFWwindow* window = nullptr;
    ~GlfwWindow() {
      if (window) glfwDestroyWindow(window);
      glfwTerminate();
    }
  };
  struct ImGuiSession {
    ~ImGuiSession() {
      ImGui_ImplOpenGL3_Shutdown();
      ImGui_ImplGlfw_Shutdown();
      ImGui::DestroyContext();
    }
  };
  if (!glfwInit()) throw RuntimeError("GLFW could not initialise (no display?).");
  GlfwWindow glfw;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfw.window = glfwCreateWindow(w, h, "ssrlab", nullptr, nullptr);
  if (!window) throw RuntimeError("no OpenGL 4.5 core window could be created.");
  glfwMakeContextCurrent(window);
  glfwSwapInterval(o.frames > 0 ? 0 : 1);
  if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)))
    throw RuntimeError("OpenGL functions could not be loaded.");
  const gl::ContextInfo info = gl::query_current_context("glfw");
  std::fprintf(stderr, "ssrlab-view: GL via glfw: %s | %s\n", info.renderer.c_str(), info.version.c_str());

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = "imgui.ini";
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 450");
  ImGuiSession imgui_session;

  // Live reload reads shaders from the source tree when it is there, else the embedded copy.
  std::string shader_dir = o.shader_dir;
  if (shader_dir.empty() && fs::is_directory(SSRLAB_SHADER_DIR)) shader_dir = SSRLAB_SHADER_DIR;
  gl::ShaderSource shaders = shader_dir.empty() ? gl::ShaderSource() : gl::ShaderSource(fs::path(shader_dir));

  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(window, &fb_w, &fb_h);
  Renderer renderer(scene, std::max(fb_w, 1), std::max(fb_h, 1), shaders);
  const gl::PassTimer::Clock clock = info.software ? gl::PassTimer::Clock::Cpu : gl::PassTimer::Clock::Gpu;
  Side sides[2];
  sides[0].technique = std::move(requested);
  sides[1].technique = std::move(requested_b);
  for (Side& s : sides) {
    s.technique->load(renderer.shaders());
    s.timer = std::make_unique<gl::PassTimer>(clock);
  }
  gl::Program diff_prog = gl::Program::compute(renderer.shaders(), "render/diff.comp");
  gl::Texture2D composed;  // what the window and screenshots show (no UI)
  gl::Framebuffer blit_fbo("viewer blit");

  int view = static_cast<int>(initial_view);
  int compare = o.diff ? CompareDiff : o.split >= 0 ? CompareSplit : CompareOff;
  float split = o.split >= 0 ? static_cast<float>(o.split) : 0.5f;
  float diff_scale = 0.25f;
  bool dragging_divider = false;
  bool show_ui = true;
  std::string status;
  std::string psnr_key;  // the keys of the images the PSNR was computed on
  double psnr = 0;
  bool psnr_valid = false;
  double last_time = glfwGetTime();
  glm::dvec2 last_mouse{0};
  int frame = 0;
  std::map<int, bool> key_was_down;
  std::vector<std::string> view_names_c;
  for (const auto& n : view_mode_names()) view_names_c.push_back(n);

  auto save = [&](const std::string& path) {
    write_png(path, composed ? read_rgba8(composed) : renderer.read_display());
    status = "saved " + path;
    std::printf("ssrlab-view: %s\n", status.c_str());
  };
  auto reload = [&] {
    try {
      renderer.reload_shaders();
      for (Side& s : sides) s.technique->load(renderer.shaders());
      diff_prog = gl::Program::compute(renderer.shaders(), "render/diff.comp");
      for (Side& s : sides) s.shown_key.clear();
      status = "shaders reloaded";
    } catch (const std::exception& e) {
      status = e.what();  // the last good programs keep running
    }
  };

  // Technique picker + parameter panel of one side.
  auto technique_panel = [&](Side& side, const char* label) {
    ImGui::PushID(label);
    const auto& reg = technique_registry();
    if (ImGui::BeginCombo(label, side.technique->name().c_str())) {
      for (const TechniqueInfo& t : reg) {
        if (ImGui::Selectable(t.name.c_str(), t.name == side.technique->name())) {
          auto next = t.create();
          try {
            next->load(renderer.shaders());
            side.technique = std::move(next);
            side.valid = false;
            side.shown_key.clear();
            side.request = 0;
            side.history.clear();
          } catch (const std::exception& e) {
            status = e.what();
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
      else if (side.shown_key != frame_key(orbit.cam, view, renderer.settings.exposure, fb_w, fb_h) +
                                     "|" + technique_key(*side.technique))
        ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "stale: the view changed");
      else ImGui::TextDisabled("up to date");
    }
    if (ImGui::TreeNodeEx("parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
      ParamSet params = side.technique->params();
      draw_param_panel(params);
      ImGui::TreePop();
    }
    ImGui::PopID();
  };

  while (!glfwWindowShouldClose(window)) {
    glfwPollEvents();
    const double now = glfwGetTime();
    const float dt = static_cast<float>(now - last_time);
    last_time = now;

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();

    // --- input (ImGui 1.86 has no named keys: GLFW key state, edges detected here) ------------
    auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
    auto pressed = [&](int key) {
      const bool d = down(key), was = key_was_down[key];
      key_was_down[key] = d;
      return d && !was;
    };
    if (!io.WantCaptureKeyboard) {
      if (pressed(GLFW_KEY_F2)) show_ui = !show_ui;
      if (pressed(GLFW_KEY_F12)) save(timestamped_name());
      if (pressed(GLFW_KEY_F5)) reload();
      float speed = 3.0f * dt * (io.KeyShift ? 4.0f : 1.0f) * (io.KeyCtrl ? 0.25f : 1.0f);
      const glm::vec3 fwd = glm::normalize(orbit.cam.target - orbit.cam.position);
      const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
      glm::vec3 move{0};
      if (down(GLFW_KEY_W)) move += fwd;
      if (down(GLFW_KEY_S)) move -= fwd;
      if (down(GLFW_KEY_D)) move += right;
      if (down(GLFW_KEY_A)) move -= right;
      if (down(GLFW_KEY_E)) move.y += 1;
      if (down(GLFW_KEY_Q)) move.y -= 1;
      orbit.cam.position += move * speed;
      orbit.cam.target += move * speed;
    }
    glm::dvec2 mouse;
    glfwGetCursorPos(window, &mouse.x, &mouse.y);
    const glm::vec2 delta = glm::vec2(mouse - last_mouse);
    last_mouse = mouse;
    // The split divider: drag it with the left button (window coordinates, as ImGui's).
    const float divider_x = split * io.DisplaySize.x;
    const bool near_divider = compare == CompareSplit && std::abs(static_cast<float>(mouse.x) - divider_x) < 6.0f;
    if (!io.WantCaptureMouse && near_divider && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
      dragging_divider = true;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging_divider = false;
    if (dragging_divider && io.DisplaySize.x > 0)
      split = std::clamp(static_cast<float>(mouse.x) / io.DisplaySize.x, 0.0f, 1.0f);
    if ((near_divider && !io.WantCaptureMouse) || dragging_divider) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    if (!io.WantCaptureMouse && !dragging_divider) {
      if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        orbit.from_camera(orbit.cam);
        orbit.yaw -= delta.x * 0.005f;
        orbit.pitch += delta.y * 0.005f;
        orbit.update_position();
      }
      if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
        const glm::vec3 fwd = glm::normalize(orbit.cam.target - orbit.cam.position);
        const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
        const glm::vec3 up = glm::cross(right, fwd);
        const float k = glm::length(orbit.cam.target - orbit.cam.position) * 0.002f;
        const glm::vec3 pan = (-right * delta.x + up * delta.y) * k;
        orbit.cam.position += pan;
        orbit.cam.target += pan;
      }
      if (io.MouseWheel != 0) {
        orbit.from_camera(orbit.cam);
        orbit.distance = std::clamp(orbit.distance * std::pow(0.9f, io.MouseWheel), 0.05f, 1000.0f);
        orbit.update_position();
      }
    }

    // --- UI -----------------------------------------------------------------------------------
    if (compare == CompareSplit) {  // the divider and labels are UI: never in screenshots
      ImDrawList* bg = ImGui::GetBackgroundDrawList();
      const float x = split * io.DisplaySize.x;
      bg->AddLine(ImVec2(x, 0), ImVec2(x, io.DisplaySize.y),
                  dragging_divider ? IM_COL32(255, 220, 80, 255) : IM_COL32(255, 255, 255, 200), 2.0f);
      if (show_ui) {
        const std::string right_label = "B: " + sides[1].technique->name();
        bg->AddText(ImVec2(x - 8 - ImGui::CalcTextSize(("A: " + sides[0].technique->name()).c_str()).x,
                           io.DisplaySize.y - 22), IM_COL32(255, 255, 255, 230),
                    ("A: " + sides[0].technique->name()).c_str());
        bg->AddText(ImVec2(x + 8, io.DisplaySize.y - 22), IM_COL32(255, 255, 255, 230), right_label.c_str());
      }
    }
    if (show_ui) {
      ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
      ImGui::SetNextWindowSize(ImVec2(380, 0), ImGuiCond_FirstUseEver);
      ImGui::Begin("ssrlab");
      ImGui::Text("%s", info.renderer.c_str());
      ImGui::Combo("view", &view, [](void* data, int i, const char** out) {
        *out = static_cast<std::vector<std::string>*>(data)->at(static_cast<std::size_t>(i)).c_str();
        return true;
      }, &view_names_c, static_cast<int>(view_names_c.size()));
      ImGui::SliderFloat("exposure", &renderer.settings.exposure, -8.0f, 8.0f, "%.2f stops");
      if (ImGui::BeginCombo("camera", orbit.cam.name.c_str())) {
        for (const Camera& c : scene.cameras)
          if (ImGui::Selectable(c.name.c_str(), c.name == orbit.cam.name)) orbit.from_camera(c);
        ImGui::EndCombo();
      }
      ImGui::TextUnformatted("compare:");
      ImGui::SameLine();
      ImGui::RadioButton("A only", &compare, CompareOff);
      ImGui::SameLine();
      ImGui::RadioButton("split", &compare, CompareSplit);
      ImGui::SameLine();
      ImGui::RadioButton("difference", &compare, CompareDiff);
      if (compare == CompareSplit) ImGui::SliderFloat("divider", &split, 0.0f, 1.0f, "%.3f");
      if (compare == CompareDiff) {
        ImGui::SliderFloat("full scale", &diff_scale, 0.01f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("mean |A - B| over RGB (display values) shown as the hottest colour");
      }
      if (compare != CompareOff) {
        if (sides[0].request > 0 || sides[1].request > 0) ImGui::Text("PSNR A vs B: computing...");
        else if (!psnr_valid) ImGui::TextDisabled("PSNR A vs B: -");
        else if (std::isinf(psnr)) ImGui::Text("PSNR A vs B: identical");
        else ImGui::Text("PSNR A vs B: %.2f dB", psnr);
      }
      if (ImGui::CollapsingHeader("technique A", ImGuiTreeNodeFlags_DefaultOpen)) technique_panel(sides[0], "A");
      if (compare != CompareOff && ImGui::CollapsingHeader("technique B", ImGuiTreeNodeFlags_DefaultOpen))
        technique_panel(sides[1], "B");
      if (ImGui::CollapsingHeader("timing", ImGuiTreeNodeFlags_DefaultOpen)) {
        const char* clock_name = sides[0].timer->clock_name();
        for (int i = 0; i < (compare != CompareOff ? 2 : 1); ++i) {
          Side& s = sides[i];
          ImGui::PushID(i);
          ImGui::Text("%s: %s", i == 0 ? "A" : "B", s.technique->name().c_str());
          double total = 0, tech = 0;
          for (const auto& p : s.last_times) {
            ImGui::Text("  %-12s %7.3f ms", p.name.c_str(), p.ms);
            total += p.ms;
            if (!is_frame_pass(p.name)) tech += p.ms;
          }
          ImGui::Text("  %-12s %7.3f ms (%s clock)", "total", total, clock_name);
          if (!s.history.empty()) {
            const std::vector<float> h(s.history.begin(), s.history.end());
            const float hi = *std::max_element(h.begin(), h.end());
            char overlay[64];
            std::snprintf(overlay, sizeof overlay, "technique %.3f ms (%s)", tech, clock_name);
            ImGui::PlotLines("##technique", h.data(), static_cast<int>(h.size()), 0, overlay, 0.0f,
                             std::max(hi * 1.2f, 1e-3f), ImVec2(0, 50));
          }
          ImGui::PopID();
        }
        ImGui::Text("frame %.1f ms", static_cast<double>(dt) * 1000.0);
        if (clock == gl::PassTimer::Clock::Cpu)
          ImGui::TextDisabled("cpu: CPU clock around glFinish (llvmpipe), not GPU time");
      }
      if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
      ImGui::End();
    }
    ImGui::Render();

    // --- frame --------------------------------------------------------------------------------
    glfwGetFramebufferSize(window, &fb_w, &fb_h);
    if (fb_w > 0 && fb_h > 0) {  // minimised windows have a 0x0 framebuffer: skip the frame
      renderer.resize(fb_w, fb_h);
      if (!composed || composed.width() != fb_w || composed.height() != fb_h) {
        composed = gl::Texture2D("viewer composed", GL_RGBA8, fb_w, fb_h);
        for (Side& s : sides) {
          s.copy = gl::Texture2D("viewer side copy", GL_RGBA8, fb_w, fb_h);
          const std::uint8_t black[4] = {0, 0, 0, 255};
          glClearTexImage(s.copy.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, black);
          s.valid = false;
          s.shown_key.clear();
        }
        psnr_valid = false;
        psnr_key.clear();
      }
      const std::string fkey = frame_key(orbit.cam, view, renderer.settings.exposure, fb_w, fb_h);
      const int n_sides = compare == CompareOff ? 1 : 2;
      bool inputs_done = false;
      for (int i = 0; i < n_sides; ++i) {
        Side& s = sides[i];
        if (s.request == 2) { s.request = 1; continue; }  // one frame showing "computing..."
        // On-demand techniques run when asked (and once in the scripted --frames mode).
        const bool run_it = !on_demand(*s.technique) || s.request == 1 || (o.frames > 0 && !s.valid);
        if (!run_it) continue;
        s.request = 0;
        s.timer->begin_frame();
        if (!inputs_done) renderer.render_inputs(orbit.cam, s.timer.get());
        inputs_done = true;
        renderer.run_technique(*s.technique, s.timer.get());
        renderer.composite_and_display(static_cast<ViewMode>(view), s.timer.get());
        s.timer->end_frame();
        glMemoryBarrier(GL_ALL_BARRIER_BITS);  // the display pass wrote with imageStore
        glCopyImageSubData(renderer.display().id(), GL_TEXTURE_2D, 0, 0, 0, 0, s.copy.id(), GL_TEXTURE_2D,
                           0, 0, 0, 0, fb_w, fb_h, 1);
        s.valid = true;
        s.shown_key = fkey + "|" + technique_key(*s.technique);
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
      if (compare == CompareDiff) {
        glUseProgram(diff_prog.id());
        glBindTextureUnit(20, sides[0].copy.id());
        glBindTextureUnit(21, sides[1].copy.id());
        glBindImageTexture(3, composed.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
        glUniform1f(0, diff_scale);
        diff_prog.dispatch_2d(fb_w, fb_h);
        glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
        glBindTextureUnit(20, 0);
        glBindTextureUnit(21, 0);
      } else {
        glCopyImageSubData(sides[0].copy.id(), GL_TEXTURE_2D, 0, 0, 0, 0, composed.id(), GL_TEXTURE_2D,
                           0, 0, 0, 0, fb_w, fb_h, 1);
        const int x0 = std::clamp(static_cast<int>(std::lround(split * static_cast<float>(fb_w))), 0, fb_w);
        if (compare == CompareSplit && x0 < fb_w)
          glCopyImageSubData(sides[1].copy.id(), GL_TEXTURE_2D, 0, x0, 0, 0, composed.id(), GL_TEXTURE_2D,
                             0, x0, 0, 0, fb_w - x0, fb_h, 1);
      }
      // PSNR of A vs B, on the CPU, whenever either image changed.
      if (compare != CompareOff && sides[0].valid && sides[1].valid) {
        const std::string key = sides[0].shown_key + "#" + sides[1].shown_key;
        if (key != psnr_key) {
          psnr = psnr8(read_rgba8(sides[0].copy), read_rgba8(sides[1].copy));
          psnr_valid = true;
          psnr_key = key;
        }
      } else if (compare != CompareOff) {
        psnr_valid = false;
        psnr_key.clear();
      }
      glNamedFramebufferTexture(blit_fbo.id(), GL_COLOR_ATTACHMENT0, composed.id(), 0);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, fb_w, fb_h);
      glBlitNamedFramebuffer(blit_fbo.id(), 0, 0, 0, fb_w, fb_h, 0, 0, fb_w, fb_h,
                             GL_COLOR_BUFFER_BIT, GL_NEAREST);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      glfwSwapBuffers(window);
      ++frame;
      if (o.frames > 0 && frame >= o.frames) {
        if (!o.screenshot.empty()) save(o.screenshot);
        if (compare != CompareOff && psnr_valid)
          std::printf("ssrlab-view: PSNR A vs B %.2f dB\n", psnr);
        break;
      }
    }
  }

  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ssrlab-view: interactive screen-space reflection viewer"};
  Options o;
  app.add_option("--scene", o.scene, "Built-in scene name or a .json/.obj path.")->capture_default_str();
  app.add_option("--technique", o.technique, "Technique to start with.")->capture_default_str();
  app.add_option("--set", o.sets, "Parameter assignment technique.key=value (repeatable).");
  app.add_option("--size", o.size, "Window size WIDTHxHEIGHT.")->capture_default_str();
  app.add_option("--camera", o.camera, "Named camera of the scene.");
  app.add_option("--view", o.view, "Initial view (final, reflection, confidence, lit, ...).")->capture_default_str();
  app.add_option("--frames", o.frames, "Render this many frames, then exit (0: interactive).")->check(CLI::NonNegativeNumber);
  app.add_option("--screenshot", o.screenshot, "With --frames: write the last frame to this PNG.");
  app.add_option("--shaders", o.shader_dir, "Shader directory for live reload (F5).");
  app.add_option("--technique-b", o.technique_b, "Technique B (right of the split, or diffed against A).")->capture_default_str();
  app.add_option("--split", o.split, "Start in split view with the divider at X (0..1 of the width).")->check(CLI::Range(0.0, 1.0));
  app.add_flag("--diff", o.diff, "Start in difference mode: a heat map of |A - B| and the PSNR.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "ssrlab-view: %s\n", e.what());
    return 2;
  }
  try {
    return run(o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "ssrlab-view: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ssrlab-view: %s\n", e.what());
    return 1;
  }
}
