#include "render/renderer.h"

#include "gl/readback.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "core/errors.h"
#include "scene/animation.h"
#include "shared/bindings.h"
#include "shared/frame.h"

namespace ssr {

double technique_ms(const gl::FrameTimes& frame) {
  for (const gl::PassTime& p : frame)
    if (p.depth == 0 && p.name == kTechniqueSpan) return p.ms;
  return 0.0;
}

namespace {
std::uint64_t next_id() {
  static std::atomic<std::uint64_t> id{1};
  return id++;
}

bool same_camera(const Camera& a, const Camera& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up &&
         a.fov_y_deg == b.fov_y_deg && a.near_plane == b.near_plane && a.far_plane == b.far_plane;
}

// The parameter values, bit for bit: a change of any of them resets the technique's history.
std::string param_signature(ParamSet p) {
  std::string s;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double v = p.get(i);
    s.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  return s;
}

void clear_texture(const gl::Texture2D& t) {
  const float zero[4] = {0, 0, 0, 0};
  const GLuint zero_u[4] = {0, 0, 0, 0};
  const bool integer = t.format() == GL_R32UI || t.format() == GL_RGBA16UI || t.format() == GL_RG32UI;
  if (integer) glClearTexImage(t.id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, zero_u);
  else if (t.format() == GL_DEPTH_COMPONENT32F) glClearTexImage(t.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, zero);
  else glClearTexImage(t.id(), 0, GL_RGBA, GL_FLOAT, zero);
}

void copy_texture(const gl::Texture2D& from, const gl::Texture2D& to) {
  glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, 0, 0, 0, to.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                     from.width(), from.height(), 1);
}
}  // namespace

Renderer::Renderer(const Scene& scene, int width, int height, gl::ShaderSource shaders)
    : scene_(scene), shaders_(std::move(shaders)) {
  scene_id_ = next_id();
  geometry_id_ = scene_id_;
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
  if (posed_) {
    posed_->lights = lights;
    posed_->environment = environment;
    posed_->ambient = ambient;
  }
  gpu_scene_->upload_lights(lights);
  ++generation_;
  inputs_valid_ = false;
  inputs_lost_ = "the lighting changed";
}

