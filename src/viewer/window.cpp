#include "viewer/window.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "gl/gl.h"
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "core/errors.h"
#include "gl/readback.h"

namespace ssr {

Window::Window(int w, int h, bool vsync, std::string ini) : ini_(std::move(ini)) {
  if (!glfwInit()) throw RuntimeError("GLFW could not initialise (no display?).");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(w, h, "ssrlab", nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw RuntimeError("no OpenGL 4.5 core window could be created.");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(vsync ? 1 : 0);
  try {
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)))
      throw RuntimeError("OpenGL functions could not be loaded.");
    info_ = gl::query_current_context("glfw");
    std::fprintf(stderr, "ssrlab-view: GL via glfw: %s | %s\n", info_.renderer.c_str(), info_.version.c_str());
    // The window system may give less than asked (an X screen holds at most 32767 pixels a
    // side); a smaller frame than the command line named would be a silent lie in every figure.
    GLint max_dims[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_dims);
    if (w > max_dims[0] || h > max_dims[1])
      throw InputError("a " + std::to_string(w) + "x" + std::to_string(h) + " window is larger than this GL's viewport limit " +
                       std::to_string(max_dims[0]) + "x" + std::to_string(max_dims[1]) + ".");
    int got_w = 0, got_h = 0;
    glfwGetFramebufferSize(window_, &got_w, &got_h);
    if (got_w != w || got_h != h)
      throw InputError("the window system opened a " + std::to_string(got_w) + "x" + std::to_string(got_h) +
                       " window, not the " + std::to_string(w) + "x" + std::to_string(h) + " asked for.");
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
  // Ours first: ImGui's backend chains to the callback installed before it.
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &Window::on_key);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = ini_.c_str();
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 450");
}

Window::~Window() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void Window::on_key(GLFWwindow* w, int key, int, int action, int) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
  if (!self || action != GLFW_PRESS) return;
  self->presses_.push_back(key);
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }

void Window::set_size(int w, int h) { glfwSetWindowSize(window_, w, h); }

void Window::framebuffer_size(int* w, int* h) const { glfwGetFramebufferSize(window_, w, h); }

void Window::poll() { glfwPollEvents(); }

void Window::begin_ui() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void Window::present(RgbaImage8* capture) {
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (capture) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    *capture = {w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4)};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, capture->pixels.data());
    gl::flip_rows(capture->pixels, w, h, 4);  // GL rows go up
  }
  glfwSwapBuffers(window_);
}

std::vector<int> Window::take_presses() {
  taken_ = std::exchange(presses_, {});
  return taken_;
}

bool Window::held_or_tapped(int key) const {
  return glfwGetKey(window_, key) == GLFW_PRESS || std::find(taken_.begin(), taken_.end(), key) != taken_.end();
}

}  // namespace ssr
