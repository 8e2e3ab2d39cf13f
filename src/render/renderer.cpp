#include "render/renderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/errors.h"
#include "shared/bindings.h"
#include "shared/frame.h"
#include "techniques/technique.h"

namespace ssr {

const std::vector<std::string>& view_mode_names() {
  static const std::vector<std::string> names = {"final", "reflection", "confidence", "lit",
                                                 "normal", "depth", "albedo", "roughness",
                                                 "metallic", "mask", "steps", "hits", "distance",
                                                 "offsets", "holes", "reflected"};
  return names;
}

ViewMode parse_view_mode(const std::string& name) {
  const auto& names = view_mode_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<ViewMode>(i);
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
  throw InputError("unknown view '" + name + "' (known: " + known + ").");
}

Renderer::Renderer(const Scene& scene, int width, int height, gl::ShaderSource shaders)
    : scene_(scene), shaders_(std::move(shaders)) {
  static std::atomic<std::uint64_t> next_id{1};
  scene_id_ = next_id++;
  scene_diagonal_ = bounding_diagonal(scene_);
  // Reversed-Z: depth 1 at the near plane, 0 at the far plane, in [0,1] clip space.
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  reload_shaders();
  gpu_scene_ = std::make_unique<GpuScene>(scene_);
  frame_ubo_ = gl::make_buffer("frame uniforms", sizeof(shared::FrameUniforms));
  resize(width, height);
}

Renderer::~Renderer() = default;

void Renderer::set_lighting(const std::vector<Light>& lights, const Environment& environment, float ambient) {
  Scene probe;  // only the lighting part is checked: the geometry did not change
  probe.name = scene_.name;
  probe.lights = lights;
  probe.environment = environment;
  probe.ambient = ambient;
  validate_lighting(probe);
  scene_.lights = lights;
  scene_.environment = environment;
  scene_.ambient = ambient;
  gpu_scene_->upload_lights(lights);
}

void Renderer::reload_shaders() {
  // Build all first, then swap: a compile error leaves the running programs untouched.
  auto gbuffer = gl::Program::graphics(shaders_, "render/gbuffer.vert", "render/gbuffer.frag");
  auto glass = gl::Program::graphics(shaders_, "render/gbuffer.vert", "render/glass.frag");
  auto lighting = gl::Program::compute(shaders_, "render/lighting.comp");
  auto composite = gl::Program::compute(shaders_, "render/composite.comp");
  auto display = gl::Program::compute(shaders_, "render/display.comp");
  gbuffer_prog_ = std::move(gbuffer);
  glass_prog_ = std::move(glass);
  lighting_prog_ = std::move(lighting);
  composite_prog_ = std::move(composite);
  display_prog_ = std::move(display);
}

void Renderer::resize(int width, int height) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throw InputError("size " + std::to_string(width) + "x" + std::to_string(height) +
                     " is not supported by this GL (each side must be in [1, " +
                     std::to_string(max_size) + "]).");
  if (width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  gbuffer_.depth = gl::Texture2D("gbuffer depth", GL_DEPTH_COMPONENT32F, width, height);
  gbuffer_.normal_roughness = gl::Texture2D("gbuffer normal+roughness", GL_RGBA16F, width, height);
  gbuffer_.albedo_metallic = gl::Texture2D("gbuffer albedo+metallic", GL_RGBA8, width, height);
  // 16 bits a channel: the object id is a mesh index (Scene::kMaxMeshes = 65536).
  gbuffer_.material = gl::Texture2D("gbuffer material", GL_RGBA16UI, width, height);
  gbuffer_.emission = gl::Texture2D("gbuffer emission", GL_RGBA16F, width, height);
  gbuffer_.fbo = gl::Framebuffer("gbuffer");
  const GLuint fbo = gbuffer_.fbo.id();
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, gbuffer_.depth.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, gbuffer_.normal_roughness.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, gbuffer_.albedo_metallic.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, gbuffer_.material.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT3, gbuffer_.emission.id(), 0);
  const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                         GL_COLOR_ATTACHMENT3};
  glNamedFramebufferDrawBuffers(fbo, 4, bufs);
  if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw RuntimeError("the G-buffer framebuffer is incomplete at " + std::to_string(width) +
                       "x" + std::to_string(height) + ".");
  gbuffer_.back_depth = gl::Texture2D("gbuffer back-face depth", GL_DEPTH_COMPONENT32F, width, height);
  gbuffer_.back_fbo = gl::Framebuffer("gbuffer back faces");
  glNamedFramebufferTexture(gbuffer_.back_fbo.id(), GL_DEPTH_ATTACHMENT, gbuffer_.back_depth.id(), 0);
  glNamedFramebufferDrawBuffer(gbuffer_.back_fbo.id(), GL_NONE);
  gbuffer_.glass_depth = gl::Texture2D("glass depth", GL_DEPTH_COMPONENT32F, width, height);
  gbuffer_.glass_surface = gl::Texture2D("glass normal+ior", GL_RGBA16F, width, height);
  gbuffer_.glass_tint = gl::Texture2D("glass tint", GL_RGBA8, width, height);
  gbuffer_.glass_fbo = gl::Framebuffer("glass");
  glNamedFramebufferTexture(gbuffer_.glass_fbo.id(), GL_DEPTH_ATTACHMENT, gbuffer_.glass_depth.id(), 0);
  glNamedFramebufferTexture(gbuffer_.glass_fbo.id(), GL_COLOR_ATTACHMENT0, gbuffer_.glass_surface.id(), 0);
  glNamedFramebufferTexture(gbuffer_.glass_fbo.id(), GL_COLOR_ATTACHMENT1, gbuffer_.glass_tint.id(), 0);
  glNamedFramebufferDrawBuffers(gbuffer_.glass_fbo.id(), 2, bufs);
  lit_ = gl::Texture2D("lit", GL_RGBA16F, width, height);
  // Techniques fetch the lit colour at fractional hit positions: bilinear.
  glTextureParameteri(lit_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(lit_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  reflection_ = gl::Texture2D("reflection", GL_RGBA16F, width, height);
  color_ = gl::Texture2D("color", GL_RGBA16F, width, height);
  display_ = gl::Texture2D("display", GL_RGBA8, width, height);
  linear_ = gl::Texture2D("display linear", GL_RGBA16F, width, height);
  debug_ = gl::Texture2D("technique debug", GL_RGBA16F, width, height);
  refraction_ = gl::Texture2D("refraction", GL_RGBA16F, width, height);
  if (glGetError() == GL_OUT_OF_MEMORY)
    throw RuntimeError("the GL has not enough memory for " + std::to_string(width) + "x" +
                       std::to_string(height) + " targets.");
}

void Renderer::bind_frame_inputs() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, UBO_FRAME, frame_ubo_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_LIGHTS, gpu_scene_->lights_ssbo());
  glBindTextureUnit(TEX_DEPTH, gbuffer_.depth.id());
  glBindTextureUnit(TEX_NORMAL_ROUGHNESS, gbuffer_.normal_roughness.id());
  glBindTextureUnit(TEX_ALBEDO_METALLIC, gbuffer_.albedo_metallic.id());
  glBindTextureUnit(TEX_MATERIAL, gbuffer_.material.id());
  glBindTextureUnit(TEX_EMISSION, gbuffer_.emission.id());
  glBindTextureUnit(TEX_LIT, lit_.id());
  glBindTextureUnit(TEX_REFLECTION, reflection_.id());
  glBindTextureUnit(TEX_COLOR, color_.id());
  glBindTextureUnit(TEX_BACK_DEPTH, gbuffer_.back_depth.id());
  glBindTextureUnit(TEX_DEBUG, debug_.id());
  glBindTextureUnit(TEX_GLASS_DEPTH, gbuffer_.glass_depth.id());
  glBindTextureUnit(TEX_GLASS_SURFACE, gbuffer_.glass_surface.id());
  glBindTextureUnit(TEX_GLASS_TINT, gbuffer_.glass_tint.id());
  glBindTextureUnit(TEX_REFRACTION, refraction_.id());
}

