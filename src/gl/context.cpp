#include "gl/context.h"

#include <dlfcn.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include <glad/egl.h>

#include "core/errors.h"
#include "gl/gl.h"

namespace ssr::gl {

namespace {

bool has_ext(const char* list, const char* ext) {
  if (!list) return false;
  const std::size_t n = std::strlen(ext);
  for (const char* p = list; (p = std::strstr(p, ext)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

ContextInfo fill_info(const std::string& path) { return query_current_context(path); }

// ---- EGL ---------------------------------------------------------------------------------------

class EglContext final : public HeadlessContext {
 public:
  EglContext(EGLDisplay dpy, EGLContext ctx, const std::string& path) : dpy_(dpy), ctx_(ctx) {
    info_ = fill_info(path);
  }
  ~EglContext() override {
    eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy_, ctx_);
    eglTerminate(dpy_);
  }

 private:
  EGLDisplay dpy_;
  EGLContext ctx_;
};

GLADapiproc egl_get_proc(const char* name) {
  return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

// Makes a 4.5 core context current on `dpy` without any surface. Returns nullptr on failure.
EGLContext make_egl_context(EGLDisplay dpy, bool debug) {
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) return nullptr;
  // Reload with the display so that display extensions resolve.
  if (!gladLoaderLoadEGL(dpy)) return nullptr;
  const char* exts = eglQueryString(dpy, EGL_EXTENSIONS);
  if (!has_ext(exts, "EGL_KHR_surfaceless_context") || !eglBindAPI(EGL_OPENGL_API)) {
    eglTerminate(dpy);
    return nullptr;
  }
  EGLConfig config = nullptr;
  if (!has_ext(exts, "EGL_KHR_no_config_context")) {
    const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(dpy, attribs, &config, 1, &n) || n < 1) {
      const EGLint any[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      if (!eglChooseConfig(dpy, any, &config, 1, &n) || n < 1) {
        eglTerminate(dpy);
        return nullptr;
      }
    }
  }
  const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                EGL_CONTEXT_MINOR_VERSION, 5,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
                                EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctx_attribs);
  if (ctx == EGL_NO_CONTEXT) {
    eglTerminate(dpy);
    return nullptr;
  }
  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx) || !gladLoadGL(egl_get_proc)) {
    eglDestroyContext(dpy, ctx);
    eglTerminate(dpy);
    return nullptr;
  }
  return ctx;
}

std::unique_ptr<HeadlessContext> try_egl(bool debug, std::string& why) {
  if (!gladLoaderLoadEGL(EGL_NO_DISPLAY)) {
    why += " EGL: libEGL.so.1 could not be loaded;";
    return nullptr;
  }
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  // 1. Device platform: hardware devices first, Mesa's software device last.
  if (has_ext(client, "EGL_EXT_platform_device") && eglQueryDevicesEXT) {
    EGLDeviceEXT devices[16];
    EGLint n = 0;
    if (eglQueryDevicesEXT(16, devices, &n)) {
      std::vector<EGLDeviceEXT> order;
      for (int pass = 0; pass < 2; ++pass)
        for (int i = 0; i < n; ++i) {
          const char* dext = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
          const bool software = has_ext(dext, "EGL_MESA_device_software");
          if (software == (pass == 1)) order.push_back(devices[i]);
        }
      for (EGLDeviceEXT dev : order) {
        EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, dev, nullptr);
        if (dpy == EGL_NO_DISPLAY) continue;
        if (EGLContext ctx = make_egl_context(dpy, debug))
          return std::make_unique<EglContext>(dpy, ctx, "egl-device");
        gladLoaderLoadEGL(EGL_NO_DISPLAY);
      }
    }
    why += " EGL device platform: no device gave a 4.5 core context;";
  }
  // 2. Mesa's surfaceless platform.
  if (has_ext(client, "EGL_MESA_platform_surfaceless") && eglGetPlatformDisplayEXT) {
    EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                              nullptr);
    if (dpy != EGL_NO_DISPLAY)
      if (EGLContext ctx = make_egl_context(dpy, debug))
        return std::make_unique<EglContext>(dpy, ctx, "egl-surfaceless");
    why += " EGL surfaceless: no 4.5 core context;";
  }
  return nullptr;
}

// ---- OSMesa (dlopen'ed: its headers are not needed, the few entry points are declared here) ----

using OSMesaContextH = void*;
constexpr int OSMESA_FORMAT = 0x22, OSMESA_RGBA = 0x1908, OSMESA_DEPTH_BITS = 0x30,
              OSMESA_PROFILE = 0x33, OSMESA_CORE_PROFILE = 0x34,
              OSMESA_CONTEXT_MAJOR_VERSION = 0x36, OSMESA_CONTEXT_MINOR_VERSION = 0x37;

class OSMesaContext final : public HeadlessContext {
 public:
  using DestroyFn = void (*)(OSMesaContextH);
  OSMesaContext(void* lib, OSMesaContextH ctx, DestroyFn destroy)
      : lib_(lib), ctx_(ctx), destroy_(destroy) {}  // info_ is filled once current
  ~OSMesaContext() override {
    destroy_(ctx_);
    // The library stays loaded: Mesa does not support being unloaded and reloaded.
    (void)lib_;
  }

