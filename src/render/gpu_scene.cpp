#include "render/gpu_scene.h"

#include <algorithm>
#include <cstddef>

#include <glm/gtc/type_ptr.hpp>

#include "shared/bindings.h"
#include "shared/frame.h"

namespace ssr {

namespace {
gl::Texture2D upload_image(const Image& im, GLenum format, const char* label) {
  gl::Texture2D tex(label, format, im.width, im.height, 0);
  // Scene images store the top row first; GL's first row is the bottom (v = 0).
  std::vector<std::uint8_t> flipped(im.rgba.size());
  const std::size_t row = static_cast<std::size_t>(im.width) * 4;
  for (int y = 0; y < im.height; ++y)
    std::copy_n(im.rgba.data() + row * static_cast<std::size_t>(im.height - 1 - y), row,
                flipped.data() + row * static_cast<std::size_t>(y));
  glTextureSubImage2D(tex.id(), 0, 0, 0, im.width, im.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      flipped.data());
  glGenerateTextureMipmap(tex.id());
  glTextureParameteri(tex.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(tex.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  return tex;
}
}  // namespace

GpuScene::GpuScene(const Scene& scene) : vao_("scene vao") {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  for (const Mesh& m : scene.meshes) {
    const Material& mat = scene.materials[static_cast<std::size_t>(m.material)];
    Draw d{};
    d.index_count = static_cast<GLsizei>(m.indices.size());
    d.index_offset = static_cast<GLintptr>(indices.size() * sizeof(std::uint32_t));
    d.base_vertex = static_cast<GLint>(vertices.size());
    vertices.insert(vertices.end(), m.vertices.begin(), m.vertices.end());
    indices.insert(indices.end(), m.indices.begin(), m.indices.end());
    shared::DrawUniforms u{};
    u.albedo_metallic = glm::vec4(mat.albedo, mat.metallic);
    u.material = glm::vec4(mat.roughness, mat.reflectance, mat.normal_strength, mat.ior);
    u.emission = glm::vec4(mat.emission, 0.0f);
    u.ids = glm::ivec4(m.reflector, mat.albedo_texture >= 0, mat.normal_texture >= 0,
                       mat.transparent ? 1 : 0);
    u.object = glm::ivec4(static_cast<int>(draws_.size()), 0, 0, 0);
    u.model = u.prev_model = u.normal_model = glm::mat4(1.0f);
    d.ubo = gl::make_buffer("draw " + m.name, sizeof u, &u, GL_DYNAMIC_STORAGE_BIT);
    d.transparent = mat.transparent;
    has_transparent_ |= mat.transparent;
    draws_.push_back(std::move(d));
  }
  for (const Image& im : scene.images) {
    textures_.push_back(upload_image(im, GL_SRGB8_ALPHA8, "albedo map"));
    normal_textures_.push_back(upload_image(im, GL_RGBA8, "normal map"));
  }
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const Material& mat = scene.materials[static_cast<std::size_t>(scene.meshes[i].material)];
    draws_[i].albedo_tex =
        mat.albedo_texture >= 0 ? textures_[static_cast<std::size_t>(mat.albedo_texture)].id() : 0;
    draws_[i].normal_tex = mat.normal_texture >= 0
                               ? normal_textures_[static_cast<std::size_t>(mat.normal_texture)].id()
                               : 0;
  }

  vbo_ = gl::make_buffer("scene vertices", static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                         vertices.data(), 0);
  ibo_ = gl::make_buffer("scene indices",
                         static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                         indices.data(), 0);
  const GLuint vao = vao_.id();
  glVertexArrayVertexBuffer(vao, 0, vbo_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, ibo_.id());
  auto attrib = [&](GLuint loc, GLint n, std::size_t offset) {
    glEnableVertexArrayAttrib(vao, loc);
    glVertexArrayAttribFormat(vao, loc, n, GL_FLOAT, GL_FALSE, static_cast<GLuint>(offset));
    glVertexArrayAttribBinding(vao, loc, 0);
  };
  attrib(0, 3, offsetof(Vertex, position));
  attrib(1, 3, offsetof(Vertex, normal));
  attrib(2, 2, offsetof(Vertex, uv));
  attrib(3, 4, offsetof(Vertex, tangent));

  upload_lights(scene.lights);
}

void GpuScene::upload_lights(const std::vector<Light>& scene_lights) {
  std::vector<shared::GpuLight> lights;
  for (const Light& l : scene_lights) {
    shared::GpuLight g{};
    if (l.type == Light::Type::Point)
      g.position_type = glm::vec4(l.position, 0.0f);
    else
      g.position_type = glm::vec4(glm::normalize(l.direction), 1.0f);
    g.color_range = glm::vec4(l.color * l.intensity, l.range);
    lights.push_back(g);
  }
  light_count_ = static_cast<int>(lights.size());
  lights_ = gl::make_buffer("lights", static_cast<GLsizeiptr>(lights.size() * sizeof(shared::GpuLight)),
                            lights.data(), 0);
}

void GpuScene::set_transforms(const std::vector<glm::mat4>& model, const std::vector<glm::mat4>& prev_model) {
  for (std::size_t i = 0; i < draws_.size(); ++i) {
    Draw& d = draws_[i];
    const glm::mat4 m = i < model.size() ? model[i] : glm::mat4(1.0f);
    const glm::mat4 p = i < prev_model.size() ? prev_model[i] : glm::mat4(1.0f);
    if (m == d.model && p == d.prev_model) continue;  // static meshes upload nothing
    d.model = m;
    d.prev_model = p;
    const glm::mat4 mats[3] = {m, p, glm::transpose(glm::inverse(m))};
    glNamedBufferSubData(d.ubo.id(), offsetof(shared::DrawUniforms, model), sizeof mats, mats);
  }
}

void GpuScene::draw(bool transparent) const {
  glBindVertexArray(vao_.id());
  for (const Draw& d : draws_) {
    if (d.transparent != transparent) continue;
    glBindBufferBase(GL_UNIFORM_BUFFER, UBO_DRAW, d.ubo.id());
    glBindTextureUnit(TEX_ALBEDO_MAP, d.albedo_tex);
    glBindTextureUnit(TEX_NORMAL_MAP, d.normal_tex);
    glDrawElementsBaseVertex(GL_TRIANGLES, d.index_count, GL_UNSIGNED_INT,
                             reinterpret_cast<const void*>(d.index_offset), d.base_vertex);
  }
  glBindVertexArray(0);
}

}  // namespace ssr