void Renderer::render_backfaces() {
  // Two-sided scenes have no "inside": the back faces are those wound clockwise as seen from
  // the camera. The nearest of them bounds each front surface's thickness (2012 blog).
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_.back_fbo.id());
  glViewport(0, 0, width_, height_);
  const float depth_clear = 0.0f;
  glClearNamedFramebufferfv(gbuffer_.back_fbo.id(), GL_DEPTH, 0, &depth_clear);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glUseProgram(gbuffer_prog_.id());
  gpu_scene_->draw(/*transparent=*/false);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void Renderer::render_inputs(const Camera& camera, gl::PassTimer* timer) {
  camera_ = camera;
  matrices_ = camera_matrices(camera, width_, height_);
  shared::FrameUniforms f{};
  f.view = matrices_.view;
  f.proj = matrices_.proj;
  f.inv_view = glm::inverse(matrices_.view);
  f.inv_proj = glm::inverse(matrices_.proj);
  f.view_proj = matrices_.proj * matrices_.view;
  f.viewport = {float(width_), float(height_), 1.0f / float(width_), 1.0f / float(height_)};
  f.camera_pos = glm::vec4(camera.position, 1.0f);
  f.clip = {camera.near_plane, camera.far_plane,
            std::tan(glm::radians(camera.fov_y_deg) * 0.5f), float(width_) / float(height_)};
  const Environment& e = scene_.environment;
  const float type = e.type == Environment::Type::Constant ? 1.0f : 0.0f;
  f.env_zenith = glm::vec4(e.zenith * e.intensity, type);
  f.env_horizon = glm::vec4(e.horizon * e.intensity, 0.0f);
  f.env_ground = glm::vec4(e.ground * e.intensity, 0.0f);
  f.env_constant = glm::vec4(e.constant * e.intensity, 0.0f);
  f.settings = {scene_.ambient, settings.exposure, settings.reflective_f0, 0.0f};
  f.counts = {gpu_scene_->light_count(), static_cast<int>(scene_.reflectors.size()), frame_index_++, 0};
  f.clip_plane = settings.clip_plane;
  glNamedBufferSubData(frame_ubo_.id(), 0, sizeof f, &f);
  bind_frame_inputs();

  {
    gl::ScopedPass pass(timer, "gbuffer");
    glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_.fbo.id());
    glViewport(0, 0, width_, height_);
    const float zero[4] = {0, 0, 0, 0};
    const GLuint zero_u[4] = {0, 0, 0, 0};
    const float depth_clear = 0.0f;  // reversed-Z: far
    glClearNamedFramebufferfv(gbuffer_.fbo.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(gbuffer_.fbo.id(), GL_COLOR, 1, zero);
    glClearNamedFramebufferuiv(gbuffer_.fbo.id(), GL_COLOR, 2, zero_u);
    glClearNamedFramebufferfv(gbuffer_.fbo.id(), GL_COLOR, 3, zero);
    glClearNamedFramebufferfv(gbuffer_.fbo.id(), GL_DEPTH, 0, &depth_clear);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CLIP_DISTANCE0);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // two-sided: scenes may be seen from inside
    glDisable(GL_BLEND);
    glUseProgram(gbuffer_prog_.id());
    gpu_scene_->draw(/*transparent=*/false);
    // Transparent surfaces: their own small G-buffer, depth-tested against the opaque depth
    // (copied in first) so only glass in front of opaque geometry lands there.
    const float none[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(gbuffer_.glass_fbo.id(), GL_COLOR, 0, none);
    if (gpu_scene_->has_transparent()) {
      glCopyImageSubData(gbuffer_.depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, gbuffer_.glass_depth.id(),
                         GL_TEXTURE_2D, 0, 0, 0, 0, width_, height_, 1);
      glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_.glass_fbo.id());
      glUseProgram(glass_prog_.id());
      gpu_scene_->draw(/*transparent=*/true);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CLIP_DISTANCE0);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  {
    gl::ScopedPass pass(timer, "lighting");
    glBindImageTexture(IMG_OUT, lit_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    lighting_prog_.dispatch_2d(width_, height_);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void Renderer::run_technique(Technique& technique, gl::PassTimer* timer) {
  if (technique.needs_backfaces()) {
    bind_frame_inputs();
    gl::ScopedPass pass(timer, "backfaces");
    render_backfaces();
  }
  const float zero[4] = {0, 0, 0, 0};
  if (!technique.writes_debug()) glClearTexImage(debug_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  if (!technique.writes_refraction()) glClearTexImage(refraction_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  blend_ = technique.composite_blend();
  bind_frame_inputs();
  glBindImageTexture(IMG_OUT2, debug_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(IMG_REFRACTION, refraction_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  TechniqueInputs in{*this, gbuffer_, lit_, frame_ubo_.id(), width_, height_, scene_, timer, scene_diagonal_};
  technique.run(in, reflection_);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void Renderer::composite_and_display(ViewMode view, gl::PassTimer* timer) {
  bind_frame_inputs();
  {
    gl::ScopedPass pass(timer, "composite");
    glBindImageTexture(IMG_OUT, color_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glProgramUniform1i(composite_prog_.id(), 0, blend_);
    composite_prog_.dispatch_2d(width_, height_);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  {
    gl::ScopedPass pass(timer, "display");
    glBindImageTexture(IMG_OUT, display_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glBindImageTexture(IMG_OUT2, linear_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glProgramUniform1i(display_prog_.id(), 0, static_cast<int>(view));
    display_prog_.dispatch_2d(width_, height_);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

void Renderer::render(const Camera& camera, Technique& technique, ViewMode view,
                      gl::PassTimer* timer) {
  render_inputs(camera, timer);
  run_technique(technique, timer);
  composite_and_display(view, timer);
}

namespace {
template <class T>
void flip_rows(std::vector<T>& px, int width, int height, int channels) {
  const std::size_t row = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(px.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)),
                     px.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y + 1)),
                     px.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - 1 - y)));
}
}  // namespace

RgbaImage8 Renderer::read_display() const {
  RgbaImage8 im{width_, height_, {}};
  im.pixels.resize(static_cast<std::size_t>(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(display_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    static_cast<GLsizei>(im.pixels.size()), im.pixels.data());
  flip_rows(im.pixels, width_, height_, 4);
  return im;
}

RgbaImageF Renderer::read_texture(const gl::Texture2D& tex) const {
  RgbaImageF im{tex.width(), tex.height(), {}};
  im.pixels.resize(static_cast<std::size_t>(tex.width()) * tex.height() * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(tex.id(), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(im.pixels.size() * sizeof(float)), im.pixels.data());
  flip_rows(im.pixels, tex.width(), tex.height(), 4);
  return im;
}

std::vector<std::uint16_t> Renderer::read_material() const {
  std::vector<std::uint16_t> m(static_cast<std::size_t>(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glGetTextureImage(gbuffer_.material.id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT,
                    static_cast<GLsizei>(m.size() * sizeof(std::uint16_t)), m.data());
  flip_rows(m, width_, height_, 4);
  return m;
}

RgbaImageF Renderer::read_linear() const { return read_texture(linear_); }

std::vector<float> Renderer::read_depth() const {
  std::vector<float> d(static_cast<std::size_t>(width_) * height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(gbuffer_.depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(d.size() * sizeof(float)), d.data());
  flip_rows(d, width_, height_, 1);
  return d;
}

}  // namespace ssr
