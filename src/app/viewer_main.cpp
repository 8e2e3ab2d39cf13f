// ssrlab-view: the interactive viewer (GLFW window + Dear ImGui).
//
//   mouse: left drag orbits around the target, right drag pans, wheel zooms
//   WASD/QE: fly (Shift x4, Ctrl x0.25)   F12: screenshot   F5: reload shaders   F2: hide UI
//   --frames N --screenshot F.png: render N frames, save the frame, exit (for tests).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
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
};

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
  apply_assignments(*requested, o.sets);
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
  std::unique_ptr<Technique> technique = std::move(requested);

  // Live reload reads shaders from the source tree when it is there, else the embedded copy.
  std::string shader_dir = o.shader_dir;
  if (shader_dir.empty() && fs::is_directory(SSRLAB_SHADER_DIR)) shader_dir = SSRLAB_SHADER_DIR;
  gl::ShaderSource shaders = shader_dir.empty() ? gl::ShaderSource() : gl::ShaderSource(fs::path(shader_dir));

  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(window, &fb_w, &fb_h);
  Renderer renderer(scene, std::max(fb_w, 1), std::max(fb_h, 1), shaders);
  technique->load(renderer.shaders());
  gl::PassTimer timer(info.software ? gl::PassTimer::Clock::Cpu : gl::PassTimer::Clock::Gpu);
  gl::Framebuffer blit_fbo("viewer blit");

  int view = static_cast<int>(initial_view);
  bool show_ui = true;
  std::string status;
  gl::FrameTimes last_times;
  double last_time = glfwGetTime();
  glm::dvec2 last_mouse{0};
  int frame = 0;
  std::map<int, bool> key_was_down;
  std::vector<std::string> view_names_c;
  for (const auto& n : view_mode_names()) view_names_c.push_back(n);

  auto save = [&](const std::string& path) {
    write_png(path, renderer.read_display());
    status = "saved " + path;
    std::printf("ssrlab-view: %s\n", status.c_str());
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
      if (pressed(GLFW_KEY_F5)) {
        try {
          renderer.reload_shaders();
          technique->load(renderer.shaders());
          status = "shaders reloaded";
        } catch (const std::exception& e) {
          status = e.what();  // the last good programs keep running
        }
      }
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
    if (!io.WantCaptureMouse) {
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
    if (show_ui) {
      ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
      ImGui::SetNextWindowSize(ImVec2(380, 0), ImGuiCond_FirstUseEver);
      ImGui::Begin("ssrlab");
      ImGui::Text("%s", info.renderer.c_str());
      const auto& reg = technique_registry();
      if (ImGui::BeginCombo("technique", technique->name().c_str())) {
        for (const TechniqueInfo& t : reg) {
          if (ImGui::Selectable(t.name.c_str(), t.name == technique->name())) {
            auto next = t.create();
            try {
              next->load(renderer.shaders());
              technique = std::move(next);
            } catch (const std::exception& e) {
              status = e.what();
            }
          }
          if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t.description.c_str());
        }
        ImGui::EndCombo();
      }
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
      if (ImGui::CollapsingHeader("parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
        ParamSet params = technique->params();
        draw_param_panel(params);
      }
      if (ImGui::CollapsingHeader("timing", ImGuiTreeNodeFlags_DefaultOpen)) {
        double total = 0;
        for (const auto& p : last_times) {
          ImGui::Text("%-12s %7.3f ms", p.name.c_str(), p.ms);
          total += p.ms;
        }
        ImGui::Text("%-12s %7.3f ms (%s clock)", "total", total, timer.clock_name());
        ImGui::Text("frame %.1f ms", static_cast<double>(dt) * 1000.0);
      }
      if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
      ImGui::End();
    }
    ImGui::Render();

    // --- frame --------------------------------------------------------------------------------
    glfwGetFramebufferSize(window, &fb_w, &fb_h);
    if (fb_w > 0 && fb_h > 0) {  // minimised windows have a 0x0 framebuffer: skip the frame
      renderer.resize(fb_w, fb_h);
      timer.begin_frame();
      renderer.render(orbit.cam, *technique, static_cast<ViewMode>(view), &timer);
      timer.end_frame();
      if (!timer.completed().empty()) {
        last_times = timer.completed().back();
        timer.completed().clear();
      }
      glNamedFramebufferTexture(blit_fbo.id(), GL_COLOR_ATTACHMENT0, renderer.display().id(), 0);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, fb_w, fb_h);
      glBlitNamedFramebuffer(blit_fbo.id(), 0, 0, 0, fb_w, fb_h, 0, 0, fb_w, fb_h,
                             GL_COLOR_BUFFER_BIT, GL_NEAREST);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      glfwSwapBuffers(window);
      ++frame;
      if (o.frames > 0 && frame >= o.frames) {
        if (!o.screenshot.empty()) save(o.screenshot);
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
