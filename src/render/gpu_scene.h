// A Scene uploaded to the GL: one vertex/index buffer for all meshes, material textures, lights.
#pragma once
#include <vector>

#include "gl/objects.h"
#include "scene/scene.h"

namespace ssr {

class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);
  // Draws the opaque (or the transparent) meshes into the bound framebuffer with the bound
  // program. Transparent meshes are kept out of the opaque G-buffer (2012 blog): what lies
  // behind them must stay visible to the tracers.
  void draw(bool transparent) const;
  bool has_transparent() const { return has_transparent_; }
  // Each mesh's animation transform this frame and the previous one (missing entries: identity):
  // the G-buffer moves the rest-pose vertices and draws motion vectors from the pair.
  void set_transforms(const std::vector<glm::mat4>& model, const std::vector<glm::mat4>& prev_model);
  // Replaces the lights (the viewer edits them live); the caller validated them.
  void upload_lights(const std::vector<Light>& lights);
  GLuint lights_ssbo() const { return lights_.id(); }
  int light_count() const { return light_count_; }
  // The albedo (sRGB, mip-mapped) texture of scene image i.
  GLuint albedo_texture(int image) const { return textures_[static_cast<std::size_t>(image)].id(); }
  GLuint normal_texture(int image) const { return normal_textures_[static_cast<std::size_t>(image)].id(); }

 private:
  struct Draw {
    GLsizei index_count;
    GLintptr index_offset;  // bytes
    GLint base_vertex;
    GLuint albedo_tex, normal_tex;  // 0 = none
    gl::Buffer ubo;                 // DrawUniforms
    bool transparent;
    glm::mat4 model{1.0f}, prev_model{1.0f};  // as uploaded
  };
  gl::VertexArray vao_;
  gl::Buffer vbo_, ibo_, lights_;
  std::vector<gl::Texture2D> textures_;        // one per scene image, as albedo (sRGB)
  std::vector<gl::Texture2D> normal_textures_; // one per scene image, linear (normal maps)
  std::vector<Draw> draws_;
  int light_count_ = 0;
  bool has_transparent_ = false;
};

}  // namespace ssr
