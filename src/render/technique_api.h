// The contract between the frame (render/) and the techniques: what a technique declares, what
// it may read for one frame, what it writes. The frame includes this header and never a
// technique; techniques (techniques/, reference/) include it and render/ headers, never the
// reverse.
//
// A technique declares (TechniqueDecl) the frame resources it reads, the outputs it writes and
// the internal textures it needs. The frame builds optional resources (back-face depth, the
// Hi-Z pyramid, history) only when a technique that runs declares them, clears the outputs a
// technique does not write, allocates its internal textures, and calls reset() when its history
// stops being valid.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/params.h"
#include "gl/program.h"
#include "gl/timer.h"
#include "render/camera.h"
#include "render/targets.h"
#include "render/views.h"
#include "scene/scene.h"

namespace ssr {

class GpuScene;

// Frame resources a technique may read (bit flags for TechniqueDecl::reads). Texture units are
// in shared/bindings.h.
enum FrameRead : std::uint32_t {
  kReadDepth = 1u << 0,            // TEX_DEPTH (D32F, reversed-Z)
  kReadNormalRoughness = 1u << 1,  // TEX_NORMAL_ROUGHNESS
  kReadAlbedoMetallic = 1u << 2,   // TEX_ALBEDO_METALLIC, TEX_MATERIAL, TEX_EMISSION
  kReadLit = 1u << 3,              // TEX_LIT: lit colour without reflections
  kReadGlass = 1u << 4,            // TEX_GLASS_DEPTH/SURFACE/TINT: transparent surfaces
  kReadBackDepth = 1u << 5,        // TEX_BACK_DEPTH: nearest back faces (built on demand)
  kReadHiz = 1u << 6,              // TEX_HIZ: the depth pyramid (built on demand)
  kReadMotion = 1u << 7,           // TEX_MOTION: motion vectors (shared/frame.h says the units)
  kReadPrevLit = 1u << 8,          // TEX_PREV_LIT: the previous frame's lit colour (history)
  kReadPrevColor = 1u << 9,        // TEX_PREV_COLOR: this technique's previous final colour
  kReadPrevDepth = 1u << 10,       // TEX_PREV_DEPTH (history)
  kReadPrevNormal = 1u << 11,      // TEX_PREV_NORMAL_ROUGHNESS (history)
  kReadReflectors = 1u << 12,      // FrameContext::scene.reflectors: the planar rectangles
};
constexpr std::uint32_t kReadGBuffer = kReadDepth | kReadNormalRoughness | kReadAlbedoMetallic;
constexpr std::uint32_t kReadHistory = kReadPrevLit | kReadPrevColor | kReadPrevDepth | kReadPrevNormal;

// An internal texture the frame allocates for a technique (one set per technique instance).
struct TextureDecl {
  std::string name;        // GL label
  GLenum format = GL_RGBA16F;
  int divisor = 1;         // size = ceil(frame size / divisor): 2 = half resolution
  bool persistent = false; // kept across frames (the technique's own history); zeroed on reset()
  bool operator==(const TextureDecl&) const = default;
};

// A debug view that shows one of the technique's own textures (a stage's output): the display
// pass samples TextureDecl number `texture` at TEX_STAGE_VIEW (views.h says how it is shown).
struct StageView {
  ViewMode view;
  int texture;
  bool operator==(const StageView&) const = default;
};

struct TechniqueDecl {
  std::uint32_t reads = kReadGBuffer | kReadLit;
  bool writes_refraction = false;     // glass pixels' refraction (IMG_REFRACTION); else cleared
  std::vector<ViewMode> debug_views;  // the debug image's views it fills (IMG_OUT2); none: cleared
  std::vector<TextureDecl> textures;  // FrameContext::textures, in this order
  // Debug views of those textures (also listed in debug_views). The renderer reads them after
  // run(): they name the textures the last run wrote (a history pair alternates).
  std::vector<StageView> stage_views;
  int blend = 0;                      // composite: 0 standard, 1 Roberts (mix(lit, refl, a))
  // Handles planar reflector pixels only (ppr without a fallback, the planar oracle): the
  // breakdown reports every other pixel as not handled instead of scoring what it leaves there.
  bool planar_only = false;
  // Its shaders record per-ray telemetry when compiled with SSR_TELEMETRY (render/telemetry.h).
  bool telemetry = false;
  // Its image changes from frame to frame on a still camera (new samples every frame, history
  // that accumulates): the viewer's figures follow it frame by frame.
  bool varies_per_frame = false;
};

// When a frame is: its index in a sequence, its time, and whether a camera cut precedes it.
// History carries from frame i to frame i + 1 only (same size, same scene, no cut).
struct FrameTime {
  int index = 0;
  float seconds = 0;
  bool cut = false;
};

struct FrameSettings {
  float exposure = 0.0f;             // stops, applied before tone mapping
  float reflective_f0 = 0.1f;        // pixels whose max F0 reaches this do reflection work
  glm::vec4 clip_plane{0, 0, 0, 1};  // world plane; the G-buffer keeps dot(plane, (p,1)) >= 0
  bool operator==(const FrameSettings&) const = default;
};
// The settings a user sets (exposure, reflective_f0; the clip plane is the planar oracle's), as a
// parameter table: the commands' --exposure, the viewer's panel, scripts and presets all check
// and describe them through it (prefix "frame").
std::span<const ParamDesc> frame_settings_table();
ParamSet frame_settings_params(FrameSettings& settings);
// Sets one ("exposure", ...) through the table: InputError naming the key (or `option`, the
// command-line option that carried the value, e.g. "--exposure") and the range.
void set_frame_setting(FrameSettings& settings, const std::string& key, double value, const std::string& option = "");
// The command-line option of a frame setting's row: "--exposure", "--reflective-f0".
std::string frame_setting_option(const ParamDesc& d);

// Everything a technique may read for one frame, and its outputs. The frame's inputs are bound
// at their named slots when run() is called; rebind() restores them (after a technique drew with
// bindings of its own).
struct FrameContext {
  int width = 0, height = 0;
  const Scene& scene;           // posed at this frame's time
  std::uint64_t geometry_id;    // changes whenever the (posed) geometry does: key caches on it
  const Camera& camera;
  const CameraMatrices& matrices;
  const FrameSettings& settings;
  FrameTime time;
  // The renderer's frame: the same again when one frame is rendered twice (the viewer showing
  // another view of it), which must not advance a technique's history a second time.
  std::uint64_t serial;
  bool history_valid;           // the history resources hold the previous frame of a sequence
  // kReadPrevColor: TEX_PREV_COLOR holds this technique's final colour of the previous frame
  // (false on the first frame, after a reset and after a cut: nothing there to read).
  bool previous_color;
  float scene_diagonal;         // world units: the scene's bounding-box diagonal ("auto" lengths)
  GLuint frame_ubo;             // FrameUniforms, bound at UBO_FRAME
  const GBuffer& gbuffer;
  const gl::Texture2D& lit;     // RGBA16F, bilinear
  const gl::Texture2D& motion;  // RG16F motion vectors
  const gl::Texture2D* hiz;     // null unless declared
  const GpuScene& gpu_scene;    // material textures (the reference shades with them)
  std::vector<gl::Texture2D*> textures;  // the declared internal textures
  gl::Texture2D* reflection;    // RGBA16F: rgb radiance, a confidence in [0,1]
  gl::Texture2D* refraction;    // RGBA16F: radiance, confidence (glass pixels)
  // RGBA16F: the debug views' channels (display.comp), bound at IMG_OUT2; null when nothing
  // reads them this frame: then a technique runs its variant that leaves them unwritten (the
  // stores and what feeds them cost linear-binary a fifth of its time on the H200).
  gl::Texture2D* debug;
  gl::PassTimer* timer;         // may be null
  std::function<void()> rebind;
};

class Technique {
 public:
  Technique();
  virtual ~Technique() = default;
  Technique(const Technique&) = delete;
  Technique& operator=(const Technique&) = delete;
  // Unique in the process: the frame keys a technique's history and textures on it.
  std::uint64_t instance_id() const { return instance_id_; }

  virtual const std::string& name() const = 0;
  // The technique's parameters; valid for the technique's lifetime. Needs no GL context.
  virtual ParamSet params() = 0;
  // The values the last run used, "auto" resolved (the image's and the scene's sizes decide
  // them): what the viewer shows beside "auto" and starts from when auto is unticked. Before a
  // run, or for a technique that resolves nothing: params().
  virtual ParamSet ran_params() { return params(); }
  // (Re)builds GL programs from `src`. Throws RuntimeError with file:line on a compile error,
  // leaving the previous programs in place.
  virtual void load(const gl::ShaderSource& src) = 0;
  // What it reads and writes with its current parameters.
  virtual TechniqueDecl declare() const = 0;
  // Writes the outputs it declares, reading only what it declares.
  virtual void run(const FrameContext& frame) = 0;
  // Forget any history: called by the frame on a camera cut, a resize, a scene change, a
  // parameter change, or when the technique skipped a frame. The frame zeroes its persistent
  // textures itself.
  virtual void reset() {}

 private:
  std::uint64_t instance_id_;
};

}  // namespace ssr