void Renderer::reload_shaders() {
  // Build all first, then swap: a compile error leaves the running programs untouched.
  auto gbuffer = gl::Program::graphics(shaders_, "render/gbuffer.vert", "render/gbuffer.frag");
  auto glass = gl::Program::graphics(shaders_, "render/gbuffer.vert", "render/glass.frag");
  auto lighting = gl::Program::compute(shaders_, "render/lighting.comp");
  auto composite = gl::Program::compute(shaders_, "render/composite.comp");
  auto display = gl::Program::compute(shaders_, "render/display.comp");
  HizPyramid hiz;
  hiz.load(shaders_);
  gbuffer_prog_ = std::move(gbuffer);
  glass_prog_ = std::move(glass);
  lighting_prog_ = std::move(lighting);
  composite_prog_ = std::move(composite);
  display_prog_ = std::move(display);
  hiz_ = std::move(hiz);
  inputs_valid_ = false;
  inputs_lost_ = "the shaders were reloaded";
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
  motion_ = gl::Texture2D("gbuffer motion", GL_RG16F, width, height);
  gbuffer_.fbo = gl::Framebuffer("gbuffer");
  attach_gbuffer();
  if (glCheckNamedFramebufferStatus(gbuffer_.fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
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
  const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferTexture(gbuffer_.glass_fbo.id(), GL_DEPTH_ATTACHMENT, gbuffer_.glass_depth.id(), 0);
  glNamedFramebufferTexture(gbuffer_.glass_fbo.id(), GL_COLOR_ATTACHMENT0, gbuffer_.glass_surface.id(), 0);
  glNamedFramebufferTexture(gbuffer_.glass_fbo.id(), GL_COLOR_ATTACHMENT1, gbuffer_.glass_tint.id(), 0);
  glNamedFramebufferDrawBuffers(gbuffer_.glass_fbo.id(), 2, bufs);
  lit_ = gl::Texture2D("lit", GL_RGBA16F, width, height);
  reflection_ = gl::Texture2D("reflection", GL_RGBA16F, width, height);
  color_ = gl::Texture2D("color", GL_RGBA16F, width, height);
  display_ = gl::Texture2D("display", GL_RGBA8, width, height);
  linear_ = gl::Texture2D("display linear", GL_RGBA16F, width, height);
  debug_ = gl::Texture2D("technique debug", GL_RGBA16F, width, height);
  refraction_ = gl::Texture2D("refraction", GL_RGBA16F, width, height);
  debug_dirty_ = refraction_dirty_ = true;  // undefined until written or cleared
  debug_written_ = false;
  // Techniques fetch the lit colour at fractional hit positions: bilinear.
  glTextureParameteri(lit_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(lit_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  history_.reset();  // reallocated at the new size when a technique next declares it
  ++generation_;
  inputs_valid_ = false;
  inputs_lost_ = "the image size changed";
  if (glGetError() == GL_OUT_OF_MEMORY)
    throw RuntimeError("the GL has not enough memory for " + std::to_string(width) + "x" +
                       std::to_string(height) + " targets.");
}

// The G-buffer's attachments: again after each history swap (the depth and normal targets
// trade places with the previous frame's).
void Renderer::attach_gbuffer() {
  const GLuint fbo = gbuffer_.fbo.id();
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, gbuffer_.depth.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, gbuffer_.normal_roughness.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, gbuffer_.albedo_metallic.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, gbuffer_.material.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT3, gbuffer_.emission.id(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT4, motion_.id(), 0);
  const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                         GL_COLOR_ATTACHMENT3, GL_COLOR_ATTACHMENT4};
  glNamedFramebufferDrawBuffers(fbo, 5, bufs);
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
  glBindTextureUnit(TEX_MOTION, motion_.id());
  if (hiz_built_) glBindTextureUnit(TEX_HIZ, hiz_.texture().id());
  if (history_) {
    glBindTextureUnit(TEX_PREV_LIT, history_->lit.id());
    glBindTextureUnit(TEX_PREV_DEPTH, history_->depth.id());
    glBindTextureUnit(TEX_PREV_NORMAL_ROUGHNESS, history_->normal_roughness.id());
  }
}

// ---- The frame -------------------------------------------------------------------------------

void Renderer::render(const FrameRequest& request, Technique& technique, ViewMode view,
                      gl::PassTimer* timer) {
  render_inputs(request, timer);  // G-buffer + motion, lighting (once per frame)
  // What techniques derive from the inputs (back faces, the depth pyramid) is built inside each
  // one's span, so its time counts it: the viewer's B found A's pyramid built and looked faster.
  backfaces_built_ = hiz_built_ = false;
  const TechniqueDecl decl = technique.declare();
  if (decl.reads & (kReadPrevLit | kReadPrevDepth | kReadPrevNormal)) ensure_history();
  TechniqueState& state = technique_state(technique, decl);
  {
    gl::ScopedPass span(timer, kTechniqueSpan);
    if (decl.reads & kReadBackDepth) backface_pass(timer);
    if (decl.reads & kReadHiz) hiz_pass(timer);
    technique_pass(technique, decl, state, debug_outputs || view_info(view).debug, timer);
  }
  composite_pass(decl.blend, timer);
  display_pass(view, timer);
  if (decl.reads & kReadPrevColor) keep_color(state);
}

namespace {
// The settings the frame's inputs and the techniques depend on: all but the exposure, which only
// the display pass applies (moving its slider keeps the frame, and every history with it).
bool same_inputs(FrameSettings a, const FrameSettings& b) {
  a.exposure = b.exposure;
  return a == b;
}
}  // namespace

void Renderer::render_inputs(const FrameRequest& request, gl::PassTimer* timer) {
  if (is_current(request)) {
    sync_exposure();
    return;
  }
  begin_frame(request);
  gbuffer_pass(timer);
  lighting_pass(timer);
  // Without a previous frame the history holds this one: reprojection reads the identity.
  if (history_ && !history_valid()) {
    copy_texture(lit_, history_->lit);
    copy_texture(gbuffer_.depth, history_->depth);
    copy_texture(gbuffer_.normal_roughness, history_->normal_roughness);
  }
}

void Renderer::sync_exposure() {
  if (settings.exposure == frame_settings_.exposure) return;
  frame_settings_.exposure = settings.exposure;
  glNamedBufferSubData(frame_ubo_.id(), offsetof(shared::FrameUniforms, settings) + sizeof(float), sizeof(float),
                       &settings.exposure);  // settings.y
}

void Renderer::display_color(const gl::Texture2D& color, gl::PassTimer* timer) {
  sync_exposure();
  copy_texture(color, color_);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  display_pass(ViewMode::Final, timer);
}

void Renderer::redisplay(ViewMode view, gl::PassTimer* timer) {
  composite_pass(blend_, timer);
  display_pass(view, timer);
}

bool Renderer::is_current(const FrameRequest& r) const {
  return inputs_valid_ && same_camera(r.camera, camera_) && r.time.index == time_.index &&
         r.time.seconds == time_.seconds && r.time.cut == time_.cut && same_inputs(settings, frame_settings_);
}

void Renderer::begin_frame(const FrameRequest& request) {
  // History carries over only to the next index of the same sequence, at the same size, in the
  // same scene, with nothing between them that invalidates it.
  const bool continues = serial_ > 0 && inputs_valid_ && request.time.index == time_.index + 1 &&
                         !request.time.cut && same_inputs(settings, frame_settings_);
  const char* why_not = continues                                ? ""
                        : serial_ == 0                          ? "the first frame"
                        : !inputs_valid_                        ? inputs_lost_
                        : request.time.cut                      ? "a camera cut"
                        : request.time.index != time_.index + 1 ? "not the next frame of a sequence"
                                                                : "the frame settings changed";
  const float previous_seconds = time_.seconds;
  const glm::mat4 previous_view_proj = matrices_.proj * matrices_.view;
  const glm::mat4 previous_view = matrices_.view;

  camera_ = request.camera;
  time_ = request.time;
  matrices_ = camera_matrices(camera_, width_, height_);
  const bool moving = !scene_.animation.objects.empty();
  std::vector<glm::mat4> prev_models = models_;
  if (moving && (!posed_ || posed_time_ != time_.seconds)) {
    // A new pose (only when the time changed: caches keyed on geometry_id_ stay valid).
    models_ = mesh_transforms(scene_, time_.seconds);
    posed_ = std::make_unique<Scene>(ssr::posed_scene(scene_, time_.seconds));
    posed_time_ = time_.seconds;
    geometry_id_ = next_id();
  }
  if (!continues) prev_models = models_;  // no previous frame: no object motion either
  gpu_scene_->set_transforms(models_, prev_models);
  if (history_ && continues) {
    // The ring: this frame renders into last frame's history targets.
    std::swap(lit_, history_->lit);
    std::swap(gbuffer_.depth, history_->depth);
    std::swap(gbuffer_.normal_roughness, history_->normal_roughness);
    attach_gbuffer();
  }
  history_break_ = why_not;
  ++serial_;
  frame_settings_ = settings;
  inputs_valid_ = true;
  backfaces_built_ = hiz_built_ = false;
  // States of techniques that did not run on the last frame have no history left to keep.
  std::erase_if(states_, [&](const auto& kv) { return kv.second.serial + 2 <= serial_; });

  shared::FrameUniforms f{};
  f.view = matrices_.view;
  f.proj = matrices_.proj;
  f.inv_view = glm::inverse(matrices_.view);
  f.inv_proj = glm::inverse(matrices_.proj);
  f.view_proj = matrices_.proj * matrices_.view;
  f.viewport = {float(width_), float(height_), 1.0f / float(width_), 1.0f / float(height_)};
  f.camera_pos = glm::vec4(camera_.position, 1.0f);
  f.clip = {camera_.near_plane, camera_.far_plane,
            std::tan(glm::radians(camera_.fov_y_deg) * 0.5f), float(width_) / float(height_)};
  const Environment& e = scene_.environment;
  const float type = e.type == Environment::Type::Constant ? 1.0f : 0.0f;
  f.env_zenith = glm::vec4(e.zenith * e.intensity, type);
  f.env_horizon = glm::vec4(e.horizon * e.intensity, 0.0f);
  f.env_ground = glm::vec4(e.ground * e.intensity, 0.0f);
  f.env_constant = glm::vec4(e.constant * e.intensity, 0.0f);
  f.settings = {scene_.ambient, settings.exposure, settings.reflective_f0, 0.0f};
  f.counts = {gpu_scene_->light_count(), static_cast<int>(scene_.reflectors.size()), time_.index, 0};
  f.clip_plane = settings.clip_plane;
  f.prev_view_proj = continues ? previous_view_proj : f.view_proj;
  f.prev_view = continues ? previous_view : f.view;
  f.time = {time_.seconds, continues ? time_.seconds - previous_seconds : 0.0f, continues ? 1.0f : 0.0f, 0.0f};
  glNamedBufferSubData(frame_ubo_.id(), 0, sizeof f, &f);
}

void Renderer::gbuffer_pass(gl::PassTimer* timer) {
  bind_frame_inputs();
  gl::ScopedPass pass(timer, kFramePasses[0]);  // gbuffer
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_.fbo.id());
  glViewport(0, 0, width_, height_);
  const float zero[4] = {0, 0, 0, 0};
  const GLuint zero_u[4] = {0, 0, 0, 0};
  const float depth_clear = 0.0f;  // reversed-Z: far
  for (int i : {0, 1, 3, 4}) glClearNamedFramebufferfv(gbuffer_.fbo.id(), GL_COLOR, i, zero);
  glClearNamedFramebufferuiv(gbuffer_.fbo.id(), GL_COLOR, 2, zero_u);
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
  glClearNamedFramebufferfv(gbuffer_.glass_fbo.id(), GL_COLOR, 0, zero);
  if (gpu_scene_->has_transparent()) {
    copy_texture(gbuffer_.depth, gbuffer_.glass_depth);
    glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_.glass_fbo.id());
    glUseProgram(glass_prog_.id());
    gpu_scene_->draw(/*transparent=*/true);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CLIP_DISTANCE0);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void Renderer::lighting_pass(gl::PassTimer* timer) {
  bind_frame_inputs();
  gl::ScopedPass pass(timer, kFramePasses[1]);  // lighting
  glBindImageTexture(IMG_OUT, lit_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(IMG_MOTION, motion_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG16F);
  lighting_prog_.dispatch_2d(width_, height_);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void Renderer::backface_pass(gl::PassTimer* timer) {
  if (backfaces_built_) return;
  backfaces_built_ = true;
  bind_frame_inputs();
  gl::ScopedPass pass(timer, "backfaces");
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

void Renderer::hiz_pass(gl::PassTimer* timer) {
  if (hiz_built_) return;
  gl::ScopedPass pass(timer, "hiz pyramid");
  hiz_.build(gbuffer_.depth);
  hiz_built_ = true;
}

void Renderer::ensure_history() {
  if (history_) return;
  history_.emplace(History{gl::Texture2D("history lit", GL_RGBA16F, width_, height_),
                           gl::Texture2D("history depth", GL_DEPTH_COMPONENT32F, width_, height_),
                           gl::Texture2D("history normal+roughness", GL_RGBA16F, width_, height_)});
  glTextureParameteri(history_->lit.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(history_->lit.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // First asked for now: there is no previous frame yet.
  copy_texture(lit_, history_->lit);
  copy_texture(gbuffer_.depth, history_->depth);
  copy_texture(gbuffer_.normal_roughness, history_->normal_roughness);
  // A frame that kept its history until a technique first asked for it (a reason already given,
  // a resize or the first frame, stays).
  if (history_valid()) history_break_ = "no technique kept a history before this frame";
}

Renderer::TechniqueState& Renderer::technique_state(Technique& t, const TechniqueDecl& decl) {
  auto [it, fresh] = states_.try_emplace(t.instance_id());
  TechniqueState& s = it->second;
  const std::string params = param_signature(t.params());
  const bool same_frame = !fresh && s.serial == serial_;
  const bool continues = !fresh && s.serial + 1 == serial_ && history_valid();
  const bool resized = s.width != width_ || s.height != height_;
  bool reset = fresh || (!same_frame && !continues) || s.params != params || resized ||
               s.generation != generation_;
  if (resized || s.decls != decl.textures) {
    s.textures.clear();
    for (const TextureDecl& d : decl.textures) {
      const int w = (width_ + d.divisor - 1) / d.divisor, h = (height_ + d.divisor - 1) / d.divisor;
      s.textures.emplace_back(t.name() + " " + d.name, d.format, w, h);
    }
    s.decls = decl.textures;
    reset = true;
  }
  if (!(decl.reads & kReadPrevColor)) {
    s.prev_color = gl::Texture2D();  // released: a later resize would have left them stale
    s.next_color = gl::Texture2D();
    s.next_color_kept = false;
  } else if (s.prev_color.width() != width_ || s.prev_color.height() != height_) {
    for (gl::Texture2D* c : {&s.prev_color, &s.next_color}) {
      *c = gl::Texture2D(t.name() + " previous colour", GL_RGBA16F, width_, height_);
      glTextureParameteri(c->id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTextureParameteri(c->id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    s.next_color_kept = false;
    reset = true;
  }
  if (!same_frame) {  // last frame's colour becomes the previous one
    std::swap(s.prev_color, s.next_color);
    s.prev_color_valid = s.next_color_kept;
    s.next_color_kept = false;
  }
  if (reset) {
    for (std::size_t i = 0; i < s.textures.size(); ++i)
      if (s.decls[i].persistent) clear_texture(s.textures[i]);
    // Not read until a frame keeps one again; zeroed, so no history texture holds a stale value.
    s.prev_color_valid = s.next_color_kept = false;
    if (s.prev_color) {
      clear_texture(s.prev_color);
      clear_texture(s.next_color);
    }
    t.reset();
  }
  s.serial = serial_;
  s.params = params;
  s.width = width_;
  s.height = height_;
  s.generation = generation_;
  return s;
}

void Renderer::technique_pass(Technique& t, const TechniqueDecl& decl, TechniqueState& state, bool debug,
                              gl::PassTimer* timer) {
  // Outputs the technique does not write are cleared, so nobody reads or shows another's image;
  // once, after a technique that wrote them (a clear each frame took 0.29 ms at 1080p on the H200).
  const auto clear_unless_written = [](bool writes, bool& dirty, const gl::Texture2D& tex) {
    if (!writes && dirty) clear_texture(tex);
    dirty = writes;
  };
  // Only views of the debug image itself count: stage views show the technique's own textures
  // and telemetry views the ray counts (stochastic declares those and writes no debug image, so
  // the viewer's inspector showed the previous technique's steps as stochastic's).
  const bool image_view = std::any_of(decl.debug_views.begin(), decl.debug_views.end(), [&](ViewMode v) {
    const bool stage = std::any_of(decl.stage_views.begin(), decl.stage_views.end(),
                                   [v](const StageView& s) { return s.view == v; });
    return !stage && !view_info(v).telemetry;
  });
  debug_written_ = debug && image_view;
  clear_unless_written(debug_written_, debug_dirty_, debug_);
  clear_unless_written(decl.writes_refraction, refraction_dirty_, refraction_);
  const auto rebind = [this, &state] {
    bind_frame_inputs();
    glBindImageTexture(IMG_OUT2, debug_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(IMG_REFRACTION, refraction_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    if (state.prev_color) glBindTextureUnit(TEX_PREV_COLOR, state.prev_color.id());
  };
  rebind();
  FrameContext ctx{width_, height_, posed_scene(), geometry_id_, camera_, matrices_, frame_settings_,
                   time_, serial_, history_valid(), state.prev_color_valid, scene_diagonal_, frame_ubo_.id(),
                   gbuffer_, lit_, motion_, hiz_built_ ? &hiz_.texture() : nullptr, *gpu_scene_, {}, &reflection_,
                   &refraction_, debug ? &debug_ : nullptr, timer, rebind};
  for (gl::Texture2D& tex : state.textures) ctx.textures.push_back(&tex);
  t.run(ctx);
  // After the run: a history pair's views name the texture this run wrote (declared before it, a
  // reset in between showed the pair it had just zeroed).
  stage_views_.clear();
  for (const StageView& v : t.declare().stage_views)
    stage_views_.emplace_back(v.view, state.textures.at(static_cast<std::size_t>(v.texture)).id());
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void Renderer::composite_pass(int blend, gl::PassTimer* timer) {
  blend_ = blend;
  bind_frame_inputs();
  gl::ScopedPass pass(timer, kFramePasses[2]);  // composite
  glBindImageTexture(IMG_OUT, color_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glProgramUniform1i(composite_prog_.id(), 0, blend_);
  composite_prog_.dispatch_2d(width_, height_);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void Renderer::display_pass(ViewMode view, gl::PassTimer* timer) {
  bind_frame_inputs();
  gl::ScopedPass pass(timer, kFramePasses[3]);  // display
  glBindImageTexture(IMG_OUT, display_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glBindImageTexture(IMG_OUT2, linear_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glProgramUniform1i(display_prog_.id(), 0, static_cast<int>(view));
  GLuint stage = debug_.id();  // a valid texture at the unit even when the view reads none
  for (const auto& [mode, id] : stage_views_)
    if (mode == view) stage = id;
  glBindTextureUnit(TEX_STAGE_VIEW, stage);
  if (view_info(view).telemetry) telemetry_.bind_for(width_, height_);
  display_prog_.dispatch_2d(width_, height_);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
}

// The technique's composited colour, for its next frame (TEX_PREV_COLOR).
void Renderer::keep_color(TechniqueState& state) {
  copy_texture(color_, state.next_color);
  state.next_color_kept = true;
}

RgbaImage8 Renderer::read_display() const {
  return {width_, height_, gl::read_texture<std::uint8_t>(display_, GL_RGBA, GL_UNSIGNED_BYTE, 4)};
}

RgbaImageF Renderer::read_texture(const gl::Texture2D& tex) const {
  return {tex.width(), tex.height(), gl::read_texture<float>(tex, GL_RGBA, GL_FLOAT, 4)};
}

std::vector<std::uint16_t> Renderer::read_material() const {
  return gl::read_texture<std::uint16_t>(gbuffer_.material, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT, 4);
}

RgbaImageF Renderer::read_linear() const { return read_texture(linear_); }

std::vector<float> Renderer::read_depth() const {
  return gl::read_texture<float>(gbuffer_.depth, GL_DEPTH_COMPONENT, GL_FLOAT, 1);
}

}  // namespace ssr
