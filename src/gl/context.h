// Headless OpenGL 4.5 core contexts.
//
// Order tried by `Backend::Auto`: EGL device platform (a hardware GPU first, then Mesa's software
// device), EGL surfaceless (Mesa), then OSMesa. EGL and OSMesa are opened with dlopen, so the
// `ssrlab` binary links no GL library and runs where there is no window system.
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace ssr::gl {

enum class Backend { Auto, Egl, OSMesa };

struct ContextInfo {
  std::string path;      // e.g. "egl-device (NVIDIA)", "egl-surfaceless", "osmesa"
  std::string renderer;  // GL_RENDERER
  std::string version;   // GL_VERSION
  std::string vendor;    // GL_VENDOR
  bool software = false; // llvmpipe/softpipe/swrast: GPU timer queries are not trustworthy
};

class HeadlessContext {
 public:
  // Creates, makes current and loads GL. Throws RuntimeError with one sentence when no
  // 4.5 core context can be had by the chosen path(s). `debug` requests a KHR_debug context.
  static std::unique_ptr<HeadlessContext> create(Backend backend = Backend::Auto,
                                                 bool debug = false);
  virtual ~HeadlessContext() = default;
  const ContextInfo& info() const { return info_; }

 protected:
  ContextInfo info_;
};

// Fills ContextInfo's GL strings from the current context (also used by the viewer).
ContextInfo query_current_context(const std::string& path);

// Parses "egl" / "osmesa" / "auto"; throws InputError otherwise.
Backend parse_backend(const std::string& s);
std::string backend_names();  // what parse_backend takes: "auto|egl|osmesa"

// Turns on KHR_debug output: GL errors are recorded for take_gl_errors(); with `verbose`, every
// message above notification severity also goes to stderr.
void enable_debug_output(bool verbose);

// The GL errors recorded since the last call (KHR_debug messages and glGetError), then clears.
std::vector<std::string> take_gl_errors();

}  // namespace ssr::gl
