// The deferred frame (ARCHITECTURE §1). Renderer::render is the frame, as its pass list:
//   G-buffer (+ motion vectors) -> lighting -> [back faces] [Hi-Z] -> technique -> composite ->
//   display -> history
// The bracketed passes run only when the technique declares their resources (technique_api.h).
// The inputs (G-buffer, lighting) are rendered once per frame: several techniques may run on
// one frame (compare, the viewer's split), each rendering through the same function.
//
// The Renderer owns every frame target at one size, the history (previous-frame targets,
// swapped each frame) and, per technique instance, its declared internal textures and its
// previous composited colour.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/image.h"
#include "gl/program.h"
#include "gl/timer.h"
#include "render/camera.h"
#include "render/gpu_scene.h"
#include "render/hiz_pyramid.h"
#include "render/targets.h"
#include "render/technique_api.h"
#include "render/telemetry.h"
#include "render/views.h"
#include "scene/scene.h"

namespace ssr {

// The frame's own timed passes: what every technique pays, not part of its time (bench's
// technique time, the viewer's plots).
inline constexpr const char* kFramePasses[] = {"gbuffer", "lighting", "composite", "display"};
// The first kFrameInputPasses of them draw the frame's inputs: once a frame, under the first
// technique rendered (render_inputs()); the others run with every technique.
inline constexpr std::size_t kFrameInputPasses = 2;
// The technique's time: one span around everything it costs, the inputs it declares (back
// faces, the Hi-Z pyramid) and its own passes, which nest inside the span.
inline constexpr const char* kTechniqueSpan = "technique";
// The technique span's time in a frame's timings (0 if the frame did not run the technique).
double technique_ms(const gl::FrameTimes& frame);

// One frame to render: a camera at a time. Consecutive indices (with no cut) carry history.
struct FrameRequest {
  FrameRequest(const Camera& c, FrameTime t = {}) : camera(c), time(t) {}  // NOLINT: implicit
  Camera camera;
  FrameTime time;
};

class Renderer {
 public:
  // Needs a current GL 4.5 context. `shaders` is where programs come from (embedded or a dir).
  Renderer(const Scene& scene, int width, int height, gl::ShaderSource shaders = gl::ShaderSource());
  ~Renderer();

  // Throws InputError when the GL cannot hold the size (0, or above GL_MAX_TEXTURE_SIZE).
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  const Scene& scene() const { return scene_; }
  // Unique for every Renderer (and so every scene upload) in the process: caches key on this,
  // never on an address that a later scene may reuse.
  std::uint64_t scene_id() const { return scene_id_; }
  // The diagonal of the scene's bounding box (world units): "auto" ray lengths.
  float scene_diagonal() const { return scene_diagonal_; }
  const gl::ShaderSource& shaders() const { return shaders_; }
  // Replaces the lights, environment and ambient (live editing); the geometry stays. Throws
  // InputError, changing nothing, when the result would not pass validate(). Resets history.
  void set_lighting(const std::vector<Light>& lights, const Environment& environment, float ambient);
  // Rebuilds the fixed passes' programs (live reload); keeps the old ones on failure and throws.
  void reload_shaders();

  FrameSettings settings;
  // Techniques write their debug image (debug()) on every frame, not only when the view shown is
  // one of its debug views: for whoever reads it outside render() (the viewer's inspector).
  bool debug_outputs = false;

  // The frame: renders `request`'s inputs unless they are this frame's already, then runs the
  // technique, composites and displays `view`.
  void render(const FrameRequest& request, Technique& technique, ViewMode view, gl::PassTimer* timer);
  // The input passes only (G-buffer, motion, lighting): for a frame that no technique runs on
  // (the planar oracle's mirrored views). A no-op when `request` is the current frame.
  void render_inputs(const FrameRequest& request, gl::PassTimer* timer);
  // Composites the current reflection and refraction targets again (with the last technique's
  // blend) and displays `view`: to show another view of the same frame, or an image copied in.
  void redisplay(ViewMode view, gl::PassTimer* timer = nullptr);
  // Displays `color` (a composited colour of this frame's size: an earlier run's copy) in the
  // final view at the current exposure, without running anything: the viewer's slow on-demand
  // reference keeps its image when only the exposure moves.
  void display_color(const gl::Texture2D& color, gl::PassTimer* timer = nullptr);

  const GBuffer& gbuffer() const { return gbuffer_; }
  const gl::Texture2D& lit() const { return lit_; }
  const gl::Texture2D& motion() const { return motion_; }
  const gl::Texture2D& reflection() const { return reflection_; }
  const gl::Texture2D& debug() const { return debug_; }  // RGBA16F: the debug views' channels
  // Whether the last frame's technique wrote debug() (it has debug views, and they were asked for).
  bool debug_written() const { return debug_written_; }
  const gl::Texture2D& refraction() const { return refraction_; }  // RGBA16F: radiance, confidence
  // Whoever writes debug() or refraction() outside a technique says so: the next technique that
  // does not write them then gets them cleared (technique_pass clears them only when dirty).
  void outputs_written() { debug_dirty_ = refraction_dirty_ = true; }
  const gl::Texture2D& color() const { return color_; }
  const gl::Texture2D& display() const { return display_; }  // RGBA8 (sRGB values)
  // The previous frame's targets (null until some technique declared them).
  const gl::Texture2D* prev_lit() const { return history_ ? &history_->lit : nullptr; }
  const gl::Texture2D* prev_depth() const { return history_ ? &history_->depth : nullptr; }
  const gl::Texture2D* prev_normal_roughness() const { return history_ ? &history_->normal_roughness : nullptr; }
  // Whether this frame's history resources hold the previous frame (false on the first frame, a
  // cut, a resize, a skipped index, a scene change).
  bool history_valid() const { return *history_break_ == '\0'; }
  // Why it does not ("" when it does): "the first frame", "the image size changed", "a camera
  // cut", ... (the viewer says it: a layout switch to or from the grid's cells is a resize).
  const char* history_break() const { return history_break_; }
  const CameraMatrices& matrices() const { return matrices_; }
  const Camera& camera() const { return camera_; }
  const FrameTime& frame_time() const { return time_; }
  const GpuScene& gpu_scene() const { return *gpu_scene_; }
  // The scene posed at the current frame's time (the scene itself when nothing moves).
  const Scene& posed_scene() const { return posed_ ? *posed_ : scene_; }
  GLuint frame_ubo() const { return frame_ubo_.id(); }
  // Binds the frame UBO, lights and every target at their named slots (shared/bindings.h).
  void bind_frame_inputs() const;

