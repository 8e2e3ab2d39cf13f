// A Scene uploaded to the GL: one vertex/index buffer for all meshes, material textures, lights.
#pragma once
#include <vector>

#include "gl/objects.h"
#include "scene/scene.h"

namespace ssr {

class GpuScene {
 public:
  explicit GpuScene(const Scene& scene);
  // Draws every mesh into the bound framebuffer with the bound G-buffer program.
  void draw_gbuffer() const;
  GLuint lights_ssbo() const { return lights_.id(); }
  int light_count() const { return light_count_; }
  // The albedo (sRGB, mip-mapped) texture of scene image i.
  GLuint albedo_texture(int image) const { return textures_[static_cast<std::size_t>(image)].id(); }

 private:
  struct Draw {
    GLsizei index_count;
    GLintptr index_offset;  // bytes
    GLint base_vertex;
    GLuint albedo_tex, normal_tex;  // 0 = none
    gl::Buffer ubo;                 // DrawUniforms
  };
  gl::VertexArray vao_;
  gl::Buffer vbo_, ibo_, lights_;
  std::vector<gl::Texture2D> textures_;        // one per scene image, as albedo (sRGB)
  std::vector<gl::Texture2D> normal_textures_; // one per scene image, linear (normal maps)
  std::vector<Draw> draws_;
  int light_count_ = 0;
};

}  // namespace ssr
