// The deferred frame (DESIGN §1): G-buffer -> lighting -> technique -> composite -> display.
//
// The Renderer owns every target at one size and the programs of the fixed passes; the
// technique is passed in per frame so that several techniques can run on the same frame inputs.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "gl/program.h"
#include "gl/timer.h"
#include "render/camera.h"
#include "render/gpu_scene.h"
#include "render/targets.h"
#include "scene/scene.h"
#include "shared/display.h"

namespace ssr {

class Technique;

enum class ViewMode : int {
  Final = VIEW_FINAL, Reflection = VIEW_REFLECTION, Confidence = VIEW_CONFIDENCE,
  Lit = VIEW_LIT, Normal = VIEW_NORMAL, Depth = VIEW_DEPTH, Albedo = VIEW_ALBEDO,
  Roughness = VIEW_ROUGHNESS, Metallic = VIEW_METALLIC, Mask = VIEW_MASK,
  Steps = VIEW_STEPS, Hits = VIEW_HITS, Distance = VIEW_DISTANCE, Offsets = VIEW_OFFSETS,
  Holes = VIEW_HOLES, Reflected = VIEW_REFLECTED,
};
// Names as the CLI takes them ("final", "reflection", ...), in enum order.
const std::vector<std::string>& view_mode_names();
ViewMode parse_view_mode(const std::string& name);  // throws InputError

struct FrameSettings {
  float exposure = 0.0f;             // stops, applied before tone mapping
  float reflective_f0 = 0.1f;        // pixels whose max F0 reaches this do reflection work
  glm::vec4 clip_plane{0, 0, 0, 1};  // world plane; the G-buffer keeps dot(plane, (p,1)) >= 0
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
  // Unique for every Renderer (and so every scene upload) in the process: techniques that cache
  // per-scene data key it on this, never on an address that a later scene may reuse.
  std::uint64_t scene_id() const { return scene_id_; }
  // The diagonal of the scene's bounding box (world units): "auto" ray lengths.
  float scene_diagonal() const { return scene_diagonal_; }
  const gl::ShaderSource& shaders() const { return shaders_; }
  // Replaces the lights, environment and ambient (live editing); the geometry stays. Throws
  // InputError, changing nothing, when the result would not pass validate().
  void set_lighting(const std::vector<Light>& lights, const Environment& environment, float ambient);
  // Rebuilds the fixed passes' programs (live reload); keeps the old ones on failure and throws.
  void reload_shaders();

  FrameSettings settings;

  // Runs G-buffer + lighting for `camera`, then the technique, composite and display.
  void render(const Camera& camera, Technique& technique, ViewMode view, gl::PassTimer* timer);
  // The passes before the technique, and the ones after, for callers that run several
  // techniques on the same frame inputs.
  void render_inputs(const Camera& camera, gl::PassTimer* timer);
  void run_technique(Technique& technique, gl::PassTimer* timer);
  void composite_and_display(ViewMode view, gl::PassTimer* timer);

  const GBuffer& gbuffer() const { return gbuffer_; }
  const gl::Texture2D& lit() const { return lit_; }
  const gl::Texture2D& reflection() const { return reflection_; }
  const gl::Texture2D& debug() const { return debug_; }  // RGBA16F: steps, hit share, distance
  const gl::Texture2D& refraction() const { return refraction_; }  // RGBA16F: radiance, confidence
  const gl::Texture2D& color() const { return color_; }
  const gl::Texture2D& display() const { return display_; }  // RGBA8 (sRGB values)
  const CameraMatrices& matrices() const { return matrices_; }
  const Camera& camera() const { return camera_; }
  const GpuScene& gpu_scene() const { return *gpu_scene_; }
  GLuint frame_ubo() const { return frame_ubo_.id(); }
  // Binds the frame UBO, lights and every target at their named slots (DESIGN: shared/bindings.h).
  void bind_frame_inputs() const;

  RgbaImage8 read_display() const;
  RgbaImageF read_linear() const;              // the displayed view's linear values
  RgbaImageF read_texture(const gl::Texture2D& tex) const;  // any float-readable target
  std::vector<float> read_depth() const;       // reversed-Z, row 0 = top
  // The G-buffer's material target, 4 values a pixel (reflector id, reflectance*255, flags,
  // object id), row 0 = top.
  std::vector<std::uint16_t> read_material() const;

 private:
  Scene scene_;
  gl::ShaderSource shaders_;
  std::unique_ptr<GpuScene> gpu_scene_;
  int width_ = 0, height_ = 0;
  GBuffer gbuffer_;
  gl::Texture2D lit_, reflection_, color_, display_, linear_, debug_, refraction_;
  void render_backfaces();
  gl::Buffer frame_ubo_;
  gl::Program gbuffer_prog_, glass_prog_, lighting_prog_, composite_prog_, display_prog_;
  CameraMatrices matrices_{};
  int blend_ = 0;  // the last technique's composite blend
  Camera camera_{};
  int frame_index_ = 0;
  std::uint64_t scene_id_ = 0;
  float scene_diagonal_ = 0;
};

}  // namespace ssr
