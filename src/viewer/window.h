// The viewer's window: GLFW with an OpenGL 4.5 core context, Dear ImGui on top, and the keys
// as events. Keys arrive through GLFW's key callback (chained with ImGui's), so a tap between two
// slow frames is still seen; the fly keys are read as "held or tapped since the last frame".
#pragma once
#include <string>
#include <vector>

#include "core/image.h"
#include "gl/context.h"

struct GLFWwindow;

namespace ssr {

class Window {
 public:
  // Opens a window of exactly `w` x `h` framebuffer pixels (InputError when the GL or the window
  // system cannot hold it), makes its context current, starts ImGui (layout kept in `ini`).
  Window(int w, int h, bool vsync, std::string ini);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  const gl::ContextInfo& info() const { return info_; }
  bool should_close() const;
  void set_size(int w, int h);      // in framebuffer pixels (the window system may adjust)
  void framebuffer_size(int* w, int* h) const;

  void poll();          // window events, key callbacks included
  void begin_ui();      // an ImGui frame
  // ImGui's draw data over what is bound, then swap; with `capture`, the whole window as shown
  // (read back before the swap) goes there.
  void present(RgbaImage8* capture = nullptr);

  // Keys pressed since the last call, in the order pressed (GLFW key codes).
  std::vector<int> take_presses();
  // Whether `key` is down now or was among the last take_presses (a tap between frames counts).
  bool held_or_tapped(int key) const;

 private:
  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);
  GLFWwindow* window_ = nullptr;
  gl::ContextInfo info_;
  std::string ini_;              // ImGui keeps a pointer to it
  std::vector<int> presses_;     // since the last take_presses
  std::vector<int> taken_;       // what the last take_presses returned
};

}  // namespace ssr