  // What an instrumented technique (SSR_TELEMETRY) records: begin() it before rendering with
  // one; the telemetry views show its per-pixel words.
  TelemetryBuffer& telemetry() { return telemetry_; }

  RgbaImage8 read_display() const;
  RgbaImageF read_linear() const;              // the displayed view's linear values
  RgbaImageF read_texture(const gl::Texture2D& tex) const;  // any float-readable target
  std::vector<float> read_depth() const;       // reversed-Z, row 0 = top
  // The G-buffer's material target, 4 values a pixel (reflector id, reflectance*255, flags,
  // object id), row 0 = top.
  std::vector<std::uint16_t> read_material() const;

 private:
  struct History {
    gl::Texture2D lit, depth, normal_roughness;
  };
  // Per technique instance: its declared textures and its previous composited colour.
  struct TechniqueState {
    std::uint64_t serial = 0;          // the frame it last ran on
    std::string params;                // its parameters then (a change resets it)
    int width = 0, height = 0;
    std::uint64_t generation = 0;
    std::vector<TextureDecl> decls;
    std::vector<gl::Texture2D> textures;
    // kReadPrevColor: the final colour of the frame before (TEX_PREV_COLOR), and this frame's,
    // kept after each run and swapped in when the next frame begins (a second run of one frame
    // still reads the frame before).
    gl::Texture2D prev_color, next_color;
    bool prev_color_valid = false, next_color_kept = false;
  };

  bool is_current(const FrameRequest& request) const;
  void sync_exposure();  // the frame uniforms' exposure to `settings`' (the display's alone)
  void begin_frame(const FrameRequest& request);
  void gbuffer_pass(gl::PassTimer* timer);
  void lighting_pass(gl::PassTimer* timer);
  void backface_pass(gl::PassTimer* timer);
  void hiz_pass(gl::PassTimer* timer);
  void ensure_history();
  TechniqueState& technique_state(Technique& t, const TechniqueDecl& decl);
  // `debug`: something reads the debug image this frame (FrameContext::debug).
  void technique_pass(Technique& t, const TechniqueDecl& decl, TechniqueState& state, bool debug,
                      gl::PassTimer* timer);
  void composite_pass(int blend, gl::PassTimer* timer);
  void display_pass(ViewMode view, gl::PassTimer* timer);
  void keep_color(TechniqueState& state);
  void attach_gbuffer();

  Scene scene_;
  gl::ShaderSource shaders_;
  TelemetryBuffer telemetry_;
  std::unique_ptr<GpuScene> gpu_scene_;
  std::unique_ptr<Scene> posed_;  // the scene at posed_time_ (only for scenes with moving objects)
  float posed_time_ = 0;
  int width_ = 0, height_ = 0;
  GBuffer gbuffer_;
  gl::Texture2D lit_, motion_, reflection_, color_, display_, linear_, debug_, refraction_;
  // debug_ / refraction_ may hold something other than zeros (technique_pass clears them for a
  // technique that does not write them).
  bool debug_dirty_ = true, refraction_dirty_ = true;
  bool debug_written_ = false;
  std::optional<History> history_;
  gl::Buffer frame_ubo_;
  gl::Program gbuffer_prog_, glass_prog_, lighting_prog_, composite_prog_, display_prog_;
  HizPyramid hiz_;
  CameraMatrices matrices_{};
  std::vector<glm::mat4> models_;  // per mesh, this frame's animation transforms (empty: static)
  int blend_ = 0;  // the last technique's composite blend
  Camera camera_{};
  FrameTime time_{};
  FrameSettings frame_settings_{};  // the settings the current inputs were rendered with
  bool inputs_valid_ = false;       // the targets hold the frame described by camera_/time_
  const char* inputs_lost_ = "the first frame";  // why inputs_valid_ went false
  const char* history_break_ = "the first frame";  // "" while the history holds the frame before
  // The last technique's stage views: the texture each shows (display_pass binds it).
  std::vector<std::pair<ViewMode, GLuint>> stage_views_;
  bool backfaces_built_ = false, hiz_built_ = false;  // this frame's on-demand resources
  std::uint64_t serial_ = 0;        // frames begun
  std::uint64_t generation_ = 1;    // bumped by anything that invalidates history
  std::uint64_t geometry_id_ = 0;
  std::map<std::uint64_t, TechniqueState> states_;
  std::uint64_t scene_id_ = 0;
  float scene_diagonal_ = 0;
};

}  // namespace ssr