 private:
  void* lib_;
  OSMesaContextH ctx_;
  DestroyFn destroy_;
  // OSMesa needs a colour buffer to make a context current; we render into FBOs only.
  std::uint8_t pixel_[4] = {};
  friend std::unique_ptr<HeadlessContext> try_osmesa(bool, std::string&);
};

using GetProcFn = GLADapiproc (*)(const char*);
GetProcFn g_osmesa_get_proc = nullptr;
GLADapiproc osmesa_get_proc(const char* name) { return g_osmesa_get_proc(name); }

std::unique_ptr<HeadlessContext> try_osmesa(bool /*debug*/, std::string& why) {
  void* lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
  if (!lib) lib = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    why += " OSMesa: libOSMesa.so.8 could not be loaded;";
    return nullptr;
  }
  using CreateFn = OSMesaContextH (*)(const int*, OSMesaContextH);
  using MakeCurrentFn = unsigned char (*)(OSMesaContextH, void*, unsigned, int, int);
  auto create = reinterpret_cast<CreateFn>(dlsym(lib, "OSMesaCreateContextAttribs"));
  auto make_current = reinterpret_cast<MakeCurrentFn>(dlsym(lib, "OSMesaMakeCurrent"));
  auto destroy = reinterpret_cast<OSMesaContext::DestroyFn>(dlsym(lib, "OSMesaDestroyContext"));
  g_osmesa_get_proc = reinterpret_cast<GetProcFn>(dlsym(lib, "OSMesaGetProcAddress"));
  if (!create || !make_current || !destroy || !g_osmesa_get_proc) {
    why += " OSMesa: entry points missing;";
    return nullptr;
  }
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
  OSMesaContextH ctx = create(attribs, nullptr);
  if (!ctx) {
    why += " OSMesa: no 4.5 core context;";
    return nullptr;
  }
  auto result = std::make_unique<OSMesaContext>(lib, ctx, destroy);
  if (!make_current(ctx, result->pixel_, GL_UNSIGNED_BYTE, 1, 1) || !gladLoadGL(osmesa_get_proc)) {
    why += " OSMesa: could not make the context current;";
    return nullptr;
  }
  result->info_ = fill_info("osmesa");
  return result;
}

bool is_45_core() {
  GLint major = 0, minor = 0, mask = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
  return (major > 4 || (major == 4 && minor >= 5)) && (mask & GL_CONTEXT_CORE_PROFILE_BIT);
}

}  // namespace

ContextInfo query_current_context(const std::string& path) {
  ContextInfo info;
  auto str = [](GLenum e) {
    const GLubyte* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  info.renderer = str(GL_RENDERER);
  info.version = str(GL_VERSION);
  info.vendor = str(GL_VENDOR);
  info.software = info.renderer.find("llvmpipe") != std::string::npos ||
                  info.renderer.find("softpipe") != std::string::npos ||
                  info.renderer.find("swrast") != std::string::npos;
  info.path = path;
  return info;
}

std::unique_ptr<HeadlessContext> HeadlessContext::create(Backend backend, bool debug) {
  std::string why;
  std::unique_ptr<HeadlessContext> ctx;
  if (backend == Backend::Auto || backend == Backend::Egl) ctx = try_egl(debug, why);
  if (!ctx && (backend == Backend::Auto || backend == Backend::OSMesa)) ctx = try_osmesa(debug, why);
  if (ctx && !is_45_core()) {
    why += " the context is not OpenGL 4.5 core (" + ctx->info().version + ");";
    ctx.reset();
  }
  if (!ctx) {
    if (!why.empty() && why.back() == ';') why.pop_back();
    throw RuntimeError("no OpenGL 4.5 core context could be created:" + why + ".");
  }
  return ctx;
}

namespace {
constexpr std::pair<Backend, const char*> kBackendNames[] = {
    {Backend::Auto, "auto"}, {Backend::Egl, "egl"}, {Backend::OSMesa, "osmesa"}};
}  // namespace

std::string backend_names() {
  std::string out;
  for (const auto& [b, n] : kBackendNames) out += (out.empty() ? "" : "|") + std::string(n);
  return out;
}

Backend parse_backend(const std::string& s) {
  for (const auto& [b, n] : kBackendNames)
    if (s == n) return b;
  throw InputError("unknown GL path '" + s + "' (one of " + backend_names() + ").");
}

namespace {
// Errors are recorded, not thrown: the callback runs inside the driver, which is C code.
std::vector<std::string> g_errors;
bool g_verbose = false;
void GLAPIENTRY debug_callback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                               const GLchar* message, const void*) {
  if (type == GL_DEBUG_TYPE_ERROR) {
    if (g_errors.size() < 64) g_errors.emplace_back(message);
  }
  if (g_verbose && severity != GL_DEBUG_SEVERITY_NOTIFICATION)
    std::fprintf(stderr, "GL debug: %s\n", message);
}
}  // namespace

void enable_debug_output(bool verbose) {
  g_verbose = verbose;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(debug_callback, nullptr);
}

std::vector<std::string> take_gl_errors() {
  std::vector<std::string> out;
  out.swap(g_errors);
  for (GLenum e; (e = glGetError()) != GL_NO_ERROR;) out.push_back("glGetError " + std::to_string(e));
  return out;
}

}  // namespace ssr::gl
